/* bl3_cli.c - the command line of the 3-D baselines (bl3.h): options,
 * the run, the trace and progress line, the output file and the SUMMARY
 * line. Computes no points itself. */
#include "bl3.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nn3.h"
#include "points3.h"
#include "solve3.h"

static void usage(const bl3_method *m)
{
    printf("Usage: %s -n N [options]\n%s\n\n"
           "  -n, --points N       number of points (required; e.g. 4096, 2^16, 1e5)\n"
           "  -s, --seed S         random seed (default 1)\n",
           m->prog, m->about);
    for (int i = 0; i < m->noptions; i++) printf(m->options[i].help, m->options[i].def);
    if (m->iterative)
        printf("      --max-iter K     stop after K iterations (default %d)\n"
               "      --target-min D   stop as soon as delta_min >= D (and every other target holds)\n"
               "      --target-avg D   stop as soon as delta_avg >= D (and every other target holds)\n"
               "      --time-limit S   stop at the first iteration boundary past S seconds\n"
               "      --trace FILE     one TSV row per iteration: iteration, seconds, delta_min,\n"
               "                       delta_avg, moved, max_disp\n",
               CFPO_DEFAULT_MAX_ITER);
    printf("  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           P3_EXTENSIONS);
}

typedef struct {
    const bl3_method *m;
    cfpo_stop_rules rules;
    int max_iter;
    double t0;
    FILE *trace;
    cli_progress pg;
    cfpo_iter_stats last;
} run_ctx;

static int on_iter(void *user, const cfpo_iter_stats *s)
{
    run_ctx *c = user;
    const double el = cli_now() - c->t0;
    c->last = *s;
    if (c->trace)
        fprintf(c->trace, "%d\t%.6f\t%.6f\t%.6f\t%lld\t%.6g\n", s->iteration, el, s->delta_min, s->delta_avg,
                (long long)s->moved, s->max_disp);
    cli_progress_line(&c->pg, 0, "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  elapsed %.1fs", s->iteration,
                      s->delta_min, s->delta_avg, (long long)s->moved, el);
    if (s->iteration == 0) return cfpo_stop_targets_met(&c->rules, s->delta_min, s->delta_avg) ? CFPO_STOP_TARGET : 0;
    return cfpo_stop_check(&c->rules, s, el, c->max_iter);
}

int bl3_main(int argc, char **argv, const bl3_method *m)
{
    const char *prog = m->prog;
    enum { OWN = 2000 };
    struct option lo[16 + BL3_MAX_OPTIONS] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"output", required_argument, 0, 'o'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'},         {"version", no_argument, 0, 'V'}};
    int k = 6;
    if (m->iterative) {
        lo[k++] = (struct option){"max-iter", required_argument, 0, 'm'};
        lo[k++] = (struct option){"target-min", required_argument, 0, 1001};
        lo[k++] = (struct option){"target-avg", required_argument, 0, 1002};
        lo[k++] = (struct option){"time-limit", required_argument, 0, 1003};
        lo[k++] = (struct option){"trace", required_argument, 0, 't'};
    }
    for (int i = 0; i < m->noptions; i++) lo[k++] = (struct option){m->options[i].cli, required_argument, 0, OWN + i};
    lo[k] = (struct option){0, 0, 0, 0};
    double opt[BL3_MAX_OPTIONS];
    for (int i = 0; i < m->noptions; i++) opt[i] = m->options[i].def;
    run_ctx c = {.m = m, .max_iter = CFPO_DEFAULT_MAX_ITER};
    cfpo_stop_rules_init(&c.rules);
    int64_t n = -1, iv;
    uint64_t seed = 1;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:o:qhV", lo, NULL)) != -1) {
        switch (ch) {
        case 'n': n = cli_arg_points(prog, optarg); break;
        case 's': seed = cli_arg_seed(prog, optarg); break;
        case 'o': out = optarg; break;
        case 'q': quiet = 1; break;
        case 't': trace = optarg; break;
        case 'm':
            if (cli_parse_i64(optarg, 0, CFPO_MAX_ITER_MAX, &iv) != 0)
                cli_usage_error(prog, "--max-iter: '%s' is not a whole number in 0..1e9", optarg);
            c.max_iter = (int)iv;
            break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &c.rules); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &c.rules); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &c.rules); break;
        case 'h': usage(m); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: {
            if (ch < OWN || ch >= OWN + m->noptions) cli_bad_option(prog, lo, argv[optind - 1]);
            const bl3_option *o = &m->options[ch - OWN];
            if (cli_parse_double(optarg, o->lo, o->hi, &opt[ch - OWN]) != 0)
                cli_usage_error(prog, "--%s: '%s' is not a number in [%g, %g]", o->cli, optarg, o->lo, o->hi);
        }
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    if (n < m->min_n) cli_usage_error(prog, "-n %lld: %s needs at least %lld points", (long long)n, prog, (long long)m->min_n);
    char err[600];
    if (out) {
        if (p3_format_of(out) == P3F_UNKNOWN) cli_usage_error(prog, "-o %s: unknown extension (%s)", out, P3_EXTENSIONS);
        if (p3_probe(out, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    }
    cli_atomic tf;
    if (trace) {
        if (cli_atomic_open(&tf, trace, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        c.trace = tf.f;
        fprintf(c.trace, "iteration\tseconds\tdelta_min\tdelta_avg\tmoved\tmax_disp\n");
    }
    cli_progress_init(&c.pg, quiet);
    c.t0 = cli_now();
    double *xyz = NULL;
    int64_t got = 0;
    bl3_info info = {.iterations = -1, .converged = -1};
    if (m->run(n, seed, opt, on_iter, &c, &xyz, &got, &info, err, sizeof err) != 0) {
        if (trace) cli_atomic_abort(&tf);
        cli_fail(prog, "%s", err);
    }
    const double seconds = cli_now() - c.t0;
    cli_progress_end(&c.pg);
    double dmin = NAN, davg = NAN;
    if (got >= 2 && cfpo3_nn_stats(xyz, (size_t)got, NULL, &dmin, &davg) != 0) cli_fail(prog, "out of memory");
    if (out && p3_write(out, xyz, (size_t)got, 1.0, err, sizeof err) != 0) {
        if (trace) cli_atomic_abort(&tf);
        cli_fail(prog, "%s", err);
    }
    if (trace && cli_atomic_commit(&tf, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    cli_summary sm = {.method = m->name, .variant = "-", .n = got, .seed = seed, .threads = 1, .ranks = 1,
                      .iterations = info.iterations, .seconds = seconds, .delta_min = dmin, .delta_avg = davg,
                      .converged = info.converged, .peak_bytes = cli_peak_rss(), .stop = info.stop};
    cli_print_summary(stdout, &sm);
    const double d = dmin * cfpo3_delta_bound((double)got);
    printf("SET3D n_asked=%lld n=%lld packing_fraction=%.6f trials=%lld\n", (long long)n, (long long)got,
           M_PI / 6.0 * (double)got * d * d * d, (long long)info.trials);
    free(xyz);
    return 0;
}
