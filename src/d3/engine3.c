/* engine3.c - the 3-D engine's life cycle: options, creation from n or
 * from given points, buckets, measures, accessors (engine3.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine3_dist.h"
#include "state3.h"
#include "rng.h"
#include "solve3.h"

#define SHIFT_STREAM 0x5a17f7e3c3d0b1a9ULL
#define COLOUR_STREAM 0x3c01a2b5e7f90d4bULL

void cfpo3_options_default(cfpo3_options *o)
{
    memset(o, 0, sizeof *o);
    o->seed = 1;
    o->tol = CFPO3_DEFAULT_TOL;
    o->relax = 1;
    o->shift = 1;
    o->skip = 1;
    o->near = 1;
}

double cfpo3_bytes_per_point_ranks(int64_t n, int ranks)
{
    cfpo3_grid G;
    char err[16];
    if (n < 1 || ranks < 1 || cfpo3_grid_choose(n, &G, err, sizeof err) != 0) return 0.0;
    const double g3 = (double)G.g * G.g * G.g;
    /* pos, prev, cellof, cids; per cell cstart, changed, solvedat, needm, fill */
    const double engine = (double)n * (24 + 24 + 4 + 8) + g3 * (8 + 8 + 8 + 8 + 8);
    /* the measure's whole-set fallback: d2, the set, its distances, then
     * the k-NN (start, ids, cell, distances, ids, fill over about n / 2
     * cells); on several ranks the gather (own points 4 doubles, all
     * points 4 doubles) comes before the k-NN */
    const double knn = 8.0 + 24 + 8 + (8 + 4 + 8 + 8) + 0.5 * (8 + 8);
    const double gather = 8.0 + 24 + 8 + 32 + 32.0 / ranks;
    const double measure = (double)n * (ranks > 1 && gather > knn ? gather : knn);
    return (engine + measure) / (double)n;
}

double cfpo3_bytes_per_point(int64_t n) { return cfpo3_bytes_per_point_ranks(n, 1); }

cfpo3_engine *cfpo3_alloc(int64_t n, const cfpo3_options *o, char *err, size_t errlen)
{
    cfpo3_grid G;
    if (cfpo3_grid_choose(n, &G, err, errlen) != 0) return NULL;
    cfpo3_engine *e = calloc(1, sizeof *e);
    if (!e) goto oom;
    e->G = G;
    e->o = *o;
    e->near = o->near ? 1 : 0;
    e->n = n;
    const size_t g3 = (size_t)G.g * G.g * G.g;
    e->pos = malloc(sizeof(double) * 3 * (size_t)n);
    e->prev = malloc(sizeof(double) * 3 * (size_t)n);
    e->cellof = calloc((size_t)n, sizeof(int32_t)); /* every point held until the first assign */
    e->cids = malloc(sizeof(int64_t) * (size_t)n);
    e->cstart = calloc(g3 + 1, sizeof(int64_t));
    e->changed = calloc(g3, sizeof(uint64_t));
    e->solvedat = calloc(g3, sizeof(uint64_t));
    e->needm = calloc(g3, sizeof(double));
    e->fill = malloc(sizeof(int64_t) * g3);
    if (!e->fill || !e->pos || !e->prev || !e->cellof || !e->cids || !e->cstart || !e->changed || !e->solvedat ||
        !e->needm) {
        cfpo3_free(e);
        goto oom;
    }
    if (cfpo3_dist_init(e, err, errlen) != 0) {
        cfpo3_free(e);
        return NULL;
    }
    return e;
oom:
    snprintf(err, errlen, "out of memory for %lld points", (long long)n);
    return NULL;
}

void cfpo3_free(cfpo3_engine *e)
{
    if (!e) return;
    free(e->pos), free(e->prev), free(e->cellof), free(e->cids), free(e->cstart);
    free(e->changed), free(e->solvedat), free(e->needm), free(e->fill);
    cfpo3_dist_free(e);
    free(e->tail_in);
    free(e);
}

void cfpo3_shift_for(const cfpo3_engine *e, int k, double s[3])
{
    if (!e->o.shift || k < 1) {
        s[0] = s[1] = s[2] = 0.0;
        return;
    }
    const int at = 1 + 4 * ((k - 1) / 4); /* shifted before 1, 5, 9, ... */
    for (int a = 0; a < 3; a++) s[a] = cfpo_rand01(e->o.seed, SHIFT_STREAM, 3 * (uint64_t)at + (uint64_t)a) * e->G.L;
}

void cfpo3_colours_for(const cfpo3_engine *e, int k, int order[27], int off[3])
{
    for (int c = 0; c < 27; c++) order[c] = c;
    off[0] = off[1] = off[2] = 0;
    if (!e->o.shift || k < 1) return;
    const int at = 1 + 4 * ((k - 1) / 4); /* the offset changes with the shift */
    for (int a = 0; a < 3; a++) {
        const int o = (int)(3.0 * cfpo_rand01(e->o.seed, COLOUR_STREAM, 3 * (uint64_t)at + (uint64_t)a));
        off[a] = o < 3 ? o : 2;
    }
    for (int c = 26; c > 0; c--) { /* Fisher-Yates, keyed by (seed, k) */
        int j = (int)((double)(c + 1) * cfpo_rand01(e->o.seed, COLOUR_STREAM ^ 1, 27 * (uint64_t)k + (uint64_t)c));
        if (j > c) j = c;
        const int t = order[c];
        order[c] = order[j];
        order[j] = t;
    }
}

void cfpo3_rebucket(cfpo3_engine *e)
{
    const int g = e->G.g;
    const size_t g3 = (size_t)g * g * g;
    memset(e->cstart, 0, sizeof(int64_t) * (g3 + 1));
    for (int64_t i = 0; i < e->n; i++)
        if (e->cellof[i] >= 0) e->cstart[e->cellof[i] + 1]++;
    for (size_t c = 0; c < g3; c++) e->cstart[c + 1] += e->cstart[c];
    /* fill by id: the ids of a cell come out increasing */
    int64_t *fill = e->fill;
    memcpy(fill, e->cstart, sizeof(int64_t) * g3);
    for (int64_t i = 0; i < e->n; i++)
        if (e->cellof[i] >= 0) e->cids[fill[e->cellof[i]]++] = i;
}

void cfpo3_assign(cfpo3_engine *e)
{
    cfpo3_dist_cells(e);
    cfpo3_rebucket(e);
}

int cfpo3_remeasure(cfpo3_engine *e)
{
    return cfpo3_dist_measure(e);
}

static cfpo3_engine *finish_create(cfpo3_engine *e, char *err, size_t errlen)
{
    cfpo3_shift_for(e, e->iter, e->shift);
    cfpo3_assign(e);
    if (cfpo3_remeasure(e) != 0) {
        snprintf(err, errlen, "out of memory for %lld points", (long long)e->n);
        cfpo3_free(e);
        return NULL;
    }
    return e;
}

cfpo3_engine *cfpo3_create(int64_t n, const cfpo3_options *o, char *err, size_t errlen)
{
    cfpo3_engine *e = cfpo3_alloc(n, o, err, errlen);
    if (!e) return NULL;
    if (cfpo3_start(n, o->seed, e->pos) != 0) {
        snprintf(err, errlen, "out of memory for %lld points", (long long)n);
        cfpo3_free(e);
        return NULL;
    }
    return finish_create(e, err, errlen);
}

cfpo3_engine *cfpo3_create_given(const double *xyz, int64_t n, const cfpo3_options *o, char *err,
                                 size_t errlen)
{
    for (int64_t i = 0; i < 3 * n; i++)
        if (!(xyz[i] >= 0.0 && xyz[i] < 1.0)) {
            snprintf(err, errlen, "point %lld has a coordinate outside [0,1)", (long long)(i / 3));
            return NULL;
        }
    cfpo3_engine *e = cfpo3_alloc(n, o, err, errlen);
    if (!e) return NULL;
    memcpy(e->pos, xyz, sizeof(double) * 3 * (size_t)n);
    e = finish_create(e, err, errlen);
    if (!e) return NULL;
    /* the first crowded cell: each rank reads the cells it holds, and the
     * answers are merged (every cell is held whole by some rank) */
    const int64_t g3 = (int64_t)e->G.g * e->G.g * e->G.g;
    int64_t v[2] = {0, 0}; /* g3 - the first crowded cell, its count */
    for (int64_t c = 0; c < g3; c++)
        if (e->cstart[c + 1] - e->cstart[c] > CFPO3_INIT_MAX_CELL) {
            v[0] = g3 - c;
            break;
        }
    comm_max_i64(v, 1);
    if (v[0] > 0) {
        const int64_t c = g3 - v[0];
        v[1] = e->cstart[c + 1] - e->cstart[c];
        comm_max_i64(v + 1, 1);
        snprintf(err, errlen, "a cell of the %dx%dx%d grid holds %lld of the given points (at most %d)", e->G.g,
                 e->G.g, e->G.g, (long long)v[1], CFPO3_INIT_MAX_CELL);
        cfpo3_free(e);
        return NULL;
    }
    return e;
}

void cfpo3_measure(const cfpo3_engine *e, double *delta_min, double *delta_avg)
{
    *delta_min = e->dmin;
    *delta_avg = e->davg;
}

int cfpo3_iterations(const cfpo3_engine *e) { return e->iter; }
int64_t cfpo3_n(const cfpo3_engine *e) { return e->n; }
const cfpo3_grid *cfpo3_grid_of(const cfpo3_engine *e) { return &e->G; }
const cfpo3_options *cfpo3_options_of(const cfpo3_engine *e) { return &e->o; }
const double *cfpo3_points(const cfpo3_engine *e) { return e->pos; }

void cfpo3_work(const cfpo3_engine *e, long *cells, long *tests, long *cuts)
{
    *cells = e->count.cells;
    *tests = e->count.tests;
    *cuts = e->count.cuts;
}

int cfpo3_gather(const cfpo3_engine *e, double *all) { return cfpo3_dist_gather(e, all); }
int64_t cfpo3_own_points(const cfpo3_engine *e) { return cfpo3_dist_own(e); }

void cfpo3_rank_timers(const cfpo3_engine *e, double v[5], int64_t *phases, int bricks[3])
{
    v[0] = e->t_compute, v[1] = e->t_halo, v[2] = e->t_migrate, v[3] = e->b_halo, v[4] = e->b_migrate;
    *phases = e->phases;
    for (int a = 0; a < 3; a++) bricks[a] = e->B.p[a];
}
