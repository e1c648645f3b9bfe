/* engine_schedule.c - the colour schedule: the phase (one colour, through
 * the backend's steps and the host's migration and halo), moving the grid
 * under the points, the sweep (every colour once), the iteration with its
 * statistics and the run loop with its stop rules. Each iteration's
 * decisions (margin, grid shift, solver, over-relaxation) come from the
 * policy (policy.h), asked once per iteration in cfpo_engine_begin; the
 * end of the near phase is its rule too.
 * The one colour loop of the project: cfpo, the library and cfpo-bench
 * all sweep through cfpo_engine_sweep.
 *
 * Why a phase is race-free (written once, here): two cells of one colour
 * are at least `period` cells apart in one direction, on the whole torus,
 * whatever the tiles (in the plain colouring in both; in a brick
 * colouring, policy.h, two cells of one row are 3 apart in x and cells of
 * different rows 3 apart in y). A point of cell C may move only inside
 * S(x), C grown by a margin below L (L - Delta(n) in the paper's variant,
 * at most L - delta(X) in the adaptive one), so it stays in C's 3x3
 * block, and solving C reads only
 * C's 3x3 block. With period 3 the blocks of two same-colour cells are
 * disjoint, so no cell is written by one thread (or rank) and read by
 * another (Parallelization Theorem). The simplified variant keeps points in
 * their own cell, so period 2 suffices. Inside a cell, points are solved in
 * id order, each seeing the moves of the ones before it.
 *
 * Between phases: points that crossed into another cell of this tile are
 * moved there; points that crossed into a halo cell migrate to the rank
 * that owns it; then every rank sends the cells next to its tile's border
 * to the neighbours whose halo holds them. So the next phase sees exactly
 * what one process would see, and the output is the same bytes for any
 * number of ranks and threads.
 *
 * Skipping: a cell is solved again only if some cell of its 3x3 block
 * changed (a point moved in it, left it or arrived; for halo cells: the
 * refreshed copy differs) since its last solve. An unchanged block means
 * the same inputs (same Y in the same order, same x), hence the same
 * answer, which last time was "do not move", so the output is
 * byte-identical to recomputing everything.
 *
 * Net displacement over an iteration is kept per point (two floats that
 * travel with the point); a move there and back cancels exactly, so a
 * point cycling between cells does not keep the run from converging. */
#include "backend.h"
#include "stoprule.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void sync_host(cfpo_engine *E)
{
    if (E->be->sync_host) E->be->sync_host(E);
}

static void sync_device(cfpo_engine *E)
{
    if (E->be->sync_device) E->be->sync_device(E);
}

/* Every cell is to be solved in the next sweep (skipping aside). */
static void need_all(cfpo_engine *E)
{
    for (int64_t c = 0; c < E->cells; c++) E->mask[c] |= NEED_BIT;
}

/* After the cells of colour C changed (points moved, or the grid moved
 * under them): mark the blocks that changed, send points that left the
 * tile, move points that changed cell, clear the masks, refresh the halo.
 * `moves`: whether any cell of the colour has mask bits. */
static void settle(cfpo_engine *E, const eng_colour *C, int64_t moves)
{
    const double t1 = now();
    const int crossed = moves ? E->be->mark(E, C) : 0;
    if (crossed || E->nnb) sync_host(E);
    int rc = 0;
    if (crossed && eng_pack_migrants(E, C) != 0) rc = -1;
    if (!crossed)
        for (int k = 0; k < E->nnb; k++) E->nb[k].nout = 0;
    if (rc == 0 && eng_exchange_migrants(E) != 0) rc = -1;
    if (rc == 0 && (crossed || E->narr) && E->be->relocate(E, C->colour) != 0) rc = -1;
    if (rc != 0) eng_fatal(E, "moving points between cells");
    if (moves) E->be->unmark(E, C);
    for (size_t i = 0; i < E->narr; i++) E->mask[E->arr[i].cell] &= (uint16_t)~ARRIVE_BIT;
    E->narr = 0;
    E->t_migrate += now() - t1;
    if (E->cfg.check && !E->shifting) eng_check_migration(E);
    if (eng_refresh_halo(E) != 0) eng_fatal(E, "refreshing the halo");
    if (E->nnb) sync_device(E);
    if (E->cfg.check && !E->shifting) eng_check_halo(E);
}

int64_t cfpo_engine_phase(cfpo_engine *E, int colour, int64_t *solved)
{
    const eng_colour C = eng_colour_of(E, colour);
    const double t0 = now();
    *solved = 0;
    const int64_t moves = E->be->solve(E, &C, solved);
    E->t_compute += now() - t0;
    E->phases++;
    settle(E, &C, moves);
    return moves;
}

/* Moves the grid under the points to the offsets (shift_x, shift_y): colour by
 * colour, the points of each cell go to the cell that holds them now
 * (the same or a neighbour, as |change| < L), through the same steps as a
 * phase's moves. Then every cell is solved again and every statistics
 * block recomputed (each cell's frame and constraint square moved). */
static void move_grid(cfpo_engine *E, double shift_x, double shift_y)
{
    E->G.shift_x = shift_x;
    E->G.shift_y = shift_y;
    E->shifting = 1;
    for (int colour = 0; colour < E->G.period * E->G.period; colour++) {
        const eng_colour C = eng_colour_of(E, colour);
        E->be->regrid(E, &C);
        settle(E, &C, 1);
    }
    E->shifting = 0;
    need_all(E);
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    if (E->cfg.check) {
        eng_check_migration(E);
        eng_check_halo(E);
    }
}

/* The grid's print removed (policy.h, cfpo_policy_unprint): the set's
 * modes at the grid's lattice vectors, every rank's fixed-point sums added
 * exactly (the same field for any rank count), then one sweep of transport
 * moves along the field that cancels them; the iteration's own decisions
 * back, and every cell solved again in its sweep. The pass's moves count
 * in the iteration's net displacements, not in its moves. */
static void unprint(cfpo_engine *E)
{
    const cfpo_policy P = E->pol;
    cfpo_gridmodes_sum(&E->gm, E->px, E->py, E->nloc, E->nthreads);
    comm_sum_i64(E->gm.acc, 2 * E->gm.count);
    cfpo_gridmodes_finish(&E->gm, E->n);
    E->pol = cfpo_policy_unprint(&P, &E->G, E->dmin_now);
    E->G.margin = E->pol.margin;
    need_all(E);
    for (int colour = 0; colour < E->G.period * E->G.period; colour++) {
        int64_t sv = 0;
        cfpo_engine_phase(E, cfpo_policy_colour(&E->pol, E->G.period, colour), &sv);
    }
    E->pol = P;
    E->G.margin = P.margin;
    need_all(E);
}

/* The coming iteration's decisions, asked of the policy once (policy.h:
 * from the iteration number, the phase and delta(X) as last measured),
 * kept in E->pol for the backend; the margin they give; the grid moved to
 * their shift; then the backend's start of an iteration, and where the
 * policy asks, the grid's print removed before the iteration's sweep. */
void cfpo_engine_begin(cfpo_engine *E)
{
    E->cur++;
    E->pol = cfpo_policy_at(&E->G, E->cur, E->near, E->dmin_now);
    if (eng_brick_table(E) != 0) eng_fatal(E, "colouring the cells");
    E->G.margin = E->pol.margin;
    if (E->pol.shift_x != E->G.shift_x || E->pol.shift_y != E->G.shift_y)
        move_grid(E, E->pol.shift_x, E->pol.shift_y);
    if (E->pol.all)
        need_all(E);
    if (E->pol.transport) {
        /* the band's modes of the whole set: every rank's fixed-point grid,
         * summed exactly, so the same field for any rank count */
        if (cfpo_transport_spread(&E->lf, E->px, E->py, E->nloc, E->n) != 0) eng_fatal(E, "transport");
        comm_sum_i64(cfpo_transport_grid(&E->lf), (int)cfpo_transport_grid_count(&E->lf));
        cfpo_transport_finish(&E->lf, E->n);
    }
    E->be->begin(E);
    if (E->pol.unprint && E->gm.count) unprint(E);
}

void cfpo_engine_sweep(cfpo_engine *E, int64_t *moved, int64_t *solved)
{
    cfpo_engine_begin(E);
    *moved = *solved = 0;
    for (int colour = 0; colour < E->G.period * E->G.period; colour++) {
        int64_t sv = 0;
        *moved += cfpo_engine_phase(E, cfpo_policy_colour(&E->pol, E->G.period, colour), &sv);
        *solved += sv;
    }
}

void cfpo_engine_iterate(cfpo_engine *E, cfpo_iter_stats *s)
{
    const double t0 = now();
    int64_t v[2];
    cfpo_engine_sweep(E, &v[0], &v[1]);
    /* Every rank looks: a point that moved may have migrated to a rank
     * that moved none itself. */
    double mx[2] = {E->be->max_disp2(E), E->max_move};
    comm_sum_i64(v, 2);
    comm_max_d(mx, 2);
    s->moved = v[0];
    s->solved = v[1];
    s->max_disp = sqrt(mx[0]) / E->G.L;
    s->max_move = sqrt(mx[1]) / E->G.L;
    s->converged = cfpo_net_converged(v[0], s->max_disp, E->o.tol);
    s->near = E->near;
    /* The near phase ends when its sweep moves no point by tol (policy.h):
     * the exact solver takes over, every cell solved again, and only its
     * sweeps can end the run as converged (the same decision on every
     * rank, from the reduced counts). */
    if (cfpo_policy_near_ends(E->near, s->converged)) {
        E->near = 0;
        s->converged = 0;
        need_all(E);
    }
    /* The hyperuniform variant's stage (policy.c) schedules its own near
     * sweeps, so the near phase is over (a checkpoint says near = 0; the
     * trace's column says which sweeps were near ones); the variant ends,
     * converged, at its last iteration. */
    if (cfpo_policy_last(&E->G) > 0) {
        if (E->pol.all) {
            E->near = 0;
            s->near = E->pol.near;
        }
        s->converged = E->cur >= cfpo_policy_last(&E->G);
    }
    cfpo_engine_deltas(E, &s->delta_min, &s->delta_avg);
    double el = now() - t0;
    comm_max_d(&el, 1);
    s->seconds = el;
}
