/* policy.c - see policy.h: the constants of the adaptive schedule and the
 * functions that turn them into one iteration's decisions. Why each value
 * was chosen, and what was measured against the alternatives, is in
 * docs/method.md ("--variant adaptive"). */
#include "policy.h"

#include <math.h>

#include "rng.h"

/* Moves are over-relaxed from this iteration on ... */
#define RELAX_FROM 4
/* ... with the strong weights before this one and the mild ones after. */
#define RELAX_STRONG_UNTIL 20
static const double relax_strong[2] = {3.0, 1.8}, relax_mild[2] = {1.8, 1.4};
/* The adaptive margin never reaches past L - THETA Delta(n) ... */
#define THETA 0.7
/* ... and takes delta(X) this hair high, so rounding can only shrink S. */
#define DMIN_UP 1e-9
/* A point whose t = r0 + tol L reaches FREEZE L stays where it is. */
#define FREEZE 1.5
/* The grid moves before each of the first FAST_MOVES iterations (the
 * first sweeps print the grid most, and each sweep under one grid adds to
 * the print), then before every SHIFT_EVERY-th: iterations FAST_MOVES + 1,
 * FAST_MOVES + 1 + SHIFT_EVERY, ...; in between, skipping works. */
#define FAST_MOVES 8
#define SHIFT_EVERY 4
#define SHIFT_SALT 0x3c6ef372fe94f82aULL
/* Each move walks WALK_STEP / WALK_CYCLE of the colours' period (3 L) on
 * each axis: 3/7 of a cell, phase steps of 360 m / 7 degrees at the
 * frequencies m g / 3; the two axes start at independent points. */
#define WALK_STEP 1
#define WALK_CYCLE 7

/* The hyperuniform variant: the adaptive schedule until HU_FROM; then
 * HU_FIRST transport sweeps; then HU_ROUNDS rounds of one near sweep
 * (two cells, no over-relaxation) and HU_ROUND - 1 transport sweeps. Every
 * transport sweep keeps each point min(r0, HU_CAP Delta(n)) from all;
 * moves longer than HU_VMAX Delta(n) are shortened to it. */
#define HU_FROM 29
#define HU_FIRST 12
#define HU_ROUNDS 7
#define HU_ROUND 5
#define HU_CAP 0.92
#define HU_VMAX 0.3

static int adaptive_like(int variant)
{
    return variant == CFPO_VARIANT_ADAPTIVE || variant == CFPO_VARIANT_HYPERUNIFORM;
}

int cfpo_policy_stage_from(const cfpo_grid *G)
{
    return G->variant == CFPO_VARIANT_HYPERUNIFORM ? HU_FROM : 0;
}

int cfpo_policy_last(const cfpo_grid *G)
{
    return G->variant == CFPO_VARIANT_HYPERUNIFORM ? HU_FROM - 1 + HU_FIRST + HU_ROUNDS * HU_ROUND : 0;
}

/* The hyperuniform variant up to HU_EARLIER_MAX points keeps the earlier
 * schedule, a move before every SHIFT_EVERY-th iteration from the first
 * and one walk for both axes: its P0 at 4,096 points rose with the new one
 * (median of 20 seeds 9.0e-5 against 7.0e-5), while at such n the grid's
 * print stays within the spectrum's noise (the imprint's P grows like n;
 * docs/tried.md). Above it the variant takes the adaptive schedule: at
 * 1,048,576 points the earlier one prints 44-49x at (0, 4g/3). */
#define HU_EARLIER_MAX 65536
static int earlier_schedule(const cfpo_grid *G)
{
    return G->variant == CFPO_VARIANT_HYPERUNIFORM && G->n <= HU_EARLIER_MAX;
}

/* The number of grid moves before iteration k (k >= 1), less one. */
static int move_index(const cfpo_grid *G, int k)
{
    if (earlier_schedule(G)) return (k - 1) / SHIFT_EVERY;
    if (k <= FAST_MOVES) return k - 1;
    return FAST_MOVES + (k - FAST_MOVES - 1) / SHIFT_EVERY;
}

double cfpo_policy_walk(const cfpo_grid *G, int k, int axis)
{
    if (!adaptive_like(G->variant) || k <= 0) return 0;
    const int j = move_index(G, k);
    /* axis 0 (x) starts where the single offset of both axes used to;
     * under the earlier schedule both axes take it */
    const int apart = axis != 0 && !earlier_schedule(G);
    const double u = cfpo_rand01(G->seed ^ SHIFT_SALT, 1 + (uint64_t)apart, 0) +
                     (double)(j * WALK_STEP % WALK_CYCLE) / WALK_CYCLE;
    return G->period * (u - floor(u));
}

double cfpo_policy_shift(const cfpo_grid *G, int k, int axis)
{
    const double w = cfpo_policy_walk(G, k, axis);
    return G->L * (w - floor(w));
}

/* The adaptive variant's colouring (policy.h, cfpo_policy_colour_at;
 * docs/method.md, item 3; issue 44), and the hyperuniform variant's in
 * its adaptive sweeps (before HU_FROM) above HU_EARLIER_MAX points, where
 * it takes the adaptive schedule: without them its 4,194,304-point set
 * kept the plain colours' print (16.5 times its ring at (g / 3, 0)),
 * which its transport sweeps do not erase. Brick rows under the grid's even
 * moves, brick columns under the odd ones, the shifts drawn anew at each
 * move from the seed and the move's number (kept while the grid stays:
 * new colours under an unmoved grid cost iterations, docs/tried.md), up
 * to iteration CFPO_POLICY_BRICK_UNTIL; the plain colours after it (the
 * print is written in the first sweeps, and a run to convergence under
 * brick colours took 12-21% more iterations at 65,536 points). */
#define BRICK_SALT 0x243f6a8885a308d3ULL
static void brick_colouring(const cfpo_grid *G, int k, cfpo_policy *P)
{
    if (!adaptive_like(G->variant) || earlier_schedule(G) || G->period != 3 || G->g % 3 != 0 || k <= 0 ||
        k > CFPO_POLICY_BRICK_UNTIL)
        return;
    const int j = move_index(G, k);
    P->brick = j % 2 ? CFPO_BRICK_COLUMNS : CFPO_BRICK_ROWS;
    P->brick_key = cfpo_rand64(G->seed ^ BRICK_SALT, (uint64_t)j, 0);
}

int cfpo_policy_starts_near(int variant) { return adaptive_like(variant); }

int cfpo_policy_near_ends(int near, int converged) { return near && converged; }

/* S reaches L - max(delta(X), THETA Delta(n)) past the cell: the most the
 * convergence argument allows while delta(X) is large, and no more than
 * L - THETA Delta(n) early on. */
static double adaptive_margin(const cfpo_grid *G, double dmin)
{
    const double d = fmax(dmin * (1 + DMIN_UP), THETA) * G->delta;
    return d < G->L ? G->L - d : 0;
}

cfpo_policy cfpo_policy_at(const cfpo_grid *G, int k, int near, double dmin)
{
    cfpo_policy P = {.iteration = k, .L = G->L, .margin = G->margin};
    if (!adaptive_like(G->variant)) return P;
    P.margin = adaptive_margin(G, dmin);
    P.shift_x = cfpo_policy_shift(G, k, 0);
    P.shift_y = cfpo_policy_shift(G, k, 1);
    P.rot_x = (int)floor(cfpo_policy_walk(G, k, 0)) % G->period;
    P.rot_y = (int)floor(cfpo_policy_walk(G, k, 1)) % G->period;
    P.balanced = !earlier_schedule(G);
    P.cut = 1;
    P.freeze = FREEZE * G->L;
    if (G->variant == CFPO_VARIANT_HYPERUNIFORM && k >= HU_FROM) {
        const int j = k - HU_FROM;
        P.all = 1;
        if (j < HU_FIRST || (j - HU_FIRST) % HU_ROUND != 0) {
            P.transport = CFPO_TRANSPORT_BAND;
            P.margin = G->L; /* the cut alone: L - min(r0, cap) */
            P.cap = HU_CAP * G->delta;
            P.vmax = HU_VMAX * G->delta;
        } else {
            P.near = 1;
            P.near_cells = 2;
        }
        return P;
    }
    brick_colouring(G, k, &P);
    P.unprint = k >= CFPO_POLICY_UNPRINT_FROM && k <= CFPO_POLICY_UNPRINT_UNTIL && G->n > CFPO_POLICY_UNPRINT_MIN;
    P.near = near != 0;
    P.near_cells = P.near ? (k < CFPO_POLICY_NEAR_TWO_UNTIL ? 2 : 1) : 0;
    if (k >= RELAX_FROM) {
        const double *w = k < RELAX_STRONG_UNTIL ? relax_strong : relax_mild;
        P.relax = 2;
        P.w[0] = w[0];
        P.w[1] = w[1];
    }
    return P;
}

cfpo_policy cfpo_policy_unprint(const cfpo_policy *P, const cfpo_grid *G, double dmin)
{
    cfpo_policy U = *P;
    U.unprint = 0;
    U.near = U.near_cells = U.relax = 0;
    U.all = 1;
    U.transport = CFPO_TRANSPORT_PRINT;
    U.margin = G->L; /* the cut alone, as the band's transport: L - min(r0, cap) */
    U.cap = dmin * G->delta;
    U.vmax = CFPO_POLICY_UNPRINT_VMAX * G->delta;
    return U;
}
