/* dda.c - see dda.h. Steps: the points' rho^(1/4) and a cell list; the
 * pairs of each fixed chunk of anchors spread into the chunk's patch (a
 * square around the origin of the M x M grid: every scaled difference is
 * shorter than R Delta), or, for R = 0 or a patch as large as the grid,
 * every pair spread into the grid itself in one pass; the patches summed
 * into the grid in chunk order; one real-to-complex FFT; the real part
 * deconvolved, the diagonal and the window's transform accounted for. */
#define _GNU_SOURCE /* jn */
#include "dda.h"

#include <fftw3.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cellgrid.h"
#include "cli.h"
#include "geom.h"
#include "nufft.h"
#include "nufft_kernel.h"
#include "power.h"
#include "rings.h"

enum { CHUNKS = 32 };

enum { TAB_PER_UNIT = 1024 }; /* kernel table: samples per grid spacing */

typedef struct {
    an_nk k;
    int half, P; /* patch: grid offsets -half..half, side P = 2 half + 1 */
    int wrap;    /* spread into the M x M grid itself */
    double *tab; /* phi at t = -alpha + j / TAB_PER_UNIT, j = -1 .. w TAB_PER_UNIT + 2 (0 outside), from tab[1] */
} layout;

/* The table of the kernel (cubic interpolation: error about 1e-12 of its
 * peak, far below the spreading's own 1e-7). 0, or -1 out of memory. */
static int table_build(layout *L)
{
    const int N = L->k.w * TAB_PER_UNIT;
    if (!(L->tab = malloc(((size_t)N + 4) * sizeof *L->tab))) return -1;
    for (int j = -1; j <= N + 2; j++) {
        const double t = -L->k.alpha + (double)j / TAB_PER_UNIT;
        L->tab[j + 1] = j < 0 || j > N ? 0.0 : an_nk_at(&L->k, t);
    }
    return 0;
}

/* The w kernel values of a point at grid coordinate u, as an_nk_row, from
 * the table: the taps are one grid spacing apart, a whole number of table
 * steps, so they share one set of cubic Lagrange weights. */
static inline int table_row(const layout *L, double u, double *v)
{
    const int l0 = (int)ceil(u - L->k.alpha);
    const double p = (u - (double)l0 + L->k.alpha) * TAB_PER_UNIT; /* t of tap 0, in table steps from -alpha */
    const int j = (int)p;
    const double f = p - j, c0 = -f * (f - 1) * (f - 2) / 6, c1 = (f + 1) * (f - 1) * (f - 2) / 2,
                 c2 = -(f + 1) * f * (f - 2) / 2, c3 = (f + 1) * f * (f - 1) / 6;
    for (int a = 0; a < L->k.w; a++) {
        const double *t = L->tab + (j - a * TAB_PER_UNIT); /* tab[j - 1 + 1 ...]: j - 1 .. j + 2 */
        v[a] = c0 * t[0] + c1 * t[1] + c2 * t[2] + c3 * t[3];
    }
    return l0;
}

static void plan_layout(layout *L, size_t n, int K, double radius)
{
    L->k = (an_nk){.w = AN_DDA_WIDTH, .alpha = 0.5 * AN_DDA_WIDTH, .beta = 2.30 * AN_DDA_WIDTH};
    int M = 2 * (2 * K + 1);
    if (M < 2 * AN_DDA_WIDTH) M = 2 * AN_DDA_WIDTH;
    L->k.M = M = cfpo_nufft_fft_size(M);
    const double reach = radius * cfpo_delta_bound((double)n) * M + L->k.alpha;
    L->half = reach < M ? (int)ceil(reach) + 1 : M;
    L->P = 2 * L->half + 1;
    L->wrap = radius == 0 || L->P >= M;
}

double an_dda_bytes(size_t n, int K, double radius)
{
    layout L;
    plan_layout(&L, n, K, radius);
    const double M = L.k.M, patches = L.wrap ? 0 : (double)CHUNKS * L.P * L.P * 8.0;
    const double side = 2.0 * K + 1; /* the spectrum, the sets' sum, the rings */
    return 8.0 * M * (M + 2) + patches + 40.0 * (double)n + 24.0 * side * side + 4096.0;
}

int an_dda_check_memory(size_t n, int K, double radius, double have, char *err, size_t errlen)
{
    const double need = an_dda_bytes(n, K, radius);
    if (need <= 0.9 * have) return 0;
    snprintf(err, errlen, "the differential-domain spectrum of %zu points at K = %d needs %.2f GB, this machine has "
             "%.2f GB (a smaller -K needs less)", n, K, need / 1e9, have / 1e9);
    return -1;
}

double an_dda_window_ft(double k2, double radius, size_t n)
{
    if (radius == 0) return k2 == 0 ? 1.0 : 0.0;
    const double b = radius * cfpo_delta_bound((double)n), a = 2 * M_PI * sqrt(k2) * b;
    /* J3(a) / a^3 = (1/48) (1 - a^2/16 + a^4/640 - ...) */
    const double j = a < 1e-2 ? (1 - a * a / 16 + a * a * a * a / 640) / 48 : jn(3, a) / (a * a * a);
    return 16 * M_PI * b * b * j;
}

/* Adds weight c at the scaled difference (dx, dy) into a patch (stride P,
 * origin at (half, half)) or, wrapping, into the grid (stride s). */
static void spread(const layout *L, double dx, double dy, double c, double *g, size_t stride)
{
    double vx[32], vy[32];
    const an_nk *k = &L->k;
    const int M = k->M, w = k->w;
    const int lx = table_row(L, dx * M, vx), ly = table_row(L, dy * M, vy);
    if (!L->wrap) {
        for (int b = 0; b < w; b++) {
            double *r = g + (size_t)(ly + b + L->half) * stride + (size_t)(lx + L->half);
            const double cy = c * vy[b];
            for (int a = 0; a < w; a++) r[a] += cy * vx[a];
        }
        return;
    }
    for (int b = 0; b < w; b++) {
        int row = (ly + b) % M;
        row += row < 0 ? M : 0;
        double *r = g + (size_t)row * stride;
        const double cy = c * vy[b];
        for (int a = 0; a < w; a++) {
            int col = (lx + a) % M;
            col += col < 0 ? M : 0;
            r[col] += cy * vx[a];
        }
    }
}

typedef struct {
    const double *xy, *q; /* q = rho^(1/4) */
    size_t n;
    double b2;            /* (R Delta)^2; 0: every pair, no window */
    const an_cellgrid *G;
} pairs_in;

static double nearest(double v) { return v - floor(v + 0.5); }

/* The pairs of anchor i into g; returns how many. */
static double anchor_pairs(const pairs_in *in, const layout *L, size_t i, double *g, size_t stride)
{
    const double qi = in->q[i], xi = in->xy[2 * i], yi = in->xy[2 * i + 1];
    double count = 0;
    if (qi == 0) return 0;
    if (in->b2 == 0) { /* every pair once, no window */
        for (size_t j = i + 1; j < in->n; j++) {
            const double f = qi * in->q[j];
            if (f == 0) continue;
            spread(L, nearest(in->xy[2 * j] - xi) * f, nearest(in->xy[2 * j + 1] - yi) * f, 2.0, g, stride);
            count++;
        }
        return count;
    }
    const an_cellgrid *G = in->G;
    const size_t gs = G->g;
    const double s = sqrt(in->b2) / (qi * qi); /* R r_i */
    const long reach = (long)ceil(s / G->L), span = 2 * reach + 1 >= (long)gs ? (long)gs : 2 * reach + 1;
    long cx = (long)(xi * (double)gs), cy = (long)(yi * (double)gs);
    cx = cx >= (long)gs ? (long)gs - 1 : cx;
    cy = cy >= (long)gs ? (long)gs - 1 : cy;
    const long x0 = span == (long)gs ? 0 : cx - reach, y0 = span == (long)gs ? 0 : cy - reach;
    for (long a = 0; a < span; a++) {
        const size_t row = (size_t)(((y0 + a) % (long)gs + (long)gs) % (long)gs);
        for (long b = 0; b < span; b++) {
            const size_t c = row * gs + (size_t)(((x0 + b) % (long)gs + (long)gs) % (long)gs);
            for (size_t t = G->start[c]; t < G->start[c + 1]; t++) {
                const size_t j = G->idx[t];
                const double qj = in->q[j];
                if (qj < qi || (qj == qi && j <= i)) continue;
                const double f = qi * qj, dx = nearest(in->xy[2 * j] - xi) * f, dy = nearest(in->xy[2 * j + 1] - yi) * f;
                const double s2 = (dx * dx + dy * dy) / in->b2;
                if (s2 >= 1) continue;
                spread(L, dx, dy, 2.0 * (1 - s2) * (1 - s2), g, stride);
                count++;
            }
        }
    }
    return count;
}

/* The grid after spreading every pair; returns the number of pairs or -1. */
static double spread_pairs(const pairs_in *in, const layout *L, double *grid, size_t stride)
{
    if (L->wrap) {
        double count = 0;
        for (size_t i = 0; i < in->n; i++) count += anchor_pairs(in, L, i, grid, stride);
        return count;
    }
    const size_t P = (size_t)L->P;
    double *patch = calloc((size_t)CHUNKS * P * P, sizeof *patch);
    double counts[CHUNKS] = {0};
    if (!patch) return -1;
#pragma omp parallel for schedule(dynamic, 1)
    for (int c = 0; c < CHUNKS; c++) {
        const size_t from = in->n * (size_t)c / CHUNKS, to = in->n * (size_t)(c + 1) / CHUNKS;
        for (size_t i = from; i < to; i++) counts[c] += anchor_pairs(in, L, i, patch + (size_t)c * P * P, P);
    }
    double count = 0;
    const int M = L->k.M;
    for (int c = 0; c < CHUNKS; c++) {
        count += counts[c];
        const double *p = patch + (size_t)c * P * P;
        for (size_t r = 0; r < P; r++) {
            const int row = (((int)r - L->half) % M + M) % M;
            double *gr = grid + (size_t)row * stride;
            for (size_t t = 0; t < P; t++) gr[(((int)t - L->half) % M + M) % M] += p[r * P + t];
        }
    }
    free(patch);
    return count;
}

static int fft_real(double *grid, int M, char *err, size_t errlen)
{
    static pthread_mutex_t planner = PTHREAD_MUTEX_INITIALIZER;
    pthread_mutex_lock(&planner);
    fftw_plan plan = fftw_plan_dft_r2c_2d(M, M, grid, (fftw_complex *)grid, FFTW_ESTIMATE);
    pthread_mutex_unlock(&planner);
    if (!plan) {
        snprintf(err, errlen, "differential-domain spectrum: FFTW could not plan a %d x %d transform", M, M);
        return -1;
    }
    fftw_execute(plan);
    pthread_mutex_lock(&planner);
    fftw_destroy_plan(plan);
    pthread_mutex_unlock(&planner);
    return 0;
}

int an_dda_compute(const cfpo_density *d, const double *xy, size_t n, int K, double radius, double *S,
                   an_dda_info *info, char *err, size_t errlen)
{
    if (n < 2 || K < 1 || K > AN_KMAX || !(radius == 0 || (radius >= 1 && radius <= 64))) {
        snprintf(err, errlen, "differential-domain spectrum: bad request (n=%zu, K=%d, R=%g)", n, K, radius);
        return -1;
    }
    if (radius == 0 && n > AN_DDA_FULL_MAX) {
        snprintf(err, errlen, "differential-domain spectrum: every pair (R = 0) is O(n^2): at most %d points, "
                 "not %zu", AN_DDA_FULL_MAX, n);
        return -1;
    }
    layout L;
    plan_layout(&L, n, K, radius);
    const int M = L.k.M;
    const size_t stride = 2 * ((size_t)M / 2 + 1);
    double *q = malloc(n * sizeof *q), *phihat = malloc(((size_t)K + 1) * sizeof *phihat);
    double *grid = fftw_malloc(sizeof(double) * (size_t)M * stride);
    an_cellgrid G = {0};
    int rc = -1;
    L.tab = NULL;
    if (!q || !phihat || !grid || table_build(&L) != 0 || (radius > 0 && an_cellgrid_build(xy, n, &G) != 0))
        goto oom;
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        const double r = cfpo_density_at(d, xy[2 * i], xy[2 * i + 1]);
        q[i] = sqrt(sqrt(r));
        m += r > 0;
    }
    if (m == 0) {
        snprintf(err, errlen, "differential-domain spectrum: no point lies where the density is above 0");
        goto out;
    }
#pragma omp parallel for schedule(static)
    for (int r = 0; r < M; r++) memset(grid + (size_t)r * stride, 0, stride * sizeof *grid);
    const double b = radius * cfpo_delta_bound((double)n);
    const pairs_in in = {.xy = xy, .q = q, .n = n, .b2 = b * b, .G = &G};
    const double pairs = spread_pairs(&in, &L, grid, stride);
    if (pairs < 0) goto oom;
    if (fft_real(grid, M, err, errlen) != 0) goto out;
    an_nk_ft(&L.k, K, phihat);
    const fftw_complex *c = (const fftw_complex *)grid;
    const size_t cs = (size_t)M / 2 + 1;
    const double dm = (double)m;
#pragma omp parallel for schedule(static)
    for (int ky = -K; ky <= K; ky++) {
        const fftw_complex *row = c + (size_t)(ky < 0 ? ky + M : ky) * cs;
        const double py = phihat[ky < 0 ? -ky : ky];
        for (int kx = ky < 0; kx <= K; kx++) {
            const double k2 = (double)kx * kx + (double)ky * ky;
            const double v = 1 + row[kx][0] / (py * phihat[kx]) / dm - dm * an_dda_window_ft(k2, radius, n);
            S[an_pidx(K, kx, ky)] = v;
            S[an_pidx(K, -kx, -ky)] = v;
        }
    }
    if (info) *info = (an_dda_info){.radius = radius, .pairs = pairs, .grid = M, .m = m};
    rc = 0;
    goto out;
oom:
    snprintf(err, errlen, "out of memory for the differential-domain spectrum (%d x %d grid)", M, M);
out:
    free(q);
    free(phihat);
    free(L.tab);
    fftw_free(grid);
    an_cellgrid_free(&G);
    return rc;
}

int an_dda_summarise(const double *S, int K, size_t n, an_dda_summary *out)
{
    an_rings r;
    if (an_rings_compute(S, K, &r) != 0) return -1;
    const double sn = sqrt((double)n);
    *out = (an_dda_summary){.peak = NAN, .peak_freq = NAN, .low = NAN, .aniso_db = NAN};
    for (int i = 1; i <= K; i++)
        if (r.count[i] > 0 && (out->peak_ring == 0 || r.mean[i] > out->peak)) out->peak = r.mean[i], out->peak_ring = i;
    out->peak_freq = out->peak_ring / sn;
    double s = 0, a = 0;
    int64_t cnt = 0, rings = 0;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++)
            if (cfpo_in_lowk_band(kx, ky, (int64_t)n)) s += S[an_pidx(K, kx, ky)], cnt++;
    if (cnt) out->low = s / (double)cnt;
    for (int i = (int)ceil(0.5 * sn); i <= K && i <= 2 * sn; i++)
        if (isfinite(r.aniso_db[i])) a += r.aniso_db[i], rings++;
    if (rings) out->aniso_db = a / (double)rings;
    an_rings_free(&r);
    return 0;
}

int an_dda_write_raps(const char *path, const double *S, int K, size_t n, int sets, double radius, char *err,
                      size_t errlen)
{
    an_rings r;
    if (an_rings_compute(S, K, &r) != 0) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    cli_atomic f;
    if (cli_atomic_open(&f, path, err, errlen) != 0) {
        an_rings_free(&r);
        return -1;
    }
    fprintf(f.f, "# differential-domain spectrum (Wei and Wang 2011, symmetric normalisation), radially averaged;\n"
                 "# window radius R = %g local spacings; n=%zu, sets=%d, K=%d (analysis/README.md)\n"
                 "# ring i holds the integer frequencies k with i-1/2 <= |k| < i+1/2\n"
                 "# r\tr/sqrt(n)\tdda\tanisotropy_db\tcount\n", radius, n, sets, K);
    for (int i = 1; i <= K; i++)
        fprintf(f.f, "%d\t%.9g\t%.9g\t%.9g\t%lld\n", i, i / sqrt((double)n), r.mean[i], r.aniso_db[i],
                (long long)r.count[i]);
    an_rings_free(&r);
    return cli_atomic_commit(&f, err, errlen);
}
