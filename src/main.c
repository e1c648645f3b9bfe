/* main.c - the `cfpo` command (layer 5): parse the options, validate them,
 * run, report. Everything it computes comes from the library (the engine,
 * the plan, the run's files); this file only talks to the user. Of MPI it
 * sees only the process's start, end and rank. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "cli3.h"
#include "comm.h"
#include "dens_dist.h"
#include "dens_engine.h"
#include "dens_ops.h"
#include "density.h"
#include "engine.h"
#include "engines.h"
#include "main_prog.h"
#include "main_usage.h"
#include "omp_compat.h"
#include "plan.h"
#include "pointfile.h"
#include "run_loop.h"
#include "runfiles.h"
#include "runsignal.h"
#include "solver_simd.h"
#include "stoprule.h"
#include "tracecols.h"

static const char *prog = "cfpo";

typedef struct {
    cli_progress prog;
    FILE *trace;
    double t0;
    int64_t n;
    int max_iter;
    double last_moved[16];
    double last_min[16], last_avg[16];
    int seen; /* iterations reported */
    double seconds; /* the run's wall time, files not included */
    cfpo_stop_rules stop;
} run_ctx;

/* Iterations until a target is met, from the rise of the last 8
 * iterations (-1: met; +inf: not rising). */
static double iters_to(double target, const double *hist, int i, double now)
{
    if (!(target > 0) || now >= target) return -1;
    double rise = (now - hist[(i - 8) % 16]) / 8;
    return rise > 0 ? (target - now) / rise : INFINITY;
}

/* Rough ETA. With a quality target: the time until both targets hold,
 * from the rise of delta_min and delta_avg over the last 8 iterations.
 * Without: the number of moves decays about geometrically in the tail;
 * extrapolate the decay of the last 8 iterations down to zero moves. At
 * most the time left under --time-limit. */
static double eta_seconds(run_ctx *c, const cfpo_iter_stats *s)
{
    int i = s->iteration;
    c->last_moved[i % 16] = (double)s->moved + 0.5;
    c->last_min[i % 16] = s->delta_min;
    c->last_avg[i % 16] = s->delta_avg;
    if (++c->seen < 9) return -1; /* (a resumed run starts at its checkpoint) */
    if (c->stop.target_min > 0 || c->stop.target_avg > 0) { /* time to the targets */
        double a = iters_to(c->stop.target_min, c->last_min, i, s->delta_min);
        double b = iters_to(c->stop.target_avg, c->last_avg, i, s->delta_avg);
        double left = fmax(fmax(a, b), 0);
        if (left > c->max_iter - i) left = c->max_iter - i;
        double eta = left * s->seconds;
        if (c->stop.time_limit > 0) eta = fmin(eta, fmax(0, c->stop.time_limit - (cli_now() - c->t0)));
        return eta;
    }
    double ratio = c->last_moved[i % 16] / c->last_moved[(i - 8) % 16];
    double left = c->max_iter - i;
    if (ratio < 0.999) left = fmin(left, log(c->last_moved[i % 16]) / -(log(ratio) / 8));
    double eta = left * s->seconds;
    if (c->stop.time_limit > 0) eta = fmin(eta, fmax(0, c->stop.time_limit - (cli_now() - c->t0)));
    return eta;
}

static int on_iteration(const cfpo_iter_stats *s, void *user)
{
    run_ctx *c = user;
    if (comm_rank() != 0) return 0;
    double el = cli_now() - c->t0;
    if (c->trace) {
        double row[CFPO_TRACE_COLUMNS];
        cfpo_trace_values(s, el, row);
        cfpo_trace_write_values(c->trace, cfpo_trace_columns, row, CFPO_TRACE_COLUMNS, 1);
        fputc('\n', c->trace);
    }
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

/* --dry-run: what a run of n points on P ranks needs, from arithmetic. */
static int dry_run(int64_t n, const cfpo_options *o, int P, int fpx, int fpy)
{
    char err[512];
    cfpo_plan p;
    if (cfpo_plan_make(&p, n, o, P, fpx, fpy, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    if (comm_rank() != 0) return 0;
    printf("dry run: n=%lld on %d ranks (%d threads each), variant %s\n", (long long)n, P, p.threads,
           cfpo_variant_name(o->variant));
    printf("  grid          %lld x %lld cells (L = %.3g, Delta(n) = %.3g, %.3f points per cell)\n",
           (long long)p.G.g, (long long)p.G.g, p.G.L, p.G.delta, p.points_per_cell);
    printf("  tiling        %d x %d tiles; tile sides %lld..%lld by %lld..%lld cells\n", p.T.px, p.T.py,
           (long long)p.wmin, (long long)p.wmax, (long long)p.hmin, (long long)p.hmax);
    printf("  per rank      up to %lld cells, about %.4g points\n", (long long)p.cells_max, p.points_max);
    printf("  memory/rank   %.4g GB (%.1f bytes per point)\n", p.bytes_per_rank / 1e9,
           p.bytes_per_rank / p.points_max);
    printf("  halo/phase    %.0f cells, about %.4g bytes sent per rank (%d phases per iteration)\n",
           p.halo_cells, p.halo_bytes, p.G.period * p.G.period);
    printf("  migrate/phase at most about %.4g bytes sent per rank\n", p.migrate_bytes);
    printf("  largest rank count for this n: %lld\n", (long long)p.max_ranks);
    printf("DRYRUN n=%lld ranks=%d px=%d py=%d g=%lld cells_per_rank=%lld points_per_rank=%.0f "
           "bytes_per_rank=%.0f halo_bytes_per_phase=%.0f migrate_bytes_per_phase=%.0f\n",
           (long long)n, P, p.T.px, p.T.py, (long long)p.G.g, (long long)p.cells_max, p.points_max,
           p.bytes_per_rank, p.halo_bytes, p.migrate_bytes);
    return 0;
}

/* The command line, parsed. */
typedef struct {
    cfpo_options o;
    cfpo_engine_config cfg;
    int64_t n, dry_ranks;
    const char *out, *trace, *init, *density;
    double *init_xy; /* the points of --init */
    cfpo_density d;  /* with --density */
    const cfpo_density *dp; /* &d with --density, else NULL */
    prog_cli pc;            /* --progressive, --classes (main_prog.h) */
    int quiet, dry, every;
    int given_seed, given_variant, given_tol;
} cmdline;

static int64_t whole(const char *opt, const char *arg, int64_t lo, int64_t hi, const char *range)
{
    int64_t v;
    if (cli_parse_i64(arg, lo, hi, &v) != 0) cli_usage_error(prog, "%s: '%s' is not a whole number in %s", opt, arg, range);
    return v;
}

static void parse_tiles(cmdline *c, char *arg)
{
    char *x = strchr(arg, 'x');
    int64_t a, b;
    if (!x) cli_usage_error(prog, "--tiles: '%s' is not of the form AxB (e.g. 2x3)", arg);
    *x = '\0';
    int bad = cli_parse_i64(arg, 1, 1 << 20, &a) != 0 || cli_parse_i64(x + 1, 1, 1 << 20, &b) != 0;
    *x = 'x';
    if (bad) cli_usage_error(prog, "--tiles: '%s' is not of the form AxB (e.g. 2x3)", arg);
    c->cfg.px = (int)a;
    c->cfg.py = (int)b;
}

/* One option of the sampler itself. Returns 0 when ch is not one. */
static int sampler_option(cmdline *c, int ch, char *arg)
{
    switch (ch) {
    case 'n': c->n = cli_arg_points(prog, arg); break;
    case 's': c->o.seed = cli_arg_seed(prog, arg); c->given_seed = 1; break;
    case 'v':
        if (cfpo_variant_parse(arg, &c->o.variant) != 0)
            cli_usage_error(prog, "--variant: '%s' is not one of adaptive, paper, simplified, hyperuniform", arg);
        c->given_variant = 1;
        break;
    case 't': c->o.threads = (int)whole("--threads", arg, 1, 4096, "1..4096"); break;
    case 'm': c->o.max_iter = (int)whole("--max-iter", arg, 0, CFPO_MAX_ITER_MAX, "0..1e9"); break;
    case 'T':
        if (cli_parse_double(arg, 0, CFPO_TOL_MAX, &c->o.tol) != 0)
            cli_usage_error(prog, "--tol: '%s' is not a number in [0, %g]", arg, CFPO_TOL_MAX);
        c->given_tol = 1;
        break;
    case 'K': c->o.skip = 0; break;
    case 1001: cli_stop_option(prog, "target-min", arg, &c->o.stop); break;
    case 1002: cli_stop_option(prog, "target-avg", arg, &c->o.stop); break;
    case 1003: cli_stop_option(prog, "time-limit", arg, &c->o.stop); break;
    default: return 0;
    }
    return 1;
}

/* One option about files, ranks and checks. Returns 0 when ch is not one. */
static int run_option(cmdline *c, int ch, char *arg)
{
    switch (ch) {
    case 'o': c->out = arg; break;
    case 'r': c->trace = arg; break;
    case 'q': c->quiet = 1; break;
    case 'X': parse_tiles(c, arg); break;
    case 'C': c->cfg.check = 1; break;
    case 'P': c->cfg.checkpoint = arg; break;
    case 'E': c->every = (int)whole("--checkpoint-every", arg, 1, 1000000000, "1..1e9"); break;
    case 'R': c->cfg.resume = arg; break;
    case 'I': c->init = arg; break;
    case 'D': c->dry = 1; break;
    case 'N': c->dry_ranks = whole("--ranks", arg, 1, 1 << 24, "1..16777216"); break;
    case 1004: c->density = arg; break;
    default: return 0;
    }
    return 1;
}

/* Parses argv into c; --help and --version answer and exit. */
static void parse(int argc, char **argv, cmdline *c)
{
    static const struct option longopts[] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"variant", required_argument, 0, 'v'}, {"threads", required_argument, 0, 't'},
        {"max-iter", required_argument, 0, 'm'}, {"tol", required_argument, 0, 'T'},
        {"no-skip", no_argument, 0, 'K'}, {"output", required_argument, 0, 'o'},
        {"trace", required_argument, 0, 'r'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'}, {"version", no_argument, 0, 'V'},
        {"tiles", required_argument, 0, 'X'}, {"check", no_argument, 0, 'C'},
        {"checkpoint", required_argument, 0, 'P'}, {"checkpoint-every", required_argument, 0, 'E'},
        {"resume", required_argument, 0, 'R'}, {"dry-run", no_argument, 0, 'D'},
        {"ranks", required_argument, 0, 'N'}, {"target-min", required_argument, 0, 1001},
        {"target-avg", required_argument, 0, 1002}, {"time-limit", required_argument, 0, 1003},
        {"init", required_argument, 0, 'I'}, {"density", required_argument, 0, 1004},
        {"box", required_argument, 0, 1005},
        {"progressive", no_argument, 0, PROG_OPT_PROGRESSIVE}, {"base", required_argument, 0, PROG_OPT_BASE},
        {"classes", required_argument, 0, PROG_OPT_CLASSES}, {"level-min", required_argument, 0, PROG_OPT_LEVEL_MIN},
        {"relax", required_argument, 0, PROG_OPT_RELAX}, {"joint", required_argument, 0, PROG_OPT_JOINT},
        {"joint-prefix", required_argument, 0, PROG_OPT_JOINT_PREFIX},
        {"joint-full", required_argument, 0, PROG_OPT_JOINT_FULL},
        {"joint-hold", required_argument, 0, PROG_OPT_JOINT_HOLD},
        {"joint-last", required_argument, 0, PROG_OPT_JOINT_LAST},
        {"joint-candidates", required_argument, 0, PROG_OPT_JOINT_CANDIDATES},
        {"joint-solve", required_argument, 0, PROG_OPT_JOINT_SOLVE},
        {"joint-avg", required_argument, 0, PROG_OPT_JOINT_AVG},
        {"joint-soft", required_argument, 0, PROG_OPT_JOINT_SOFT},
        {"joint-circum", required_argument, 0, PROG_OPT_JOINT_CIRCUM},
        {"joint-pairs", required_argument, 0, PROG_OPT_JOINT_PAIRS},
        {"polish", required_argument, 0, PROG_OPT_POLISH},
        {"level-iter", required_argument, 0, PROG_OPT_LEVEL_ITER},
        {"level-balance", required_argument, 0, PROG_OPT_LEVEL_BALANCE},
        {"level-balance-order", no_argument, 0, PROG_OPT_LEVEL_BALANCE_ORDER},
        {"polish-floor", required_argument, 0, PROG_OPT_POLISH_FLOOR},
        {"classes-levels", no_argument, 0, PROG_OPT_CLASSES_LEVELS},
        {"class-union-floor", required_argument, 0, PROG_OPT_CLASS_UNION_FLOOR},
        {"class-reach", required_argument, 0, PROG_OPT_CLASS_REACH},
        {"class-swaps", required_argument, 0, PROG_OPT_CLASS_SWAPS},
        {0, 0, 0, 0}};
    cfpo_options_init(&c->o);
    c->n = c->dry_ranks = -1;
    c->every = -1;
    opterr = 0;
    int ch;
    while ((ch = getopt_long(argc, argv, ":n:s:t:o:qhV", longopts, NULL)) != -1) {
        if (sampler_option(c, ch, optarg) || run_option(c, ch, optarg) || prog_cli_option(&c->pc, prog, ch, optarg))
            continue;
        switch (ch) {
        case 1005: cli_usage_error(prog, "--box is for --dim 3 (the 2-D engine writes the unit square)");
        case 'h': if (comm_rank() == 0) cfpo_main_usage(); comm_finalize(); exit(0);
        case 'V': if (comm_rank() == 0) printf("cfpo %s (LocalCFPO: %s)\n", CFPO_VERSION, cfpo_solver_name()); comm_finalize(); exit(0);
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, longopts, argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
}

/* --resume: n, seed, variant and tol come from the checkpoint; options
 * that say otherwise are a usage error. */
static void take_from_checkpoint(cmdline *c)
{
    char err[512];
    cfpo_checkpoint_info info;
    if (cfpo_checkpoint_peek(c->cfg.resume, &info, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    if (info.hash && !c->dp)
        cli_usage_error(prog, "--resume %s: the checkpoint was made with a density; give the same --density SPEC",
                        c->cfg.resume);
    if (c->dp && info.hash != c->dp->hash)
        cli_fail(prog, "--resume %s: the checkpoint was made %s (hash %016llx, --density %s has %016llx)",
                 c->cfg.resume, info.hash ? "with another density" : "without a density",
                 (unsigned long long)info.hash, c->density, (unsigned long long)c->dp->hash);
    if (c->dp && !cfpo_density_is_flat(c->dp)) info.variant = c->o.variant; /* the density engine has one */
    if ((c->n >= 0 && c->n != info.n) || (c->given_seed && c->o.seed != info.seed) ||
        (c->given_variant && c->o.variant != info.variant) || (c->given_tol && c->o.tol != info.tol))
        cli_usage_error(prog, "--resume %s: the checkpoint is for n=%lld seed=%llu variant=%s tol=%g; "
                        "leave those options out or give the same values", c->cfg.resume,
                        (long long)info.n, (unsigned long long)info.seed,
                        cfpo_variant_name(info.variant), info.tol);
    c->n = info.n;
    c->o.seed = info.seed;
    c->o.variant = info.variant;
    c->o.tol = info.tol;
}

/* --init: the points of the file, and n from them. */
static void take_from_points(cmdline *c)
{
    char err[512];
    size_t n;
    if (pf_read(c->init, &c->init_xy, &n, err, sizeof err) != 0) cli_fail(prog, "--init %s", err);
    if (c->n >= 0 && c->n != (int64_t)n)
        cli_usage_error(prog, "--init %s: the file holds %zu points, -n says %lld; leave -n out or give the same",
                        c->init, n, (long long)c->n);
    c->n = (int64_t)n;
    c->cfg.start_xy = c->init_xy;
}

/* --density: enough points for it, and cells for every rank. */
static void density_fits(const cmdline *c)
{
    char err[512];
    if (cfpo_density_check_n(c->dp, c->n, err, sizeof err) != 0)
        cli_usage_error(prog, "--density %s: %s", c->density, err);
    const int64_t g = cfpo_dens_grid(c->dp, c->n), most = cfpo_dens_dist_max_ranks(g);
    if (comm_size() > most) /* a rank needs cells of every colour (dens_dist.h) */
        cli_usage_error(prog, "--density %s at n=%lld: the grid has %lld x %lld cells, enough for at most %lld rank%s "
                        "(this run has %d); use fewer ranks or more points", c->density, (long long)c->n,
                        (long long)g, (long long)g, (long long)most, most == 1 ? "" : "s", comm_size());
}

/* --progressive and --classes: the options they do not take (yet). */
static void progressive_fits(const cmdline *c)
{
    const char *what = c->pc.p.classes ? "--classes" : "--progressive";
    if (c->pc.p.relax > 0 && (c->cfg.checkpoint || c->cfg.resume))
        cli_usage_error(prog, "--relax does not go with %s (not supported yet)",
                        c->cfg.checkpoint ? "--checkpoint" : "--resume");
    if (c->cfg.resume && c->n < 0) cli_usage_error(prog, "--resume with %s needs the run's -n N", what);
    const char *bad = c->init ? "--init"
                    : c->density ? "--density" : c->dry ? "--dry-run" : c->cfg.px > 0 ? "--tiles"
                    : c->cfg.check ? "--check"
                    : c->o.stop.time_limit > 0 ? "--time-limit" : NULL;
    if (bad) cli_usage_error(prog, "%s does not go with %s (not supported yet)", bad, what);
}

/* Options that only make sense together, the defaults that depend on
 * others, the checkpoint's run. */
static void settle_options(cmdline *c)
{
    if (c->density) {
        if (c->dry) cli_usage_error(prog, "--dry-run does not go with --density");
        if (c->given_variant)
            cli_usage_error(prog, "--variant does not go with --density (the density run has one variant)");
        if (c->cfg.px > 0 || c->cfg.check) cli_usage_error(prog, "--tiles and --check do not go with --density");
        char err[600];
        if (cfpo_density_load(c->density, &c->d, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        c->dp = &c->d;
    }
    if (!c->given_tol) c->o.tol = cfpo_engines_default_tol(c->o.variant, c->dp);
    if (c->every > 0 && !c->cfg.checkpoint) cli_usage_error(prog, "--checkpoint-every needs --checkpoint FILE");
    if (c->cfg.checkpoint) c->cfg.checkpoint_every = c->every > 0 ? c->every : 100;
    if (c->dry_ranks > 0 && !c->dry)
        cli_usage_error(prog, "--ranks is for --dry-run (under mpirun the rank count is mpirun's)");
    if (c->cfg.resume && c->dry) cli_usage_error(prog, "--dry-run and --resume do not go together");
    if (c->init && (c->cfg.resume || c->dry))
        cli_usage_error(prog, "--init does not go with %s", c->dry ? "--dry-run" : "--resume");
    if (c->pc.on) progressive_fits(c);
    if (c->cfg.resume && !c->pc.on) take_from_checkpoint(c); /* a level's checkpoint: progressive.c */
    if (c->init) take_from_points(c);
    if (c->n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    if (c->dp && !cfpo_density_is_flat(c->dp)) density_fits(c);
    prog_cli_settle(&c->pc, prog, c->n, c->o.variant);
}

/* The run's files and this machine's room for it (not for --dry-run). */
static void validate(const cmdline *c)
{
    char err[512];
    if (cfpo_runfiles_check(c->out, c->trace, c->cfg.checkpoint, comm_size(), err, sizeof err) != 0)
        cli_usage_error(prog, "%s", err);
    if (c->dp && !cfpo_density_is_flat(c->dp)) return; /* the density engine checks its memory as it allocates */
    int vr = cfpo_plan_check(c->n, &c->o, c->cfg.px, c->cfg.py, err, sizeof err);
    if (vr == -1) cli_usage_error(prog, "%s", err);
    if (vr != 0) cli_fail(prog, "%s", err);
}

/* Runs the engine with progress and trace; writes the files. Fills R
 * (for the report); exits on failure, leaving no file. A run stopped by
 * SIGTERM or SIGUSR1 after its checkpoint writes no output (res->stop
 * says so). */
static void run(cmdline *c, run_ctx *ctx, cfpo_run_engine *R, cfpo_result *res)
{
    char err[600];
    cfpo_runfiles *files = cfpo_runfiles_open(c->out, c->trace, c->cfg.checkpoint, c->n, err, sizeof err);
    if (!files) cli_fail(prog, "%s", err);
    *ctx = (run_ctx){.n = c->n, .max_iter = c->o.max_iter, .stop = c->o.stop, .trace = cfpo_runfiles_trace(files)};
    cli_progress_init(&ctx->prog, c->quiet || comm_rank() != 0);
    c->o.progress = on_iteration;
    c->o.user = ctx;
    /* the trace and the progress line show each iteration's deltas; else
     * the density engine measures only where a rule reads them (the
     * measure is collective: one choice on every rank, though only rank
     * 0 may show a line) */
    c->o.lazy_measure = comm_all(!c->trace && !ctx->prog.enabled);
    ctx->t0 = cli_now();
    if (c->cfg.checkpoint) runsignal_install(); /* after the files' clean-up handler: SIGTERM saves */
    int rc = cfpo_engines_open(c->n, &c->o, &c->cfg, c->dp, ctx->t0, R, err, sizeof err);
    if (rc == 0) rc = cfpo_run_loop(R, c->cfg.checkpoint, c->cfg.checkpoint ? c->cfg.checkpoint_every : 0, res, err,
                                    sizeof err);
    runsignal_restore();
    cli_progress_end(&ctx->prog);
    ctx->seconds = cli_now() - ctx->t0;
    if (rc != 0) {
        cfpo_runfiles_abort(files);
        cli_fail(prog, "%s", err);
    }
    if (res->stop == CFPO_STOP_SIGNAL) {
        cfpo_runfiles_abort(files);
        return;
    }
    if (cfpo_runfiles_commit(files, R, err, sizeof err) != 0) cli_fail(prog, "%s", err);
}

/* Several ranks under a density: each rank's points against n / P. */
static void print_density_ranks(const cfpo_engine_timing *tm, const int64_t *own, int P, int64_t n)
{
    int64_t lo = own[0], hi = own[0];
    printf("RANKS ranks=%d points=", P);
    for (int r = 0; r < P; r++) {
        printf("%s%lld", r ? "," : "", (long long)own[r]);
        lo = own[r] < lo ? own[r] : lo;
        hi = own[r] > hi ? own[r] : hi;
    }
    printf(" min_over_mean=%.3f max_over_mean=%.3f compute_s=%.3f/%.3f/%.3f migrate_s=%.3f/%.3f/%.3f "
           "halo_s=%.3f/%.3f/%.3f\n", (double)lo * P / (double)n, (double)hi * P / (double)n, tm->compute[0],
           tm->compute[1], tm->compute[2], tm->migrate[0], tm->migrate[1], tm->migrate[2], tm->halo[0],
           tm->halo[1], tm->halo[2]);
}

/* The SUMMARY line (and DENSITY with a density), and with several ranks
 * the RANKS line (collective). */
static void report(const cmdline *c, cfpo_run_engine *R, const cfpo_result *res, double seconds)
{
    uint64_t peak, peak_max;
    cfpo_plan_peak_memory(&peak, &peak_max);
    cfpo_engine_timing tm;
    R->ops->timing(R->E, &tm);
    const int P = comm_size(), dens = strcmp(R->ops->name, "density") == 0;
    int64_t *own = dens ? calloc((size_t)P, sizeof *own) : NULL;
    if (dens && !comm_all(own != NULL)) cli_fail(prog, "out of memory");
    if (dens) comm_allgather_i64(cfpo_dens_run_own_points(R), own);
    if (comm_rank() != 0) {
        free(own);
        return;
    }
    cli_summary sm = {.method = c->dp ? "cfpo-density" : "cfpo",
                      .variant = dens ? "density" : cfpo_variant_name(c->o.variant), .n = c->n,
                      .seed = c->o.seed, .threads = c->o.threads > 0 ? c->o.threads : omp_get_num_procs(),
                      .ranks = P, .iterations = res->iterations, .seconds = seconds,
                      .delta_min = res->delta_min, .delta_avg = res->delta_avg,
                      .converged = res->converged, .peak_bytes = peak, .stop = cfpo_stop_name(res->stop)};
    cli_print_summary(stdout, &sm);
    if (c->dp)
        printf("DENSITY spec=%s hash=%016llx pixels=%lldx%lld contrast=%.4g support=%.4g cells=%lld levels=%d "
               "engine=%s\n",
               c->density, (unsigned long long)c->dp->hash, (long long)c->dp->w, (long long)c->dp->h,
               c->dp->rho_max / c->dp->rho_min, c->dp->support, (long long)R->ops->cells_per_side(R->E),
               cfpo_dens_run_levels(R), R->ops->name);
    if (P > 1 && dens) print_density_ranks(&tm, own, P, c->n);
    if (P > 1 && !dens) {
        const cfpo_tiling *T = cfpo_engine_tiling(R->E);
        const double ph = tm.phases > 0 ? (double)tm.phases : 1;
        printf("RANKS ranks=%d tiles=%dx%d phases=%lld compute_s=%.3f/%.3f/%.3f migrate_s=%.3f/%.3f/%.3f "
               "halo_s=%.3f/%.3f/%.3f halo_bytes_per_phase=%.0f/%.0f/%.0f "
               "migrate_bytes_per_phase=%.0f/%.0f/%.0f peak_bytes_per_rank=%lld\n",
               P, T->px, T->py, (long long)tm.phases, tm.compute[0], tm.compute[1], tm.compute[2],
               tm.migrate[0], tm.migrate[1], tm.migrate[2], tm.halo[0], tm.halo[1], tm.halo[2],
               tm.halo_bytes[0] / ph, tm.halo_bytes[1] / ph, tm.halo_bytes[2] / ph,
               tm.migrate_bytes[0] / ph, tm.migrate_bytes[1] / ph, tm.migrate_bytes[2] / ph,
               (long long)peak_max);
    }
    if (c->cfg.check)
        fprintf(stderr, "cfpo: check: %lld migrations and %lld halo refreshes verified on rank 0\n",
                (long long)tm.checked_migrations, (long long)tm.checked_halos);
    if (res->stop == CFPO_STOP_SIGNAL)
        fprintf(stderr, "cfpo: stopped by a signal at iteration %d; checkpoint %s written, no output; continue "
                "with --resume %s\n", res->iterations, c->cfg.checkpoint, c->cfg.checkpoint);
    fflush(stdout);
    free(own);
}

/* cfpo --dim 3: the 3-D front end (src/d3/cli3.h); under mpirun one
 * brick of the grid per rank. */
static int run_3d(int argc, char **argv)
{
    int rc = cfpo3_cli_main(prog, argc, argv);
    comm_finalize();
    return rc;
}

int main(int argc, char **argv)
{
    comm_init(&argc, &argv);
    cli_set_exit(comm_rank() != 0, comm_finalize);
    if (cfpo_cli_take_dim(prog, &argc, argv) == 3) return run_3d(argc, argv);
    if (!cfpo_solver_name()) cli_usage_error(prog, "CFPO_SOLVER: bad value '%s' (plain, avx2, avx512 or auto)", getenv("CFPO_SOLVER"));
    cmdline c = {0};
    parse(argc, argv, &c);
    settle_options(&c);
    if (c.dry) {
        int rc = dry_run(c.n, &c.o, c.dry_ranks > 0 ? (int)c.dry_ranks : comm_size(), c.cfg.px, c.cfg.py);
        comm_finalize();
        return rc;
    }
    validate(&c);
    if (c.pc.on) {
        int rc = prog_cli_main(&c.pc, prog, c.n, &c.o, c.out, c.trace, c.quiet, c.cfg.checkpoint,
                               c.cfg.checkpoint_every, c.cfg.resume);
        comm_finalize();
        return rc;
    }
    run_ctx ctx;
    cfpo_result res;
    cfpo_run_engine R;
    run(&c, &ctx, &R, &res);
    report(&c, &R, &res, ctx.seconds);
    R.ops->free(R.E);
    free(c.init_xy);
    if (c.dp) cfpo_density_free(&c.d);
    comm_finalize();
    return res.stop == CFPO_STOP_SIGNAL ? 3 : 0;
}
