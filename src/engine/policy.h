/* policy.h - layer 2 (may include cfpo_types.h, geom.h, rng.h, grid.h):
 * the variants' per-iteration policy, in one place.
 *
 * Owns: every decision of the adaptive variant's schedule (docs/method.md,
 * "--variant adaptive", items 2, 3 and 5-7) and the same decisions for the
 * paper's and the simplified variants (fixed margin, no shift, exact
 * solves, no over-relaxation), as pure functions of the grid (variant, L,
 * Delta(n), seed), the iteration and the run's statistics (delta(X) as last
 * measured; whether the near phase still runs, which the statistics of an
 * earlier sweep ended). The schedule (engine_schedule.c) asks
 * cfpo_policy_at once per iteration and keeps the answer in the engine;
 * every backend reads it from there and applies the two per-point rules
 * below (the square a point may move in, and the over-relaxed spot), so no
 * backend holds a constant or a decision of the schedule. As functions of
 * the iteration number and of reduced statistics only, the decisions are
 * the same on every rank and thread, and a run resumed from a checkpoint
 * makes them as the uninterrupted run does.
 *
 * The adaptive schedule, iteration k (1-based):
 *   k        the near solve searches   moves over-relaxed with w =
 *   1-3      2 Voronoi cells           (none: the solver's spot)
 *   4-6      2                         3.0, else 1.8
 *   7-19     1                         3.0, else 1.8
 *   20 on    1                         1.8, else 1.4
 * The near solve runs from the first iteration until a near sweep
 * converges, LocalCFPO after it (its cells column matters only before).
 * The grid moves before each of iterations 1-8 and then before 9, 13,
 * 17, ..., staying for the three iterations after each of those; move j
 * (from 0) puts each axis at its own offset on a walk, sigma_j = 3 L
 * frac(u + j / 7) with u from the seed, one u for x and an independent one
 * for y: 3/7 of a cell a move around the colours' period 3 L. The grid is
 * shifted by sigma_j mod L on that axis and the sweep starts with colour
 * (r_y, r_x), r = floor(sigma_j / L) (which is the grid shifted by
 * (sigma_x, sigma_y) itself). In the adaptive variant (and in the
 * hyperuniform one's adaptive sweeps above 65,536 points) the colours are
 * brick colourings, rows of cells shifted under the even moves and
 * columns under the odd ones, swept in the brick order (below;
 * docs/method.md, item 3). Each sweep under one grid prints the grid
 * and its colours on the set (a density wave at the frequencies m g / 3,
 * m = 1..4, of phase 2 pi m sigma_j / (3 L) on its axis), and the print
 * outlives the sweep: with one grid for four sweeps from the start, a
 * spike 30-60x its ring at a million points; with the walk each move's
 * print at the cells' and the colours' strongest frequencies (m = 3, 4:
 * phase steps of 154 and 206 degrees) mostly cancels the last one's, and
 * moving the grid before every one of the first eight sweeps, while the
 * set is loose enough to take the print, keeps each print from growing
 * (docs/method.md, item 3). The two walks keep the same step, which
 * leaves a print along (-1, 1) unturned (P(-g, g) 5-14 times its ring at
 * a million points, 52 at four million): no constant pair of steps turns
 * every (mx, my) g / 3, |mx|, |my| <= 4, by more than 14 degrees a move,
 * and the walks apart that were measured turned the diagonals but left
 * more at (0, g), (g, 0) or (0, 4g/3) (docs/tried.md). The margin of every
 * iteration is L - max(delta(X) (1 + 1e-9), 0.7 Delta(n)), at least 0;
 * each point's square is cut to a margin of min(margin, L - t),
 * t = r0 + tol L, and a point with t >= 1.5 L stays where it is.
 * Does not own: the adaptive start (start.c), the tolerance's default
 * (cfpo_types.h), the solvers (geom.h), applying a shift (the schedule). */
#ifndef CFPO_POLICY_H
#define CFPO_POLICY_H

#include <math.h>

#include "cfpo_types.h"
#include "geom.h"
#include "grid.h"
#include "rng.h"

/* The default tolerance of a run: of the variant on the uniform torus,
 * or, under a density that is not flat (density), CFPO_DENSITY_TOL (the
 * density engine, docs/method.md "Density": a move must gain more than
 * this many local spacings in the measure, and a run has converged when no
 * point moved that far in an iteration). The one place a run's default is
 * chosen (cfpo_types.h holds the three values). */
static inline double cfpo_policy_default_tol(int variant, int density)
{
    if (density) return CFPO_DENSITY_TOL;
    return variant == CFPO_VARIANT_ADAPTIVE || variant == CFPO_VARIANT_HYPERUNIFORM ? CFPO_ADAPTIVE_TOL
                                                                                      : CFPO_DEFAULT_TOL;
}

/* The density engine's schedule ends a run (docs/method.md, "Density"):
 * every CFPO_POLICY_DENSITY_WINDOW iterations it compares delta_avg with
 * its value one window earlier (*ref, 0 before the first window ends) and
 * calls the run converged when it rose by less than
 * CFPO_POLICY_DENSITY_STALL; the tail after that polishes delta_avg by
 * less than 1e-3 over hundreds of iterations. Returns 1 when iteration k
 * ends the run; updates *ref at each window's end. A pure function of the
 * iteration, the measured delta_avg and *ref (which a checkpoint keeps).
 * 1e-4 since the relaxed start (dens_relax.h, 2026-11-29): from it the
 * shipped image creeps by 6e-5 a window for 48 iterations more than from
 * the Hilbert start, for under 2e-4 of delta_avg. */
#define CFPO_POLICY_DENSITY_WINDOW 16
#define CFPO_POLICY_DENSITY_STALL 1e-4
static inline int cfpo_policy_density_stalled(int k, double davg, double *ref)
{
    if (k <= 0 || k % CFPO_POLICY_DENSITY_WINDOW != 0) return 0;
    const int stalled = *ref > 0 && davg - *ref < CFPO_POLICY_DENSITY_STALL;
    *ref = davg;
    return stalled;
}

/* The density engine's over-relaxation (docs/method.md, "Density"): a
 * point's move from a to the candidate c is pushed on to a + w (c - a)
 * when that spot passes the same rules as c (it gains tol, f there is
 * above the old value against every point that can matter, it is in the
 * box and the cell); else the point goes to c. As in the uniform path,
 * it carries a move across many points in one sweep. */
#define CFPO_POLICY_DENSITY_RELAX 1.8
/* Its weights by iteration (since 2026-11-29, issue 42), tried in order
 * until a spot passes: none in iterations 1 to
 * CFPO_POLICY_DENSITY_RELAX_FROM - 1, where relaxed moves slow delta_min's
 * first climb (each gives up part of its point's own gain); then
 * CFPO_POLICY_DENSITY_RELAX_STRONG up to CFPO_POLICY_DENSITY_RELAX_STRONG_TO,
 * which carries the loose set's moves further, and
 * CFPO_POLICY_DENSITY_RELAX_LATE after it; each followed by
 * CFPO_POLICY_DENSITY_RELAX and CFPO_POLICY_DENSITY_RELAX_MILD. At 65,536
 * points (0.85, 0.90) is reached after 7-9 iterations instead of 10-11;
 * the late weights' stronger first try keeps the converged quality that
 * the relaxation's late start alone lost (a single 1.8 from iteration 10
 * on: delta_avg 0.0010 lower at the stop); docs/tried.md, results
 * 2026-11-29-density8. Writes the weights into w[3]; returns their count. */
#define CFPO_POLICY_DENSITY_RELAX_FROM 4
#define CFPO_POLICY_DENSITY_RELAX_STRONG 3.0
#define CFPO_POLICY_DENSITY_RELAX_STRONG_TO 9
#define CFPO_POLICY_DENSITY_RELAX_LATE 2.2
#define CFPO_POLICY_DENSITY_RELAX_MILD 1.4
static inline int cfpo_policy_density_relax(int k, double w[3])
{
    if (k < CFPO_POLICY_DENSITY_RELAX_FROM) return 0;
    w[0] = k <= CFPO_POLICY_DENSITY_RELAX_STRONG_TO ? CFPO_POLICY_DENSITY_RELAX_STRONG : CFPO_POLICY_DENSITY_RELAX_LATE;
    w[1] = CFPO_POLICY_DENSITY_RELAX;
    w[2] = CFPO_POLICY_DENSITY_RELAX_MILD;
    return 3;
}
/* The uniform path's near solves search two Voronoi cells before this
 * iteration, one after (policy.c). */
#define CFPO_POLICY_NEAR_TWO_UNTIL 7
/* The adaptive variant's brick colourings (cfpo_policy_colour_at) up to
 * this iteration, the plain colours after it (policy.c). */
#define CFPO_POLICY_BRICK_UNTIL 40
/* The density engine's near solve (docs/method.md, "Density", item 5).
 * In a 3 x 3 block whose largest q is at most CFPO_POLICY_DENSITY_NEAR_FLAT
 * times its smallest, a solve follows the uniform path's near solve: the
 * polygons of the point's two nearest neighbours in the measure before
 * iteration CFPO_POLICY_NEAR_TWO_UNTIL, its nearest's alone after, and a
 * point they give no move stays (as in the uniform path's near phase).
 * In a steeper block, the two nearest's polygons first, and the `all`
 * nearest's (DENS_CELLS, ten, as LocalCFPO) when those give no move:
 * across a steep change the nearest polygons can miss the spots a point
 * should reach. That fall-back runs in every iteration of the first group
 * of CFPO_POLICY_DENSITY_FALL_EVERY (iterations 1-4, the start's largest
 * moves: without it the shipped image at 65,536 points took 4-8
 * iterations to (0.85, 0.90) instead of 3) and after that in the first
 * iteration of each group (the grid's new offset, when every cell is
 * solved). The accept rule is the same for every solve, so delta_min
 * never falls. A pure function of the block and the iteration.
 *
 * The steep block's solve in the other iterations of a group is the first
 * part of its solve in the group's first: the same two polygons, the same
 * relaxed spots and accept checks, and only where those give no move does
 * the first iteration go on to the ten. So a cell that moved nothing in
 * any iteration of the group moves nothing when solved again in a later
 * one, and the engine's skip of unchanged cells (and a resume, which
 * solves every cell in its first iteration) stays exact.
 *
 * Since 2026-12-01 (dens22, issue 42) the blocks flat within 20% take the
 * uniform near solve; until then that ran only in blocks flat within 2%,
 * blocks flat within 2-20% took the two polygons in every iteration and
 * fell back to five (ten until 2026-12-01), and steeper blocks searched
 * all ten (the price: about 0.0007 of converged delta_avg, results
 * 2026-12-01-dens22). Since 2026-12-02 (dens25) the steep blocks'
 * fall-back runs as above, where it ran in every iteration: at 4,096
 * points an iteration on the ramp 1:256 costs 1.456x a flat density's
 * instructions (was 1.610x) and 1.69x its native seconds (was 1.89x),
 * for about 0.0002 of the shipped image's converged delta_avg (results
 * 2026-12-02-dens25, docs/tried.md). */
#define CFPO_POLICY_DENSITY_NEAR_CELLS 2
#define CFPO_POLICY_DENSITY_NEAR_FLAT 1.2
#define CFPO_POLICY_DENSITY_FALL_EVERY 4
/* Returns the polygons of the near solve in a block with smallest q qlo
 * and largest qhi in iteration k (1, 2, ...), and in *fall the polygons a
 * point it gives no move is solved over (0: none; `all` in iterations 1
 * to CFPO_POLICY_DENSITY_FALL_EVERY and in the first iteration of each
 * later group of that many). */
static inline int cfpo_policy_density_near(int k, double qlo, double qhi, int all, int *fall)
{
    if (qhi <= qlo * CFPO_POLICY_DENSITY_NEAR_FLAT) {
        *fall = 0;
        return k < CFPO_POLICY_NEAR_TWO_UNTIL ? 2 : 1;
    }
    *fall = k <= CFPO_POLICY_DENSITY_FALL_EVERY || (k - 1) % CFPO_POLICY_DENSITY_FALL_EVERY == 0 ? all : 0;
    return CFPO_POLICY_DENSITY_NEAR_CELLS < all ? CFPO_POLICY_DENSITY_NEAR_CELLS : all;
}

#define CFPO_BRICK_ROWS 1
#define CFPO_BRICK_COLUMNS 2
/* The decisions for one iteration. */
typedef struct {
    int iteration;  /* k, the iteration they are for (0: before the first) */
    double L;       /* the cell side, for the per-point rules */
    double margin;  /* how far S reaches past the cell: the grid's fixed
                       margin (paper, simplified) or the adaptive one */
    double shift_x; /* the grid's offsets in this iteration */
    double shift_y;
    int rot_x;      /* the sweep solves colours (rot_y + a, rot_x + b) mod */
    int rot_y;      /* period in the order (a, b) = (0, 0), (0, 1), ... (0 but
                       in the adaptive-like variants) */
    int balanced;   /* 1: (a, b) in the balanced order instead (period 3) */
    int brick;      /* the colouring (cfpo_policy_colour_at): 0 the plain
                       one, CFPO_BRICK_ROWS or CFPO_BRICK_COLUMNS */
    uint64_t brick_key; /* with brick: the key of the rows' (columns') shifts */
    int cut;        /* 1: each point's square is cut to keep it t from the
                       points beyond its block (adaptive) */
    double freeze;  /* with cut: a point whose t reaches this stays (1.5 L) */
    int near;       /* 1: the near solve (cfpo_near_solve); 0: LocalCFPO */
    int near_cells; /* with near: the Voronoi cells it searches (2 or 1) */
    int relax;      /* the over-relaxation weights to try, in order: 0 or 2 */
    double w[2];
    int all;        /* 1: every cell is solved (the hyperuniform stage) */
    int transport;  /* a transport sweep instead of solves, along the band's
                       field (CFPO_TRANSPORT_BAND, transport.h) or the
                       grid's print's (CFPO_TRANSPORT_PRINT, gridmodes.h) */
    double cap;     /* with transport: a point keeps min(r0, cap) from all */
    double vmax;    /* with transport: the longest displacement followed */
    int unprint;    /* 1: before its own sweep, the iteration takes one
                       sweep of cfpo_policy_unprint's (the grid's print
                       removed) */
} cfpo_policy;

#define CFPO_TRANSPORT_BAND 1
#define CFPO_TRANSPORT_PRINT 2

/* The grid's print (gridmodes.h) is removed before the sweeps of
 * iterations CFPO_POLICY_UNPRINT_FROM to CFPO_POLICY_UNPRINT_UNTIL of the
 * adaptive-like variants (the hyperuniform one's adaptive sweeps
 * included): after each of the eight fast grid moves' sweeps, which write
 * nearly all of it (docs/tried.md, issue 44). Removed once only, after
 * the eighth, the next sweep writes it again at the same phase (the set's
 * neighbourhoods, settled by then, carry it); removed after each, the
 * neighbourhoods settle without it. In runs of more than
 * CFPO_POLICY_UNPRINT_MIN points: at fewer, the print's P, which grows
 * like n, stays within the spectrum's noise, and their sets stay the
 * bytes they were. */
#define CFPO_POLICY_UNPRINT_FROM 2
#define CFPO_POLICY_UNPRINT_UNTIL 9
#define CFPO_POLICY_UNPRINT_MIN 65536
/* The removal's sweep, from iteration P's decisions and delta(X) /
 * Delta(n) = dmin as last measured: transport moves along the print's
 * field, each point keeping min(r0, delta(X)) from all (delta(X) never
 * falls), none longer than CFPO_POLICY_UNPRINT_VMAX Delta(n) (the field
 * moves points by about 0.001 Delta(n) at 4M; the bound keeps a start
 * with a strong lattice of its own, --init, from large linearised moves);
 * P's grid, colouring and square. */
#define CFPO_POLICY_UNPRINT_VMAX 0.01
cfpo_policy cfpo_policy_unprint(const cfpo_policy *P, const cfpo_grid *G, double dmin);

/* The last iteration of a run of grid G (the hyperuniform variant's), or
 * 0 where the convergence rule alone ends a run. */
int cfpo_policy_last(const cfpo_grid *G);
/* The first iteration of the hyperuniform stage (0 for other variants). */
int cfpo_policy_stage_from(const cfpo_grid *G);

/* The decisions for iteration k of a run of grid G, the run being in its
 * near phase (near) with delta(X) / Delta(n) = dmin as last measured (1
 * before the first measurement). A pure function of its arguments. */
cfpo_policy cfpo_policy_at(const cfpo_grid *G, int k, int near, double dmin);

/* The grid's offset on axis 0 (x) or 1 (y) in iteration k (0 before the
 * first, and always 0 but in the adaptive-like variants): sigma_j mod L of
 * that axis for the grid's move j in force in iteration k (above). */
double cfpo_policy_shift(const cfpo_grid *G, int k, int axis);
/* sigma_j / L of axis 0 (x) or 1 (y) in iteration k, in [0, period): the
 * walk (0 where cfpo_policy_shift is 0). */
double cfpo_policy_walk(const cfpo_grid *G, int k, int axis);
/* The colour the sweep of a policy solves j-th (j in [0, period^2)). */
/* The balanced order (docs/method.md, item 3; issue 44): a sweep's
 * colours in row order give every row of colours its turn together, so a
 * row's cells move before or after their neighbours' by two thirds of a
 * sweep on average, and that difference prints the colours' period on y
 * at (0, g / 3). The first harmonic of the colours' turns, squared and
 * summed over the four directions of the 3 x 3 colours (x, y, x + y,
 * x - y), is the same for every order (270); row order puts 243 of it on
 * y, this one at most 75 on any direction. Entry j: a * 3 + b. */
static const int cfpo_policy_balanced_order[9] = {0, 1, 4, 5, 7, 8, 3, 2, 6};
/* The brick order (issue 44): under a brick colouring (below) the
 * shifted axis holds no colours' period, and only the three rows (brick
 * rows; columns under brick columns) of colours, r = y mod 3, print: a row
 * of cells whose turns come earlier in the sweep on average moves before
 * its neighbours and prints the period on y, as the plain colouring's row
 * order does. Entry j: r * 3 + i, the i-th colour of row r; the rows'
 * turns are {0, 5, 7}, {1, 3, 8}, {2, 4, 6}, the same mean (4) for every
 * row. After two sweeps at 1,048,576 points (seed 1) (0, g / 3) stands at
 * 0.9 times its ring against 13.3 with the rows in turn (turns {0, 3, 6},
 * {1, 4, 7}, {2, 5, 8}) and 27 with the balanced order (docs/tried.md). */
static const int cfpo_policy_brick_order[9] = {0, 3, 6, 4, 7, 1, 8, 2, 5};
static inline int cfpo_policy_colour(const cfpo_policy *P, int period, int j)
{
    if (P->brick && period == 3) {
        const int r = cfpo_policy_brick_order[j] / 3, i = cfpo_policy_brick_order[j] % 3;
        if (P->brick == CFPO_BRICK_ROWS) return ((r + P->rot_y) % 3) * 3 + (i + P->rot_x) % 3;
        return ((i + P->rot_y) % 3) * 3 + (r + P->rot_x) % 3;
    }
    if (P->balanced && period == 3) j = cfpo_policy_balanced_order[j];
    return ((j / period + P->rot_y) % period) * period + (j % period + P->rot_x) % period;
}

/* The colourings (period 3, g a multiple of 3). Plain: global cell
 * (x, y) has colour (y mod 3) 3 + (x mod 3). Brick rows: every row of
 * cells y is shifted by its own s_y in {0, 1, 2}, colour
 * (y mod 3) 3 + ((x - s_y) mod 3); brick columns the same with the roles
 * of x and y swapped. Two cells of one colour are then either in one row
 * (column), x 3 apart, or in rows 3 apart, so their 3x3 blocks are
 * disjoint for any shifts (the brick tilings by 3x3 squares), and every
 * 3x3 block of cells holds one cell of each colour. The shift of row
 * (column) i is a hash of the iteration's key and the global index i, so
 * the colouring is the same on every rank and thread. */
static inline int cfpo_policy_brick_shift(uint64_t key, int64_t i)
{
    return (int)(cfpo_mix64(key ^ (0x9e3779b97f4a7c15ULL * (uint64_t)(i + 1))) % 3);
}
/* The colour of global cell (gx, gy), each in [0, g). */
static inline int cfpo_policy_colour_at(const cfpo_policy *P, int period, int64_t gx, int64_t gy)
{
    if (P->brick == CFPO_BRICK_ROWS) gx += period - cfpo_policy_brick_shift(P->brick_key, gy);
    else if (P->brick == CFPO_BRICK_COLUMNS) gy += period - cfpo_policy_brick_shift(P->brick_key, gx);
    return (int)(gy % period) * period + (int)(gx % period);
}

/* Whether a run of this variant starts in the near phase (adaptive). */
int cfpo_policy_starts_near(int variant);

/* Whether the near phase ends after a sweep whose statistics say
 * `converged` (no point moved by tol L): then every cell is solved again
 * by LocalCFPO, and the sweep does not count as converged. */
int cfpo_policy_near_ends(int near, int converged);

/* The square a point may move in, in its cell's frame (cell = [0, L]^2),
 * for a point at distance r0 from its nearest neighbour in the block, with
 * t = r0 + tol L: the cell grown by the margin, or, with P->cut, by
 * min(margin, L - t) (negative: shrunk), so that every spot of it is at
 * least t from every point beyond the 3x3 block and a move raises the
 * point's distance to all of X (docs/method.md, item 2). Returns 0 when
 * the point stays (t >= 1.5 L: a hole no move inside the block improves). */
static inline int cfpo_policy_square(const cfpo_policy *P, double t, cfpo_square *S)
{
    double e = P->margin;
    if (P->cut) {
        if (t >= P->freeze) return 0;
        e = fmin(P->margin, P->L - t);
    }
    *S = (cfpo_square){-e, -e, P->L + e, P->L + e};
    return 1;
}

/* Over-relaxation (docs/method.md, item 5): the solver's spot (*nx, *ny)
 * for the point (x, y) of block (bx, by)[0, m), index self, is pushed on
 * along the move to x + w (spot - x) for the first weight w of P->w whose
 * spot lies in S and is farther than sqrt(floor2) from every other point
 * of the block; else the spot stays. Nothing when P->relax is 0.
 *
 * Why over-relaxation keeps the iteration from cycling: the spot taken is
 * in the square and farther than the floor from every point of the block,
 * so (the square keeps it at least t from the points outside the block) it
 * raises x's distance to all of X just as the solver's does. Pushing past
 * the farthest spot gives up some of x's own gain to leave room for its
 * crowded neighbours, whose moves come later in the sweep: like
 * over-relaxed Gauss-Seidel, it carries a move across many points in one
 * sweep where exact moves need many sweeps. Not in the first iterations:
 * their long moves, pushed on, print the grid on the set (a spike at
 * frequency (g, 0) that the later iterations take long to wash out). The
 * strong weights carry the near phase's short moves further while the set
 * is far from converged; the mild ones after them converge in fewer
 * iterations, to a higher delta_min. */
static inline void cfpo_policy_relax(const cfpo_policy *P, const cfpo_square *S, const double *bx, const double *by, int m,
                       int self, double x, double y, double floor2, double *nx, double *ny)
{
    for (int q = 0; q < P->relax; q++) {
        const double rx = x + P->w[q] * (*nx - x), ry = y + P->w[q] * (*ny - y);
        if (rx >= S->x0 && rx <= S->x1 && ry >= S->y0 && ry <= S->y1 &&
            cfpo_min_dist2(rx, ry, bx, by, m, self) > floor2) {
            *nx = rx;
            *ny = ry;
            return;
        }
    }
}

#endif
