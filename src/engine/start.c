/* start.c - see start.h. */
#include "start.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bigmem.h"
#include "geom.h"
#include "rng.h"
#include "start_relax.h"

#define START_SALT 0x2545f4914f6cdd1dULL
#define EXTRA_SALT 0x9e6c63d0676a9a99ULL
#define WARP_SALT 0x7f4a7c159e3779b9ULL
#define WARP_MAX_MODES 64
/* The warp's strength, measured at 65,536 points (docs/method.md): an rms
 * displacement of 1.5 start cells at a wavelength of 8 start cells removes
 * the start lattice's spike without making holes. Its 64 modes are
 * applied as shears one after the other (warp below), which keeps area
 * exactly; summed at one point they kept it to first order only, and
 * their second order beat pairs of modes into long waves (k_i - k_j)
 * that the relaxed start kept (docs/results/2026-11-29-imprint11.md). */
#define WARP_AMP 1.5
#define WARP_LEN 8.0
#define WARP_MODES 64

typedef struct {
    int64_t h;        /* start cells per side */
    uint64_t extra;   /* n - h^2 */
    double amp;       /* displacement amplitude, in start cells */
    double len;       /* wavelength of the field, in start cells */
    int modes;
} start_params;

static void params(const cfpo_grid *G, start_params *p)
{
    int64_t h = (int64_t)floor(sqrt((double)G->n));
    while (h * h > G->n) h--;
    while ((h + 1) * (h + 1) <= G->n) h++;
    p->h = h;
    p->extra = (uint64_t)(G->n - h * h);
    p->amp = WARP_AMP;
    p->len = WARP_LEN;
    p->modes = WARP_MODES;
}

typedef struct {
    double kx, ky, ph, cx, cy; /* wave vector, phase, displacement direction * amplitude */
} mode;

/* The modes: `modes` plane waves with integer wave vectors of length near
 * h / len (so they are periodic on the torus), each with a displacement
 * perpendicular to its wave vector, scaled so the rms displacement is
 * amp / h. */
static int make_modes(const cfpo_grid *G, const start_params *p, mode *md)
{
    if (!(p->amp > 0) || p->modes < 1) return 0;
    const double K = (double)p->h / p->len;
    const uint64_t key = G->seed ^ WARP_SALT;
    const double a = p->amp / (double)p->h / sqrt(0.5 * p->modes);
    for (int j = 0; j < p->modes; j++) {
        double ang = 2 * M_PI * cfpo_rand01(key, (uint64_t)j, 0);
        double rad = K * (0.75 + 0.5 * cfpo_rand01(key, (uint64_t)j, 1));
        double kx = round(rad * cos(ang)), ky = round(rad * sin(ang));
        if (kx == 0 && ky == 0) kx = 1;
        double kk = sqrt(kx * kx + ky * ky);
        md[j].kx = 2 * M_PI * kx;
        md[j].ky = 2 * M_PI * ky;
        md[j].ph = 2 * M_PI * cfpo_rand01(key, (uint64_t)j, 2);
        md[j].cx = -a * ky / kk;
        md[j].cy = a * kx / kk;
    }
    return p->modes;
}

/* The modes applied one after the other: each moves points along its
 * crests only (c is perpendicular to k, so k . x does not change), a shear
 * that keeps area exactly; so does their sequence. Summed at the same x
 * the modes would keep area only to first order, and their second order
 * beats pairs of modes into long waves (k_i - k_j) that a relaxed start
 * keeps (docs/tried.md, issue 44). */
static void warp(const mode *md, int nm, double *x, double *y)
{
    double u = *x, v = *y;
    for (int j = 0; j < nm; j++) {
        const double s = sin(md[j].kx * u + md[j].ky * v + md[j].ph);
        u += md[j].cx * s;
        v += md[j].cy * s;
    }
    *x = cfpo_wrap01(u);
    *y = cfpo_wrap01(v);
}

static uint64_t start_count(const cfpo_grid *G, const start_params *p, int64_t i, int64_t j)
{
    const uint64_t cells = (uint64_t)(p->h * p->h);
    const uint64_t base = 1 + p->extra / cells, rem = p->extra % cells;
    if (rem == 0) return base;
    uint64_t c = (uint64_t)(j * p->h + i);
    return base + (cfpo_permute(c, cells, cfpo_mix64(G->seed ^ EXTRA_SALT)) < rem ? 1 : 0);
}

static int cmp_pt(const void *a, const void *b)
{
    const cfpo_start_pt *p = a, *q = b;
    if (p->cell != q->cell) return p->cell < q->cell ? -1 : 1;
    return p->key < q->key ? -1 : (p->key > q->key);
}

/* pts[0, m) by (cell, key), cells in [c0, c0 + ncell): a stable counting
 * sort by cell, applied in place by following the permutation's cycles,
 * then each cell's run by key (an insertion sort: the runs are short and
 * in key order already, but where the band's start rows wrap the torus).
 * The keys are unique, so this is the order cmp_pt gives. Returns -1 (and
 * leaves pts as they were) if the work arrays cannot be had. */
static int sort_by_cell(cfpo_start_pt *pts, size_t m, int64_t c0, int64_t ncell)
{
    if (m >= UINT32_MAX || ncell < 1) return -1;
    uint32_t *pos = calloc((size_t)ncell + 1, sizeof *pos), *dest = malloc((m ? m : 1) * sizeof *dest);
    if (!pos || !dest) {
        free(pos);
        free(dest);
        return -1;
    }
    for (size_t i = 0; i < m; i++) pos[pts[i].cell - c0 + 1]++;
    for (int64_t c = 0; c < ncell; c++) pos[c + 1] += pos[c];
    for (size_t i = 0; i < m; i++) dest[i] = pos[pts[i].cell - c0]++;
    for (size_t i = 0; i < m; i++)
        while (dest[i] != i) {
            const uint32_t d = dest[i];
            const cfpo_start_pt t = pts[d];
            pts[d] = pts[i];
            pts[i] = t;
            dest[i] = dest[d];
            dest[d] = d;
        }
    for (size_t i = 1; i < m; i++) {
        const cfpo_start_pt t = pts[i];
        size_t j = i;
        while (j > 0 && pts[j - 1].cell == t.cell && pts[j - 1].key > t.key) {
            pts[j] = pts[j - 1];
            j--;
        }
        pts[j] = t;
    }
    free(pos);
    free(dest);
    return 0;
}

/* The relaxation (start_relax.h) of the m points *pts made from the start
 * rows [ylo, yhi) (torus units, unwrapped), then only those in optimisation
 * rows [y0, y1) kept in a new *pts, their cells set. The old array is freed
 * before the relaxation's work arrays are taken, so the start's peak
 * memory stays under the engine's. 0, or -1 when out of memory (*pts is
 * then freed and NULL). */
static int relax_band(const cfpo_grid *G, cfpo_start_pt **pts, size_t *m, double ylo, double yhi, int64_t y0,
                      int64_t y1, int threads)
{
    const size_t k = *m, db = k * sizeof(double), kb = k * sizeof(uint64_t);
    double *x = cfpo_map_bytes(db), *y = cfpo_map_bytes(db);
    uint64_t *key = cfpo_map_bytes(kb);
    int rc = -1;
    if (x && y && key) {
        for (size_t i = 0; i < k; i++) {
            x[i] = (*pts)[i].x;
            y[i] = (*pts)[i].y;
            key[i] = (*pts)[i].key;
        }
        free(*pts);
        *pts = NULL;
        rc = cfpo_start_relax(x, y, key, k, G->n, ylo, yhi, threads);
    }
    size_t kept = 0;
    for (size_t i = 0; rc == 0 && i < k; i++) {
        const int64_t cy = cfpo_grid_cy(G, y[i]);
        kept += cy >= y0 && cy < y1;
    }
    cfpo_start_pt *out = rc == 0 ? malloc((kept ? kept : 1) * sizeof *out) : NULL;
    if (out) {
        size_t j = 0;
        for (size_t i = 0; i < k; i++) {
            const int64_t cy = cfpo_grid_cy(G, y[i]);
            if (cy < y0 || cy >= y1) continue;
            out[j].cell = cy * G->g + cfpo_grid_cx(G, x[i]);
            out[j].key = key[i];
            out[j].x = x[i];
            out[j].y = y[i];
            j++;
        }
        *m = j;
    }
    free(*pts);
    *pts = out;
    cfpo_unmap_bytes(x, db);
    cfpo_unmap_bytes(y, db);
    cfpo_unmap_bytes(key, kb);
    return out ? 0 : -1;
}

int64_t cfpo_start_band(const cfpo_grid *G, int64_t y0, int64_t y1, int threads, int relax_on, cfpo_start_pt **out)
{
    start_params p;
    params(G, &p);
    mode md[WARP_MAX_MODES];
    const int nm = make_modes(G, &p, md);
    /* Start rows whose points can land in rows [y0, y1): the band's extent
     * plus the largest displacement, at most every row once. */
    const int relax = relax_on && cfpo_start_relax_steps(G->n) > 0;
    const double reach = (nm ? p.amp * sqrt(2.0 * nm) + 1.0 : 1.0) + (relax ? cfpo_start_relax_reach(G->n) * (double)p.h : 0);
    int64_t jlo = (int64_t)floor((double)y0 * G->L * (double)p.h - reach) - 1;
    int64_t jhi = (int64_t)ceil((double)y1 * G->L * (double)p.h + reach) + 1;
    if (jhi - jlo > p.h) { jlo = 0; jhi = p.h; }
    const uint64_t per = 1 + p.extra / (uint64_t)(p.h * p.h) + 1;
    const size_t row = (size_t)p.h * (size_t)per, cap = (size_t)(jhi - jlo) * row;
    cfpo_start_pt *pts = malloc((cap ? cap : 1) * sizeof *pts);
    size_t *kept = malloc((size_t)(jhi - jlo + 1) * sizeof *kept);
    if (!pts || !kept) {
        free(pts);
        free(kept);
        return -1;
    }
    const uint64_t seed = G->seed ^ START_SALT;
    /* Start rows in parallel, each into its own run of slots; every point
     * is a pure function of its start cell, so the result (sorted below)
     * does not depend on the thread count. */
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads > 0 ? threads : 1)
    for (int64_t jj = jlo; jj < jhi; jj++) {
        const int64_t j = (jj % p.h + p.h) % p.h;
        size_t m = (size_t)(jj - jlo) * row;
        for (int64_t i = 0; i < p.h; i++) {
            const uint64_t cnt = start_count(G, &p, i, j), sc = (uint64_t)(j * p.h + i);
            for (uint64_t k = 0; k < cnt; k++) {
                double x = cfpo_wrap01(((double)i + cfpo_rand01(seed, 2 * sc + 1, 2 * k)) / (double)p.h);
                double y = cfpo_wrap01(((double)j + cfpo_rand01(seed, 2 * sc + 1, 2 * k + 1)) / (double)p.h);
                warp(md, nm, &x, &y);
                const int64_t cy = cfpo_grid_cy(G, y);
                if (!relax && (cy < y0 || cy >= y1)) continue; /* else kept for the relaxation */
                pts[m].cell = cy * G->g + cfpo_grid_cx(G, x);
                pts[m].key = sc * per + k;
                pts[m].x = x;
                pts[m].y = y;
                m++;
            }
        }
        kept[jj - jlo] = m - (size_t)(jj - jlo) * row;
    }
    size_t m = 0;
    for (int64_t r = 0; r < jhi - jlo; r++) {
        memmove(pts + m, pts + (size_t)r * row, kept[r] * sizeof *pts);
        m += kept[r];
    }
    free(kept);
    if (relax && relax_band(G, &pts, &m, (double)jlo / (double)p.h, (double)jhi / (double)p.h, y0, y1, threads) != 0)
        return -1;
    if (sort_by_cell(pts, m, y0 * G->g, (y1 - y0) * G->g) != 0) qsort(pts, m, sizeof *pts, cmp_pt);
    *out = pts;
    return (int64_t)m;
}
