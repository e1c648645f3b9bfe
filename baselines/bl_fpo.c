/* bl_fpo.c - FPO and LFPO (fpo.h) as baseline methods (bl_method.h): their
 * options (--global/--local, --start), their n check and their engine.
 * Two rows, one engine: LFPO is FPO with `local` set by default. */
#include <stdio.h>

#include "bl_method.h"
#include "fpo.h"

enum { LOCAL, START };

#define FPO_OPTIONS(local_default, global_mark, local_mark)                                                      \
    {{.cli = "local", .py = "", .type = BL_FLAG, .def = local_default, .cli_off = "global",                       \
      .help = "      --global         global FPO: the largest empty circle of the whole set" global_mark "\n"      \
              "      --local          LFPO: the largest empty circle in the removed point's\n"                   \
              "                       2-ring only" local_mark "\n"},                                             \
     {.cli = "start", .py = "start", .type = BL_CHOICE, .def = FPO_START_RANDOM,                                \
      .bad = "is not one of random, grid",                                                                       \
      .choices = {[FPO_START_RANDOM] = "random", [FPO_START_GRID] = "grid"},                                     \
      .help = "      --start S        random (default: uniform points) or grid (cfpo's\n"                         \
              "                       stratified start, the same points as\n"                                     \
              "                       `cfpo --variant paper -s S`)\n"}}

static const bl_option FPO_OPTS[] = FPO_OPTIONS(0, " (default)", "");
static const bl_option LFPO_OPTS[] = FPO_OPTIONS(1, "", " (default)");

static void options_of(const bl_value *v, double tol, fpo_options *o)
{
    fpo_options_init(o);
    o->tol = tol;
    o->local = (int)v[LOCAL].i;
    o->start = (int)v[START].i;
}

static const char *method_name(const bl_value *v) { return v[LOCAL].i ? "lfpo" : "fpo"; }

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    fpo_options o;
    options_of(v, tol, &o);
    return fpo_validate(n, &o, err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    fpo_options o;
    options_of(v, tol, &o);
    o.seed = seed;
    return fpo_create(n, &o, err, errlen);
}

static void *create_density(const bl_value *v, int64_t n, uint64_t seed, double tol, const cfpo_density *d,
                            char *err, size_t errlen)
{
    fpo_options o;
    options_of(v, tol, &o);
    o.seed = seed;
    o.density = d;
    if (fpo_validate(n, &o, err, errlen) != 0) return NULL;
    return fpo_create(n, &o, err, errlen);
}

static const char *density_refuses(const bl_value *v)
{
    return v[START].i == FPO_START_GRID ? "--start grid does not go with --density (the start is drawn from the density)"
                                        : NULL;
}

static void iterate(void *E, cfpo_iter_stats *s) { fpo_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { fpo_deltas(E, a, b); }
static const double *points(void *E) { return fpo_points(E); }
static void destroy(void *E) { fpo_free(E); }

#define FPO_ROW(row_name, row_prog, opts)                                                                       \
    {.name = row_name, .prog = row_prog, .kind = BL_ITERATIVE,                                                   \
     .about = "Farthest Point Optimization (Schloemer, Heck, Deussen 2011) on the unit torus,\n"                 \
              "on CGAL's periodic Delaunay triangulation. Prints one SUMMARY line on stdout.",                   \
     BL_OPTIONS(opts), BL_ENGINE, .method_name = method_name, .create_density = create_density,                 \
     .density_refuses = density_refuses,                                                                         \
     .density_help = "the start drawn proportional to rho; each point moves to\n"                              \
                     "                       the Delaunay circumcentre of largest smallest measure when\n"       \
                     "                       that raises its own (--start grid does not apply)"}

const bl_method bl_fpo = FPO_ROW("fpo", "cfpo-fpo", FPO_OPTS);
const bl_method bl_lfpo = FPO_ROW("lfpo", "cfpo-lfpo", LFPO_OPTS);
