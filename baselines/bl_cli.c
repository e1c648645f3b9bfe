/* bl_cli.c - see bl_cli.h. */
#include "bl_cli.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_loop.h"
#include "bl_run.h"
#include "cli.h"
#include "density.h"
#include "pointfile.h"
#include "stoprule.h"

static void usage(const bl_method *m)
{
    printf("Usage: %s -n N [options]\n%s\n\n"
           "  -n, --points N       number of points (required; e.g. 4096, 2^16, 1e5)\n"
           "  -s, --seed S         random seed (default 1)\n",
           m->prog, m->about);
    for (int i = 0; i < m->noptions; i++) printf(m->options[i].help, m->options[i].def);
    if (m->create_density)
        printf("      --density SPEC   follow a density, SPEC as `cfpo --density` (an image, a\n"
               "                       .npy array, cos:..., ramp:..., balzer):\n"
               "                       %s;\n"
               "                       delta_min, delta_avg and the targets in the symmetric\n"
               "                       measure m = |x_i - x_j| (rho_i rho_j)^(1/4) / Delta(n)\n"
               "                       (baselines/README.md)\n",
               m->density_help ? m->density_help : "the method under the density");
    printf("      --max-iter K     stop after K iterations (default %d)\n"
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
           CFPO_DEFAULT_MAX_ITER, CFPO_DEFAULT_TOL, PF_EXTENSIONS, m->ncolumns ? ", then the method's own" : "");
}

typedef struct {
    const bl_method *m;
    bl_run *run;
} row_ctx;

/* The trace row and the progress line. */
static int on_row(void *user, void *E, const cfpo_iter_stats *s, double el)
{
    const row_ctx *c = user;
    bl_run *r = c->run;
    if (r->tf) {
        double row[CFPO_TRACE_COMMON + BL_MAX_COLUMNS];
        bl_trace_values(c->m, E, s, el, row);
        cfpo_trace_write_values(r->tf, cfpo_trace_columns, row, CFPO_TRACE_COMMON, 1);
        cfpo_trace_write_values(r->tf, c->m->columns, row + CFPO_TRACE_COMMON, c->m->ncolumns, 0);
        fputc('\n', r->tf);
    }
    cli_progress_line(&r->pg, 0,
                      "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  max_disp %.3g  "
                      "%.2fs/iter  elapsed %.1fs",
                      s->iteration, s->delta_min, s->delta_avg, (long long)s->moved,
                      s->max_disp, s->seconds, el);
    return 0;
}

/* The trace's header line. */
static void header(const bl_method *m, char *buf, size_t len)
{
    size_t k = 0;
    buf[0] = 0;
    for (int c = 0; c < CFPO_TRACE_COMMON + m->ncolumns && k < len; c++)
        k += (size_t)snprintf(buf + k, len - k, "%s%s", c ? "\t" : "",
                              c < CFPO_TRACE_COMMON ? cfpo_trace_columns[c].name
                                                    : m->columns[c - CFPO_TRACE_COMMON].name);
}

int bl_iter_main(int argc, char **argv, const bl_method *m)
{
    const char *prog = m->prog;
    enum { FIXED = 13, OWN = 2000, DENSITY = 1004 };
    struct option longopts[FIXED + 2 * BL_MAX_OPTIONS + 1] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"max-iter", required_argument, 0, 'm'}, {"tol", required_argument, 0, 'T'},
        {"output", required_argument, 0, 'o'}, {"trace", required_argument, 0, 'r'},
        {"quiet", no_argument, 0, 'q'}, {"help", no_argument, 0, 'h'},
        {"version", no_argument, 0, 'V'}, {"target-min", required_argument, 0, 1001},
        {"target-avg", required_argument, 0, 1002}, {"time-limit", required_argument, 0, 1003},
        {"density", required_argument, 0, DENSITY}};
    /* option i: --cli is OWN + 2 i, a flag's --cli_off OWN + 2 i + 1 */
    int k = FIXED;
    for (int i = 0; i < m->noptions; i++) {
        const bl_option *o = &m->options[i];
        if (o->cli[0])
            longopts[k++] = (struct option){o->cli, o->type == BL_FLAG ? no_argument : required_argument, 0, OWN + 2 * i};
        if (o->type == BL_FLAG && o->cli_off) longopts[k++] = (struct option){o->cli_off, no_argument, 0, OWN + 2 * i + 1};
    }
    longopts[k] = (struct option){0, 0, 0, 0};
    bl_value v[BL_MAX_OPTIONS];
    bl_defaults(m, v);
    bl_loop_args a = {.n = -1, .seed = 1, .tol = CFPO_DEFAULT_TOL, .max_iter = CFPO_DEFAULT_MAX_ITER};
    cfpo_stop_rules_init(&a.rules);
    const char *out = NULL, *trace = NULL, *spec = NULL;
    int quiet = 0, ch;
    char err[600];
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:o:qhV", longopts, NULL)) != -1) {
        int64_t iv;
        switch (ch) {
        case 'n': a.n = cli_arg_points(prog, optarg); break;
        case 's': a.seed = cli_arg_seed(prog, optarg); break;
        case 'm':
            if (cli_parse_i64(optarg, 0, CFPO_MAX_ITER_MAX, &iv) != 0)
                cli_usage_error(prog, "--max-iter: '%s' is not a whole number in 0..1e9", optarg);
            a.max_iter = (int)iv;
            break;
        case 'T':
            if (cli_parse_double(optarg, 0, CFPO_TOL_MAX, &a.tol) != 0)
                cli_usage_error(prog, "--tol: '%s' is not a number in [0, %g]", optarg, CFPO_TOL_MAX);
            break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &a.rules); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &a.rules); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &a.rules); break;
        case DENSITY:
            if (!m->create_density) cli_usage_error(prog, "--density is not offered by %s", prog);
            spec = optarg;
            break;
        case 'o': out = optarg; break;
        case 'r': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(m); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default:
            if (ch < OWN || ch >= OWN + 2 * m->noptions) cli_bad_option(prog, longopts, argv[optind - 1]);
            if (bl_option_parse(m, (ch - OWN) / 2, optarg, (ch - OWN) % 2, v, err, sizeof err) != 0)
                cli_usage_error(prog, "%s", err);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (a.n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    bl_check_output_name(prog, out);
    cfpo_density dens;
    if (spec) {
        if (cfpo_density_load(spec, &dens, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        if (cfpo_density_check_n(&dens, a.n, err, sizeof err) != 0) cli_usage_error(prog, "--density %s: %s", spec, err);
        a.density = &dens;
        const char *why = m->density_refuses ? m->density_refuses(v) : NULL;
        if (why) cli_usage_error(prog, "%s", why);
    }
    const int vr = m->check_n(v, a.n, a.tol, err, sizeof err);
    if (vr == -1) cli_usage_error(prog, "%s", err);
    if (vr != 0) cli_fail(prog, "%s", err);
    char head[512];
    header(m, head, sizeof head);
    bl_run run;
    bl_run_open(&run, prog, out, trace, (size_t)a.n, head, quiet);
    row_ctx rc = {m, &run};
    bl_outcome o;
    void *E = bl_loop(m, v, &a, run.t0, on_row, &rc, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    const double seconds = cli_now() - run.t0;
    bl_run_finish(&run, m->points(E), (size_t)a.n);
    cli_summary sm = {.method = m->method_name ? m->method_name(v) : m->name, .variant = "-", .n = a.n,
                      .seed = a.seed, .threads = 1, .ranks = 1, .iterations = o.iterations, .seconds = seconds,
                      .delta_min = o.last.delta_min, .delta_avg = o.last.delta_avg,
                      .converged = o.last.converged, .peak_bytes = cli_peak_rss(),
                      .stop = cfpo_stop_name(o.why)};
    cli_print_summary(stdout, &sm);
    m->destroy(E);
    if (spec) {
        printf("DENSITY spec=%s hash=%016llx pixels=%lldx%lld contrast=%.4g support=%.4g\n", spec,
               (unsigned long long)dens.hash, (long long)dens.w, (long long)dens.h, dens.rho_max / dens.rho_min,
               dens.support);
        cfpo_density_free(&dens);
    }
    return 0;
}
