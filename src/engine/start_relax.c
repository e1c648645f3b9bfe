/* start_relax.c - see start_relax.h. */
#include "start_relax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"

/* r = RADIUS Delta(n); each pair nearer than r is pushed apart by
 * ALPHA (r - d) / 2 on each side, a point's whole move capped at CAP r;
 * STEPS steps (docs/tried.md, 2026-11-29, issue 44: 8 steps reach
 * delta_min 0.51, 16 steps 0.59 at 1,048,576 points; a full step,
 * ALPHA = 1, or a wider r overshoots and stalls near 0.3). */
#define RADIUS 1.0
#define ALPHA 0.5
#define CAP 0.5
#define STEPS 32

static double radius(int64_t n) { return RADIUS * sqrt(2.0 / (sqrt(3.0) * (double)n)); }

int cfpo_start_relax_steps(int64_t n)
{
    /* the 3 x 3 bins must be distinct bins of the torus */
    return n > 0 && floor(1.0 / radius(n)) >= 3 ? STEPS : 0;
}

double cfpo_start_relax_reach(int64_t n)
{
    /* per step a point's dependence widens by r and by the moves of both
     * ends (CAP r each); its own moves add CAP r a step */
    return cfpo_start_relax_steps(n) * radius(n) * (1 + 3 * CAP) + radius(n);
}

static inline double wrap_half(double d)
{
    if (d > 0.5) return d - 1.0;
    if (d < -0.5) return d + 1.0;
    return d;
}

static inline int64_t axis_bin(double v, int64_t nb)
{
    int64_t b = (int64_t)(v * (double)nb);
    return b >= nb ? nb - 1 : (b < 0 ? 0 : b);
}

typedef struct {
    int64_t nb, rb0, rows; /* bins a side; the band's first bin row; its rows */
    uint32_t *off;         /* CSR offsets over the band's bins (rows x nb) */
    uint32_t *idx;         /* points, bin by bin, each bin's by key */
} bins;

/* The band's bin of a torus bin (bx, by), or -1 when the row is not in
 * the band. */
static inline int64_t band_bin(const bins *B, int64_t bx, int64_t by)
{
    const int64_t rel = ((by - B->rb0) % B->nb + B->nb) % B->nb;
    return rel < B->rows ? rel * B->nb + bx : -1;
}

static void bin_points(bins *B, const double *x, const double *y, const uint64_t *key, size_t m, int32_t *bof)
{
    const int64_t nbin = B->rows * B->nb;
    memset(B->off, 0, (size_t)(nbin + 1) * sizeof *B->off);
    for (size_t i = 0; i < m; i++) {
        bof[i] = (int32_t)band_bin(B, axis_bin(x[i], B->nb), axis_bin(y[i], B->nb));
        if (bof[i] >= 0) B->off[bof[i] + 1]++;
    }
    for (int64_t b = 0; b < nbin; b++) B->off[b + 1] += B->off[b];
    for (size_t i = 0; i < m; i++) /* off[b] runs ahead, then is restored */
        if (bof[i] >= 0) B->idx[B->off[bof[i]]++] = (uint32_t)i;
    for (int64_t b = nbin; b > 0; b--) B->off[b] = B->off[b - 1];
    B->off[0] = 0;
    for (int64_t b = 0; b < nbin; b++) /* each bin by key: the sum's order */
        for (uint32_t s = B->off[b] + 1; s < B->off[b + 1]; s++) {
            const uint32_t t = B->idx[s];
            uint32_t j = s;
            while (j > B->off[b] && key[B->idx[j - 1]] > key[t]) {
                B->idx[j] = B->idx[j - 1];
                j--;
            }
            B->idx[j] = t;
        }
}

/* One point's move from the old positions (x, y). */
static void move_one(const bins *B, const double *x, const double *y, size_t i, double r, double *nx, double *ny)
{
    const int64_t bx = axis_bin(x[i], B->nb), by = axis_bin(y[i], B->nb);
    double fx = 0, fy = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t b = band_bin(B, (bx + dx + B->nb) % B->nb, (by + dy + B->nb) % B->nb);
            if (b < 0) continue;
            for (uint32_t s = B->off[b]; s < B->off[b + 1]; s++) {
                const uint32_t j = B->idx[s];
                if (j == i) continue;
                const double ex = wrap_half(x[i] - x[j]), ey = wrap_half(y[i] - y[j]);
                const double d = sqrt(ex * ex + ey * ey);
                if (d < r && d > 0) {
                    const double w = 0.5 * (r - d) / d;
                    fx += w * ex;
                    fy += w * ey;
                }
            }
        }
    const double len = ALPHA * sqrt(fx * fx + fy * fy), lim = CAP * r;
    const double s = len > lim ? ALPHA * lim / len : ALPHA;
    double u = x[i] + s * fx, v = y[i] + s * fy;
    u -= floor(u);
    v -= floor(v);
    *nx = u < 1.0 ? u : 0.0;
    *ny = v < 1.0 ? v : 0.0;
}

int cfpo_start_relax(double *x, double *y, const uint64_t *key, size_t m, int64_t n, double ylo, double yhi,
                     int threads)
{
    const int steps = cfpo_start_relax_steps(n);
    if (steps == 0 || m == 0) return 0;
    const double r = radius(n);
    bins B;
    B.nb = (int64_t)floor(1.0 / r);
    if (yhi - ylo >= 1.0) {
        B.rb0 = 0;
        B.rows = B.nb;
    } else {
        B.rb0 = (int64_t)floor(ylo * (double)B.nb);
        B.rows = (int64_t)ceil(yhi * (double)B.nb) - B.rb0 + 1;
        if (B.rows > B.nb) B.rows = B.nb;
    }
    if (m >= UINT32_MAX || B.rows * B.nb >= INT32_MAX) return -1;
    B.off = malloc((size_t)(B.rows * B.nb + 1) * sizeof *B.off);
    B.idx = malloc(m * sizeof *B.idx);
    int32_t *bof = malloc(m * sizeof *bof);
    double *x2 = malloc(m * sizeof *x2), *y2 = malloc(m * sizeof *y2);
    if (!B.off || !B.idx || !bof || !x2 || !y2) {
        free(B.off); free(B.idx); free(bof); free(x2); free(y2);
        return -1;
    }
    double *px = x, *py = y, *qx = x2, *qy = y2;
    for (int k = 0; k < steps; k++) {
        bin_points(&B, px, py, key, m, bof);
#pragma omp parallel for schedule(static, 4096) num_threads(threads > 0 ? threads : 1)
        for (size_t i = 0; i < m; i++) move_one(&B, px, py, i, r, &qx[i], &qy[i]);
        double *t = px; px = qx; qx = t;
        t = py; py = qy; qy = t;
    }
    if (px != x) {
        memcpy(x, px, m * sizeof *x);
        memcpy(y, py, m * sizeof *y);
    }
    free(B.off); free(B.idx); free(bof); free(x2); free(y2);
    return 0;
}
