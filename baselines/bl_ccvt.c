/* bl_ccvt.c - CCVT (ccvt.h) as a baseline method (bl_method.h): its
 * options, its memory model, its engine and its trace column. */
#include <stdio.h>

#include "bl_method.h"
#include "ccvt.h"

enum { M, POINT_SET, UPDATE, ASSIGN };

static const bl_option OPTS[] = {
    {.cli = "points-per-site", .py = "points_per_site", .type = BL_INT, .lo = 1, .hi = 1 << 20, .def = 0,
     .bad = "is not a whole number in 1..2^20",
     .help = "      --points-per-site M  discrete points per site (default 1024 up to\n"
             "                       n = 16384, then 2^24 / n, at least 16); memory 16 n M bytes\n"},
    {.cli = "point-set", .py = "point_set", .type = BL_CHOICE, .def = CCVT_POINTS_LATTICE,
     .bad = "is neither lattice nor random",
     .choices = {[CCVT_POINTS_LATTICE] = "lattice", [CCVT_POINTS_RANDOM] = "random"},
     .help = "      --point-set P    lattice (default: a regular lattice of n M nodes) or random\n"
             "                       (uniform random points)\n"},
    {.cli = "update", .py = "update", .type = BL_CHOICE, .def = CCVT_UPDATE_PAIR, .bad = "is neither pair nor pass",
     .choices = {[CCVT_UPDATE_PAIR] = "pair", [CCVT_UPDATE_PASS] = "pass"},
     .help = "      --update U       pair (default: sites move right after their pair swaps)\n"
             "                       or pass (every site that swapped moves after the pass;\n"
             "                       converged also when no site moves --tol * L)\n"},
    {.cli = "assign", .py = "assign", .type = BL_CHOICE, .def = CCVT_ASSIGN_NEAREST,
     .bad = "is neither nearest nor curve",
     .choices = {[CCVT_ASSIGN_NEAREST] = "nearest", [CCVT_ASSIGN_CURVE] = "curve"},
     .help = "      --assign A       nearest (default: the points, last first, each to the\n"
             "                       nearest site not yet full, as Balzer's code) or curve (runs\n"
             "                       of m points along a Hilbert curve to the sites in its order)\n"},
};

static const bl_column COLUMNS[] = {{"swaps", "%lld"}};

/* 16 bytes a discrete point, 8 more while the start is sorted, and 10 KiB
 * a site besides: a fit with room to the peak resident sets measured,
 * 0.41 GB at n = 16,384, m = 1024 and 1.05 GB at n = 65,536, m = 256. */
static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    const int64_t m = v[M].i > 0 ? v[M].i : ccvt_default_m(n);
    const double bytes = (double)((uint64_t)n * (uint64_t)m * 24 + (uint64_t)n * 10240);
    return bl_check_n_memory("ccvt", n, tol, bytes, err, errlen);
}

/* The options as given (--point-set is not consulted under a density:
 * the capacity points are drawn from it). */
static ccvt_options options_of(const bl_value *v, uint64_t seed, double tol)
{
    ccvt_options o;
    ccvt_options_init(&o);
    o.seed = seed;
    o.tol = tol;
    o.m = v[M].i;
    o.points = (int)v[POINT_SET].i;
    o.update = (int)v[UPDATE].i;
    o.assign = (int)v[ASSIGN].i;
    return o;
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    const ccvt_options o = options_of(v, seed, tol);
    return ccvt_create(n, &o, err, errlen);
}

static void *create_density(const bl_value *v, int64_t n, uint64_t seed, double tol, const cfpo_density *d,
                            char *err, size_t errlen)
{
    ccvt_options o = options_of(v, seed, tol);
    o.density = d;
    return ccvt_create(n, &o, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { ccvt_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { ccvt_deltas(E, a, b); }
static const double *points(void *E) { return ccvt_sites(E); }
static void destroy(void *E) { ccvt_free(E); }
static void column_values(void *E, double *out) { out[0] = (double)ccvt_swaps(E); }

const bl_method bl_ccvt = {
    .name = "ccvt",
    .prog = "cfpo-ccvt",
    .kind = BL_ITERATIVE,
    .about = "Capacity-constrained Voronoi tessellation (Balzer, Schloemer, Deussen 2009) on the\n"
             "unit torus: every site owns m discrete points (by default the nodes of a\n"
             "regular lattice, as Balzer's code); points are swapped between neighbouring\n"
             "sites while that lowers the energy, and both sites of a pair that swapped move\n"
             "to the centroids of their points at once; converged when a whole pass swaps\n"
             "nothing (--tol plays no part unless --update pass). Prints one SUMMARY line\n"
             "on stdout.",
    BL_OPTIONS(OPTS),
    BL_COLUMNS(COLUMNS),
    BL_ENGINE,
    .column_values = column_values,
    .create_density = create_density,
    .density_help = "the n M points and the start sites drawn proportional to\n"
                    "                       rho, so each site's M points carry 1/n of its mass\n"
                    "                       (--point-set plays no part)",
};
