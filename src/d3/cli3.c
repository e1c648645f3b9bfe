/* cli3.c - the 3-D front end shared by `cfpo --dim 3` (src/main.c) and
 * the cfpo3d command (main3d.c): CFPO on the unit 3-torus (docs/cli.md,
 * "Three dimensions"). Parses the options, opens the 3-D engine behind the
 * one engine interface (engine3_ops.h) and runs it through the schedule
 * of rounds (sched3.h: the one run loop, the flatness rule, shakes; stop
 * rules, progress line, checkpoints), then writes the point
 * files (points3.h) and the SUMMARY and BOX3D lines. Under mpirun every
 * rank runs this; the engine cuts the grid into bricks (engine3_dist.h),
 * rank 0 alone prints, traces and writes the files (of the set gathered
 * in id order), and every failure is agreed so that the job reports it
 * once and every rank exits alike. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bricks3.h"
#include "cli.h"
#include "cli3.h"
#include "comm.h"
#include "engine3.h"
#include "engine3_ops.h"
#include "omp_compat.h"
#include "points3.h"
#include "run_loop.h"
#include "sched3.h"
#include "solve3.h"
#include "stopflat.h"
#include "stoprule.h"

static const char *prog = "cfpo3d"; /* set by cfpo3_cli_main */

/* The progress line and the trace, after every iteration (the
 * schedule's callback). */
typedef struct {
    cli_progress *pr;
    FILE *trace;
    double t0;
} run_ctx;

static int on_iteration(const cfpo_iter_stats *st, int round, int first, void *user)
{
    run_ctx *x = user;
    if (first) return 0; /* the set before a round's first iteration: no line, no row */
    cli_progress_line(x->pr, 0, "round %d  iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  solved %lld  %.2fs/iter  elapsed %.1fs",
                      round, st->iteration, st->delta_min, st->delta_avg, (long long)st->moved, (long long)st->solved,
                      st->seconds, cli_now() - x->t0);
    if (x->trace)
        fprintf(x->trace, "%d %.6f %.6f %lld %lld %.6g %.4f %d %d\n", st->iteration, st->delta_min, st->delta_avg,
                (long long)st->moved, (long long)st->solved, st->max_disp, st->seconds, st->near, round);
    return 0;
}
#define MAX_OUT 8

static void usage(void)
{
    printf("usage: %s%s -n N [options]       CFPO on the unit 3-torus\n\n"
           "  -n N                 number of points (at least %lld; 2^20 and 1e6 forms too)\n"
           "  -s, --seed S         seed (default 1)\n"
           "  -t, --threads T      OpenMP threads (default: all cores); the output does not depend on it\n"
           "  -o, --output FILE    write the points (repeatable, up to %d files); format by extension:\n"
           "                       " P3_EXTENSIONS "\n"
           "      --box L          side of the box in .xyz, LAMMPS and .gro files and of\n"
           "                       BOX3D's delta_min_box (default 1)\n"
           "      --max-iter K     at most K iterations in all (default %d)\n"
           "      --tol T          move gain and convergence, relative to the cell side (default %g)\n"
           "      --target-min D   stop once delta_min >= D\n"
           "      --target-avg D   stop once delta_avg >= D (with --target-min: both)\n"
           "      --time-limit S   stop at the first iteration boundary past S seconds\n"
           "      --flat W         a round ends once delta_min and delta_avg each rose by less than\n"
           "                       --flat-gain G over its last W iterations (default %d; 0: off)\n"
           "      --flat-gain G    (default %g)\n"
           "      --shake K        after round 0, K rounds: the best set so far shaken by up to\n"
           "                       --shake-amp A (default %g) Delta3 per axis and run again; the\n"
           "                       best set is written (default %d; 0: one round)\n"
           "      --init FILE      start from this n x 3 set (.npy, text, CSV, raw) instead of the jittered grid\n"
           "      --checkpoint F   write a checkpoint to F every --checkpoint-every K iterations and at the end\n"
           "      --checkpoint-every K  (default 10)\n"
           "      --resume F       continue from checkpoint F (n, seed, tol, the policy and the schedule\n"
           "                       come from it)\n"
           "      --no-relax       move to the solver's spot (no over-relaxation)\n"
           "      --no-shift       keep the grid fixed\n"
           "      --no-skip        solve every cell every iteration (same output, slower)\n"
           "      --no-near        the exact solve from the first iteration (no near phase)\n"
           "      --trace FILE     one line an iteration: iteration delta_min delta_avg moved solved max_disp seconds\n"
           "                       near (1: the near solve) round\n"
           "      --dry-run        print the grid and memory and exit\n"
           "  -q, --quiet          no progress line\n"
           "Under mpirun the grid is cut into one brick per rank (bricks of at least 3 cells a side);\n"
           "the output and checkpoints are the same bytes for any rank and thread count.\n"
           "  -h, --help, -V, --version\n",
           prog, strcmp(prog, "cfpo") == 0 ? " --dim 3" : "", (long long)cfpo3_grid_min_n(), MAX_OUT, CFPO_DEFAULT_MAX_ITER, CFPO3_DEFAULT_TOL, CFPO3_SCHED_FLAT, CFPO3_SCHED_GAIN, CFPO3_SCHED_AMP, CFPO3_SCHED_ROUNDS);
}

typedef struct {
    int64_t n;
    int n_given, seed_given, tol_given, policy_given, sched_given;
    cfpo3_options o;
    int max_iter, every, quiet, dry;
    double box;
    const char *out[MAX_OUT];
    int nout;
    const char *init, *ckpt, *resume, *trace;
    cfpo_stop_rules stop;
    cfpo3_sched_opts so; /* --shake, --shake-amp, --flat, --flat-gain */
} cmdline;

/* Options of the 2-D command that have no meaning on the 3-torus: refused
 * by name (long option codes 2000 + index). */
static const char *const two_d_only[] = {"density", "tiles", "check", "ranks"};

/* Parses argv into c. Returns 1 when --help or --version answered (the
 * caller then exits 0), else 0; usage errors exit. */
static int parse(cmdline *c, int argc, char **argv)
{
    static const struct option lo[] = {
        {"seed", required_argument, 0, 's'}, {"threads", required_argument, 0, 't'},
        {"output", required_argument, 0, 'o'}, {"box", required_argument, 0, 'B'},
        {"max-iter", required_argument, 0, 'm'}, {"tol", required_argument, 0, 'T'},
        {"target-min", required_argument, 0, 1001}, {"target-avg", required_argument, 0, 1002},
        {"time-limit", required_argument, 0, 1003}, {"init", required_argument, 0, 'I'},
        {"checkpoint", required_argument, 0, 'P'}, {"checkpoint-every", required_argument, 0, 'E'},
        {"resume", required_argument, 0, 'R'}, {"no-relax", no_argument, 0, 1010},
        {"no-shift", no_argument, 0, 1011}, {"no-skip", no_argument, 0, 1012},
        {"no-near", no_argument, 0, 1013}, {"flat", required_argument, 0, 1004},
        {"flat-gain", required_argument, 0, 1005}, {"shake", required_argument, 0, 1006},
        {"shake-amp", required_argument, 0, 1007},
        {"dry-run", no_argument, 0, 'D'}, {"trace", required_argument, 0, 'r'}, {"quiet", no_argument, 0, 'q'},
        {"help", no_argument, 0, 'h'}, {"version", no_argument, 0, 'V'}, {"variant", required_argument, 0, 1020},
        {"density", required_argument, 0, 2000}, {"tiles", required_argument, 0, 2001},
        {"check", no_argument, 0, 2002}, {"ranks", required_argument, 0, 2003}, {0, 0, 0, 0}};
    memset(c, 0, sizeof *c);
    cfpo3_options_default(&c->o);
    cfpo_stop_rules_init(&c->stop);
    c->max_iter = CFPO_DEFAULT_MAX_ITER;
    c->every = -1;
    c->box = 1.0;
    cfpo3_sched_default(&c->so);
    opterr = 0;
    int ch;
    int64_t v;
    while ((ch = getopt_long(argc, argv, ":n:s:t:o:qhV", lo, NULL)) != -1) {
        switch (ch) {
        case 'n': c->n = cli_arg_points(prog, optarg); c->n_given = 1; break;
        case 's': c->o.seed = cli_arg_seed(prog, optarg); c->seed_given = 1; break;
        case 't':
            if (cli_parse_i64(optarg, 1, 4096, &v) != 0) cli_usage_error(prog, "--threads must be 1..4096, not '%s'", optarg);
            c->o.threads = (int)v;
            break;
        case 'o':
            if (c->nout == MAX_OUT) cli_usage_error(prog, "at most %d output files", MAX_OUT);
            c->out[c->nout++] = optarg;
            break;
        case 'B':
            if (cli_parse_double(optarg, 0.0, 1e300, &c->box) != 0 || !(c->box > 0.0))
                cli_usage_error(prog, "--box must be a positive finite number, not '%s'", optarg);
            break;
        case 'm':
            if (cli_parse_i64(optarg, 0, CFPO_MAX_ITER_MAX, &v) != 0)
                cli_usage_error(prog, "--max-iter must be 0..%d, not '%s'", CFPO_MAX_ITER_MAX, optarg);
            c->max_iter = (int)v;
            break;
        case 'T':
            if (cli_parse_double(optarg, 0.0, CFPO_TOL_MAX, &c->o.tol) != 0 || !(c->o.tol > 0.0))
                cli_usage_error(prog, "--tol must be in (0, %g], not '%s'", CFPO_TOL_MAX, optarg);
            c->tol_given = 1;
            break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &c->stop); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &c->stop); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &c->stop); break;
        case 1004:
            if (cli_parse_i64(optarg, 0, CFPO_FLAT_MAXW, &v) != 0)
                cli_usage_error(prog, "--flat must be 0..%d iterations, not '%s'", CFPO_FLAT_MAXW, optarg);
            c->so.flat = (int)v;
            c->sched_given = 1;
            break;
        case 1005:
            if (cli_parse_double(optarg, 0.0, 1.0, &c->so.flat_gain) != 0 || !(c->so.flat_gain > 0.0))
                cli_usage_error(prog, "--flat-gain must be in (0, 1], not '%s'", optarg);
            c->sched_given = 1;
            break;
        case 1006:
            if (cli_parse_i64(optarg, 0, CFPO3_SCHED_ROUNDS_MAX, &v) != 0)
                cli_usage_error(prog, "--shake must be 0..%d rounds, not '%s'", CFPO3_SCHED_ROUNDS_MAX, optarg);
            c->so.rounds = (int)v;
            c->sched_given = 1;
            break;
        case 1007:
            if (cli_parse_double(optarg, 0.0, 1.0, &c->so.amp) != 0 || !(c->so.amp > 0.0))
                cli_usage_error(prog, "--shake-amp must be in (0, 1], not '%s'", optarg);
            c->sched_given = 1;
            break;
        case 'I': c->init = optarg; break;
        case 'P': c->ckpt = optarg; break;
        case 'E':
            if (cli_parse_i64(optarg, 1, CFPO_MAX_ITER_MAX, &v) != 0)
                cli_usage_error(prog, "--checkpoint-every must be 1..%d, not '%s'", CFPO_MAX_ITER_MAX, optarg);
            c->every = (int)v;
            break;
        case 'R': c->resume = optarg; break;
        case 1010: c->o.relax = 0; c->policy_given = 1; break;
        case 1011: c->o.shift = 0; c->policy_given = 1; break;
        case 1012: c->o.skip = 0; c->policy_given = 1; break;
        case 1013: c->o.near = 0; c->policy_given = 1; break;
        case 'D': c->dry = 1; break;
        case 'r': c->trace = optarg; break;
        case 'q': c->quiet = 1; break;
        case 1020:
            if (strcmp(optarg, "adaptive") != 0)
                cli_usage_error(prog, "--variant %s does not apply in 3-D: the 3-D engine has one variant, adaptive",
                                optarg);
            break;
        case 2000: case 2001: case 2002: case 2003:
            cli_usage_error(prog, "--%s does not apply in 3-D (the 3-D engine runs the uniform torus; under mpirun its rank count is mpirun's)",
                            two_d_only[ch - 2000]);
        case 'h': usage(); return 1;
        case 'V': printf("%s %s (3-D engine)\n", prog, CFPO_VERSION); return 1;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, lo, argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (c->init && c->resume) cli_usage_error(prog, "--init and --resume exclude each other");
    if (c->resume && (c->seed_given || c->tol_given || c->policy_given || c->sched_given))
        cli_usage_error(prog, "--resume takes the seed, tolerance, policy and schedule from the checkpoint");
    if (!c->n_given && !c->init && !c->resume) cli_usage_error(prog, "-n is required");
    if (c->every > 0 && !c->ckpt) cli_usage_error(prog, "--checkpoint-every needs --checkpoint");
    if (c->every < 0) c->every = 10;
    if (c->n_given && c->n < cfpo3_grid_min_n())
        cli_usage_error(prog, "n = %lld is too small: at least %lld points are needed in 3-D",
                        (long long)c->n, (long long)cfpo3_grid_min_n());
    cfpo3_grid G;
    char gerr[512];
    if (c->n_given && !c->dry && cfpo3_grid_choose(c->n, &G, gerr, sizeof gerr) == 0) { /* bricks for this many ranks */
        cfpo3_bricks B;
        if (cfpo3_bricks_init(&B, G.g, comm_size(), comm_rank(), gerr, sizeof gerr) != 0)
            cli_usage_error(prog, "%s", gerr);
        cfpo3_bricks_free(&B);
    }
    for (int i = 0; i < c->nout; i++) {
        if (p3_format_of(c->out[i]) == P3F_UNKNOWN)
            cli_usage_error(prog, "%s: unknown output format (use " P3_EXTENSIONS ")", c->out[i]);
        char err[512];
        if (p3_check_box(c->out[i], c->box, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
        for (int j = 0; j < i; j++)
            if (strcmp(c->out[i], c->out[j]) == 0) cli_usage_error(prog, "output %s given twice", c->out[i]);
    }
    if (c->ckpt)
        for (int i = 0; i < c->nout; i++)
            if (strcmp(c->ckpt, c->out[i]) == 0) cli_usage_error(prog, "--checkpoint is also an output");
    return 0;
}

/* Rank 0's verdict bad (with its message in err) becomes every rank's:
 * the job fails once, every rank alike. */
static void agree_or_fail(int64_t bad, char *err, size_t errlen)
{
    comm_bcast(&bad, sizeof bad, 0);
    if (!bad) return;
    comm_bcast(err, errlen, 0);
    cli_fail(prog, "%s", err);
}

/* Writes the output files: set (3n by id, every rank) or, when NULL, e's
 * set gathered in id order; rank 0 writes. 0, or -1 with err (the same on
 * every rank). */
static int write_outputs(const cmdline *c, cfpo3_engine *e, const double *set, char *err, size_t errlen)
{
    const int64_t n = cfpo3_n(e);
    double *all = NULL;
    const double *pts = set ? set : cfpo3_points(e);
    if (!set && comm_size() > 1) {
        all = malloc(sizeof(double) * 3 * (size_t)n);
        if (comm_all(all != NULL) == 0 || cfpo3_gather(e, all) != 0) {
            free(all);
            snprintf(err, errlen, "out of memory gathering the points");
            return -1;
        }
        pts = all;
    }
    int64_t bad = 0;
    if (comm_rank() == 0)
        for (int i = 0; i < c->nout && !bad; i++)
            if (p3_write(c->out[i], pts, (size_t)n, c->box, err, errlen) != 0) bad = 1;
    free(all);
    comm_bcast(&bad, sizeof bad, 0);
    if (bad) comm_bcast(err, errlen, 0);
    return bad ? -1 : 0;
}

/* The RANKS line (several ranks; collective): into line on rank 0. */
static void ranks_line(cfpo_run_engine *R, char *line, size_t len)
{
    line[0] = 0;
    cfpo3_engine *e = R->E;
    cfpo_engine_timing tm;
    R->ops->timing(R->E, &tm);
    int b[3];
    double v[5];
    int64_t ph0;
    cfpo3_rank_timers(e, v, &ph0, b);
    const int P = comm_size();
    int64_t *own = calloc((size_t)P, sizeof *own);
    if (comm_all(own != NULL) == 0) {
        free(own);
        return;
    }
    comm_allgather_i64(cfpo3_own_points(e), own);
    if (comm_rank() == 0) {
        const double ph = tm.phases > 0 ? (double)tm.phases : 1;
        size_t k = (size_t)snprintf(line, len, "RANKS ranks=%d bricks=%dx%dx%d points=", P, b[0], b[1], b[2]);
        for (int r = 0; r < P && k < len; r++) k += (size_t)snprintf(line + k, len - k, "%s%lld", r ? "," : "", (long long)own[r]);
        if (k < len) snprintf(line + k, len - k, " phases=%lld compute_s=%.3f/%.3f/%.3f migrate_s=%.3f/%.3f/%.3f halo_s=%.3f/%.3f/%.3f "
               "halo_bytes_per_phase=%.0f/%.0f/%.0f migrate_bytes_per_phase=%.0f/%.0f/%.0f\n",
               (long long)tm.phases, tm.compute[0], tm.compute[1], tm.compute[2], tm.migrate[0], tm.migrate[1],
               tm.migrate[2], tm.halo[0], tm.halo[1], tm.halo[2], tm.halo_bytes[0] / ph, tm.halo_bytes[1] / ph,
               tm.halo_bytes[2] / ph, tm.migrate_bytes[0] / ph, tm.migrate_bytes[1] / ph, tm.migrate_bytes[2] / ph);
    }
    free(own);
}

int cfpo3_cli_main(const char *name, int argc, char **argv)
{
    prog = name;
    cmdline c;
    if (parse(&c, argc, argv)) return 0;
    char err[512];
    if (c.dry) {
        int64_t n = c.n;
        if (!c.n_given) cli_usage_error(prog, "--dry-run needs -n");
        cfpo3_grid G;
        if (cfpo3_grid_choose(n, &G, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
        const double bpp = cfpo3_bytes_per_point(n);
        /* a rank: the heap (every rank holds n-long arrays) and what this
         * process holds already (libraries, MPI) */
        const double bpr = cfpo3_bytes_per_point_ranks(n, comm_size());
        const double proc = (double)cli_peak_rss();
        if (comm_rank() == 0)
            printf("%s dry run: n=%lld grid=%d^3 cells=%lld points_per_cell=%.3f L/Delta3=%.4f "
                   "bytes_per_point=%.1f total_bytes=%.0f max_ranks=%lld ranks=%d bytes_per_point_rank=%.1f "
                   "process_bytes=%.0f rank_bytes=%.0f\n",
                   prog, (long long)n, G.g, (long long)G.g * G.g * G.g, (double)n / ((double)G.g * G.g * G.g),
                   G.L / G.delta3, bpp, bpp * (double)n, (long long)cfpo3_bricks_max(G.g), comm_size(), bpr, proc,
                   bpr * (double)n + proc);
        return 0;
    }
    /* the files can be written (rank 0 writes them; every rank learns) */
    int64_t bad = 0;
    if (comm_rank() == 0) {
        for (int i = 0; i < c.nout && !bad; i++)
            if (p3_probe(c.out[i], err, sizeof err) != 0) bad = 1;
        if (c.ckpt && !bad) { /* the checkpoint's folder must take a file */
            char *tmp = NULL;
            const int fd = safefile_create(c.ckpt, &tmp, err, sizeof err);
            if (fd < 0) {
                bad = 1;
            } else {
                close(fd);
                unlink(tmp);
                free(tmp);
            }
        }
    }
    agree_or_fail(bad, err, sizeof err);
    const double t0 = cli_now();
    cfpo3_engine *e = NULL;
    if (c.resume) {
        e = cfpo3_checkpoint_read(c.resume, c.o.threads, err, sizeof err);
        if (!e) cli_fail(prog, "%s", err);
        if (c.n_given && c.n != cfpo3_n(e))
            cli_usage_error(prog, "-n %lld disagrees with the checkpoint's n = %lld", (long long)c.n,
                            (long long)cfpo3_n(e));
    } else if (c.init) {
        double *xyz;
        size_t n;
        if (p3_read(c.init, &xyz, &n, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        if (c.n_given && (size_t)c.n != n)
            cli_usage_error(prog, "-n %lld disagrees with %s, which holds %zu points", (long long)c.n, c.init, n);
        if ((int64_t)n < cfpo3_grid_min_n())
            cli_usage_error(prog, "%s holds %zu points: at least %lld are needed in 3-D", c.init, n,
                            (long long)cfpo3_grid_min_n());
        e = cfpo3_create_given(xyz, (int64_t)n, &c.o, err, sizeof err);
        free(xyz);
        if (!e) cli_fail(prog, "%s: %s", c.init, err);
    } else {
        e = cfpo3_create(c.n, &c.o, err, sizeof err);
        if (!e) cli_fail(prog, "%s", err);
    }
    const int64_t n = cfpo3_n(e);
    const int root = comm_rank() == 0;
    cli_atomic tr = {0};
    if (c.trace) { /* rank 0's */
        bad = root && cli_atomic_open(&tr, c.trace, err, sizeof err) != 0;
        agree_or_fail(bad, err, sizeof err);
        if (root) fprintf(tr.f, "# iteration delta_min delta_avg moved solved max_disp seconds near round\n");
    }
    const int tracing = c.trace && root;
    cli_progress pr;
    cli_progress_init(&pr, c.quiet || !root);
    /* the schedule (sched3.h): rounds of the one run loop, shakes between */
    run_ctx ctx = {.pr = &pr, .trace = tracing ? tr.f : NULL, .t0 = t0};
    cfpo3_sched_args sa = {.so = c.so, .max_iter = c.max_iter, .stop = c.stop, .t0 = t0, .ckpt = c.ckpt,
                           .every = c.every, .on_iter = on_iteration, .user = &ctx};
    cfpo3_sched_result sr;
    if (cfpo3_sched_run(e, &sa, &sr, err, sizeof err) != 0) {
        cli_progress_end(&pr);
        if (tracing) cli_atomic_abort(&tr);
        cli_fail(prog, "%s", err);
    }
    e = sr.e;
    cli_progress_end(&pr);
    const int stop = sr.stop;
    if (stop == CFPO_STOP_SIGNAL) {
        if (tracing) cli_atomic_abort(&tr);
    } else {
        if (write_outputs(&c, e, sr.best, err, sizeof err) != 0) {
            if (tracing) cli_atomic_abort(&tr);
            cli_fail(prog, "%s", err);
        }
        bad = tracing && cli_atomic_commit(&tr, err, sizeof err) != 0;
        agree_or_fail(bad, err, sizeof err);
    }
    free(sr.best);
    cfpo_options lo;
    memset(&lo, 0, sizeof lo);
    cfpo_run_engine R;
    cfpo3_as_run(e, &lo, t0, &R); /* the last round's engine, for the RANKS line */
    long work[3];
    cfpo3_work(e, &work[0], &work[1], &work[2]);
    int64_t wsum[3] = {work[0], work[1], work[2]};
    comm_sum_i64(wsum, 3);
    char rline[4096];
    if (comm_size() > 1) ranks_line(&R, rline, sizeof rline);
    if (!root) {
        cfpo3_free(e);
        return stop == CFPO_STOP_SIGNAL ? 3 : 0;
    }
    const double dmin = sr.dmin, davg = sr.davg;
    const cfpo3_options *o = cfpo3_options_of(e);
    cli_summary s = {"cfpo3d", /* the 3-D engine, under either command */ o->relax ? "adaptive" : "adaptive-norelax", n, sr.seed,
                     o->threads > 0 ? o->threads : omp_get_max_threads(), comm_size(),
                     sr.iterations, cli_now() - t0, dmin, davg, sr.converged,
                     cli_peak_rss(), cfpo_stop_name(stop)};
    cli_print_summary(stdout, &s);
    const double d = dmin * cfpo3_delta_bound((double)n);
    printf("BOX3D side=%.17g delta_min_box=%.9g packing_fraction=%.6f\n", c.box, d * c.box,
           M_PI / 6.0 * (double)n * d * d * d);
    if (comm_size() > 1) printf("%s", rline);
    if (sr.so.rounds > 0)
        printf("SHAKE3D rounds=%d amp=%g best_round=%d flat=%d flat_gain=%g\n", sr.rounds_done, sr.so.amp,
               sr.best_round, sr.so.flat, sr.so.flat_gain);
    if (getenv("CFPO3D_WORK")) /* the solver's work over every rank, for measuring */
        printf("WORK3D cells=%lld tests=%lld cuts=%lld\n", (long long)wsum[0], (long long)wsum[1],
               (long long)wsum[2]);
    if (stop == CFPO_STOP_SIGNAL)
        fprintf(stderr, "%s: stopped by a signal at iteration %d; checkpoint %s written, no output; continue "
                "with --resume %s\n", prog, sr.signal_iter, c.ckpt, c.ckpt);
    cfpo3_free(e);
    return stop == CFPO_STOP_SIGNAL ? 3 : 0;
}

/* --dim D (or --dim=D), taken out of argv (the rest keeps its order, up
 * to a "--"): 2 (also without the option) or 3; anything else is a usage
 * error. */
int cfpo_cli_take_dim(const char *prog, int *argc, char **argv)
{
    int dim = 2, k = 1, i = 1;
    for (; i < *argc && strcmp(argv[i], "--") != 0; i++) {
        const char *v = NULL;
        if (strcmp(argv[i], "--dim") == 0) {
            if (i + 1 >= *argc) cli_usage_error(prog, "option '--dim' needs a value");
            v = argv[++i];
        } else if (strncmp(argv[i], "--dim=", 6) == 0) v = argv[i] + 6;
        if (!v) {
            argv[k++] = argv[i];
            continue;
        }
        if (strcmp(v, "2") != 0 && strcmp(v, "3") != 0)
            cli_usage_error(prog, "--dim: '%s' is not 2 or 3 (the dimension of the torus)", v);
        dim = v[0] - '0';
    }
    for (; i < *argc; i++) argv[k++] = argv[i];
    argv[k] = NULL;
    *argc = k;
    return dim;
}
