/* bl_ccdt.c - CCDT (ccdt.h) as a baseline method (bl_method.h): its
 * option (--reference), its memory model, its engine and its trace
 * columns. */
#include <stdio.h>

#include "bl_method.h"
#include "ccdt.h"

static const bl_option OPTS[] = {
    {.cli = "reference", .py = "reference", .type = BL_INT, .lo = 1, .hi = 1000000000, .def = 0,
     .bad = "is not a whole number in 1..1e9",
     .help = "      --reference K    the reference schedule instead: per iteration one sweep with\n"
             "                       full steps, then re-triangulation; K iterations, no damping\n"},
};

static const bl_column COLUMNS[] = {{"sweeps", "%lld"}, {"step", "%.6g"}, {"new_edges", "%lld"}, {"area_cv", "%.6g"}};

/* CGAL's periodic triangulation (rebuilt each iteration) and two flat
 * copies of its connectivity. Peak resident set measured (/usr/bin/time -v):
 * 37.2 MB at n = 65,536, 131.3 MB at n = 262,144, i.e. about 480 bytes a
 * point + 6 MB; 720 bytes a point + 8 MiB keeps 1.5 times room. */
static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    const double bytes = (double)((uint64_t)n * 720 + ((uint64_t)8 << 20));
    return bl_check_n_memory("ccdt", n, tol, bytes, err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    ccdt_engine *E = ccdt_create(n, seed, tol, err, errlen);
    if (E) ccdt_set_reference(E, (int)v[0].i);
    return E;
}

static void iterate(void *E, cfpo_iter_stats *s) { ccdt_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { ccdt_deltas(E, a, b); }
static const double *points(void *E) { return ccdt_points(E); }
static void destroy(void *E) { ccdt_free(E); }
static void column_values(void *E, double *out)
{
    out[0] = ccdt_sweeps(E);
    out[1] = ccdt_step(E);
    out[2] = (double)ccdt_new_edges(E);
    out[3] = ccdt_area_cv(E);
}

const bl_method bl_ccdt = {
    .name = "ccdt",
    .prog = "cfpo-ccdt",
    .kind = BL_ITERATIVE,
    .about = "Capacity-constrained Delaunay triangulation (Xu, Liu, Gotsman, Gortler 2011) on the\n"
             "unit torus, on CGAL's periodic Delaunay triangulation. Each iteration alternates\n"
             "a geometry phase (connectivity fixed: Gauss-Seidel sweeps move every point to the\n"
             "least-squares position that equalises its triangles' areas) with a Delaunay\n"
             "phase (re-triangulation); the step is damped against cycling, guarded against\n"
             "inversions, and the run goes to convergence (--tol). Prints one SUMMARY line on\n"
             "stdout.",
    BL_OPTIONS(OPTS),
    BL_COLUMNS(COLUMNS),
    BL_ENGINE,
    .column_values = column_values,
};
