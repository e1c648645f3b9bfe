/* bl_lloyd.c - Lloyd's CVT (lloyd.h) as a baseline method (bl_method.h):
 * its cap on iterations, its memory model and its engine. */
#include <stdio.h>

#include "bl_method.h"
#include "lloyd.h"

static const bl_option OPTS[] = {
    {.cli = "iterations", .py = "iterations", .type = BL_INT, .lo = 0, .hi = 1000000000, .def = LLOYD_ITERATIONS,
     .bad = "is not a whole number in 0..1e9",
     .help = "      --iterations K   the run ends (as converged) after K iterations (default %g,\n"
             "                       before the hexagonal CVT); 0: only by --tol\n"},
};

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return -1;
    }
    return bl_check_n_memory("lloyd", n, tol, lloyd_bytes(n), err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    return lloyd_create(n, seed, tol, (int)v[0].i, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { lloyd_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { lloyd_deltas(E, a, b); }
static const double *points(void *E) { return lloyd_points(E); }
static void destroy(void *E) { lloyd_free(E); }

const bl_method bl_lloyd = {
    .name = "lloyd",
    .prog = "cfpo-lloyd",
    .kind = BL_ITERATIVE,
    .about = "Lloyd's algorithm (1982) on the unit torus, on CGAL's periodic Delaunay\n"
             "triangulation: from uniform points, every site moves at once to the centroid\n"
             "of its Voronoi cell, towards a centroidal Voronoi tessellation; converged when\n"
             "no site moves --tol * L, or after --iterations steps. Prints one SUMMARY line on stdout.",
    BL_OPTIONS(OPTS),
    BL_ENGINE,
};
