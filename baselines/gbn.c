/* gbn.c - see gbn.h.
 *
 * Truncation: a neighbour at distance r >= R = cutoff * s adds at most
 * r exp(-r^2 / (2 s^2)) to a point's gradient sum. Over a set no denser
 * than about n points per unit area, the terms left out total about
 * 2 pi n s^3 int_c^inf u^2 exp(-u^2/2) du (c = cutoff), i.e. with s^2 n =
 * sigma^2 = 1 and c = 6, 2 pi s * 6.6e-8 = 4e-7 s, against sums of order
 * s; times the step 0.25 a move differs by about 1e-7 of the spacing from
 * the untruncated one. The authors' float kernel stops being exact at
 * 5.8 s (the Gaussian below one float ulp): the same order. */
#include "gbn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "grid.h"
#include "rng.h"
#include "omp_compat.h"
#include "stats.h"
#include "stoprule.h"

static const uint64_t START_STREAM = 0x47424e5354525400ULL; /* "GBNSTRT" */

struct gbn_engine {
    int64_t n;
    gbn_options o;
    double L;          /* cfpo's cell side for n: the tolerance's scale */
    double inv2s2;     /* 1 / (2 s^2) */
    double R2;         /* the cutoff radius squared */
    double step;       /* the authors' step (divided by sigma^2 when sigma > 1) */
    int64_t G;         /* cells per side (1: every pair) */
    int done;          /* iterations made */
    int sorted;        /* sxy, cell and start are of the current points */
    double *xy, *nxy;  /* the points, the next points */
    double *sxy;       /* the points in cell order */
    int64_t *start;    /* G^2 + 1 offsets into sxy */
    int64_t *cell;     /* the cell of each point */
};

void gbn_options_init(gbn_options *o)
{
    memset(o, 0, sizeof *o);
    o->seed = 1;
    o->sigma = GBN_SIGMA;
    o->step = GBN_STEP;
    o->cutoff = GBN_CUTOFF;
    o->iterations = GBN_ITERATIONS;
    o->tol = CFPO_DEFAULT_TOL;
    o->threads = 1;
}

double gbn_bytes(int64_t n) { return (double)n * 72 + 64.0 * 1024 * 1024; }

gbn_engine *gbn_create(int64_t n, const gbn_options *o, char *err, size_t errlen)
{
    cfpo_grid Gr;
    if (cfpo_grid_init(&Gr, n, CFPO_VARIANT_FULL, o->seed, err, errlen) != 0) return NULL;
    gbn_engine *E = calloc(1, sizeof *E);
    if (!E) goto oom;
    E->n = n;
    E->o = *o;
    E->L = Gr.L;
    const double s = o->sigma / sqrt((double)n), R = o->cutoff * s;
    E->inv2s2 = 1.0 / (2 * s * s);
    E->R2 = R * R;
    E->step = o->sigma > 1 ? o->step / (o->sigma * o->sigma) : o->step;
    E->G = (int64_t)floor(1.0 / R);
    if (E->G < 3) E->G = 1; /* a 3 x 3 block would wrap onto itself: take every pair */
    E->xy = malloc(2 * (size_t)n * sizeof(double));
    E->nxy = malloc(2 * (size_t)n * sizeof(double));
    E->sxy = malloc(2 * (size_t)n * sizeof(double));
    E->cell = malloc((size_t)n * sizeof(int64_t));
    E->start = calloc((size_t)(E->G * E->G + 1), sizeof(int64_t));
    if (!E->xy || !E->nxy || !E->sxy || !E->cell || !E->start) goto oom;
    for (int64_t i = 0; i < 2 * n; i++) E->xy[i] = cfpo_rand01(o->seed, START_STREAM, (uint64_t)i);
    return E;
oom:
    gbn_free(E);
    snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
    return NULL;
}

void gbn_free(gbn_engine *E)
{
    if (!E) return;
    free(E->xy);
    free(E->nxy);
    free(E->sxy);
    free(E->cell);
    free(E->start);
    free(E);
}

const double *gbn_points(const gbn_engine *E) { return E->xy; }

void gbn_deltas(gbn_engine *E, double *dmin, double *davg)
{
    if (cfpo_nn_stats(E->xy, (size_t)E->n, NULL, dmin, davg) != 0) *dmin = *davg = NAN;
}

static int64_t cell_of(const gbn_engine *E, double x, double y)
{
    int64_t cx = (int64_t)(x * (double)E->G), cy = (int64_t)(y * (double)E->G);
    if (cx >= E->G) cx = E->G - 1;
    if (cy >= E->G) cy = E->G - 1;
    return cy * E->G + cx;
}

/* The points in cell order (a stable counting sort: by index within a cell). */
static void sort_cells(gbn_engine *E)
{
    const int64_t nc = E->G * E->G;
    memset(E->start, 0, (size_t)(nc + 1) * sizeof(int64_t));
    for (int64_t i = 0; i < E->n; i++) {
        E->cell[i] = cell_of(E, E->xy[2 * i], E->xy[2 * i + 1]);
        E->start[E->cell[i] + 1]++;
    }
    for (int64_t c = 0; c < nc; c++) E->start[c + 1] += E->start[c];
    int64_t *fill = malloc((size_t)nc * sizeof(int64_t));
    if (fill) memcpy(fill, E->start, (size_t)nc * sizeof(int64_t));
    for (int64_t i = 0; i < E->n; i++) {
        /* fill NULL (out of memory for G^2 counters): recount per point */
        int64_t at;
        if (fill) at = fill[E->cell[i]]++;
        else {
            at = E->start[E->cell[i]];
            for (int64_t j = 0; j < i; j++) at += E->cell[j] == E->cell[i];
        }
        E->sxy[2 * at] = E->xy[2 * i];
        E->sxy[2 * at + 1] = E->xy[2 * i + 1];
    }
    free(fill);
}

static inline double wrap_half(double d)
{
    if (d < -0.5) d += 1.0;
    if (d >= 0.5) d -= 1.0;
    return d;
}

/* The sum over the points of sxy[lo..hi) within the cutoff, skipping the
 * point itself (the same coordinates: points never coincide in a blue
 * noise set; a coincident pair adds nothing either way, d = 0). */
static inline void add_range(const gbn_engine *E, double x, double y, int64_t lo, int64_t hi, double *gx,
                             double *gy)
{
    for (int64_t k = lo; k < hi; k++) {
        const double dx = wrap_half(x - E->sxy[2 * k]), dy = wrap_half(y - E->sxy[2 * k + 1]);
        const double r2 = dx * dx + dy * dy;
        if (r2 >= E->R2 || r2 == 0) continue;
        const double g = exp(-r2 * E->inv2s2);
        *gx += dx * g;
        *gy += dy * g;
    }
}

static void cell_gradient(const gbn_engine *E, int64_t i, double *gx, double *gy)
{
    const double x = E->xy[2 * i], y = E->xy[2 * i + 1];
    *gx = *gy = 0;
    if (E->G == 1) {
        add_range(E, x, y, 0, E->n, gx, gy);
        return;
    }
    const int64_t G = E->G, c = E->cell[i], cx = c % G, cy = c / G;
    for (int64_t oy = -1; oy <= 1; oy++)
        for (int64_t ox = -1; ox <= 1; ox++) {
            const int64_t nc = ((cy + oy + G) % G) * G + (cx + ox + G) % G;
            add_range(E, x, y, E->start[nc], E->start[nc + 1], gx, gy);
        }
}

void gbn_cell_gradient(gbn_engine *E, int64_t i, double *gx, double *gy)
{
    if (!E->sorted) sort_cells(E);
    E->sorted = 1;
    cell_gradient(E, i, gx, gy);
}

void gbn_full_gradient(const gbn_engine *E, int64_t i, double *gx, double *gy)
{
    const double x = E->xy[2 * i], y = E->xy[2 * i + 1];
    *gx = *gy = 0;
    for (int64_t j = 0; j < E->n; j++) {
        if (j == i) continue;
        const double dx = wrap_half(x - E->xy[2 * j]), dy = wrap_half(y - E->xy[2 * j + 1]);
        const double g = exp(-(dx * dx + dy * dy) * E->inv2s2);
        *gx += dx * g;
        *gy += dy * g;
    }
}

static inline double wrap01(double x)
{
    if (x < 0) {
        x += 1.0;
        if (x >= 1.0) x = 0; /* -tiny + 1 rounds to 1 */
    } else if (x >= 1.0) x -= 1.0;
    return x;
}

void gbn_iterate(gbn_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const int64_t n = E->n;
    if (!E->sorted) sort_cells(E);
    const double tolL = E->o.tol * E->L;
    int64_t moved = 0;
    double maxd2 = 0;
    const int threads = E->o.threads > 0 ? E->o.threads : omp_get_num_procs();
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : moved) reduction(max : maxd2)
    for (int64_t i = 0; i < n; i++) {
        double gx, gy;
        cell_gradient(E, i, &gx, &gy);
        const double mx = E->step * gx, my = E->step * gy;
        E->nxy[2 * i] = wrap01(E->xy[2 * i] + mx);
        E->nxy[2 * i + 1] = wrap01(E->xy[2 * i + 1] + my);
        const double d2 = mx * mx + my * my;
        if (d2 >= tolL * tolL) moved++;
        if (d2 > maxd2) maxd2 = d2;
    }
    double *t = E->xy;
    E->xy = E->nxy;
    E->nxy = t;
    E->done++;
    E->sorted = 0;
    s->moved = moved;
    s->solved = n;
    s->max_disp = sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = E->done >= E->o.iterations || cfpo_net_converged(moved, s->max_disp, E->o.tol);
    gbn_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}
