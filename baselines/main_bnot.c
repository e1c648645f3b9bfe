/* main_bnot.c - the `cfpo-bnot` command: blue noise through optimal
 * transport (bnot.h) with the iterative baselines' command line
 * (iter_main.h). */
#include <stdio.h>

#include "bnot.h"
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

static void *create(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)ctx;
    return bnot_create(n, seed, tol, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { bnot_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { bnot_deltas(E, a, b); }
static const double *points(void *E) { return bnot_points(E); }
static void destroy(void *E) { bnot_free(E); }
static void trace_values(void *E, char *buf, size_t len)
{
    snprintf(buf, len, "\t%d\t%lld\t%.3g\t%.9f", bnot_newton_steps(E), (long long)bnot_cg_iterations(E),
             bnot_cap_err(E), bnot_energy_nsm(E));
}

int main(int argc, char **argv)
{
    const it_method m = {
        .prog = "cfpo-bnot",
        .method = "bnot",
        .about = "Blue noise through optimal transport (de Goes, Breeden, Ostromoukhov, Desbrun 2012)\n"
                 "on the unit torus, on CGAL's regular triangulation with periodic copies: every\n"
                 "iteration moves each site to the centroid of its power cell, then solves the\n"
                 "weights (damped Newton) that give every power cell the area 1/n. Prints one\n"
                 "SUMMARY line on stdout.",
        .options_help = "",
        .trace_extra = "\tnewton\tcg\tcap_err\tenergy",
        .bytes = bytes,
        .create = create,
        .iterate = iterate,
        .deltas = deltas,
        .trace_values = trace_values,
        .points = points,
        .destroy = destroy,
    };
    return it_main(argc, argv, &m, NULL);
}
