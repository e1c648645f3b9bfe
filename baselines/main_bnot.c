/* main_bnot.c - the `cfpo-bnot` command: blue noise through optimal
 * transport (bnot.h) with the iterative baselines' command line
 * (iter_main.h). */
#include <stdio.h>

#include "bnot.h"
#include "cli.h"
#include "iter_main.h"

/* CGAL's regular triangulation (rebuilt at every Newton step), the cells,
 * the Hessian and the CG vectors: peak resident set measured 15.2 MB at
 * n = 16,384 and 41.1 MB at 65,536, i.e. about 540 bytes a point over
 * 6.7 MB; 1000 bytes a point with room. */
static uint64_t bytes(void *ctx, int64_t n)
{
    (void)ctx;
    return (uint64_t)n * 1000 + ((uint64_t)8 << 20);
}

/* --epsilon E (0: the run to --tol), --no-breaker, --max-rounds R,
 * --round-iters K */
static int parse_option(void *ctx, int which, const char *arg, char *err, size_t errlen)
{
    bnot_rule *r = ctx;
    int64_t v;
    switch (which) {
    case 0:
        if (cli_parse_double(arg, 0, 1e3, &r->epsilon) != 0) {
            snprintf(err, errlen, "--epsilon: '%s' is not a number in [0, 1000]", arg);
            return -1;
        }
        return 0;
    case 1: r->breaker = 0; return 0;
    case 2:
    case 3:
        if (cli_parse_i64(arg, 1, 1000000, &v) != 0) {
            snprintf(err, errlen, "--%s: '%s' is not a whole number in 1..1e6", which == 2 ? "max-rounds" : "round-iters",
                     arg);
            return -1;
        }
        if (which == 2) r->max_rounds = (int)v;
        else r->round_iters = (int)v;
        return 0;
    }
    return -1;
}

static void *create(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    const bnot_rule *r = ctx;
    if (r->epsilon > 0) return bnot_create_rule(n, NULL, seed, 0, tol, r, err, errlen);
    return bnot_create(n, seed, tol, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { bnot_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { bnot_deltas(E, a, b); }
static const double *points(void *E) { return bnot_points(E); }
static void destroy(void *E) { bnot_free(E); }
static void trace_values(void *E, char *buf, size_t len)
{
    snprintf(buf, len, "\t%d\t%lld\t%.3g\t%.9f\t%.6g\t%d\t%d\t%lld", bnot_newton_steps(E),
             (long long)bnot_cg_iterations(E), bnot_cap_err(E), bnot_energy_nsm(E), bnot_grad_norm(E),
             bnot_step_phase(E), bnot_round(E), (long long)bnot_last_regular(E));
}

int main(int argc, char **argv)
{
    bnot_rule rule;
    bnot_rule_init(&rule);
    const it_method m = {
        .prog = "cfpo-bnot",
        .method = "bnot",
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
        .options_help = "      --epsilon E      the stopping rule's epsilon (default 0.2); 0: run until no\n"
                        "                       site moves --tol * L, capacities to 1e-8, no breaker\n"
                        "      --no-breaker     stop after the first round\n"
                        "      --max-rounds R   rounds of optimisation at most (default 20)\n"
                        "      --round-iters K  iterations a round at most (default 20)\n",
        .options = (const it_option[]){{"epsilon", 1}, {"no-breaker", 0}, {"max-rounds", 1}, {"round-iters", 1},
                                       {NULL, 0}},
        .parse_option = parse_option,
        .trace_extra = "\tnewton\tcg\tcap_err\tenergy\tgrad_norm\tphase\tround\tregular",
        .bytes = bytes,
        .create = create,
        .iterate = iterate,
        .deltas = deltas,
        .trace_values = trace_values,
        .points = points,
        .destroy = destroy,
    };
    return it_main(argc, argv, &m, &rule);
}
