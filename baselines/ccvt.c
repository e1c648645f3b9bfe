/* ccvt.c - see ccvt.h. */
#include "ccvt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "dens_draw.h"
#include "dens_measure.h"
#include "geom.h"
#include "grid.h"
#include "hilbert.h"
#include "rng.h"
#include "stats.h"
#include "stoprule.h"

/* Random streams: the points' coordinates, the Hilbert curve's offset. */
#define CCVT_POINT_STREAM 0x4343565450544eULL  /* "CCVTPTN" */
#define CCVT_OFFSET_STREAM 0x434356544f4653ULL /* "CCVTOFS" */
#define CCVT_SITE_STREAM 0x43435654534954ULL   /* "CCVTSIT" */
/* Under a density: four more numbers for point k (site i), counter 4k + j. */
#define CCVT_POINT_DENS_STREAM 0x43435654504e44ULL /* "CCVTPND" */
#define CCVT_SITE_DENS_STREAM 0x43435654534944ULL  /* "CCVTSID" */
#define CCVT_MAX_POINTS (1LL << 31)

struct ccvt_engine {
    int64_t n, m;
    double L, tol;
    int update;         /* CCVT_UPDATE_PAIR or CCVT_UPDATE_PASS */
    double *site0;      /* 2 n: the sites at the start of the pass */
    double *pts;        /* 2 n m: slot k of site i at 2 (i m + k) */
    double *site;       /* 2 n */
    double *r;          /* largest distance of each site to its points */
    unsigned char *dirty_prev, *dirty_cur;
    double *gi, *gj;    /* per-pair scratch: gains */
    int32_t *ci, *cj;   /* per-pair scratch: candidate slots */
    int64_t *pairs;     /* pair list: i * n + j, i < j */
    size_t npairs, cap_pairs;
    int32_t *cell_start, *cell_sites;
    double *nn;
    int64_t swaps;
    double energy_swapped;
    int check;          /* compute energy_swapped every iteration */
    const cfpo_density *dens; /* NULL, or the density (deltas in its measure) */
    dens_draw draw;     /* its draws, during the start */
};


void ccvt_options_init(ccvt_options *o)
{
    memset(o, 0, sizeof *o);
    o->seed = 1;
    o->tol = CFPO_DEFAULT_TOL;
    o->points = CCVT_POINTS_LATTICE;
    o->update = CCVT_UPDATE_PAIR;
}

int ccvt_lattice_shape(int64_t N, int64_t *cols, int64_t *rows)
{
    int64_t a = (int64_t)floor(sqrt((double)N));
    while (a > 1 && (a + 1) * (a + 1) <= N) a++;
    while (a > 1 && N % a != 0) a--;
    *rows = a;
    *cols = N / a;
    return a >= 1 && *cols <= 2 * a ? 0 : -1;
}

int64_t ccvt_default_m(int64_t n)
{
    int64_t m = n > 0 ? ((int64_t)1 << 24) / n : 1024;
    if (m > 1024) m = 1024;
    if (m < 16) m = 16;
    return m;
}

static double d2(const double *p, const double *s)
{
    return cfpo_torus_dist2(p[0], p[1], s[0], s[1]);
}

/* Site i's centroid: its position plus the mean of the periodic
 * differences of its points (all within half a period of it). */
static void centroid(const ccvt_engine *E, int64_t i, const double *ref, double *c)
{
    const double *p = E->pts + 2 * i * E->m;
    double sx = 0, sy = 0;
    for (int64_t k = 0; k < E->m; k++) {
        sx += cfpo_torus_diff(p[2 * k], ref[0]);
        sy += cfpo_torus_diff(p[2 * k + 1], ref[1]);
    }
    c[0] = cfpo_wrap01(ref[0] + sx / (double)E->m);
    c[1] = cfpo_wrap01(ref[1] + sy / (double)E->m);
}

static double radius(const ccvt_engine *E, int64_t i)
{
    const double *p = E->pts + 2 * i * E->m, *s = E->site + 2 * i;
    double r2 = 0;
    for (int64_t k = 0; k < E->m; k++) {
        double v = d2(p + 2 * k, s);
        if (v > r2) r2 = v;
    }
    return sqrt(r2);
}

static ccvt_engine *alloc_engine(int64_t n, int64_t m, double L, double tol, char *err, size_t errlen)
{
    if (n < 2 || m < 1 || n * m > CCVT_MAX_POINTS) {
        snprintf(err, errlen, "n = %lld sites of m = %lld points: need n >= 2, m >= 1, n m <= 2^31",
                 (long long)n, (long long)m);
        return NULL;
    }
    ccvt_engine *E = calloc(1, sizeof *E);
    if (!E) goto oom;
    E->n = n;
    E->m = m;
    E->L = L;
    E->tol = tol;
    E->pts = malloc((size_t)(2 * n * m) * sizeof *E->pts);
    E->site = malloc((size_t)(2 * n) * sizeof *E->site);
    E->site0 = malloc((size_t)(2 * n) * sizeof *E->site0);
    E->r = malloc((size_t)n * sizeof *E->r);
    E->dirty_prev = malloc((size_t)n);
    E->dirty_cur = calloc((size_t)n, 1);
    E->gi = malloc((size_t)m * sizeof *E->gi);
    E->gj = malloc((size_t)m * sizeof *E->gj);
    E->ci = malloc((size_t)m * sizeof *E->ci);
    E->cj = malloc((size_t)m * sizeof *E->cj);
    E->nn = malloc((size_t)n * sizeof *E->nn);
    if (!E->pts || !E->site || !E->site0 || !E->r || !E->dirty_prev || !E->dirty_cur || !E->gi || !E->gj ||
        !E->ci || !E->cj || !E->nn)
        goto oom;
    memset(E->dirty_prev, 1, (size_t)n);
    return E;
oom:
    ccvt_free(E);
    snprintf(err, errlen, "out of memory for %lld sites of %lld points (%.0f MiB of points)",
             (long long)n, (long long)m, 16.0 * (double)n * (double)m / 1048576.0);
    return NULL;
}

/* Sites at the centroids of their points, the first point as reference. */
static void init_sites(ccvt_engine *E)
{
    for (int64_t i = 0; i < E->n; i++) {
        centroid(E, i, E->pts + 2 * i * E->m, E->site + 2 * i);
        E->r[i] = radius(E, i);
    }
}

ccvt_engine *ccvt_create_from(int64_t n, int64_t m, const double *pts, double L, double tol,
                              char *err, size_t errlen)
{
    ccvt_engine *E = alloc_engine(n, m, L, tol, err, errlen);
    if (!E) return NULL;
    memcpy(E->pts, pts, (size_t)(2 * n * m) * sizeof *pts);
    init_sites(E);
    return E;
}

/* The curve's index of (x, y) shifted by (ox, oy) on the torus. */
static uint32_t hilbert_key(double x, double y, double ox, double oy)
{
    uint32_t hx = (uint32_t)(cfpo_wrap01(x + ox) * 65536.0) & 0xffff;
    uint32_t hy = (uint32_t)(cfpo_wrap01(y + oy) * 65536.0) & 0xffff;
    return (uint32_t)cfpo_hilbert(65536, hx, hy);
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Discrete point k of the start: node (k mod cols, k div cols) of the
 * cols x rows lattice from the origin (Balzer's), or uniform random. */
static void start_point(const ccvt_engine *E, const ccvt_options *o, int64_t cols, int64_t rows, int64_t k,
                        double *xy)
{
    if (E->dens) {
        xy[0] = cfpo_rand01(o->seed, CCVT_POINT_STREAM, 2 * (uint64_t)k);
        xy[1] = cfpo_rand01(o->seed, CCVT_POINT_STREAM, 2 * (uint64_t)k + 1);
        dens_draw_at(&E->draw, o->seed, CCVT_POINT_DENS_STREAM, (uint64_t)k, &xy[0], &xy[1]);
    } else if (o->points == CCVT_POINTS_LATTICE) {
        xy[0] = (double)(k % cols) / (double)cols;
        xy[1] = (double)(k / cols) / (double)rows;
    } else {
        xy[0] = cfpo_rand01(o->seed, CCVT_POINT_STREAM, 2 * (uint64_t)k);
        xy[1] = cfpo_rand01(o->seed, CCVT_POINT_STREAM, 2 * (uint64_t)k + 1);
    }
}

/* Balzer's start: the sites uniform random in index order; the points,
 * the last first (lattice: columns from the right, each from the top),
 * each to the nearest site not yet full (periodic distance), found by
 * rings of a grid of about 2 sites a cell, full sites taken out of it.
 * 0, or -1 out of memory. */
static int assign_nearest(ccvt_engine *E, const ccvt_options *o, int64_t cols, int64_t rows)
{
    const int64_t n = E->n, m = E->m, N = n * m;
    int64_t g = (int64_t)floor(sqrt((double)n / 2.0));
    if (g < 1) g = 1;
    int64_t *start = calloc((size_t)(g * g + 1), sizeof *start), *fill = calloc((size_t)n, sizeof *fill);
    int32_t *cs = malloc((size_t)n * sizeof *cs), *cnt = calloc((size_t)(g * g), sizeof *cnt);
    if (!start || !fill || !cs || !cnt) {
        free(start); free(fill); free(cs); free(cnt);
        return -1;
    }
#define CELL(x, y) ((((int64_t)((y) * (double)g)) % g) * g + ((int64_t)((x) * (double)g)) % g)
    for (int64_t i = 0; i < n; i++) start[CELL(E->site[2 * i], E->site[2 * i + 1]) + 1]++;
    for (int64_t c = 0; c < g * g; c++) start[c + 1] += start[c];
    for (int64_t i = 0; i < n; i++) {
        const int64_t c = CELL(E->site[2 * i], E->site[2 * i + 1]);
        cs[start[c] + cnt[c]++] = (int32_t)i;
    }
    const double side = 1.0 / (double)g;
    for (int64_t t = N - 1; t >= 0; t--) {
        double p[2];
        if (o->points == CCVT_POINTS_LATTICE && !E->dens) { /* Balzer's order: x outer, y inner */
            p[0] = (double)(t / rows) / (double)cols;
            p[1] = (double)(t % rows) / (double)rows;
        } else {
            start_point(E, o, cols, rows, t, p);
        }
        const int64_t c0 = CELL(p[0], p[1]), cx = c0 % g, cy = c0 / g;
        double best = INFINITY;
        int64_t bi = -1;
        for (int64_t r = 0; r <= g / 2 + 1; r++) {
            if (bi >= 0 && (double)(r - 1) * side * ((double)(r - 1) * side) >= best) break;
            for (int64_t dy = -r; dy <= r; dy++)
                for (int64_t dx = -r; dx <= r; dx++) {
                    if (dx > -r && dx < r && dy > -r && dy < r) continue; /* ring r only */
                    const int64_t c = ((cy + dy) % g + g) % g * g + ((cx + dx) % g + g) % g;
                    for (int32_t k = 0; k < cnt[c]; k++) {
                        const int64_t i = cs[start[c] + k];
                        const double d = d2(p, E->site + 2 * i);
                        if (d < best || (d == best && i < bi)) { best = d; bi = i; }
                    }
                }
        }
        E->pts[2 * (bi * m + fill[bi])] = p[0];
        E->pts[2 * (bi * m + fill[bi]) + 1] = p[1];
        if (++fill[bi] == m) { /* full: out of its cell */
            const int64_t c = CELL(E->site[2 * bi], E->site[2 * bi + 1]);
            for (int32_t k = 0; k < cnt[c]; k++)
                if (cs[start[c] + k] == bi) { cs[start[c] + k] = cs[start[c] + --cnt[c]]; break; }
        }
    }
#undef CELL
    free(start); free(fill); free(cs); free(cnt);
    return 0;
}

static ccvt_engine *sites_and_points(ccvt_engine *E, const ccvt_options *o, int64_t cols, int64_t rows, char *err,
                                     size_t errlen);

ccvt_engine *ccvt_create(int64_t n, const ccvt_options *o, char *err, size_t errlen)
{
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, o->seed, err, errlen) != 0) return NULL;
    int64_t m = o->m > 0 ? o->m : ccvt_default_m(n), cols = 0, rows = 0;
    const int64_t N = n * m;
    if (o->points == CCVT_POINTS_LATTICE && !o->density && ccvt_lattice_shape(N, &cols, &rows) != 0) {
        snprintf(err, errlen,
                 "n m = %lld points have no lattice of nearly square cells (best %lld x %lld); "
                 "choose another --points-per-site or --point-set random",
                 (long long)N, (long long)cols, (long long)rows);
        return NULL;
    }
    ccvt_engine *E = alloc_engine(n, m, G.L, o->tol, err, errlen);
    if (!E) return NULL;
    E->update = o->update;
    E->dens = o->density;
    if (E->dens && dens_draw_init(&E->draw, E->dens) != 0) {
        ccvt_free(E);
        snprintf(err, errlen, "out of memory for the density's draws");
        return NULL;
    }
    ccvt_engine *R = sites_and_points(E, o, cols, rows, err, errlen); /* frees E on failure */
    if (R) dens_draw_free(&R->draw);
    return R;
}

/* The sites and the points' assignment (ccvt_create). */
static ccvt_engine *sites_and_points(ccvt_engine *E, const ccvt_options *o, int64_t cols, int64_t rows, char *err,
                                     size_t errlen)
{
    const int64_t n = E->n, N = n * E->m;
    if (o->assign == CCVT_ASSIGN_NEAREST) {
        for (int64_t i = 0; i < 2 * n; i++) E->site[i] = cfpo_rand01(o->seed, CCVT_SITE_STREAM, (uint64_t)i);
        if (E->dens)
            for (int64_t i = 0; i < n; i++)
                dens_draw_at(&E->draw, o->seed, CCVT_SITE_DENS_STREAM, (uint64_t)i, &E->site[2 * i], &E->site[2 * i + 1]);
        if (assign_nearest(E, o, cols, rows) != 0) {
            ccvt_free(E);
            snprintf(err, errlen, "out of memory for the start of %lld points", (long long)N);
            return NULL;
        }
        for (int64_t i = 0; i < n; i++) E->r[i] = radius(E, i);
        return E;
    }
    uint64_t *key = malloc((size_t)(N > n ? N : n) * sizeof *key);
    if (!key) {
        ccvt_free(E);
        snprintf(err, errlen, "out of memory for the start of %lld points", (long long)N);
        return NULL;
    }
    const double ox = cfpo_rand01(o->seed, CCVT_OFFSET_STREAM, 0);
    const double oy = cfpo_rand01(o->seed, CCVT_OFFSET_STREAM, 1);
    /* the sites: uniform random, in the order of the curve */
    for (int64_t i = 0; i < n; i++) {
        double x = cfpo_rand01(o->seed, CCVT_SITE_STREAM, 2 * (uint64_t)i);
        double y = cfpo_rand01(o->seed, CCVT_SITE_STREAM, 2 * (uint64_t)i + 1);
        if (E->dens) dens_draw_at(&E->draw, o->seed, CCVT_SITE_DENS_STREAM, (uint64_t)i, &x, &y);
        key[i] = (uint64_t)hilbert_key(x, y, ox, oy) << 32 | (uint64_t)i;
    }
    qsort(key, (size_t)n, sizeof *key, cmp_u64);
    for (int64_t r = 0; r < n; r++) {
        uint64_t i = key[r] & 0xffffffffu;
        E->site[2 * r] = cfpo_rand01(o->seed, CCVT_SITE_STREAM, 2 * i);
        E->site[2 * r + 1] = cfpo_rand01(o->seed, CCVT_SITE_STREAM, 2 * i + 1);
        if (E->dens) dens_draw_at(&E->draw, o->seed, CCVT_SITE_DENS_STREAM, i, &E->site[2 * r], &E->site[2 * r + 1]);
    }
    /* the points, in the order of the curve: run r of m goes to site r */
    for (int64_t k = 0; k < N; k++) {
        double xy[2];
        start_point(E, o, cols, rows, k, xy);
        key[k] = (uint64_t)hilbert_key(xy[0], xy[1], ox, oy) << 32 | (uint64_t)k;
    }
    qsort(key, (size_t)N, sizeof *key, cmp_u64);
    for (int64_t s = 0; s < N; s++) start_point(E, o, cols, rows, (int64_t)(key[s] & 0xffffffffu), E->pts + 2 * s);
    free(key);
    for (int64_t i = 0; i < n; i++) E->r[i] = radius(E, i);
    return E;
}

void ccvt_free(ccvt_engine *E)
{
    if (!E) return;
    dens_draw_free(&E->draw);
    free(E->pts);
    free(E->site);
    free(E->site0);
    free(E->r);
    free(E->dirty_prev);
    free(E->dirty_cur);
    free(E->gi);
    free(E->gj);
    free(E->ci);
    free(E->cj);
    free(E->pairs);
    free(E->cell_start);
    free(E->cell_sites);
    free(E->nn);
    free(E);
}

/* ---- the pairs that can swap -------------------------------------------- */

static int push_pair(ccvt_engine *E, int64_t i, int64_t j)
{
    if (E->npairs == E->cap_pairs) {
        size_t c = E->cap_pairs ? 2 * E->cap_pairs : 1024;
        int64_t *p = realloc(E->pairs, c * sizeof *p);
        if (!p) return -1;
        E->pairs = p;
        E->cap_pairs = c;
    }
    E->pairs[E->npairs++] = i < j ? i * E->n + j : j * E->n + i;
    return 0;
}

static int near_enough(const ccvt_engine *E, int64_t i, int64_t j)
{
    double rr = 2 * (E->r[i] > E->r[j] ? E->r[i] : E->r[j]);
    return d2(E->site + 2 * i, E->site + 2 * j) < rr * rr * (1 + 1e-12) + 1e-300;
}

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* Every pair i < j with |s_i - s_j| < 2 max(r_i, r_j), in increasing
 * (i, j) order: a hash grid of cells at least 2 max r wide, 3x3 blocks. */
static int build_pairs(ccvt_engine *E)
{
    const int64_t n = E->n;
    double rmax = 0;
    for (int64_t i = 0; i < n; i++)
        if (E->r[i] > rmax) rmax = E->r[i];
    E->npairs = 0;
    int64_t g = (int64_t)floor(1.0 / (2 * rmax * (1 + 1e-9) + 1e-300));
    if (g > 4096) g = 4096;
    if (g < 3) { /* wide regions (tiny n or an early start): all pairs */
        for (int64_t i = 0; i < n; i++)
            for (int64_t j = i + 1; j < n; j++)
                if (near_enough(E, i, j) && push_pair(E, i, j) != 0) return -1;
        return 0;
    }
    free(E->cell_start);
    free(E->cell_sites);
    E->cell_start = calloc((size_t)(g * g + 1), sizeof *E->cell_start);
    E->cell_sites = malloc((size_t)n * sizeof *E->cell_sites);
    if (!E->cell_start || !E->cell_sites) return -1;
#define CELL_OF(i) (((int64_t)(E->site[2 * (i) + 1] * g) % g) * g + ((int64_t)(E->site[2 * (i)] * g) % g))
    for (int64_t i = 0; i < n; i++) E->cell_start[CELL_OF(i) + 1]++;
    for (int64_t c = 0; c < g * g; c++) E->cell_start[c + 1] += E->cell_start[c];
    for (int64_t i = 0; i < n; i++) E->cell_sites[E->cell_start[CELL_OF(i)]++] = (int32_t)i;
    for (int64_t c = g * g; c > 0; c--) E->cell_start[c] = E->cell_start[c - 1];
    E->cell_start[0] = 0;
    for (int64_t i = 0; i < n; i++) {
        int64_t c = CELL_OF(i), cx = c % g, cy = c / g;
        for (int64_t dy = -1; dy <= 1; dy++)
            for (int64_t dx = -1; dx <= 1; dx++) {
                int64_t nc = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                for (int32_t t = E->cell_start[nc]; t < E->cell_start[nc + 1]; t++) {
                    int64_t j = E->cell_sites[t];
                    if (j > i && near_enough(E, i, j) && push_pair(E, i, j) != 0) return -1;
                }
            }
    }
#undef CELL_OF
    qsort(E->pairs, E->npairs, sizeof *E->pairs, cmp_i64);
    /* g == 3: a neighbour can be found from two cells; keep it once */
    size_t w = 0;
    for (size_t k = 0; k < E->npairs; k++)
        if (w == 0 || E->pairs[k] != E->pairs[w - 1]) E->pairs[w++] = E->pairs[k];
    E->npairs = w;
    return 0;
}

/* ---- the swap step of one pair ---------------------------------------------- */

static const double *g_sort_gain;
static int cmp_gain_desc(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    double gx = g_sort_gain[x], gy = g_sort_gain[y];
    if (gx != gy) return gx < gy ? 1 : -1;
    return (x > y) - (x < y);
}

/* Gains of site a's points for moving to site b; their maximum. */
static double gains(const ccvt_engine *E, int64_t a, int64_t b, double *g)
{
    const double *p = E->pts + 2 * a * E->m, *sa = E->site + 2 * a, *sb = E->site + 2 * b;
    double best = -INFINITY;
    for (int64_t k = 0; k < E->m; k++) {
        g[k] = d2(p + 2 * k, sa) - d2(p + 2 * k, sb);
        if (g[k] > best) best = g[k];
    }
    return best;
}

static int64_t candidates(const ccvt_engine *E, const double *g, double above, int32_t *c)
{
    int64_t k = 0;
    for (int64_t t = 0; t < E->m; t++)
        if (g[t] > above) c[k++] = (int32_t)t;
    g_sort_gain = g;
    qsort(c, (size_t)k, sizeof *c, cmp_gain_desc);
    return k;
}

/* Site i to the centroid of its points; its radius with it. */
static void to_centroid(ccvt_engine *E, int64_t i)
{
    double c[2];
    centroid(E, i, E->site + 2 * i, c);
    E->site[2 * i] = c[0];
    E->site[2 * i + 1] = c[1];
    if (E->update == CCVT_UPDATE_PAIR) E->r[i] = radius(E, i);
}

/* Swaps while the best remaining point of i and of j gain together; returns
 * the swaps made and adds their total gain to *gain. */
static int64_t swap_pair(ccvt_engine *E, int64_t i, int64_t j, double *gain)
{
    double mi = gains(E, i, j, E->gi), mj = gains(E, j, i, E->gj);
    if (!(mi + mj > 0)) return 0;
    int64_t ki = candidates(E, E->gi, -mj, E->ci), kj = candidates(E, E->gj, -mi, E->cj);
    int64_t k = ki < kj ? ki : kj, s = 0;
    double *pi = E->pts + 2 * i * E->m, *pj = E->pts + 2 * j * E->m;
    for (; s < k; s++) {
        double g = E->gi[E->ci[s]] + E->gj[E->cj[s]];
        if (!(g > 0)) break;
        *gain += g;
        double *a = pi + 2 * E->ci[s], *b = pj + 2 * E->cj[s], t0 = a[0], t1 = a[1];
        a[0] = b[0];
        a[1] = b[1];
        b[0] = t0;
        b[1] = t1;
    }
    return s;
}

/* ---- one iteration ----------------------------------------------------------- */

void ccvt_iterate(ccvt_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const int64_t n = E->n;
    int iteration = s->iteration;
    memset(s, 0, sizeof *s);
    s->iteration = iteration;
    /* radii of the sites that changed in the last iteration (the others
     * are as they were) */
    for (int64_t i = 0; i < n; i++)
        if (E->dirty_prev[i]) E->r[i] = radius(E, i);
    if (build_pairs(E) != 0) {
        /* out of memory for the pair list: compare every pair in turn */
        E->npairs = 0;
    }
    double gain = 0;
    E->swaps = 0;
    memset(E->dirty_cur, 0, (size_t)n);
    memcpy(E->site0, E->site, (size_t)(2 * n) * sizeof *E->site);
    for (size_t k = 0; k < E->npairs; k++) {
        int64_t i = E->pairs[k] / n, j = E->pairs[k] % n;
        if (!(E->dirty_prev[i] || E->dirty_prev[j] || E->dirty_cur[i] || E->dirty_cur[j])) continue;
        s->solved++;
        int64_t w = swap_pair(E, i, j, &gain);
        if (w) {
            E->swaps += w;
            E->dirty_cur[i] = E->dirty_cur[j] = 1;
            if (E->update == CCVT_UPDATE_PAIR) { /* Balzer's: both move now */
                to_centroid(E, i);
                to_centroid(E, j);
            }
        }
    }
    E->energy_swapped = E->check ? ccvt_energy(E) : NAN;
    /* the sites that swapped move to their centroids (once a pass) */
    double maxd2 = 0;
    for (int64_t i = 0; i < n; i++) {
        if (!E->dirty_cur[i]) continue;
        if (E->update == CCVT_UPDATE_PASS) to_centroid(E, i);
        double dd = d2(E->site0 + 2 * i, E->site + 2 * i);
        if (dd > maxd2) maxd2 = dd;
        s->moved++;
    }
    unsigned char *t = E->dirty_prev;
    E->dirty_prev = E->dirty_cur;
    E->dirty_cur = t;
    s->max_disp = sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = E->update == CCVT_UPDATE_PAIR ? E->swaps == 0 : cfpo_net_converged(E->swaps, s->max_disp, E->tol);
    ccvt_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

int64_t ccvt_swaps(const ccvt_engine *E) { return E->swaps; }
void ccvt_set_update(ccvt_engine *E, int update) { E->update = update; }
void ccvt_set_check(ccvt_engine *E, int on) { E->check = on; }
double ccvt_energy_after_swaps(const ccvt_engine *E) { return E->energy_swapped; }

double ccvt_energy(const ccvt_engine *E)
{
    double e = 0;
    for (int64_t i = 0; i < E->n; i++) {
        const double *p = E->pts + 2 * i * E->m, *si = E->site + 2 * i;
        for (int64_t k = 0; k < E->m; k++) e += d2(p + 2 * k, si);
    }
    return e;
}

void ccvt_deltas(ccvt_engine *E, double *dmin, double *davg)
{
    const int rc = E->dens ? cfpo_dens_nn(E->dens, E->site, (size_t)E->n, E->nn, dmin, davg)
                           : cfpo_nn_stats(E->site, (size_t)E->n, E->nn, dmin, davg);
    if (rc != 0) *dmin = *davg = NAN;
}

const double *ccvt_sites(const ccvt_engine *E) { return E->site; }
const double *ccvt_points(const ccvt_engine *E) { return E->pts; }
int64_t ccvt_m(const ccvt_engine *E) { return E->m; }
