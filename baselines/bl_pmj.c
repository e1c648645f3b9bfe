/* bl_pmj.c - progressive multi-jittered (0,2) sequences (pmj.h) as a
 * baseline method (bl_method.h): a direct sampler (its create makes the
 * set; no iterations), pmj02bn by default, pmj02 with --candidates 1. */
#include <math.h>
#include <stdio.h>

#include "bl_method.h"
#include "bl_set.h"
#include "pmj.h"

enum { CANDIDATES, GLOBAL };

static const bl_option OPTS[] = {
    {.cli = "candidates", .py = "candidates", .type = BL_INT, .lo = 1, .hi = PMJ_MAX_CANDIDATES, .def = PMJ_CANDIDATES,
     .bad = "is not a whole number in 1..100000",
     .help = "      --candidates C   valid candidates a point, the one farthest from the\n"
             "                       points before it kept (default %g: pmj02bn; 1: pmj02,\n"
             "                       SUMMARY method=pmj02)\n"},
    {.cli = "global", .py = "global_candidates", .type = BL_FLAG, .def = 0,
     .help = "      --global         candidates from every subquadrant with a valid position,\n"
             "                       not only the one the progressive order names (not the\n"
             "                       paper's; SUMMARY method=pmj02bn-global)\n"},
};

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    if (n > PMJ_MAX_N) {
        snprintf(err, errlen, "n = %lld is too large (at most 2^26 points)", (long long)n);
        return -1;
    }
    /* the points twice (integers, output), the strata ((k + 1) 2^k bytes, 2^k < 2n), the grid */
    const double k = ceil(log2((double)n)) + 1;
    return bl_check_n_memory("pmj02bn", n, tol, (double)n * 48 + 2 * (double)n * k, err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)tol;
    const pmj_params p = {.candidates = (int)v[CANDIDATES].i, .global = (int)v[GLOBAL].i};
    bl_set *S = bl_set_new(n, err, errlen);
    if (S && pmj_points(n, seed, &p, S->xy, NULL, err, errlen) != 0) {
        bl_set_destroy(S);
        return NULL;
    }
    return S;
}

static const char *pmj_name(const bl_value *v)
{
    if (v[GLOBAL].i) return v[CANDIDATES].i == 1 ? "pmj02-global" : "pmj02bn-global";
    return v[CANDIDATES].i == 1 ? "pmj02" : "pmj02bn";
}

const bl_method bl_pmj02bn = {
    .name = "pmj02bn", .prog = "cfpo-pmj02bn", .kind = BL_ITERATIVE,
    .about = "Progressive multi-jittered (0,2) sequence with blue noise (pmj02bn; Christensen,\n"
             "Kensler and Kilpatrick, EGSR 2018) on the unit square, the unit torus here:\n"
             "each new point in the subquadrant the paper's progressive order gives it, in\n"
             "an elementary interval of every shape that no earlier point occupies (every\n"
             "prefix of 2^k points a (0,k,2)-net), the best of C such candidates by periodic\n"
             "distance to the earlier points. The output order is the sequence's: every\n"
             "prefix is the sequence so far. Direct: no iterations. Prints one SUMMARY line\n"
             "on stdout.",
    BL_OPTIONS(OPTS), .method_name = pmj_name, .check_n = check_n, .create = create, BL_SET_ENGINE,
};
