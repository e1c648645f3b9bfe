/* main_ccdt.c - the `cfpo-ccdt` command: capacity-constrained Delaunay
 * triangulation (ccdt.h) with the iterative baselines' command line
 * (iter_main.h). */
#include <stdio.h>

#include "ccdt.h"
#include "cli.h"
#include "iter_main.h"

/* CGAL's periodic triangulation (rebuilt each iteration) and two flat
 * copies of its connectivity. Peak resident set measured (/usr/bin/time -v):
 * 37.2 MB at n = 65,536, 131.3 MB at n = 262,144, i.e. about 480 bytes a
 * point + 6 MB; 720 bytes a point + 8 MiB keeps 1.5 times room. */
static uint64_t bytes(void *ctx, int64_t n)
{
    (void)ctx;
    return (uint64_t)n * 720 + ((uint64_t)8 << 20);
}

/* --reference K: the reference schedule for K iterations */
static int parse_option(void *ctx, int which, const char *arg, char *err, size_t errlen)
{
    (void)which;
    int64_t v;
    if (cli_parse_i64(arg, 1, 1000000000, &v) != 0) {
        snprintf(err, errlen, "--reference: '%s' is not a whole number in 1..1e9", arg);
        return -1;
    }
    *(int *)ctx = (int)v;
    return 0;
}

static void *create(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    ccdt_engine *E = ccdt_create(n, seed, tol, err, errlen);
    if (E) ccdt_set_reference(E, *(int *)ctx);
    return E;
}

static void iterate(void *E, cfpo_iter_stats *s) { ccdt_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { ccdt_deltas(E, a, b); }
static const double *points(void *E) { return ccdt_points(E); }
static void destroy(void *E) { ccdt_free(E); }
static void trace_values(void *E, char *buf, size_t len)
{
    snprintf(buf, len, "\t%d\t%.6g\t%lld\t%.6g", ccdt_sweeps(E), ccdt_step(E), (long long)ccdt_new_edges(E),
             ccdt_area_cv(E));
}

int main(int argc, char **argv)
{
    int ref_iters = 0;
    const it_method m = {
        .prog = "cfpo-ccdt",
        .method = "ccdt",
        .about = "Capacity-constrained Delaunay triangulation (Xu, Liu, Gotsman, Gortler 2011) on the\n"
                 "unit torus, on CGAL's periodic Delaunay triangulation. Each iteration alternates\n"
                 "a geometry phase (connectivity fixed: Gauss-Seidel sweeps move every point to the\n"
                 "least-squares position that equalises its triangles' areas) with a Delaunay\n"
                 "phase (re-triangulation); the step is damped against cycling, guarded against\n"
                 "inversions, and the run goes to convergence (--tol). Prints one SUMMARY line on\n"
                 "stdout.",
        .options_help = "      --reference K    the reference schedule instead: per iteration one sweep with\n"
                        "                       full steps, then re-triangulation; K iterations, no damping\n",
        .options = (const it_option[]){{"reference", 1}, {NULL, 0}},
        .parse_option = parse_option,
        .trace_extra = "\tsweeps\tstep\tnew_edges\tarea_cv",
        .bytes = bytes,
        .create = create,
        .iterate = iterate,
        .deltas = deltas,
        .trace_values = trace_values,
        .points = points,
        .destroy = destroy,
    };
    return it_main(argc, argv, &m, &ref_iters);
}
