/* main.c - the `cfpo` command: options, progress, trace, output, summary.
 * Everything it computes comes from the engine; this file only talks to
 * the user. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "engine.h"
#include "omp_compat.h"
#include "pointfile.h"

static const char *prog = "cfpo";

static void usage(void)
{
    printf("Usage: cfpo -n N [options]\n"
           "Blue-noise points on the unit torus by parallel Constrained Farthest Point\n"
           "Optimization (Chen & Gotsman). Prints one SUMMARY line on stdout.\n\n"
           "  -n, --points N       number of points (required; e.g. 65536, 2^20, 1e6)\n"
           "  -s, --seed S         random seed (default 1)\n"
           "      --variant V      cfpo (default: 9 phases, S = cell grown by L - Delta)\n"
           "                       or simplified (4 phases, S = own cell)\n"
           "  -t, --threads T      OpenMP threads (default: all cores, here %d)\n"
           "      --max-iter K     stop after K iterations (default %d)\n"
           "      --tol T          a move must gain more than T * cell side; converged when\n"
           "                       no point's net move over an iteration reaches it\n"
           "                       (default %g; 0 = any strict gain)\n"
           "      --no-skip        re-solve every point every iteration (same output)\n"
           "  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     one TSV row per iteration\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           omp_get_num_procs(), CFPO_DEFAULT_MAX_ITER, CFPO_DEFAULT_TOL, PF_EXTENSIONS);
}

typedef struct {
    cli_progress prog;
    FILE *trace;
    double t0;
    int64_t n;
    int max_iter;
    double last_moved[16];
} run_ctx;

/* Rough ETA: the number of moves decays about geometrically in the tail;
 * extrapolate the decay of the last 8 iterations down to zero moves. */
static double eta_seconds(run_ctx *c, const cfpo_iter_stats *s)
{
    int i = s->iteration;
    c->last_moved[i % 16] = (double)s->moved + 0.5;
    if (i < 9) return -1;
    double ratio = c->last_moved[i % 16] / c->last_moved[(i - 8) % 16];
    if (!(ratio < 0.999)) return (double)(c->max_iter - i) * s->seconds;
    double rate = log(ratio) / 8;
    double left = log(c->last_moved[i % 16]) / -rate;
    if (left > c->max_iter - i) left = c->max_iter - i;
    return left * s->seconds;
}

static int on_iteration(const cfpo_iter_stats *s, void *user)
{
    run_ctx *c = user;
    double el = cli_now() - c->t0;
    if (c->trace)
        fprintf(c->trace, "%d\t%.9f\t%.9f\t%lld\t%lld\t%.6g\t%.6f\t%.6f\n", s->iteration,
                s->delta_min, s->delta_avg, (long long)s->moved, (long long)s->solved,
                s->max_disp, s->seconds, el);
    double eta = eta_seconds(c, s);
    char etas[32] = "?";
    if (eta >= 0) snprintf(etas, sizeof etas, "~%.0fs", eta);
    cli_progress_line(&c->prog, 0,
                      "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  %.2f Mpts/s  "
                      "elapsed %.1fs  ETA %s",
                      s->iteration, s->delta_min, s->delta_avg, (long long)s->moved,
                      s->seconds > 0 ? (double)c->n / s->seconds / 1e6 : 0.0, el, etas);
    return 0;
}

int main(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"variant", required_argument, 0, 'v'}, {"threads", required_argument, 0, 't'},
        {"max-iter", required_argument, 0, 'm'}, {"tol", required_argument, 0, 'T'},
        {"no-skip", no_argument, 0, 'K'}, {"output", required_argument, 0, 'o'},
        {"trace", required_argument, 0, 'r'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'}, {"version", no_argument, 0, 'V'}, {0, 0, 0, 0}};
    cfpo_options o;
    cfpo_options_init(&o);
    int64_t n = -1;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:t:o:qhV", longopts, NULL)) != -1) {
        int64_t v;
        switch (ch) {
        case 'n':
            if (cli_parse_i64(optarg, 1, INT64_MAX, &v) != 0)
                cli_usage_error(prog, "-n: '%s' is not a positive whole number", optarg);
            n = v;
            break;
        case 's':
            if (cli_parse_u64(optarg, &o.seed) != 0)
                cli_usage_error(prog, "--seed: '%s' is not a non-negative 64-bit integer", optarg);
            break;
        case 'v':
            if (strcmp(optarg, "cfpo") == 0) o.variant = CFPO_VARIANT_FULL;
            else if (strcmp(optarg, "simplified") == 0) o.variant = CFPO_VARIANT_SIMPLIFIED;
            else cli_usage_error(prog, "--variant: '%s' is not one of cfpo, simplified", optarg);
            break;
        case 't':
            if (cli_parse_i64(optarg, 1, 4096, &v) != 0)
                cli_usage_error(prog, "--threads: '%s' is not a whole number in 1..4096", optarg);
            o.threads = (int)v;
            break;
        case 'm':
            if (cli_parse_i64(optarg, 0, 1000000000, &v) != 0)
                cli_usage_error(prog, "--max-iter: '%s' is not a whole number in 0..1e9", optarg);
            o.max_iter = (int)v;
            break;
        case 'T':
            if (cli_parse_double(optarg, 0, 0.49, &o.tol) != 0)
                cli_usage_error(prog, "--tol: '%s' is not a number in [0, 0.49]", optarg);
            break;
        case 'K': o.skip = 0; break;
        case 'o': out = optarg; break;
        case 'r': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(); return 0;
        case 'V': printf("cfpo %s\n", CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default:
            if (optopt) cli_usage_error(prog, "unknown option '-%c'", optopt);
            cli_usage_error(prog, "unknown option '%s'", argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    if (out && pf_format_of(out) == PF_UNKNOWN)
        cli_usage_error(prog, "%s: unknown output format (use %s)", out, PF_EXTENSIONS);

    char err[512];
    int vr = cfpo_validate(n, &o, err, sizeof err);
    if (vr == -1) cli_usage_error(prog, "%s", err);
    if (vr != 0) cli_fail(prog, "%s", err);

    /* Open outputs first, so an unwritable path fails before the work. */
    cli_guard_tmp(NULL);
    pf_writer *w = NULL;
    if (out) {
        w = pf_writer_open(out, (size_t)n, err, sizeof err);
        if (!w) cli_fail(prog, "%s", err);
        cli_guard_tmp(pf_writer_tmpname(w));
    }
    cli_atomic tr = {0};
    run_ctx ctx = {.n = n, .max_iter = o.max_iter};
    if (trace) {
        if (cli_atomic_open(&tr, trace, err, sizeof err) != 0) {
            pf_writer_abort(w);
            cli_fail(prog, "%s", err);
        }
        ctx.trace = tr.f;
        fprintf(tr.f, "iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed\n");
    }
    cli_progress_init(&ctx.prog, quiet);
    o.progress = on_iteration;
    o.user = &ctx;

    ctx.t0 = cli_now();
    cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    cfpo_result res;
    cfpo_engine_run(E, &res);
    cli_progress_end(&ctx.prog);
    double seconds = cli_now() - ctx.t0;

    if (w) {
        if (cfpo_engine_write(E, w, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        const char *tmp = pf_writer_tmpname(w);
        char tmpcopy[4096];
        snprintf(tmpcopy, sizeof tmpcopy, "%s", tmp);
        if (pf_writer_commit(w, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        cli_unguard_tmp(tmpcopy);
    }
    if (trace && cli_atomic_commit(&tr, err, sizeof err) != 0) cli_fail(prog, "%s", err);

    cli_summary sm = {
        .method = "cfpo",
        .variant = o.variant == CFPO_VARIANT_FULL ? "cfpo" : "simplified",
        .n = n, .seed = o.seed,
        .threads = o.threads > 0 ? o.threads : omp_get_num_procs(),
        .ranks = 1, .iterations = res.iterations, .seconds = seconds,
        .delta_min = res.delta_min, .delta_avg = res.delta_avg,
        .converged = res.converged, .peak_bytes = cli_peak_rss()};
    cli_print_summary(stdout, &sm);
    cfpo_engine_free(E);
    return 0;
}
