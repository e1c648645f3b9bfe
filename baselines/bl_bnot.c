/* bl_bnot.c - BNOT (bnot.h) as a baseline method (bl_method.h): the
 * authors' schedule's options, the memory model, the engine and the trace
 * columns. */
#include <stdio.h>

#include "bl_method.h"
#include "bnot.h"

enum { EPSILON, BREAKER, MAX_ROUNDS, ROUND_ITERS };

static const bl_option OPTS[] = {
    {.cli = "epsilon", .py = "epsilon", .type = BL_REAL, .min = 0, .max = 1e3, .def = BNOT_DEFAULT_EPSILON,
     .bad = "is not a number in [0, 1000]",
     .help = "      --epsilon E      the stopping rule's epsilon (default %g); 0: run until no\n"
             "                       site moves --tol * L, capacities to 1e-8, no breaker\n"},
    {.cli = "", .py = "breaker", .type = BL_FLAG, .def = 1, .cli_off = "no-breaker",
     .help = "      --no-breaker     stop after the first round\n"},
    {.cli = "max-rounds", .py = "max_rounds", .type = BL_INT, .lo = 1, .hi = 1000000,
     .def = BNOT_DEFAULT_MAX_ROUNDS, .bad = "is not a whole number in 1..1e6",
     .help = "      --max-rounds R   rounds of optimisation at most (default %g)\n"},
    {.cli = "round-iters", .py = "round_iters", .type = BL_INT, .lo = 1, .hi = 1000000,
     .def = BNOT_DEFAULT_ROUND_ITERS, .bad = "is not a whole number in 1..1e6",
     .help = "      --round-iters K  iterations a round at most (default %g)\n"},
};

static const bl_column COLUMNS[] = {{"newton", "%lld"},   {"cg", "%lld"},    {"cap_err", "%.3g"},
                                    {"energy", "%.9f"},   {"grad_norm", "%.6g"}, {"phase", "%lld"},
                                    {"round", "%lld"},    {"regular", "%lld"}};

/* CGAL's regular triangulation (rebuilt at every Newton step), the cells,
 * the Hessian and the CG vectors: peak resident set measured 15.2 MB at
 * n = 16,384 and 41.1 MB at 65,536, i.e. about 540 bytes a point over
 * 6.7 MB; 1000 bytes a point with room. */
static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    const double bytes = (double)((uint64_t)n * 1000 + ((uint64_t)8 << 20));
    return bl_check_n_memory("bnot", n, tol, bytes, err, errlen);
}

/* The schedule's options as given. */
static bnot_rule rule_of(const bl_value *v)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.epsilon = v[EPSILON].d;
    r.breaker = (int)v[BREAKER].i;
    r.max_rounds = (int)v[MAX_ROUNDS].i;
    r.round_iters = (int)v[ROUND_ITERS].i;
    return r;
}

/* epsilon > 0: the authors' schedule; 0: the run to tol */
static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    if (!(v[EPSILON].d > 0)) return bnot_create(n, seed, tol, err, errlen);
    const bnot_rule r = rule_of(v);
    return bnot_create_rule(n, NULL, seed, 0, tol, &r, err, errlen);
}

/* the same under a density: the start drawn from rho, rho's masses */
static void *create_density(const bl_value *v, int64_t n, uint64_t seed, double tol, const cfpo_density *d,
                            char *err, size_t errlen)
{
    const bnot_rule r = rule_of(v);
    return bnot_create_density(n, NULL, seed, 0, tol, &r, d, 0, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { bnot_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { bnot_deltas(E, a, b); }
static const double *points(void *E) { return bnot_points(E); }
static void destroy(void *E) { bnot_free(E); }
static void column_values(void *E, double *out)
{
    out[0] = bnot_newton_steps(E);
    out[1] = (double)bnot_cg_iterations(E);
    out[2] = bnot_cap_err(E);
    out[3] = bnot_energy_nsm(E);
    out[4] = bnot_grad_norm(E);
    out[5] = bnot_step_phase(E);
    out[6] = bnot_round(E);
    out[7] = (double)bnot_last_regular(E);
}

const bl_method bl_bnot = {
    .name = "bnot",
    .prog = "cfpo-bnot",
    .kind = BL_ITERATIVE,
    .about = "Blue noise through optimal transport (de Goes, Breeden, Ostromoukhov, Desbrun 2012)\n"
             "on the unit torus, on CGAL's regular triangulation with periodic copies: every\n"
             "iteration moves each site to the centroid of its power cell, then solves the\n"
             "weights (damped Newton) that give every power cell the area 1/n. By default it\n"
             "runs as its authors' code does: a coarse phase (weights reset, solved, one Lloyd\n"
             "step) until the gradient norm |g| <= 2 tau, tau = 0.03 epsilon / n, then line-\n"
             "searched steps until |g| <= tau, at most 20 iterations a round (a coarse phase\n"
             "that reaches the cap ends the run, as in the UTK project's driver); then the\n"
             "regularity breaker jitters near-perfect hexagonal patches, teleports up to 100\n"
             "of their sites and runs a new round, at most 20 rounds. Prints one SUMMARY line\n"
             "on stdout.",
    BL_OPTIONS(OPTS),
    BL_COLUMNS(COLUMNS),
    BL_ENGINE,
    .column_values = column_values,
    .create_density = create_density,
    .density_help = "the start drawn proportional to rho; every power cell's\n"
                    "                       capacity is its mass of rho (1/n each), the Lloyd\n"
                    "                       step goes to rho-weighted centroids, the Newton\n"
                    "                       Hessian integrates rho along the power edges",
};
