/* main_ccvt.c - the `cfpo-ccvt` command: capacity-constrained Voronoi
 * tessellation (ccvt.h) with the iterative baselines' command line
 * (iter_main.h). The output is the sites. */
#include <stdio.h>

#include "ccvt.h"
#include "cli.h"
#include "iter_main.h"

typedef struct {
    int64_t m;
} ccvt_ctx;

static int parse_m(void *ctx, int which, const char *arg, char *err, size_t errlen)
{
    (void)which; /* the one option: --points-per-site */
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
                 "unit torus: every site owns m discrete points; points are swapped between\n"
                 "neighbouring sites while that lowers the energy, and sites move to the\n"
                 "centroids of their points. Prints one SUMMARY line on stdout.",
        .options_help =
            "      --points-per-site M  discrete points per site (default 1024 up to\n"
            "                       n = 16384, then 2^24 / n, at least 16); memory 16 n M bytes\n",
        .options = (const it_option[]){{"points-per-site", 1}, {NULL, 0}},
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
