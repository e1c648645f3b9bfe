/* bnot.h - blue noise through optimal transport (de Goes, Breeden,
 * Ostromoukhov, Desbrun, "Blue Noise through Optimal Transport", ACM
 * Transactions on Graphics 31(6), SIGGRAPH Asia 2012) on the unit torus,
 * on CGAL's Regular_triangulation_2 with periodic copies.
 *
 * Owns: the n sites and their weights; the power diagram of the sites on
 * the torus (CGAL has no periodic regular triangulation: the sites and
 * their copies shifted by the 8 unit offsets that lie within a margin m of
 * the unit square are triangulated, and the power cells of the original
 * sites are the torus's); the capacity solve (the weights that give every
 * power cell the area 1/n); the Lloyd step (every site to the centroid of
 * its power cell); the transport energy and the iteration statistics.
 * Under a density rho (bnot_create_density) "area" below means rho's mass,
 * centroids and moments are rho-weighted and an edge's length is rho's
 * integral along it (dens_poly.h); everything else is unchanged.
 * Does not own: the stopping loop, files or the command line (main_bnot.c).
 *
 * The algorithm (the paper's alternation of a capacity solve and a Lloyd
 * step):
 *   capacity solve: damped Newton on the weights w. The area A_i(w) of
 *     power cell i has dA_i/dw_j = -|e_ij| / (2 |p_i - p_j|) for each
 *     power-diagram edge e_ij between cells i and j (summed over copies),
 *     and dA_i/dw_i = -sum_j of those: a weighted graph Laplacian H. Solve
 *     H d = 1/n - A by Jacobi-preconditioned conjugate gradients (the
 *     system is singular, constant in its kernel, consistent: the right
 *     side sums to 0), relative residual 1e-3; step w + a d, a = 1, 1/2,
 *     ... until every cell keeps at least half of min(1/n, the smallest
 *     area before the step) and |A - 1/n| (2-norm) fell by a factor
 *     (1 - a/2) (Kitagawa, Merigot, Thibert's damped Newton, which
 *     converges from any start with non-empty cells). Done when every
 *     |A_i n - 1| <= cap_tol (1e-8 by default).
 *   Lloyd step: every site moves to the centroid of its power cell (all at
 *     once); the weights are kept as the start of the next solve (reset to
 *     0, the Voronoi diagram, if a cell is then empty).
 * The transport energy E = sum_i integral over cell i of |x - p_i|^2 with
 * the capacities solved: the Lloyd step lowers it on fixed cells (by
 * sum A_i |c_i - p_i|^2), and the solve then finds the optimal partition
 * with those capacities for the new sites, no costlier than the old cells,
 * so E does not increase from one iteration to the next (up to the
 * capacity tolerance).
 *
 * Choices: start uniform random (src/common/rng.h); margin m = 3 / sqrt(n) at
 * first, doubled (up to every copy) whenever a cell vertex of an original
 * site could lie in the power cell of a copy left out (checked exactly:
 * at every vertex x of every original cell, its power |x - p|^2 - w must
 * not exceed dist(x, outside the margin box)^2 - max w); points are
 * inserted one by one in a serpentine order of a grid of bins, each with
 * the previous vertex as hint, so the triangulation and every sum are the
 * same for the same input (CGAL's spatial sort shuffles with a global
 * random state). Converged when no site's Lloyd move reaches tol * L, L =
 * cfpo's cell side (as CCDT and FPO), or nothing moved.
 *
 * The authors' schedule (bnot_rule, the default of cfpo-bnot; de Goes et
 * al.'s code as the UTK project ships it), with the gradient norm
 * |g| = sqrt(sum_i (2 A_i |c_i - x_i|)^2) (c_i the centroid of cell i)
 * and tau = 0.03 epsilon / n:
 *   coarse phase: the weights reset to 0 and solved until |A - 1/n|
 *     (2-norm) < 2 tau (at most 20 Newton steps), one Lloyd step; until
 *     |g| <= 2 tau, measured after the step on the weights it was taken
 *     with;
 *   fine phase: the weights solved from the current ones until
 *     |A - 1/n| < tau, one gradient step x_i += a 2 A_i (c_i - x_i),
 *     a = n/2, n/4, ... the first that keeps every cell and lowers
 *     F = E - sum_i w_i (A_i - 1/n) by at least 1e-4 a |g|^2 (weights
 *     fixed; a = n/2 is about a Lloyd step); until |g| <= tau;
 *   at most round_iters iterations a round (the coarse phase hitting it
 *     ends the run, as in the reference);
 *   the regularity breaker, between rounds: a site is regular when the
 *     mean |V_i - V_j| over its Delaunay neighbours j, V the cells' second
 *     moments about their sites, is below n^-3 / 4 (a near-perfect
 *     hexagonal patch); when any is, every regular site and its
 *     neighbours move by a random vector of length up to jitter / n,
 *     min(max_teleport, regular) of the regular sites (random) go to
 *     uniform random positions, the weights reset, and a new round
 *     starts with the coarse phase. At most max_rounds rounds. The
 *     reference also perturbs after its last round and returns that set
 *     unoptimised; here the last round ends the run without a
 *     perturbation, so the output is always an optimised set.
 * A C interface over a C++ implementation. */
#ifndef CFPO_BASELINES_BNOT_H
#define CFPO_BASELINES_BNOT_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"
#include "density.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bnot_engine bnot_engine;

#define BNOT_CAP_TOL 1e-8

/* The defaults of the schedule's options that the command and Python
 * offer (bl_bnot.c), as bnot_rule_init sets them. */
#define BNOT_DEFAULT_EPSILON 0.2
#define BNOT_DEFAULT_MAX_ROUNDS 20
#define BNOT_DEFAULT_ROUND_ITERS 20

/* The authors' schedule (see above); epsilon 0: the run to a move
 * tolerance (tol) with capacities to cap_tol instead. */
typedef struct {
    double epsilon;    /* default 0.2 */
    int breaker;       /* the regularity breaker (default 1) */
    int max_rounds;    /* rounds of optimisation (default 20) */
    int max_teleport;  /* default 100 */
    int round_iters;   /* iterations a round at most (default 20, as the UTK
                        * project's driver runs the authors' code) */
    int max_newton;    /* Newton steps a solve at most (default 20) */
    double jitter;     /* largest jitter, times 1/n (default 1) */
} bnot_rule;
void bnot_rule_init(bnot_rule *r);

/* Uniform random start; the capacities are solved before it returns.
 * NULL with a message. */
bnot_engine *bnot_create(int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
/* A given start (n distinct points in [0,1)^2, xy interleaved), scale L,
 * capacity tolerance cap_tol (relative). For tests. */
bnot_engine *bnot_create_from(int64_t n, const double *xy, double L, double tol, double cap_tol,
                              char *err, size_t errlen);
/* The authors' schedule (r; NULL: its defaults): a given start xy (NULL:
 * uniform random from seed), scale L (0: cfpo's cell side for n); seed
 * also drives the breaker. tol only counts the moved sites of the stats. */
bnot_engine *bnot_create_rule(int64_t n, const double *xy, uint64_t seed, double L, double tol,
                              const bnot_rule *r, char *err, size_t errlen);
/* Under a density d (which must outlive the engine): the start (xy NULL)
 * is the uniform start thinned to d (dens_draw.h: for d = 1 the same
 * points); cells' areas, centroids and moments, and the Hessian's edge
 * lengths, are d's mass, d-weighted centroids and moments and d's
 * integral along the edges (dens_poly.h); the deltas in d's symmetric
 * measure (src/density/dens_measure.h). r as bnot_create_rule (NULL: the
 * authors' defaults); with d, r->epsilon 0 gives the run to tol (as
 * bnot_create, L 0: cfpo's cell side). A constant d takes the
 * uniform formulas (equal for rho = 1) unless flags has
 * BNOT_DENS_PIXELS (tests). d NULL: bnot_create_rule. */
#define BNOT_DENS_PIXELS 1
bnot_engine *bnot_create_density(int64_t n, const double *xy, uint64_t seed, double L, double tol,
                                 const bnot_rule *r, const cfpo_density *d, int flags, char *err, size_t errlen);
void bnot_free(bnot_engine *E);

/* One Lloyd step then the capacity solve (the authors' schedule: one
 * iteration of its current phase, and the breaker when a round ends).
 * s->moved: sites that moved more than tol * L; s->solved: n;
 * s->max_disp: largest move / L; s->converged: the run is over. */
void bnot_iterate(bnot_engine *E, cfpo_iter_stats *s);

/* The authors' schedule's state: |g| measured in the last iteration (NAN
 * before any), its threshold now (2 tau coarse, tau fine; 0 outside the
 * schedule), the phase (0 move-tolerance run, 1 coarse, 2 fine, 3 done),
 * the round (from 1), the breaker's perturbations so far and the regular
 * sites it found last. */
double bnot_grad_norm(const bnot_engine *E);
int bnot_phase(const bnot_engine *E);
/* the phase the last iteration's step was taken in (its |g| was judged
 * against 2 tau when 1, tau when 2) */
int bnot_step_phase(const bnot_engine *E);
int bnot_round(const bnot_engine *E);
int64_t bnot_breaks(const bnot_engine *E);
int64_t bnot_last_regular(const bnot_engine *E);
/* The regularity test on the current diagram: flag[i] = 1 for each
 * regular site (flag may be NULL); returns their number. */
int64_t bnot_regular_sites(bnot_engine *E, unsigned char *flag);
/* The breaker once: when sites are regular, jitter, teleport, reset the
 * weights and solve (coarse tolerance); returns the regular sites found
 * (0: nothing done). */
int64_t bnot_break_regularity(bnot_engine *E);

/* The transport energy (capacities as solved), and that of the cells
 * before the last Lloyd step with the sites at their centroids (the
 * energy the last solve started from; equal to bnot_energy before any
 * iteration). */
double bnot_energy(const bnot_engine *E);
double bnot_energy_moved(const bnot_engine *E);
/* n E / 2: the cells' mean normalised second moment about their sites
 * when every area is 1/n (0.0802 for a hexagonal lattice, 0.0833 for a
 * square one); the trace's `energy`. */
double bnot_energy_nsm(const bnot_engine *E);
/* Largest |A_i n - 1| (the capacity error), Newton steps of the last
 * solve, and whether it met cap_tol. */
double bnot_cap_err(const bnot_engine *E);
int bnot_newton_steps(const bnot_engine *E);
/* Conjugate-gradient iterations of the last solve, all Newton steps. */
int64_t bnot_cg_iterations(const bnot_engine *E);
int bnot_solve_ok(const bnot_engine *E);

/* The areas and centroids (absolute, unwrapped: may lie outside [0,1)) of
 * the power cells, and the weights, by site. */
const double *bnot_areas(const bnot_engine *E);
const double *bnot_centroids(const bnot_engine *E);
const double *bnot_weights(const bnot_engine *E);

void bnot_deltas(bnot_engine *E, double *dmin, double *davg);
const double *bnot_points(const bnot_engine *E);

typedef struct {
    int valid;         /* CGAL's is_valid() */
    int64_t empty;     /* original sites hidden or with area <= 0 */
    double area_sum;   /* sum of the areas of the original cells */
    double margin;     /* the margin m of the last triangulation */
} bnot_check_info;
void bnot_check(const bnot_engine *E, bnot_check_info *c);

#ifdef __cplusplus
}
#endif
#endif
