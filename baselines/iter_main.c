/* iter_main.c - see iter_main.h. The start is trace row 0; the stop rules
 * are checked after it and after every iteration, in the order converged,
 * targets, time, max-iter. */
#include "iter_main.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_run.h"
#include "cli.h"
#include "pointfile.h"
#include "stoprule.h"

static void usage(const it_method *m)
{
    printf("Usage: %s -n N [options]\n%s\n\n"
           "  -n, --points N       number of points (required; e.g. 4096, 2^16, 1e5)\n"
           "  -s, --seed S         random seed (default 1)\n"
           "%s"
           "      --max-iter K     stop after K iterations (default %d)\n"
           "      --tol T          a move must gain more than T * L, L = cfpo's cell side;\n"
           "                       converged when no point's net move over an iteration\n"
           "                       reaches it (default %g)\n"
           "      --target-min D   stop as soon as delta_min >= D (and every other target holds)\n"
           "      --target-avg D   stop as soon as delta_avg >= D (and every other target holds)\n"
           "      --time-limit S   stop at the first iteration boundary past S seconds\n"
           "  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     one TSV row per iteration (cfpo's columns%s)\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           m->prog, m->about, m->options_help, CFPO_DEFAULT_MAX_ITER, CFPO_DEFAULT_TOL,
           PF_EXTENSIONS, m->trace_extra[0] ? ", then the method's own" : "");
}

static double trace_row(bl_run *r, const it_method *m, void *E, const cfpo_iter_stats *s)
{
    double el = cli_now() - r->t0;
    if (r->tf) {
        char extra[256] = "";
        if (m->trace_values) m->trace_values(E, extra, sizeof extra);
        fprintf(r->tf, "%d\t%.9f\t%.9f\t%lld\t%lld\t%.6g\t%.6f\t%.6f%s\n", s->iteration,
                s->delta_min, s->delta_avg, (long long)s->moved, (long long)s->solved,
                s->max_disp, s->seconds, el, extra);
    }
    cli_progress_line(&r->pg, 0,
                      "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  max_disp %.3g  "
                      "%.2fs/iter  elapsed %.1fs",
                      s->iteration, s->delta_min, s->delta_avg, (long long)s->moved,
                      s->max_disp, s->seconds, el);
    return el;
}

int it_main(int argc, char **argv, const it_method *m, void *ctx)
{
    const char *prog = m->prog;
    enum { FIXED = 12, OWN = 2000 };
    struct option longopts[FIXED + IT_MAX_OPTIONS + 1] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"max-iter", required_argument, 0, 'm'}, {"tol", required_argument, 0, 'T'},
        {"output", required_argument, 0, 'o'}, {"trace", required_argument, 0, 'r'},
        {"quiet", no_argument, 0, 'q'}, {"help", no_argument, 0, 'h'},
        {"version", no_argument, 0, 'V'}, {"target-min", required_argument, 0, 1001},
        {"target-avg", required_argument, 0, 1002}, {"time-limit", required_argument, 0, 1003}};
    int own = 0;
    for (; own < IT_MAX_OPTIONS && m->options && m->options[own].name; own++)
        longopts[FIXED + own] = (struct option){m->options[own].name,
                                                m->options[own].has_arg ? required_argument : no_argument, 0,
                                                OWN + own};
    longopts[FIXED + own] = (struct option){0, 0, 0, 0};
    cfpo_stop_rules rules;
    cfpo_stop_rules_init(&rules);
    int64_t n = -1, max_iter = CFPO_DEFAULT_MAX_ITER;
    uint64_t seed = 1;
    double tol = CFPO_DEFAULT_TOL;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch;
    char err[512];
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:o:qhV", longopts, NULL)) != -1) {
        int64_t v;
        switch (ch) {
        case 'n': n = cli_arg_points(prog, optarg); break;
        case 's': seed = cli_arg_seed(prog, optarg); break;
        case 'm':
            if (cli_parse_i64(optarg, 0, 1000000000, &v) != 0)
                cli_usage_error(prog, "--max-iter: '%s' is not a whole number in 0..1e9", optarg);
            max_iter = v;
            break;
        case 'T':
            if (cli_parse_double(optarg, 0, CFPO_TOL_MAX, &tol) != 0)
                cli_usage_error(prog, "--tol: '%s' is not a number in [0, %g]", optarg, CFPO_TOL_MAX);
            break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &rules); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &rules); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &rules); break;

        case 'o': out = optarg; break;
        case 'r': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(m); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default:
            if (ch < OWN || ch >= OWN + own) cli_bad_option(prog, longopts, argv[optind - 1]);
            if (m->parse_option(ctx, ch - OWN, optarg, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    bl_check_output_name(prog, out);
    if (m->validate) {
        const int vr = m->validate(ctx, n, tol, err, sizeof err);
        if (vr == -1) cli_usage_error(prog, "%s", err);
        if (vr != 0) cli_fail(prog, "%s", err);
    } else { /* n too small (the same minimum as cfpo, whose cell side scales
              * tol) or too large for the method's own memory model */
        cfpo_options co;
        cfpo_options_init(&co);
        co.tol = tol;
        co.threads = 1;
        int vr = cfpo_validate(n, &co, err, sizeof err);
        if (vr == -1) cli_usage_error(prog, "%s", err);
        const double need = (double)m->bytes(ctx, n), have = cli_physical_memory();
        if (need > 0.9 * have)
            cli_fail(prog, "n = %lld is too large for memory: %s needs about %.1f GB, this machine has %.1f GB",
                     (long long)n, m->method, need / 1e9, have / 1e9);
    }
    char header[512];
    snprintf(header, sizeof header, "iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed%s",
             m->trace_extra);
    bl_run run;
    bl_run_open(&run, prog, out, trace, (size_t)n, header, quiet);
    void *E = m->create(ctx, n, seed, tol, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    double t = cli_now();
    m->deltas(E, &s.delta_min, &s.delta_avg);
    s.seconds = cli_now() - t;
    double el = trace_row(&run, m, E, &s);
    int it = 0;
    int why = cfpo_stop_check(&rules, &s, el, (int)max_iter);
    while (!why) {
        s.iteration = it + 1;
        m->iterate(E, &s);
        s.iteration = ++it;
        el = trace_row(&run, m, E, &s);
        why = cfpo_stop_check(&rules, &s, el, (int)max_iter);
    }
    double seconds = cli_now() - run.t0;
    bl_run_finish(&run, m->points(E), (size_t)n);
    cli_summary sm = {.method = m->method_name ? m->method_name(ctx) : m->method, .variant = "-", .n = n, .seed = seed, .threads = 1,
                      .ranks = 1, .iterations = it, .seconds = seconds,
                      .delta_min = s.delta_min, .delta_avg = s.delta_avg,
                      .converged = s.converged, .peak_bytes = cli_peak_rss(),
                      .stop = cfpo_stop_name(why)};
    cli_print_summary(stdout, &sm);
    m->destroy(E);
    return 0;
}
