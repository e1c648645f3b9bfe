/* main_ccvt.c - the `cfpo-ccvt` command: capacity-constrained Voronoi
 * tessellation (ccvt.h) with the iterative baselines' command line
 * (iter_main.h). The output is the sites. */
#include <stdio.h>
#include <string.h>

#include "ccvt.h"
#include "cli.h"
#include "iter_main.h"

typedef struct {
    int64_t m;
    int points, update, assign;
} ccvt_ctx;

/* --points-per-site M, --point-set lattice|random, --update pair|pass,
 * --assign nearest|curve */
static int parse_m(void *ctx, int which, const char *arg, char *err, size_t errlen)
{
    ccvt_ctx *c = ctx;
    if (which >= 1) {
        static const char *const name[] = {"", "point-set", "update", "assign"};
        static const char *const first[] = {"", "lattice", "pair", "nearest"};
        static const char *const second[] = {"", "random", "pass", "curve"};
        int *v = which == 1 ? &c->points : which == 2 ? &c->update : &c->assign;
        if (strcmp(arg, first[which]) == 0) *v = 0;
        else if (strcmp(arg, second[which]) == 0) *v = 1;
        else {
            snprintf(err, errlen, "--%s: '%s' is neither %s nor %s", name[which], arg, first[which], second[which]);
            return -1;
        }
        return 0;
    }
    int64_t v;
    if (cli_parse_i64(arg, 1, 1 << 20, &v) != 0) {
        snprintf(err, errlen, "--points-per-site: '%s' is not a whole number in 1..2^20", arg);
        return -1;
    }
    ((ccvt_ctx *)ctx)->m = v;
    return 0;
}

/* 16 bytes a discrete point, 8 more while the start is sorted, and 10 KiB
 * a site besides: a fit with room to the peak resident sets measured,
 * 0.41 GB at n = 16,384, m = 1024 and 1.05 GB at n = 65,536, m = 256. */
static uint64_t bytes(void *ctx, int64_t n)
{
    const int64_t m = ((ccvt_ctx *)ctx)->m > 0 ? ((ccvt_ctx *)ctx)->m : ccvt_default_m(n);
    return (uint64_t)n * (uint64_t)m * 24 + (uint64_t)n * 10240;
}

static void *create(void *ctx, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    ccvt_options o;
    ccvt_options_init(&o);
    o.seed = seed;
    o.tol = tol;
    o.m = ((ccvt_ctx *)ctx)->m;
    o.points = ((ccvt_ctx *)ctx)->points;
    o.update = ((ccvt_ctx *)ctx)->update;
    o.assign = ((ccvt_ctx *)ctx)->assign;
    return ccvt_create(n, &o, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { ccvt_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { ccvt_deltas(E, a, b); }
static const double *points(void *E) { return ccvt_sites(E); }
static void destroy(void *E) { ccvt_free(E); }
static void trace_values(void *E, char *buf, size_t len)
{
    snprintf(buf, len, "\t%lld", (long long)ccvt_swaps(E));
}

int main(int argc, char **argv)
{
    ccvt_ctx ctx = {0};
    const it_method m = {
        .prog = "cfpo-ccvt",
        .method = "ccvt",
        .about = "Capacity-constrained Voronoi tessellation (Balzer, Schloemer, Deussen 2009) on the\n"
                 "unit torus: every site owns m discrete points (by default the nodes of a\n"
                 "regular lattice, as Balzer's code); points are swapped between neighbouring\n"
                 "sites while that lowers the energy, and both sites of a pair that swapped move\n"
                 "to the centroids of their points at once; converged when a whole pass swaps\n"
                 "nothing (--tol plays no part unless --update pass). Prints one SUMMARY line\n"
                 "on stdout.",
        .options_help =
            "      --points-per-site M  discrete points per site (default 1024 up to\n"
            "                       n = 16384, then 2^24 / n, at least 16); memory 16 n M bytes\n"
            "      --point-set P    lattice (default: a regular lattice of n M nodes) or random\n"
            "                       (uniform random points)\n"
            "      --update U       pair (default: sites move right after their pair swaps)\n"
            "                       or pass (every site that swapped moves after the pass;\n"
            "                       converged also when no site moves --tol * L)\n"
            "      --assign A       nearest (default: the points, last first, each to the\n"
            "                       nearest site not yet full, as Balzer's code) or curve (runs\n"
            "                       of m points along a Hilbert curve to the sites in its order)\n",
        .options = (const it_option[]){{"points-per-site", 1}, {"point-set", 1}, {"update", 1}, {"assign", 1}, {NULL, 0}},
        .trace_extra = "\tswaps",
        .parse_option = parse_m,
        .bytes = bytes,
        .create = create,
        .iterate = iterate,
        .deltas = deltas,
        .trace_values = trace_values,
        .points = points,
        .destroy = destroy,
    };
    return it_main(argc, argv, &m, &ctx);
}
