/* pd_main.c - the command line of the Poisson-disk baselines (cfpo-dart,
 * cfpo-bs, cfpo-bridson), in cfpo's style: options, radius from -n, trace,
 * progress, output and the SUMMARY line. One function for the three
 * commands; each main_*.c passes its method. Computes nothing itself. */
#include "pd_main.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_run.h"
#include "cfpo.h"
#include "cli.h"
#include "geom.h"
#include "pd.h"
#include "pdgrid.h"
#include "pointfile.h"
#include "stats.h"

typedef struct {
    const char *prog, *method, *title;
    double rel;          /* default relative radius */
    const char *rel_why; /* one line for --help */
} method_info;

static const method_info METHODS[] = {
    [PD_DART] = {"cfpo-dart", "dart", "Dart throwing (Cook 1986): uniform darts, each kept when no earlier point\n"
                 "lies within r.", PD_DART_REL,
                 "close to dart throwing's jamming limit (about 0.777),\n"
                 "                       yet reached reliably"},
    [PD_BS] = {"cfpo-bs", "bs", "Boundary sampling (Dunbar & Humphreys 2006): a maximal Poisson-disk set grown\n"
               "on the uncovered boundary arcs of the samples' disks.", PD_BS_REL,
               "measured so that the maximal set has n points on\n"
               "                       average"},
    [PD_BRIDSON] = {"cfpo-bridson", "bridson", "Bridson's fast Poisson-disk sampling (2007), made maximal by an exact check\n"
                    "of a sample's free boundary arcs before it is retired.", PD_BRIDSON_REL,
                    "measured so that the maximal set has n points on\n"
                    "                       average"},
};

static void usage(int kind)
{
    const method_info *m = &METHODS[kind];
    printf("Usage: %s -n N [options]\n", m->prog);
    if (kind != PD_DART) printf("       %s -r R [options]\n", m->prog);
    printf("%s\nThe unit torus, periodic distances. Prints one SUMMARY line on stdout.\n\n",
           m->title);
    if (kind == PD_DART)
        printf("  -n, --points N       number of points to place (required)\n");
    else
        printf("  -n, --points N       the expected number of points: sets r = REL * Delta(N);\n"
               "                       the maximal set has about N points (the exact count is\n"
               "                       in the SUMMARY line)\n");
    printf("  -s, --seed S         random seed (default 1)\n"
           "  -r, --radius R       the Poisson-disk radius (minimum distance) itself\n"
           "      --rel-radius REL r = REL * Delta(n), Delta(n) = sqrt(2 / (sqrt(3) n));\n"
           "                       default %.4g: %s\n", m->rel, m->rel_why);
    if (kind == PD_DART)
        printf("      --max-fails F    saturation: stop when F consecutive darts are rejected\n"
               "                       (default %.0f); then nothing is written, exit 1\n",
               (double)PD_DART_MAX_FAILS);
    if (kind == PD_BRIDSON)
        printf("  -k, --candidates K   candidates per active sample (default 30)\n"
               "      --plain          the 2007 algorithm only: retire a sample after K\n"
               "                       failures (not maximal)\n");
    printf("  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     progress rows (TSV: points, trials, active, elapsed)\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure (e.g. saturation), 2 usage error.\n",
           PF_EXTENSIONS);
}

typedef struct {
    bl_run *run;
} report_ctx;

static void on_report(void *user, int64_t placed, uint64_t trials, int64_t active)
{
    bl_run *r = ((report_ctx *)user)->run;
    double el = cli_now() - r->t0;
    if (r->tf) fprintf(r->tf, "%lld\t%llu\t%lld\t%.6f\n", (long long)placed, (unsigned long long)trials,
                       (long long)active, el);
    cli_progress_line(&r->pg, 0, "points %lld  trials %llu  active %lld  elapsed %.1fs",
                      (long long)placed, (unsigned long long)trials, (long long)active, el);
}

int pd_main(int argc, char **argv, int kind)
{
    const method_info *m = &METHODS[kind];
    const char *prog = m->prog;
    static const struct option longopts[] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"radius", required_argument, 0, 'r'}, {"rel-radius", required_argument, 0, 'R'},
        {"max-fails", required_argument, 0, 'F'}, {"candidates", required_argument, 0, 'k'},
        {"plain", no_argument, 0, 'P'}, {"output", required_argument, 0, 'o'},
        {"trace", required_argument, 0, 't'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'}, {"version", no_argument, 0, 'V'}, {0, 0, 0, 0}};
    pd_params p;
    memset(&p, 0, sizeof p);
    p.seed = 1;
    p.k = 30;
    p.max_fails = PD_DART_MAX_FAILS;
    int64_t n = -1;
    double radius = -1, rel = -1;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:r:k:o:qhV", longopts, NULL)) != -1) {
        int64_t v;
        switch (ch) {
        case 'n':
            n = cli_arg_points(prog, optarg);
            break;
        case 's':
            p.seed = cli_arg_seed(prog, optarg);
            break;
        case 'r':
            if (cli_parse_double(optarg, 0, 1, &radius) != 0 || !(radius > 0))
                cli_usage_error(prog, "--radius: '%s' is not a number in (0, 1]", optarg);
            break;
        case 'R':
            if (cli_parse_double(optarg, 0, 2, &rel) != 0 || !(rel > 0))
                cli_usage_error(prog, "--rel-radius: '%s' is not a number in (0, 2]", optarg);
            break;
        case 'F':
            if (kind != PD_DART) cli_usage_error(prog, "--max-fails applies to cfpo-dart only");
            if (cli_parse_i64(optarg, 1, INT64_MAX, &v) != 0)
                cli_usage_error(prog, "--max-fails: '%s' is not a positive whole number", optarg);
            p.max_fails = (uint64_t)v;
            break;
        case 'k':
            if (kind != PD_BRIDSON) cli_usage_error(prog, "-k applies to cfpo-bridson only");
            if (cli_parse_i64(optarg, 1, 1000000, &v) != 0)
                cli_usage_error(prog, "--candidates: '%s' is not a whole number in 1..1e6", optarg);
            p.k = (int)v;
            break;
        case 'P':
            if (kind != PD_BRIDSON) cli_usage_error(prog, "--plain applies to cfpo-bridson only");
            p.plain = 1;
            break;
        case 'o': out = optarg; break;
        case 't': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(kind); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, longopts, argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (radius > 0 && rel > 0) cli_usage_error(prog, "give --radius or --rel-radius, not both");
    if (n < 0 && (kind == PD_DART || radius < 0))
        cli_usage_error(prog, kind == PD_DART ? "the number of points is required: -n N"
                                              : "-n N or --radius R is required");
    if (n >= (int64_t)UINT32_MAX)
        cli_usage_error(prog, "n = %lld is too large for one process (at most %lld)", (long long)n,
                        (long long)UINT32_MAX - 1);
    bl_check_output_name(prog, out);
    if (radius < 0) radius = (rel > 0 ? rel : m->rel) * cfpo_delta_bound((double)n);
    /* DT: r < 1/2 keeps the periodic distance meaningful; BS and Bridson
     * look 2 rho around a sample, which must stay below 1/2. */
    const double rmax = kind == PD_DART ? 0.5 : 0.25 / (1.0 + PD_RHO_EPS);
    if (!(radius < rmax))
        cli_usage_error(prog, "radius %g is too large for the unit torus (must be below %g%s)",
                        radius, rmax, n > 0 ? "; use more points or a smaller --rel-radius" : "");
    if (pdgrid_cells(radius) > 4294967295.0)
        cli_usage_error(prog, "radius %g is too small: the grid would need %.3g cells", radius,
                        pdgrid_cells(radius));
    p.r = radius;
    if (kind == PD_DART) p.target = n;
    else p.target = n > 0 ? n : (int64_t)(2.0 * m->rel * m->rel / (sqrt(3.0) * radius * radius)) + 1;
    p.report_step = p.target / 64 > 0 ? p.target / 64 : 1;

    bl_run run;
    bl_run_open(&run, prog, out, trace, kind == PD_DART ? (size_t)n : 0,
                "points\ttrials\tactive\telapsed", quiet);
    report_ctx rc = {&run};
    p.report = on_report;
    p.user = &rc;
    pd_result res;
    char err[512];
    int rv = kind == PD_DART ? dart_sample(&p, &res, err, sizeof err)
           : kind == PD_BS   ? bs_sample(&p, &res, err, sizeof err)
                             : bridson_sample(&p, &res, err, sizeof err);
    if (rv != 0) cli_fail(prog, "%s", err);
    const double seconds = cli_now() - run.t0;
    on_report(&rc, res.n, res.trials, 0);
    if (res.saturated) {
        cli_progress_end(&run.pg);
        cli_fail(prog, "saturated: placed %lld of %lld points at radius r = %.9g (%.4f Delta(n)); "
                 "%llu consecutive darts were rejected. Use a smaller --rel-radius or --radius, "
                 "or a larger --max-fails", (long long)res.n, (long long)n, radius,
                 radius / cfpo_delta_bound((double)n), (unsigned long long)p.max_fails);
    }
    if (res.n < 2 && kind != PD_DART)
        cli_fail(prog, "radius %g leaves only %lld point(s)", radius, (long long)res.n);
    bl_run_finish(&run, res.xy, (size_t)res.n);
    double dmin = 0, davg = 0;
    if (res.n >= 2 && cfpo_nn_stats(res.xy, (size_t)res.n, NULL, &dmin, &davg) != 0)
        cli_fail(prog, "out of memory for the statistics");
    cli_summary sm = {.method = m->method, .variant = "-", .n = res.n, .seed = p.seed,
                      .threads = 1, .ranks = 1, .iterations = -1, .seconds = seconds,
                      .delta_min = dmin, .delta_avg = davg, .converged = -1,
                      .peak_bytes = cli_peak_rss()};
    cli_print_summary(stdout, &sm);
    free(res.xy);
    return 0;
}
