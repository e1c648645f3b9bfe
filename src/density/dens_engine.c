/* dens_engine.c - layer 3: CFPO under a density (dens_engine.h). */
#include "dens_engine.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "dens_impl.h"
#include "dens_measure.h"
#include "dens_solve.h"
#include "dens_relax.h"
#include "dens_start.h"
#include "geom.h"
#include "omp_compat.h"
#include "policy.h"
#include "rng.h"
#include "stoprule.h"

int64_t cfpo_dens_grid(const cfpo_density *d, int64_t n)
{
    const double rmax = cfpo_delta_bound((double)n) / sqrt(d->rho_min);
    int64_t g = (int64_t)floor(1.0 / (CELL_SPACINGS * rmax));
    g -= g % 3;
    if (g < 3) g = 3;
    if (g > 3 * 8192) g = 3 * 8192;
    return g;
}

/* The start's relaxation under several ranks (dens_relax.h): every
 * rank's new places gathered in rank order. */
static int relax_share(void *ctx, int ok, const double *mine, size_t bytes, double *all)
{
    const int64_t n = *(const int64_t *)ctx;
    if (!comm_all(ok)) return -1;
    if (!mine) return 0;
    void *got = NULL;
    size_t total = 0;
    if (comm_allgatherv(mine, bytes, &got, &total) != 0) return -1;
    const int good = total == (size_t)n * 2 * sizeof *all;
    if (good) memcpy(all, got, total);
    free(got);
    return comm_all(good) ? 0 : -1;
}

cfpo_dens_engine *cfpo_dens_create(const cfpo_density *d, int64_t n, const cfpo_options *o, const double *start,
                                   int iter0, char *err, size_t errlen)
{
    if (cfpo_density_check_n(d, n, err, errlen) != 0) return NULL;
    cfpo_dens_engine *E = calloc(1, sizeof *E);
    if (!E) { snprintf(err, errlen, "out of memory"); return NULL; }
    E->d = d;
    E->n = n;
    E->o = *o;
    E->D = cfpo_delta_bound((double)n);
    const int64_t g = cfpo_dens_grid(d, n);
    E->g = g;
    E->L = 1.0 / (double)g;
    E->iter = iter0;
    E->nthreads = o->threads > 0 ? o->threads : omp_get_num_procs();
    E->s.own = E->s.loc = n;
    E->ccap = n;
    E->cell = malloc((size_t)n * sizeof *E->cell);
    E->cidx = malloc((size_t)n * sizeof *E->cidx);
    E->cxyq = malloc((size_t)n * 3 * sizeof *E->cxyq);
    /* cells sized to the local spacing: levels of finer grids (dens_levels.h) */
    int lvok = cfpo_dens_levels_init(&E->lv, d, g, E->D, CELL_SPACINGS) == 0;
    for (int l = 0; l < E->lv.n && E->lv.n > 1 && lvok; l++) {
        E->ltouch[l] = calloc((size_t)((g << l) * (g << l)), sizeof *E->ltouch[l]);
        E->lseen[l] = calloc((size_t)((g << l) * (g << l)), sizeof *E->lseen[l]);
        lvok = E->ltouch[l] != NULL && E->lseen[l] != NULL;
    }
    const int64_t gf = g << (E->lv.n - 1); /* the finest level's cells a side */
    E->cstart = malloc((size_t)(gf * gf + 1) * sizeof *E->cstart);
    E->dirty = malloc((size_t)(gf * gf));
    E->lev = E->lv.n > 1 ? malloc((size_t)n) : NULL;
    E->fine = E->lv.n > 1 ? malloc((size_t)n * sizeof *E->fine) : NULL;
    E->tb = calloc((size_t)E->nthreads, sizeof *E->tb);
    if (!lvok || (E->lv.n > 1 && (!E->lev || !E->fine)) ||
        cfpo_dens_store_reserve(&E->s, n, 0) != 0 || !E->cell || !E->cidx || !E->cxyq || !E->cstart || !E->dirty || !E->tb ||
        cfpo_dens_qbound_build(&E->qb, d) != 0 || cfpo_dens_qbound_build_min(&E->qlow, d) != 0 ||
        (start ? (memcpy(E->s.xy, start, (size_t)n * 2 * sizeof *E->s.xy), 0)
               : (cfpo_dens_start(d, n, o->seed, E->s.xy) != 0
                      ? -1
                      : cfpo_dens_relax(d, n, E->s.xy, cfpo_dens_relax_steps(n), E->nthreads, comm_rank(), comm_size(),
                                        relax_share, &n))) != 0) {
        snprintf(err, errlen, "out of memory for %lld points", (long long)n);
        cfpo_dens_free(E);
        return NULL;
    }
    for (int64_t i = 0; i < n; i++) E->s.q[i] = sqrt(cfpo_density_at(d, E->s.xy[2 * i], E->s.xy[2 * i + 1]));
    if (start) { /* a given set: no cell far fuller than the density allows (a block's work grows with its count squared) */
        dens_build_cells(E);
        const double most = 4 * (double)n * E->L * E->L * d->rho_max + 64;
        for (int64_t c = 0; c < g * g; c++)
            if ((double)(E->cstart[c + 1] - E->cstart[c]) > most) {
                snprintf(err, errlen, "the given points hold %lld in one cell of side %.3g, over the %.0f this density "
                         "allows there: too clustered to start from", (long long)(E->cstart[c + 1] - E->cstart[c]),
                         E->L, most);
                cfpo_dens_free(E);
                return NULL;
            }
    }
    if (comm_size() > 1) { /* several ranks: each keeps its cells' points */
        E->T = cfpo_dens_dist_create(g, err, errlen);
        E->all = malloc((size_t)n * 2 * sizeof *E->all);
        if (E->lv.n > 1) {
            E->cstart0 = malloc((size_t)(g * g + 1) * sizeof *E->cstart0);
            E->cidx0 = malloc((size_t)n * sizeof *E->cidx0);
            E->slot = malloc((size_t)n * sizeof *E->slot);
        }
        const int lvmem = E->lv.n == 1 || (E->cstart0 && E->cidx0 && E->slot);
        if (!E->T || !comm_all(E->all != NULL && lvmem) || cfpo_dens_dist_keep(E->T, &E->s, 0, 0) != 0) {
            if (E->T) snprintf(err, errlen, "out of memory for %lld points", (long long)n);
            cfpo_dens_free(E);
            return NULL;
        }
    }
    return E;
}

/* The cell arrays hold the store's points. 0, or -1. */
static int fit_cells(cfpo_dens_engine *E)
{
    if (E->s.loc <= E->ccap) return 0;
    const int64_t cap = E->s.loc + E->s.loc / 4 + 16;
    int64_t *cell = realloc(E->cell, (size_t)cap * sizeof *cell);
    if (cell) E->cell = cell;
    int64_t *cidx = realloc(E->cidx, (size_t)cap * sizeof *cidx);
    if (cidx) E->cidx = cidx;
    double *cxyq = realloc(E->cxyq, (size_t)cap * 3 * sizeof *cxyq);
    if (cxyq) E->cxyq = cxyq;
    if (!cell || !cidx || !cxyq) return -1;
    if (E->lv.n > 1) {
        unsigned char *lev = realloc(E->lev, (size_t)cap);
        if (lev) E->lev = lev;
        int64_t *c0 = realloc(E->cidx0, (size_t)cap * sizeof *c0);
        if (c0) E->cidx0 = c0;
        int64_t *sl = realloc(E->slot, (size_t)cap * sizeof *sl);
        if (sl) E->slot = sl;
        uint32_t *fi = realloc(E->fine, (size_t)cap * sizeof *fi);
        if (fi) E->fine = fi;
        if (!lev || !c0 || !sl || !fi) return -1;
    }
    E->ccap = cap;
    return 0;
}

/* Several ranks, after an iteration (the halo current): each own point's
 * smallest measure against the rank's points, into m. 1 when every one
 * is exact: a point it does not hold lies outside the 3 x 3 cells around
 * the point's cell, at least e away (e: the distance to that block's
 * edge), so its measure is at least e (q_i q_min)^(1/2) / Delta. */
static int measure_own(cfpo_dens_engine *E, double *m)
{
    if (cfpo_dens_nn_first(E->d, &E->qlow, &E->near, E->s.xy, E->s.q, (size_t)E->s.loc, (size_t)E->s.own, E->D, m,
                                E->nthreads) != 0)
        return -1;
    const double lo = sqrt(E->d->rho_min), G = (double)E->g;
    for (int64_t i = 0; i < E->s.own; i++) {
        if (!(E->s.q[i] > 0)) continue;
        const double gx = cfpo_wrap01(E->s.xy[2 * i] - E->sx) * G, gy = cfpo_wrap01(E->s.xy[2 * i + 1] - E->sy) * G;
        const double fx = gx - floor(gx), fy = gy - floor(gy);
        const double e = fmin(fmin(1 + fx, 2 - fx), fmin(1 + fy, 2 - fy)) * E->L;
        if (!(m[i] * (1 + 1e-9) < e * sqrt(E->s.q[i] * lo) / E->D)) return 0;
    }
    return 1;
}

/* delta_min and delta_avg of the whole set. Several ranks: each point's
 * measure from its rank's points when that is provably exact (else from
 * the whole set, gathered), the measures gathered in id order and summed
 * in that order, as on one rank: the same bits. */
static int measure_set(cfpo_dens_engine *E, double *dmin, double *davg, int halo)
{
    if (!E->T) return cfpo_dens_nn_q(E->d, &E->qlow, &E->near, E->s.xy, E->s.q, (size_t)E->n, NULL, dmin, davg, E->nthreads);
    double *m = malloc((size_t)(E->s.own + 1) * sizeof *m);
    int got = m ? (halo ? measure_own(E, m) : 0) : -1;
    if (!comm_all(got >= 0)) { free(m); return -1; }
    if (!comm_all(got == 1)) { /* a start far from the density: the whole set on every rank */
        free(m);
        if (cfpo_dens_dist_gather_values(E->T, &E->s, E->n, E->s.xy, 2, E->all) != 0) return -1;
        return comm_all(cfpo_dens_nn_q(E->d, &E->qlow, &E->near, E->all, NULL, (size_t)E->n, NULL, dmin, davg,
                                            E->nthreads) == 0)
                   ? 0
                   : -1;
    }
    const int rc = cfpo_dens_dist_gather_values(E->T, &E->s, E->n, m, 1, E->all);
    free(m);
    if (rc != 0) return -1;
    cfpo_dens_nn_sum(E->all, (size_t)E->n, dmin, davg);
    return 0;
}

/* measure_set, the values kept for the iterations that do not measure. */
static int measure(cfpo_dens_engine *E, double *dmin, double *davg, int halo)
{
    if (measure_set(E, dmin, davg, halo) != 0) return -1;
    E->last_dmin = *dmin;
    E->last_davg = *davg;
    return 0;
}

/* Whether iteration k measures the set: always, unless o.lazy_measure;
 * then where the stop rules read it (a target, at any iteration; the
 * schedule's stall rule, at each window's end). Positions never depend on
 * the measure, so the choice changes no point (the run loop measures
 * where a run stops, run_loop.h). */
static int measures(const cfpo_dens_engine *E, int k)
{
    return !E->o.lazy_measure || E->o.stop.target_min > 0 || E->o.stop.target_avg > 0 ||
           k % CFPO_POLICY_DENSITY_WINDOW == 0;
}

/* The grid's offset for iteration k: one random offset in [0, L)^2 for
 * each group of four iterations 4j + 1 .. 4j + 4 (docs/method.md,
 * "Density"); between moves the unchanged cells are skipped. */
static void grid_offset(const cfpo_dens_engine *E, int k, double *sx, double *sy)
{
    /* the steep blocks' fall-back runs when the offset is new (policy.h):
     * the skip's exactness rests on the two rhythms being one */
    _Static_assert(DENS_SHIFT_EVERY == CFPO_POLICY_DENSITY_FALL_EVERY, "the fall-back's rhythm is the grid's");
    const uint64_t grp = (uint64_t)((k - 1) / DENS_SHIFT_EVERY);
    *sx = cfpo_rand01(E->o.seed, 0xD5E1ull, grp) * E->L;
    *sy = cfpo_rand01(E->o.seed, 0xD5E2ull, grp) * E->L;
}

int cfpo_dens_iterate(cfpo_dens_engine *E, cfpo_iter_stats *s)
{
    const double t0 = omp_get_wtime();
    E->iter++;
    double sx, sy;
    grid_offset(E, E->iter, &sx, &sy);
    const int fresh = !E->placed || sx != E->sx || sy != E->sy || !E->o.skip;
    if (fresh) memset(E->dirty, 1, (size_t)(E->g * E->g));
    for (int l = 0; fresh && l < E->lv.n && E->lv.n > 1; l++)
        memset(E->lseen[l], 0, (size_t)((E->lv.g0 << l) * (E->lv.g0 << l)) * sizeof *E->lseen[l]);
    E->placed = 1;
    E->sx = sx;
    E->sy = sy;
    double tm = omp_get_wtime();
    if (E->T && (cfpo_dens_dist_migrate(E->T, &E->s, E->sx, E->sy) != 0 || !comm_all(fit_cells(E) == 0))) return -1;
    E->t_migrate += omp_get_wtime() - tm;
    int64_t moves = 0, solved = 0;
    double maxd = 0;
    if ((E->lv.n > 1 ? dens_sweep_levels(E, &moves, &solved, &maxd, &tm) : dens_sweep_grid(E, &moves, &solved, &maxd, &tm)) != 0)
        return -1;
    if (!E->T) E->t_compute += omp_get_wtime() - tm;
    E->iters_run++;
    int oom = 0;
    for (int t = 0; t < E->nthreads; t++) oom |= E->tb[t].oom;
    if (!comm_all(!oom)) return -1;
    int64_t v[2] = {moves, solved};
    comm_sum_i64(v, 2);
    moves = v[0];
    comm_max_d(&maxd, 1);
    memset(s, 0, sizeof *s);
    s->iteration = E->iter;
    s->moved = moves;
    s->solved = v[1];
    s->max_disp = maxd;
    s->max_move = maxd;
    if (measures(E, E->iter)) {
        if (measure(E, &s->delta_min, &s->delta_avg, 1) != 0) return -1;
    } else {
        s->delta_min = E->last_dmin;
        s->delta_avg = E->last_davg;
        s->stale = 1;
    }
    s->converged = cfpo_net_converged(moves, maxd, E->o.tol) ||
                   cfpo_policy_density_stalled(E->iter, s->delta_avg, &E->davg_ref);
    s->seconds = omp_get_wtime() - t0;
    comm_max_d(&s->seconds, 1);
    return 0;
}

int cfpo_dens_measure(cfpo_dens_engine *E, double *dmin, double *davg)
{
    /* after an iteration of this engine the halo is as its own measure
     * left it: the same reading, without gathering the set */
    return measure(E, dmin, davg, E->iters_run > 0);
}

int cfpo_dens_iteration(const cfpo_dens_engine *E) { return E->iter; }
double cfpo_dens_davg_ref(const cfpo_dens_engine *E) { return E->davg_ref; }
void cfpo_dens_set_davg_ref(cfpo_dens_engine *E, double ref) { E->davg_ref = ref; }

int cfpo_dens_write_points(cfpo_dens_engine *E, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    /* Own points are in id order: write them in pieces of CH points, each
     * piece one collective write of its runs of consecutive ids. */
    const int64_t CH = (int64_t)1 << 20, own = E->s.own;
    int64_t rounds = (own + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    uint64_t *first = malloc((size_t)CH * sizeof *first), *len = malloc((size_t)CH * sizeof *len);
    int ok = first && len;
    if (!comm_all(ok)) {
        free(first); free(len);
        snprintf(err, errlen, "out of memory while writing");
        return -1;
    }
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = r * CH, b = a + CH < own ? a + CH : own;
        if (a > b) a = b;
        int64_t nr = 0;
        for (int64_t i = a; i < b; i++) {
            const uint64_t id = E->s.gid ? (uint64_t)E->s.gid[i] : (uint64_t)i;
            if (nr > 0 && first[nr - 1] + len[nr - 1] == id) len[nr - 1]++;
            else { first[nr] = id; len[nr] = 1; nr++; }
        }
        if (comm_file_write_runs(f, base, 16, E->s.xy + 2 * a, nr, first, len) != 0) ok = 0;
    }
    free(first); free(len);
    if (!comm_all(ok)) {
        snprintf(err, errlen, "write failed (disk full or file system error)");
        return -1;
    }
    return 0;
}

void cfpo_dens_timing(const cfpo_dens_engine *E, cfpo_engine_timing *t)
{
    double v[3] = {E->t_compute, E->t_migrate, E->t_halo}, mn[3], mx[3], sm[3];
    for (int i = 0; i < 3; i++) mn[i] = mx[i] = sm[i] = v[i];
    comm_min_d(mn, 3);
    comm_max_d(mx, 3);
    comm_sum_d(sm, 3);
    memset(t, 0, sizeof *t);
    double *dst[3] = {t->compute, t->migrate, t->halo};
    for (int i = 0; i < 3; i++) {
        dst[i][0] = mn[i];
        dst[i][1] = sm[i] / comm_size();
        dst[i][2] = mx[i];
    }
    t->phases = 9 * (int64_t)E->iters_run;
}

const double *cfpo_dens_points(const cfpo_dens_engine *E)
{
    if (!E->T) return E->s.xy;
    return cfpo_dens_dist_gather_values(E->T, &E->s, E->n, E->s.xy, 2, E->all) == 0 ? E->all : NULL;
}

int64_t cfpo_dens_own_points(const cfpo_dens_engine *E) { return E->s.own; }

void cfpo_dens_on_move(cfpo_dens_engine *E, cfpo_dens_move_fn fn, void *user)
{
    E->on_move = fn;
    E->move_user = user;
}
int64_t cfpo_dens_cells_per_side(const cfpo_dens_engine *E) { return E->g; }
int cfpo_dens_levels_count(const cfpo_dens_engine *E) { return E->lv.n; }

void cfpo_dens_free(cfpo_dens_engine *E)
{
    if (!E) return;
    if (E->tb)
        for (int t = 0; t < E->nthreads; t++) {
            free(E->tb[t].bx); free(E->tb[t].bid); free(E->tb[t].bslot); free(E->tb[t].scratch); free(E->tb[t].nj); free(E->tb[t].ring);
            cfpo_dens_buckets_free(&E->tb[t].bk);
        }
    free(E->tb); free(E->dirty); free(E->cell); free(E->cidx); free(E->cxyq); free(E->cstart); free(E->all);
    free(E->lev); free(E->fine); free(E->cstart0); free(E->cidx0); free(E->slot); free(E->lcells); free(E->hold);
    for (int l = 0; l < CFPO_DENS_LEVELS_MAX; l++) {
        free(E->ltouch[l]);
        free(E->lseen[l]);
    }
    cfpo_dens_levels_free(&E->lv);
    cfpo_dens_store_free(&E->s);
    cfpo_dens_qbound_free(&E->qb);
    cfpo_dens_qbound_free(&E->qlow);
    cfpo_dens_nn_near_free(&E->near);
    cfpo_dens_dist_free(E->T);
    free(E);
}
