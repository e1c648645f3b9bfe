/* main_fpo.c - the `cfpo-fpo` and `cfpo-lfpo` commands: global and local
 * Farthest Point Optimization (fpo.h) with the iterative baselines'
 * command line (iter_main.h), plus --global, --local and --start. Built
 * twice: FPO_PROG names the command and FPO_LOCAL_DEFAULT picks the method
 * when --local/--global is not given. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "fpo.h"
#include "iter_main.h"

#ifndef FPO_PROG
#define FPO_PROG "cfpo-fpo"
#endif
#ifndef FPO_LOCAL_DEFAULT
#define FPO_LOCAL_DEFAULT 0
#endif

enum { OPT_GLOBAL, OPT_LOCAL, OPT_START };

static int parse(void *ctx, int which, const char *arg, char *err, size_t errlen)
{
    fpo_options *o = ctx;
    switch (which) {
    case OPT_GLOBAL: o->local = 0; return 0;
    case OPT_LOCAL: o->local = 1; return 0;
    default:
        if (strcmp(arg, "random") == 0) o->start = FPO_START_RANDOM;
        else if (strcmp(arg, "grid") == 0) o->start = FPO_START_GRID;
        else {
            snprintf(err, errlen, "--start: '%s' is not one of random, grid", arg);
            return -1;
        }
        return 0;
    }
}

static const char *method_name(void *ctx) { return ((fpo_options *)ctx)->local ? "lfpo" : "fpo"; }

static int validate(void *ctx, int64_t n, double tol, char *err, size_t errlen)
{
    fpo_options *o = ctx;
    o->tol = tol;
    return fpo_validate(n, o, err, errlen);
}

static uint64_t bytes(void *ctx, int64_t n)
{
    (void)ctx;
    return fpo_bytes(n);
}

static void *create(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    fpo_options *o = ctx;
    o->seed = seed;
    o->tol = tol;
    return fpo_create(n, o, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { fpo_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { fpo_deltas(E, a, b); }
static const double *points(void *E) { return fpo_points(E); }
static void destroy(void *E) { fpo_free(E); }

int main(int argc, char **argv)
{
    fpo_options o;
    fpo_options_init(&o);
    o.local = FPO_LOCAL_DEFAULT;
    char help[512];
    snprintf(help, sizeof help,
             "      --global         global FPO: the largest empty circle of the whole set%s\n"
             "      --local          LFPO: the largest empty circle in the removed point's\n"
             "                       2-ring only%s\n"
             "      --start S        random (default: uniform points) or grid (cfpo's\n"
             "                       stratified start, the same points as\n"
             "                       `cfpo --variant paper -s S`)\n",
             FPO_LOCAL_DEFAULT ? "" : " (default)", FPO_LOCAL_DEFAULT ? " (default)" : "");
    const it_method m = {
        .prog = FPO_PROG,
        .method = FPO_LOCAL_DEFAULT ? "lfpo" : "fpo",
        .about = "Farthest Point Optimization (Schloemer, Heck, Deussen 2011) on the unit torus,\n"
                 "on CGAL's periodic Delaunay triangulation. Prints one SUMMARY line on stdout.",
        .options_help = help,
        .options = (const it_option[]){{"global", 0}, {"local", 0}, {"start", 1}, {NULL, 0}},
        .trace_extra = "",
        .parse_option = parse,
        .method_name = method_name,
        .validate = validate,
        .bytes = bytes,
        .create = create,
        .iterate = iterate,
        .deltas = deltas,
        .points = points,
        .destroy = destroy,
    };
    return it_main(argc, argv, &m, &o);
}
