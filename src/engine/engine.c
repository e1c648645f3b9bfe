/* engine.c - the engine's lifetime: creation (grid, tiles, storage, the
 * halo's neighbours, then the initial set or a checkpoint), the memory
 * model, growing the point arrays and the solver's scratch, the getters
 * and the timing totals. See engine.h; the engine's files are listed in
 * cells.h. */
#include "backend.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"


const cfpo_grid *cfpo_engine_grid(const cfpo_engine *E) { return &E->G; }
const cfpo_tiling *cfpo_engine_tiling(const cfpo_engine *E) { return &E->T; }

uint64_t cfpo_engine_bytes(int64_t n, int variant, int threads)
{
    cfpo_grid G;
    char err[8];
    if (cfpo_grid_init(&G, n, variant, 0, err, sizeof err) != 0) return 0;
    const double t = variant == CFPO_VARIANT_HYPERUNIFORM ? cfpo_transport_bytes(n, n) : 0;
    return cfpo_engine_bytes_local(n, G.g * G.g, 0, threads) + (uint64_t)t;
}

void cfpo_engine_free(cfpo_engine *E)
{
    if (!E) return;
    cfpo_transport_free(&E->lf);
    cfpo_gridmodes_free(&E->gm);
    free(E->px); free(E->py); free(E->pid); free(E->dq);
    free(E->tx); free(E->ty); free(E->tid);
    free(E->start); free(E->start2); free(E->mask);
    free(E->bsum); free(E->bmin); free(E->bdirty);
    free(E->hstart); free(E->hstart2); free(E->hx); free(E->hy); free(E->hx2); free(E->hy2);
    free(E->hcnt);
    free(E->brick_sh);
    for (int i = 0; i < E->nnb; i++) {
        free(E->nb[i].send_cells);
        free(E->nb[i].recv_ring);
        free(E->nb[i].out);
        free(E->nb[i].hbuf);
        if (E->msg) free(E->msg[i].recv);
    }
    free(E->nb);
    free(E->msg);
    free(E->arr);
    if (E->scratch)
        for (int t = 0; t < E->nthreads; t++) free(E->scratch[t]);
    free(E->scratch);
    free(E);
}

/* ---- create ---- */

cfpo_engine *cfpo_engine_create(int64_t n, const cfpo_options *o, char *err, size_t errlen)
{
    cfpo_engine_config cfg = {0};
    return cfpo_engine_create_ex(n, o, &cfg, err, errlen);
}

/* The engine of this rank, its tile placed, nothing allocated yet. */
static cfpo_engine *new_engine(int64_t n, const cfpo_grid *G, const cfpo_tiling *T, const cfpo_options *o,
                               const cfpo_engine_config *cfg)
{
    cfpo_engine *E = calloc(1, sizeof *E);
    if (!E) return NULL;
    E->be = &eng_backend_cpu;
    E->G = *G;
    E->dmin_now = 1.0;
    E->T = *T;
    E->o = *o;
    E->cfg = *cfg;
    E->n = n;
    E->rank = comm_rank();
    E->nranks = comm_size();
    const int tx = E->rank % T->px, ty = E->rank / T->px;
    E->x0 = cfpo_tile_start(G->g, T->px, tx);
    E->w = cfpo_tile_len(G->g, T->px, tx);
    E->y0 = cfpo_tile_start(G->g, T->py, ty);
    E->h = cfpo_tile_len(G->g, T->py, ty);
    E->wrapx = T->px == 1;
    E->wrapy = T->py == 1;
    E->cells = E->w * E->h;
    E->nthreads = o->threads > 0 ? o->threads : omp_get_num_procs();
    return E;
}

/* Per-cell arrays, statistics blocks, per-thread scratch pointers and the
 * halo's neighbours. 0 or -1 (out of memory). */
static int alloc_cells(cfpo_engine *E)
{
    const size_t nc = (size_t)E->cells;
    E->start = malloc((nc + 1) * sizeof(uint32_t));
    E->start2 = malloc((nc + 1) * sizeof(uint32_t));
    E->mask = calloc(nc, sizeof(uint16_t));
    E->scratch = calloc((size_t)E->nthreads, sizeof(double *));
    E->nbx = (E->w + SB - 1) / SB;
    E->nby = (E->h + SB - 1) / SB;
    const size_t nb = (size_t)(E->nbx * E->nby);
    E->bsum = calloc(nb, sizeof(uint64_t));
    E->bmin = calloc(nb, sizeof(double));
    E->bdirty = malloc(nb);
    if (!(E->bsum && E->bmin && E->bdirty && E->start && E->start2 && E->mask && E->scratch)) return -1;
    memset(E->bdirty, 1, nb);
    for (size_t c = 0; c < nc; c++) E->mask[c] = NEED_BIT;
    return eng_build_neighbours(E);
}

/* The points: read from cfg.resume, or the variant's initial set. */
static int load_points(cfpo_engine *E, char *err, size_t errlen)
{
    const char *path = E->cfg.resume;
    if (!path && E->cfg.start_xy) return eng_take_points(E, E->cfg.start_xy, err, errlen);
    if (!path) return eng_make_initial(E, err, errlen);
    cfpo_checkpoint_info info;
    if (cfpo_checkpoint_peek(path, &info, err, errlen) != 0) return -1;
    if (info.hash != E->cfg.density_hash) {
        snprintf(err, errlen, "%s: the checkpoint was made %s", path,
                 info.hash ? "with another density (or none is given)" : "without a density");
        return -1;
    }
    if (info.n != E->n || info.seed != E->o.seed || info.variant != E->o.variant || info.tol != E->o.tol) {
        snprintf(err, errlen, "%s: checkpoint is for another run (n, seed, variant or tol differ)", path);
        return -1;
    }
    E->iter0 = (int)info.iteration;
    E->cur = E->iter0;
    E->G.shift_x = cfpo_policy_shift(&E->G, E->iter0, 0);
    E->G.shift_y = cfpo_policy_shift(&E->G, E->iter0, 1);
    E->resumed_converged = info.converged;
    E->near = info.near;
    return eng_load_checkpoint(E, err, errlen);
}

/* Check mode: the sum of every id's hash, to compare after each step. */
static void start_checks(cfpo_engine *E)
{
    uint64_t s = 0;
    for (int64_t k = 0; k < E->nloc; k++) s += cfpo_mix64(E->pid[k]);
    int64_t v = (int64_t)s;
    comm_sum_i64(&v, 1);
    E->id_sum = (uint64_t)v;
    eng_check_migration(E);
    eng_check_halo(E);
}

cfpo_engine *cfpo_engine_create_ex(int64_t n, const cfpo_options *o, const cfpo_engine_config *cfg,
                                   char *err, size_t errlen)
{
    const double born = now();
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o->variant, o->seed, err, errlen) != 0) return NULL;
    cfpo_tiling T;
    if (cfpo_tiling_init(&T, G.g, comm_size(), cfg->px, cfg->py, err, errlen) != 0) return NULL;
    cfpo_engine *E = new_engine(n, &G, &T, o, cfg);
    if (!comm_all(E != NULL)) {
        free(E);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    E->t_born = born;
    if (!comm_all(cfpo_gridmodes_init(&E->gm, G.g, n) == 0)) {
        snprintf(err, errlen, "out of memory");
        cfpo_engine_free(E);
        return NULL;
    }
    if (o->variant == CFPO_VARIANT_HYPERUNIFORM) {
        if (n / 25 * 20 > (int64_t)INT32_MAX) { /* the summed grid of about 16 n / 25 values: an int count (comm_sum_i64) */
            snprintf(err, errlen, "--variant hyperuniform: n = %lld is too large for its transport grid",
                     (long long)n);
            cfpo_engine_free(E);
            return NULL;
        }
        if (!comm_all(cfpo_transport_init(&E->lf, n, E->nthreads) == 0)) {
            snprintf(err, errlen, "out of memory for the transport's grids");
            cfpo_engine_free(E);
            return NULL;
        }
    }
    if (!comm_all(alloc_cells(E) == 0)) {
        snprintf(err, errlen, "out of memory for n = %lld (%.1f GB per rank needed)", (long long)n,
                 (double)cfpo_engine_bytes_local(n / E->nranks, G.g * G.g / E->nranks, 0, E->nthreads) / 1e9);
        cfpo_engine_free(E);
        return NULL;
    }
    E->near = cfpo_policy_starts_near(o->variant); /* a checkpoint says otherwise */
    int rc = load_points(E, err, errlen);
    if (!comm_all(rc == 0)) {
        if (rc == 0) snprintf(err, errlen, "another rank failed to make its points");
        cfpo_engine_free(E);
        return NULL;
    }
    if (eng_ensure_scratch(E) != 0 || eng_ensure_cap(E, (size_t)E->nloc + 1) != 0) rc = -1;
    if (rc == 0 && eng_refresh_halo(E) != 0) rc = -1;
    if (!comm_all(rc == 0)) {
        snprintf(err, errlen, "out of memory");
        cfpo_engine_free(E);
        return NULL;
    }
    /* The decisions of the iteration the engine stands at, until
     * cfpo_engine_begin asks for the next one's. */
    E->pol = cfpo_policy_at(&E->G, E->cur, E->near, E->dmin_now);
    if (!comm_all(eng_brick_table(E) == 0)) {
        snprintf(err, errlen, "out of memory");
        cfpo_engine_free(E);
        return NULL;
    }
    if (cfg->check) start_checks(E);
    E->t_halo = 0;
    E->b_halo = 0;
    return E;
}

void cfpo_engine_timing_get(cfpo_engine *E, cfpo_engine_timing *t)
{
    double v[5] = {E->t_compute, E->t_migrate, E->t_halo, E->b_halo, E->b_migrate};
    double mn[5], mx[5], sm[5];
    for (int i = 0; i < 5; i++) mn[i] = mx[i] = sm[i] = v[i];
    comm_min_d(mn, 5);
    comm_max_d(mx, 5);
    comm_sum_d(sm, 5);
    double *dst[5] = {t->compute, t->migrate, t->halo, t->halo_bytes, t->migrate_bytes};
    for (int i = 0; i < 5; i++) {
        dst[i][0] = mn[i];
        dst[i][1] = sm[i] / E->nranks;
        dst[i][2] = mx[i];
    }
    t->phases = E->phases;
    t->checked_migrations = E->chk_mig;
    t->checked_halos = E->chk_halo;
}
