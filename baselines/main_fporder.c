/* main_fporder.c - the `cfpo-fporder` command: a point file in the greedy
 * farthest-point order (fporder.h), written to another point file; one
 * SUMMARY line on stdout. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "cli.h"
#include "fporder.h"
#include "pointfile.h"

static const char *prog = "cfpo-fporder";

static void usage(void)
{
    printf("Usage: cfpo-fporder [options] -o OUT IN\n"
           "The points of IN in greedy farthest-point order on the unit torus: the first\n"
           "point, then each time the point farthest from those already taken (ties: the\n"
           "lower index). Exact. Every prefix of OUT is the greedy farthest-point subset\n"
           "of that size; measure them with cfpo-analyze --prefixes.\n\n"
           "  -o, --output OUT     the ordered points (any point-file format, by extension)\n"
           "      --first I        start at point I of IN (default 0, the file's first)\n"
           "  -q, --quiet          no SUMMARY line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Input and output formats: %s\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           PF_EXTENSIONS);
}

int main(int argc, char **argv)
{
    static const struct option longs[] = {{"output", required_argument, 0, 'o'}, {"first", required_argument, 0, 'f'},
                                          {"quiet", no_argument, 0, 'q'},        {"help", no_argument, 0, 'h'},
                                          {"version", no_argument, 0, 'V'},      {0, 0, 0, 0}};
    const char *out = NULL;
    int64_t first = 0;
    int quiet = 0, c;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:qhV", longs, NULL)) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 'f':
            if (cli_parse_i64(optarg, 0, INT64_MAX, &first) != 0)
                cli_usage_error(prog, "bad --first '%s' (a whole number >= 0)", optarg);
            break;
        case 'q': quiet = 1; break;
        case 'h': usage(); return 0;
        case 'V': printf("cfpo-fporder %s\n", CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, longs, argv[optind - 1]);
        }
    }
    if (optind != argc - 1) cli_usage_error(prog, optind == argc ? "no input file" : "one input file only");
    if (!out) cli_usage_error(prog, "no output file (-o OUT)");
    char err[1024];
    double *xy, *o;
    size_t n;
    const double t0 = cli_now();
    if (pf_read(argv[optind], &xy, &n, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    if (n == 0) cli_fail(prog, "%s: no points", argv[optind]);
    if ((uint64_t)first >= n) cli_fail(prog, "--first %lld: %s has %zu points", (long long)first, argv[optind], n);
    size_t *order = malloc(n * sizeof *order);
    o = malloc(2 * n * sizeof *o);
    if (!order || !o || fp_order(xy, n, (size_t)first, order) != 0) cli_fail(prog, "out of memory for n = %zu", n);
    for (size_t i = 0; i < n; i++) o[2 * i] = xy[2 * order[i]], o[2 * i + 1] = xy[2 * order[i] + 1];
    if (pf_write(out, o, n, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    if (!quiet) printf("SUMMARY method=fporder n=%zu first=%lld seconds=%.3f out=%s\n", n, (long long)first,
                       cli_now() - t0, out);
    free(order), free(o), free(xy);
    return 0;
}
