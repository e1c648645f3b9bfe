/* plan.c - see plan.h. */
#include "plan.h"

#include "cfpo.h"
#include "cli.h"
#include "comm.h"
#include "engine.h"
#include "omp_compat.h"
#include "transport.h"

int cfpo_plan_make(cfpo_plan *p, int64_t n, const cfpo_options *o, int P, int px, int py, char *err,
                   size_t errlen)
{
    *p = (cfpo_plan){.n = n, .ranks = P};
    if (cfpo_grid_init(&p->G, n, o->variant, o->seed, err, errlen) != 0) return -1;
    if (cfpo_tiling_init(&p->T, p->G.g, P, px, py, err, errlen) != 0) return -1;
    const int64_t g = p->G.g;
    const cfpo_tiling *T = &p->T;
    p->points_per_cell = (double)n / (double)(g * g);
    p->wmax = cfpo_tile_len(g, T->px, 0);
    p->hmax = cfpo_tile_len(g, T->py, 0);
    p->wmin = cfpo_tile_len(g, T->px, T->px - 1);
    p->hmin = cfpo_tile_len(g, T->py, T->py - 1);
    p->cells_max = p->wmax * p->hmax;
    p->points_max = (double)p->cells_max * p->points_per_cell;
    p->threads = o->threads > 0 ? o->threads : omp_get_num_procs();
    p->bytes_per_rank = (double)cfpo_engine_bytes_local((int64_t)(p->points_max * 1.02), p->cells_max,
                                                        cfpo_tile_ring(p->wmax, p->hmax), p->threads);
    /* the hyperuniform variant's transport grids: whole on every rank */
    if (o->variant == CFPO_VARIANT_HYPERUNIFORM)
        p->bytes_per_rank += cfpo_transport_bytes(n, (int64_t)(p->points_max * 1.02));
    /* Halo per phase: a rank sends the cells of its border that its
     * neighbours keep (every border cell, corners to up to three ranks):
     * 4 bytes of count per cell and 16 per point. */
    const int64_t sx = T->px > 1 ? 2 * p->hmax : 0, sy = T->py > 1 ? 2 * p->wmax : 0;
    const int64_t corners = (T->px > 1 && T->py > 1) ? 4 : 0;
    p->halo_cells = (double)(sx + sy + corners);
    p->halo_bytes = p->halo_cells * (4 + 16 * p->points_per_cell);
    /* Migration per phase: at most every point of the phase's colour in the
     * border cells leaves, 32 bytes each. */
    p->migrate_bytes = p->halo_cells / (p->G.period * p->G.period) * p->points_per_cell * 32 * 1.5;
    p->max_ranks = cfpo_tiling_max_ranks(g);
    return 0;
}

int cfpo_plan_check(int64_t n, const cfpo_options *o, int px, int py, char *err, size_t errlen)
{
    const int P = comm_size();
    if (P == 1) {
        int vr = cfpo_validate(n, o, err, errlen);
        if (vr != 0) return vr;
    }
    cfpo_plan p;
    if (cfpo_plan_make(&p, n, o, P, px, py, err, errlen) != 0) return -1;
    if (P == 1) return 0;
    const int64_t pmax = (int64_t)((double)p.cells_max * p.points_per_cell * 1.05) + 64;
    return cfpo_validate_ranks(n, o, pmax, p.cells_max, cfpo_tile_ring(p.wmax, p.hmax), comm_local_size(), err,
                               errlen);
}

void cfpo_plan_peak_memory(uint64_t *sum, uint64_t *max)
{
    int64_t s = (int64_t)cli_peak_rss(), m = s;
    comm_sum_i64(&s, 1);
    comm_max_i64(&m, 1);
    *sum = (uint64_t)s;
    *max = (uint64_t)m;
}
