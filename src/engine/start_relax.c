/* start_relax.c - see start_relax.h. */
#include "start_relax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bigmem.h"
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

static inline int64_t axis_bin(double v, int64_t nb)
{
    int64_t b = (int64_t)(v * (double)nb);
    return b >= nb ? nb - 1 : (b < 0 ? 0 : b);
}

typedef struct {
    int64_t nb, rb0, rows; /* bins a side; the band's first bin row; its rows */
    uint32_t *off;         /* CSR offsets over the band's bins (rows x nb) */
    double *sx, *sy;       /* the points' positions, bin by bin, each bin's by key */
} bins;

/* The band's row of a torus bin row, or -1 when it is not in the band. */
static inline int64_t band_row(const bins *B, int64_t by)
{
    int64_t rel = by - B->rb0; /* both in [0, nb) */
    if (rel < 0) rel += B->nb;
    return rel < B->rows ? rel : -1;
}

/* The band bin of a point, or -1 when its row is not in the band. */
static inline int64_t bin_of(const bins *B, double px, double py)
{
    const int64_t row = band_row(B, axis_bin(py, B->nb));
    return row < 0 ? -1 : row * B->nb + axis_bin(px, B->nb);
}

/* The order of the m points (px, py) with ids id[] (keys key[id]) by band
 * bin, each bin's by key, those outside the band's bins last in their
 * order: ord[t] is the t-th point. B->off is set; returns how many are in
 * the band's bins. */
static size_t bin_points(bins *B, const double *px, const double *py, const uint32_t *id, const uint64_t *key,
                         size_t m, uint32_t *ord)
{
    const int64_t nbin = B->rows * B->nb;
    memset(B->off, 0, (size_t)(nbin + 1) * sizeof *B->off);
    for (size_t i = 0; i < m; i++) {
        const int64_t b = bin_of(B, px[i], py[i]);
        if (b >= 0) B->off[b + 1]++;
    }
    for (int64_t b = 0; b < nbin; b++) B->off[b + 1] += B->off[b];
    const size_t nin = B->off[nbin];
    size_t out = nin;
    for (size_t i = 0; i < m; i++) { /* off[b] runs ahead, then is restored */
        const int64_t b = bin_of(B, px[i], py[i]);
        ord[b >= 0 ? B->off[b]++ : out++] = (uint32_t)i;
    }
    for (int64_t b = nbin; b > 0; b--) B->off[b] = B->off[b - 1];
    B->off[0] = 0;
    for (int64_t b = 0; b < nbin; b++) /* each bin by key: the sum's order */
        for (uint32_t s = B->off[b] + 1; s < B->off[b + 1]; s++) {
            const uint32_t t = ord[s];
            uint32_t j = s;
            while (j > B->off[b] && key[id[ord[j - 1]]] > key[id[t]]) {
                ord[j] = ord[j - 1];
                j--;
            }
            ord[j] = t;
        }
    return nin;
}

/* The pushes on (px, py) from the k points (cx, cy), which it overwrites,
 * added to (*fx, *fy) in their order. (Built with -fno-math-errno,
 * CMakeLists.txt: sqrt here never sets errno, and without the errno path
 * the first loop vectorises.) */
static void push(double px, double py, double r, double *cx, double *cy, int k, double *fx, double *fy)
{
#pragma omp simd
    for (int t = 0; t < k; t++) { /* every operation done, then chosen: no branch */
        double ex = px - cx[t], ey = py - cy[t];
        const double exm = ex - 1.0, exp = ex + 1.0, eym = ey - 1.0, eyp = ey + 1.0;
        ex = ex > 0.5 ? exm : (ex < -0.5 ? exp : ex);
        ey = ey > 0.5 ? eym : (ey < -0.5 ? eyp : ey);
        const double d = sqrt(ex * ex + ey * ey);
        const double w = 0.5 * (r - d) / (d > 0 ? d : 1.0);
        const double ws = (d < r) & (d > 0) ? w : 0.0;
        cx[t] = ws * ex;
        cy[t] = ws * ey;
    }
    for (int t = 0; t < k; t++) {
        *fx += cx[t];
        *fy += cy[t];
    }
}

/* The new position of a point at (px, py) in torus bin column bx, from
 * the binned old positions: its 3 x 3 bins in order (dy, then dx), each
 * bin's points by key; rows[dy + 1] is the band row of its bin row + dy,
 * or -1. The candidates are copied side by side; each pair's push is
 * computed on its own (the loop vectorises: element-wise IEEE operations
 * give the same bytes at any vector width), then the pushes are summed in
 * order (a pair farther than r adds zero). */
#define CHUNK 64
static void move_at(const bins *B, double px, double py, int64_t bx, const int64_t rows[3], double r, double *nx,
                    double *ny)
{
    double fx = 0, fy = 0;
    double cx[CHUNK], cy[CHUNK];
    int k = 0;
    for (int dy = 0; dy < 3; dy++) {
        if (rows[dy] < 0) continue;
        const uint32_t *o = B->off + rows[dy] * B->nb;
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t c = bx + dx < 0 ? B->nb - 1 : (bx + dx >= B->nb ? 0 : bx + dx);
            for (uint32_t t = o[c]; t < o[c + 1]; t++) {
                if (k == CHUNK) { /* a crowded start: sum what is gathered */
                    push(px, py, r, cx, cy, k, &fx, &fy);
                    k = 0;
                }
                cx[k] = B->sx[t];
                cy[k] = B->sy[t];
                k++;
            }
        }
    }
    push(px, py, r, cx, cy, k, &fx, &fy);
    const double len = ALPHA * sqrt(fx * fx + fy * fy), lim = CAP * r;
    const double s = len > lim ? ALPHA * lim / len : ALPHA;
    double u = px + s * fx, v = py + s * fy;
    u -= floor(u);
    v -= floor(v);
    *nx = u < 1.0 ? u : 0.0;
    *ny = v < 1.0 ? v : 0.0;
}

/* The band rows of torus bin rows by - 1, by, by + 1. */
static void rows_of(const bins *B, int64_t by, int64_t rows[3])
{
    for (int dy = -1; dy <= 1; dy++) rows[dy + 1] = band_row(B, (by + dy + B->nb) % B->nb);
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
        B.rb0 = (B.rb0 % B.nb + B.nb) % B.nb; /* only ever taken modulo nb */
    }
    if (m >= UINT32_MAX || B.rows * B.nb >= INT32_MAX) return -1;
    const int64_t nbin = B.rows * B.nb;
    /* (x, y) hold the positions in the order id[] (at first the callers');
     * each step orders them by bin (ord), gathers them in that order into
     * (sx, sy), turns ord into their ids, writes the new positions back
     * into (x, y) in that order, and the two id arrays swap. */
    const size_t offb = (size_t)(nbin + 1) * sizeof *B.off, db = m * sizeof(double), ib = m * sizeof(uint32_t);
    B.off = cfpo_map_bytes(offb); /* mapped: bigmem.h says why */
    B.sx = cfpo_map_bytes(db);
    B.sy = cfpo_map_bytes(db);
    uint32_t *id = cfpo_map_bytes(ib), *ord = cfpo_map_bytes(ib);
    if (!B.off || !B.sx || !B.sy || !id || !ord) {
        cfpo_unmap_bytes(B.off, offb); cfpo_unmap_bytes(B.sx, db); cfpo_unmap_bytes(B.sy, db);
        cfpo_unmap_bytes(id, ib); cfpo_unmap_bytes(ord, ib);
        return -1;
    }
    for (size_t i = 0; i < m; i++) id[i] = (uint32_t)i;
    const int nt = threads > 0 ? threads : 1;
    for (int k = 0; k < steps; k++) {
        const size_t nin = bin_points(&B, x, y, id, key, m, ord);
#pragma omp parallel num_threads(nt)
        {
#pragma omp for schedule(static, 4096)
            for (size_t t = 0; t < m; t++) {
                B.sx[t] = x[ord[t]];
                B.sy[t] = y[ord[t]];
                ord[t] = id[ord[t]]; /* from here on ord holds the ids */
            }
#pragma omp for schedule(static, 2)
            for (int64_t row = 0; row < B.rows; row++) {
                int64_t rows[3];
                rows_of(&B, (row + B.rb0) % B.nb, rows);
                for (int64_t bx = 0; bx < B.nb; bx++)
                    for (uint32_t t = B.off[row * B.nb + bx]; t < B.off[row * B.nb + bx + 1]; t++)
                        move_at(&B, B.sx[t], B.sy[t], bx, rows, r, &x[t], &y[t]);
            }
#pragma omp for schedule(static, 64)
            for (size_t t = nin; t < m; t++) { /* outside the band's bins */
                int64_t rows[3];
                rows_of(&B, axis_bin(B.sy[t], B.nb), rows);
                move_at(&B, B.sx[t], B.sy[t], axis_bin(B.sx[t], B.nb), rows, r, &x[t], &y[t]);
            }
        }
        uint32_t *tmp = id;
        id = ord;
        ord = tmp;
    }
    /* back to the callers' order */
    memcpy(B.sx, x, m * sizeof *x);
    memcpy(B.sy, y, m * sizeof *y);
    for (size_t t = 0; t < m; t++) {
        x[id[t]] = B.sx[t];
        y[id[t]] = B.sy[t];
    }
    cfpo_unmap_bytes(B.off, offb); cfpo_unmap_bytes(B.sx, db); cfpo_unmap_bytes(B.sy, db);
    cfpo_unmap_bytes(id, ib); cfpo_unmap_bytes(ord, ib);
    return 0;
}
