/* bl_direct.c - the direct samplers as baseline methods (bl_method.h):
 * white noise and jittered sampling (jitter.h) and Owen-scrambled
 * Sobol' (sobol.h). They place their n points at once: the engine's
 * create makes them and the method has no iterate, so the run loop
 * (bl_loop.c) reports the start as converged after 0 iterations; the
 * commands keep the iterative baselines' options (trace, targets) so
 * every method runs the same way in the benchmark. */
#include <stdio.h>

#include "bl_method.h"
#include "bl_set.h"
#include "jitter.h"
#include "sobol.h"

enum { WHITE, JITTER, SOBOL };

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    if (n > (int64_t)1 << 32) { /* Sobol' indices are 32-bit; one bound for the three */
        snprintf(err, errlen, "n = %lld is too large (at most 2^32 points)", (long long)n);
        return -1;
    }
    /* the points, and the nearest-neighbour statistics' grid */
    return bl_check_n_memory("the sampler", n, tol, (double)n * 48, err, errlen);
}

static void *make(int kind, const bl_value *v, int64_t n, uint64_t seed, char *err, size_t errlen)
{
    bl_set *D = bl_set_new(n, err, errlen);
    if (!D) return NULL;
    double *xy = D->xy;
    if (kind == WHITE) white_points(n, seed, xy);
    else if (kind == JITTER) jitter_points(n, seed, xy);
    else sobol_points(n, seed, !v[0].i, xy);
    return D;
}

static void *create_white(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)tol;
    return make(WHITE, v, n, seed, err, errlen);
}
static void *create_jitter(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)tol;
    return make(JITTER, v, n, seed, err, errlen);
}
static void *create_sobol(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)tol;
    return make(SOBOL, v, n, seed, err, errlen);
}

static const char *sobol_name(const bl_value *v) { return v[0].i ? "sobol-plain" : "sobol"; }

static const bl_option SOBOL_OPTS[] = {
    {.cli = "plain", .py = "plain", .type = BL_FLAG, .def = 0,
     .help = "      --plain          the unscrambled sequence (the seed plays no part;\n"
             "                       SUMMARY method=sobol-plain)\n"},
};

#define DIRECT_ENGINE .check_n = check_n, BL_SET_ENGINE

const bl_method bl_white = {
    .name = "white", .prog = "cfpo-white", .kind = BL_ITERATIVE,
    .about = "White noise: n independent uniform points on the unit torus. Direct: no\n"
             "iterations (the stop rules see the set once). Prints one SUMMARY line on stdout.",
    .noptions = 0, .create = create_white, DIRECT_ENGINE,
};

const bl_method bl_jitter = {
    .name = "jitter", .prog = "cfpo-jitter", .kind = BL_ITERATIVE,
    .about = "Jittered sampling: one uniform point in each of n strata of the unit square,\n"
             "r = round(sqrt(n)) rows of height 1/r, row k cut into floor((k+1)n/r) -\n"
             "floor(kn/r) equal cells (the m x m jitter when n = m^2). Direct: no\n"
             "iterations. Prints one SUMMARY line on stdout.",
    .noptions = 0, .create = create_jitter, DIRECT_ENGINE,
};

const bl_method bl_sobol = {
    .name = "sobol", .prog = "cfpo-sobol", .kind = BL_ITERATIVE,
    .about = "Owen-scrambled Sobol': the first n points (natural order) of the 2-D Sobol'\n"
             "sequence, a (0,2)-sequence in base 2, under nested uniform scrambling (Owen\n"
             "1995): each of the first 32 binary digits of a coordinate flipped by a random\n"
             "bit of its node in the tree of elementary intervals, the digits below uniform.\n"
             "At n = 2^m a (0,m,2)-net: every dyadic box of area 1/n holds one point; at\n"
             "other n a prefix of the sequence (each aligned block of 2^k points is a\n"
             "(0,k,2)-net). Direct: no iterations. Prints one SUMMARY line on stdout.",
    BL_OPTIONS(SOBOL_OPTS), .method_name = sobol_name, .create = create_sobol, DIRECT_ENGINE,
};
