/* main_fpo.c - the `cfpo-fpo` and `cfpo-lfpo` commands: global and local
 * Farthest Point Optimization with cfpo's options, stop rules, trace,
 * progress and summary. Everything computed comes from fpo.h; this file
 * only talks to the user. Built twice: FPO_PROG names the command and
 * FPO_LOCAL_DEFAULT picks the method when --local/--global is not given. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_run.h"
#include "cfpo.h"
#include "cli.h"
#include "fpo.h"
#include "pointfile.h"
#include "stoprule.h"

#ifndef FPO_PROG
#define FPO_PROG "cfpo-fpo"
#endif
#ifndef FPO_LOCAL_DEFAULT
#define FPO_LOCAL_DEFAULT 0
#endif

static const char *prog = FPO_PROG;

static void usage(void)
{
    printf("Usage: %s -n N [options]\n"
           "Farthest Point Optimization (Schloemer, Heck, Deussen 2011) on the unit torus,\n"
           "on CGAL's periodic Delaunay triangulation. Prints one SUMMARY line on stdout.\n\n"
           "  -n, --points N       number of points (required; e.g. 4096, 2^16, 1e5)\n"
           "  -s, --seed S         random seed (default 1)\n"
           "      --global         global FPO: the largest empty circle of the whole set%s\n"
           "      --local          LFPO: the largest empty circle in the removed point's\n"
           "                       2-ring only%s\n"
           "      --start S        random (default: uniform points) or grid (cfpo's\n"
           "                       stratified start, the same points as\n"
           "                       `cfpo --variant paper -s S`)\n"
           "      --max-iter K     stop after K iterations (default %d)\n"
           "      --tol T          a move must gain more than T * L, L = cfpo's cell side;\n"
           "                       converged when no point's net move over an iteration\n"
           "                       reaches it (default %g; 0 = any strict gain)\n"
           "      --target-min D   stop as soon as delta_min >= D (and every other target holds)\n"
           "      --target-avg D   stop as soon as delta_avg >= D (and every other target holds)\n"
           "      --time-limit S   stop at the first iteration boundary past S seconds\n"
           "  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     one TSV row per iteration (the columns of cfpo's trace)\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           prog, FPO_LOCAL_DEFAULT ? "" : " (default)", FPO_LOCAL_DEFAULT ? " (default)" : "",
           CFPO_DEFAULT_MAX_ITER, CFPO_DEFAULT_TOL, PF_EXTENSIONS);
}

/* Writes the row and the progress line; returns the elapsed seconds it
 * wrote, which the stop rules then judge. */
static double trace_row(bl_run *r, const cfpo_iter_stats *s)
{
    double el = cli_now() - r->t0;
    if (r->tf)
        fprintf(r->tf, "%d\t%.9f\t%.9f\t%lld\t%lld\t%.6g\t%.6f\t%.6f\n", s->iteration,
                s->delta_min, s->delta_avg, (long long)s->moved, (long long)s->solved,
                s->max_disp, s->seconds, el);
    cli_progress_line(&r->pg, 0,
                      "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  max_disp %.3g  "
                      "%.1fs/iter  elapsed %.1fs",
                      s->iteration, s->delta_min, s->delta_avg, (long long)s->moved,
                      s->max_disp, s->seconds, el);
    return el;
}

int main(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"global", no_argument, 0, 'G'}, {"local", no_argument, 0, 'L'},
        {"start", required_argument, 0, 'S'}, {"max-iter", required_argument, 0, 'm'},
        {"tol", required_argument, 0, 'T'}, {"output", required_argument, 0, 'o'},
        {"trace", required_argument, 0, 'r'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'}, {"version", no_argument, 0, 'V'},
        {"target-min", required_argument, 0, 1001}, {"target-avg", required_argument, 0, 1002},
        {"time-limit", required_argument, 0, 1003}, {0, 0, 0, 0}};
    fpo_options o;
    fpo_options_init(&o);
    cfpo_stop_rules rules;
    cfpo_stop_rules_init(&rules);
    o.local = FPO_LOCAL_DEFAULT;
    int64_t n = -1, max_iter = CFPO_DEFAULT_MAX_ITER;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:o:qhV", longopts, NULL)) != -1) {
        int64_t v;
        switch (ch) {
        case 'n':
            n = cli_arg_points(prog, optarg);
            break;
        case 's':
            o.seed = cli_arg_seed(prog, optarg);
            break;
        case 'G': o.local = 0; break;
        case 'L': o.local = 1; break;
        case 'S':
            if (strcmp(optarg, "random") == 0) o.start = FPO_START_RANDOM;
            else if (strcmp(optarg, "grid") == 0) o.start = FPO_START_GRID;
            else cli_usage_error(prog, "--start: '%s' is not one of random, grid", optarg);
            break;
        case 'm':
            if (cli_parse_i64(optarg, 0, 1000000000, &v) != 0)
                cli_usage_error(prog, "--max-iter: '%s' is not a whole number in 0..1e9", optarg);
            max_iter = v;
            break;
        case 'T':
            if (cli_parse_double(optarg, 0, CFPO_TOL_MAX, &o.tol) != 0)
                cli_usage_error(prog, "--tol: '%s' is not a number in [0, %g]", optarg, CFPO_TOL_MAX);
            break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &rules); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &rules); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &rules); break;
        case 'o': out = optarg; break;
        case 'r': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, longopts, argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    bl_check_output_name(prog, out);
    char err[512];
    { /* n too small (the same minimum as cfpo) or too large for FPO's memory */
        int vr = fpo_validate(n, &o, err, sizeof err);
        if (vr == -1) cli_usage_error(prog, "%s", err);
        if (vr != 0) cli_fail(prog, "%s", err);
    }

    bl_run run;
    bl_run_open(&run, prog, out, trace, (size_t)n,
                "iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed", quiet);
    fpo_engine *E = fpo_create(n, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    double t = cli_now();
    fpo_deltas(E, &s.delta_min, &s.delta_avg);
    s.seconds = cli_now() - t;
    double el = trace_row(&run, &s);
    /* The stop rules of cfpo (stoprule.h), checked after the start and after
     * every iteration, on the clock of the trace's elapsed column. */
    int it = 0;
    int why = cfpo_stop_check(&rules, &s, el, (int)max_iter);
    while (!why) {
        fpo_iterate(E, &s);
        s.iteration = ++it;
        el = trace_row(&run, &s);
        why = cfpo_stop_check(&rules, &s, el, (int)max_iter);
    }
    double seconds = cli_now() - run.t0;
    bl_run_finish(&run, fpo_points(E), (size_t)n);

    cli_summary sm = {.method = o.local ? "lfpo" : "fpo", .variant = "-", .n = n,
                      .seed = o.seed, .threads = 1, .ranks = 1, .iterations = it,
                      .seconds = seconds, .delta_min = s.delta_min, .delta_avg = s.delta_avg,
                      .converged = s.converged, .peak_bytes = cli_peak_rss(),
                      .stop = cfpo_stop_name(why)};
    cli_print_summary(stdout, &sm);
    fpo_free(E);
    return 0;
}
