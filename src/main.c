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
#include "comm.h"
#include "engine.h"
#include "tiles.h"
#include "omp_compat.h"
#include "pointfile.h"
#include "stoprule.h"

static const char *prog = "cfpo";

static void usage(void)
{
    printf("Usage: cfpo -n N [options]\n"
           "Blue-noise points on the unit torus by parallel Constrained Farthest Point\n"
           "Optimization (Chen & Gotsman). Prints one SUMMARY line on stdout.\n\n"
           "  -n, --points N       number of points (required; e.g. 65536, 2^20, 1e6)\n"
           "  -s, --seed S         random seed (default 1)\n"
           "      --variant V      adaptive (default: 9 phases, S = cell grown by\n"
           "                       L - max(delta(X), 0.7 Delta), uniform start; see docs/method.md),\n"
           "                       paper (the published algorithm: S = cell grown by\n"
           "                       L - Delta, stratified start; 'cfpo' is an alias)\n"
           "                       or simplified (4 phases, S = own cell)\n"
           "  -t, --threads T      OpenMP threads (default: all cores, here %d)\n"
           "      --max-iter K     stop after K iterations (default %d)\n"
           "      --tol T          a move must gain more than T * cell side; converged when\n"
           "                       no point's net move over an iteration reaches it\n"
           "                       (default %g, paper and simplified %g; 0 = any strict gain)\n"
           "      --no-skip        re-solve every point every iteration (same output)\n"
           "      --target-min D   stop as soon as delta_min >= D (and every other target holds)\n"
           "      --target-avg D   stop as soon as delta_avg >= D (and every other target holds)\n"
           "      --time-limit S   stop at the first iteration boundary past S seconds\n"
           "  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     one TSV row per iteration\n"
           "  -q, --quiet          no progress line\n\n"
           "Several ranks (run under mpirun; the grid is cut into one tile per rank):\n"
           "      --tiles AxB      cut into A x B tiles (default: the most square cut)\n"
           "      --checkpoint F   write the state to F (atomically) ...\n"
           "      --checkpoint-every K   ... every K iterations (default 100)\n"
           "      --resume F       continue from checkpoint F, on any number of ranks;\n"
           "                       n, seed, variant and tol come from it\n"
           "      --dry-run        print the tiling, memory per rank and bytes per phase\n"
           "                       for n on P ranks, then stop (allocates no points)\n"
           "      --ranks P        the rank count for --dry-run (default: this run's)\n"
           "      --check          verify point counts, id checksums, ownership and halos\n"
           "                       after every phase (slow; for tests)\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "With several ranks the output must be .npy or raw; it is the same file,\n"
           "byte for byte, as one process writes.\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           omp_get_num_procs(), CFPO_DEFAULT_MAX_ITER, CFPO_ADAPTIVE_TOL, CFPO_DEFAULT_TOL, PF_EXTENSIONS);
}

typedef struct {
    cli_progress prog;
    FILE *trace;
    double t0;
    int64_t n;
    int max_iter;
    double last_moved[16];
    double last_min[16], last_avg[16];
    int seen; /* iterations reported */
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
    if (c->trace)
        fprintf(c->trace, "%d\t%.9f\t%.9f\t%lld\t%lld\t%.6g\t%.6f\t%.6f\t%.6g\n", s->iteration,
                s->delta_min, s->delta_avg, (long long)s->moved, (long long)s->solved,
                s->max_disp, s->seconds, el, s->max_move);
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
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o->variant, o->seed, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    cfpo_tiling T;
    if (cfpo_tiling_init(&T, G.g, P, fpx, fpy, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    if (comm_rank() != 0) return 0;
    const int64_t g = G.g;
    const double ppc = (double)n / (double)(g * g); /* points per cell */
    const int64_t wmax = cfpo_tile_len(g, T.px, 0), hmax = cfpo_tile_len(g, T.py, 0);
    const int64_t wmin = cfpo_tile_len(g, T.px, T.px - 1), hmin = cfpo_tile_len(g, T.py, T.py - 1);
    const int64_t cmax = wmax * hmax;
    const int64_t ring = cfpo_tile_ring(wmax, hmax);
    const double pmax = (double)cmax * ppc;
    const int threads = o->threads > 0 ? o->threads : omp_get_num_procs();
    const double mem = (double)cfpo_engine_bytes_local((int64_t)(pmax * 1.02), cmax, ring, threads);
    /* Halo per phase: a rank sends the cells of its border that its
     * neighbours keep (every border cell, corners to up to three ranks):
     * 4 bytes of count per cell and 16 per point. */
    const int64_t sx = T.px > 1 ? 2 * hmax : 0, sy = T.py > 1 ? 2 * wmax : 0;
    const int64_t corners = (T.px > 1 && T.py > 1) ? 4 : 0;
    const double halo_cells = (double)(sx + sy + corners);
    const double halo = halo_cells * (4 + 16 * ppc);
    /* Migration per phase: at most every point of the phase's colour in the
     * border cells leaves, 32 bytes each. */
    const double mig = halo_cells / (G.period * G.period) * ppc * 32 * 1.5;
    printf("dry run: n=%lld on %d ranks (%d threads each), variant %s\n", (long long)n, P, threads,
           cfpo_variant_name(o->variant));
    printf("  grid          %lld x %lld cells (L = %.3g, Delta(n) = %.3g, %.3f points per cell)\n",
           (long long)g, (long long)g, G.L, G.delta, ppc);
    printf("  tiling        %d x %d tiles; tile sides %lld..%lld by %lld..%lld cells\n", T.px, T.py,
           (long long)wmin, (long long)wmax, (long long)hmin, (long long)hmax);
    printf("  per rank      up to %lld cells, about %.4g points\n", (long long)cmax, pmax);
    printf("  memory/rank   %.4g GB (%.1f bytes per point)\n", mem / 1e9, mem / pmax);
    printf("  halo/phase    %.0f cells, about %.4g bytes sent per rank (%d phases per iteration)\n",
           halo_cells, halo, G.period * G.period);
    printf("  migrate/phase at most about %.4g bytes sent per rank\n", mig);
    printf("  largest rank count for this n: %lld\n", (long long)cfpo_tiling_max_ranks(g));
    printf("DRYRUN n=%lld ranks=%d px=%d py=%d g=%lld cells_per_rank=%lld points_per_rank=%.0f "
           "bytes_per_rank=%.0f halo_bytes_per_phase=%.0f migrate_bytes_per_phase=%.0f\n",
           (long long)n, P, T.px, T.py, (long long)g, (long long)cmax, pmax, mem, halo, mig);
    return 0;
}

int main(int argc, char **argv)
{
    comm_init(&argc, &argv);
    const int rank = comm_rank(), P = comm_size();
    cli_set_exit(rank != 0, comm_finalize);
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
        {0, 0, 0, 0}};
    cfpo_options o;
    cfpo_options_init(&o);
    cfpo_engine_config cfg = {0};
    int64_t n = -1, dry_ranks = -1;
    const char *out = NULL, *trace = NULL;
    int quiet = 0, ch, dry = 0, given_seed = 0, given_variant = 0, given_tol = 0, every = -1;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":n:s:t:o:qhV", longopts, NULL)) != -1) {
        int64_t v;
        switch (ch) {
        case 'n':
            n = cli_arg_points(prog, optarg);
            break;
        case 's':
            o.seed = cli_arg_seed(prog, optarg);
            given_seed = 1;
            break;
        case 'v':
            if (cfpo_variant_parse(optarg, &o.variant) != 0)
                cli_usage_error(prog, "--variant: '%s' is not one of adaptive, paper, simplified", optarg);
            given_variant = 1;
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
            if (cli_parse_double(optarg, 0, CFPO_TOL_MAX, &o.tol) != 0)
                cli_usage_error(prog, "--tol: '%s' is not a number in [0, %g]", optarg, CFPO_TOL_MAX);
            given_tol = 1;
            break;
        case 'K': o.skip = 0; break;
        case 1001: cli_stop_option(prog, "target-min", optarg, &o.stop); break;
        case 1002: cli_stop_option(prog, "target-avg", optarg, &o.stop); break;
        case 1003: cli_stop_option(prog, "time-limit", optarg, &o.stop); break;
        case 'o': out = optarg; break;
        case 'r': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'X': {
            char *x = strchr(optarg, 'x');
            int64_t a, b;
            if (!x) cli_usage_error(prog, "--tiles: '%s' is not of the form AxB (e.g. 2x3)", optarg);
            *x = '\0';
            int bad = cli_parse_i64(optarg, 1, 1 << 20, &a) != 0 || cli_parse_i64(x + 1, 1, 1 << 20, &b) != 0;
            *x = 'x';
            if (bad) cli_usage_error(prog, "--tiles: '%s' is not of the form AxB (e.g. 2x3)", optarg);
            cfg.px = (int)a;
            cfg.py = (int)b;
            break;
        }
        case 'C': cfg.check = 1; break;
        case 'P': cfg.checkpoint = optarg; break;
        case 'E':
            if (cli_parse_i64(optarg, 1, 1000000000, &v) != 0)
                cli_usage_error(prog, "--checkpoint-every: '%s' is not a whole number in 1..1e9", optarg);
            every = (int)v;
            break;
        case 'R': cfg.resume = optarg; break;
        case 'D': dry = 1; break;
        case 'N':
            if (cli_parse_i64(optarg, 1, 1 << 24, &v) != 0)
                cli_usage_error(prog, "--ranks: '%s' is not a whole number in 1..16777216", optarg);
            dry_ranks = v;
            break;
        case 'h': if (rank == 0) usage(); comm_finalize(); return 0;
        case 'V': if (rank == 0) printf("cfpo %s\n", CFPO_VERSION); comm_finalize(); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default:
            if (optopt) cli_usage_error(prog, "unknown option '-%c'", optopt);
            cli_usage_error(prog, "unknown option '%s'", argv[optind - 1]);
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (!given_tol) o.tol = cfpo_default_tol(o.variant);
    if (every > 0 && !cfg.checkpoint) cli_usage_error(prog, "--checkpoint-every needs --checkpoint FILE");
    if (cfg.checkpoint) cfg.checkpoint_every = every > 0 ? every : 100;
    if (dry_ranks > 0 && !dry) cli_usage_error(prog, "--ranks is for --dry-run (under mpirun the rank count is mpirun's)");
    if (cfg.resume && dry) cli_usage_error(prog, "--dry-run and --resume do not go together");
    char err[512];
    if (cfg.resume) {
        cfpo_checkpoint_info info;
        if (cfpo_checkpoint_peek(cfg.resume, &info, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        if ((n >= 0 && n != info.n) || (given_seed && o.seed != info.seed) ||
            (given_variant && o.variant != info.variant) || (given_tol && o.tol != info.tol))
            cli_usage_error(prog, "--resume %s: the checkpoint is for n=%lld seed=%llu variant=%s tol=%g; "
                            "leave those options out or give the same values", cfg.resume,
                            (long long)info.n, (unsigned long long)info.seed,
                            cfpo_variant_name(info.variant), info.tol);
        n = info.n;
        o.seed = info.seed;
        o.variant = info.variant;
        o.tol = info.tol;
    }
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    if (dry) {
        int rc = dry_run(n, &o, dry_ranks > 0 ? (int)dry_ranks : P, cfg.px, cfg.py);
        comm_finalize();
        return rc;
    }
    pf_format fmt = out ? pf_format_of(out) : PF_UNKNOWN;
    if (out && fmt == PF_UNKNOWN)
        cli_usage_error(prog, "%s: unknown output format (use %s)", out, PF_EXTENSIONS);
    if (out && fmt == PF_TEXT && P > 1)
        cli_usage_error(prog, "%s: text output needs one rank (no rank holds the whole set); use .npy or .bin", out);
    if (cfg.checkpoint && out && strcmp(cfg.checkpoint, out) == 0)
        cli_usage_error(prog, "--checkpoint and -o name the same file");

    /* The grid, the cut into tiles and the memory of the largest tile. */
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o.variant, o.seed, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    cfpo_tiling T;
    if (P == 1) {
        int vr = cfpo_validate(n, &o, err, sizeof err);
        if (vr == -1) cli_usage_error(prog, "%s", err);
        if (vr != 0) cli_fail(prog, "%s", err);
    }
    if (cfpo_tiling_init(&T, G.g, P, cfg.px, cfg.py, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    if (P > 1) {
        const int64_t wmax = cfpo_tile_len(G.g, T.px, 0), hmax = cfpo_tile_len(G.g, T.py, 0);
        const int64_t pmax = (int64_t)((double)(wmax * hmax) * (double)n / (double)(G.g * G.g) * 1.05) + 64;
        int vr = cfpo_validate_ranks(n, &o, pmax, wmax * hmax, cfpo_tile_ring(wmax, hmax), comm_local_size(),
                                     err, sizeof err);
        if (vr == -1) cli_usage_error(prog, "%s", err);
        if (vr != 0) cli_fail(prog, "%s", err);
    }

    /* Open outputs first, so an unwritable path fails before the work. */
    cli_guard_tmp(NULL);
    pf_writer *w = NULL;
    comm_file *cf = NULL;
    if (out && fmt == PF_TEXT) {
        w = pf_writer_open(out, (size_t)n, err, sizeof err);
        if (!w) cli_fail(prog, "%s", err);
        cli_guard_tmp(pf_writer_tmpname(w));
    } else if (out) {
        cf = comm_file_create(out, err, sizeof err);
        if (!cf) cli_fail(prog, "%s", err);
        if (rank == 0) cli_guard_tmp(comm_file_tmpname(cf));
    }
    cli_atomic tr = {0};
    run_ctx ctx = {.n = n, .max_iter = o.max_iter, .stop = o.stop};
    if (trace) {
        int ok = rank != 0 || cli_atomic_open(&tr, trace, err, sizeof err) == 0;
        if (!comm_all(ok)) {
            pf_writer_abort(w);
            if (cf) comm_file_commit(cf, 0, err, sizeof err);
            cli_fail(prog, "%s", ok ? "cannot open the trace file" : err);
        }
        if (rank == 0) {
            ctx.trace = tr.f;
            fprintf(tr.f, "iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed\tmax_move\n");
        }
    }
    cli_progress_init(&ctx.prog, quiet || rank != 0);
    o.progress = on_iteration;
    o.user = &ctx;

    ctx.t0 = cli_now();
    cfpo_engine *E = cfpo_engine_create_ex(n, &o, &cfg, err, sizeof err);
    if (!E) {
        pf_writer_abort(w);
        if (cf) comm_file_commit(cf, 0, err + 256, sizeof err - 256);
        if (rank == 0 && trace) cli_atomic_abort(&tr);
        cli_fail(prog, "%s", err);
    }
    cfpo_result res;
    int rr = cfpo_engine_run(E, &res, err, sizeof err);
    cli_progress_end(&ctx.prog);
    if (rr != 0) {
        pf_writer_abort(w);
        if (cf) comm_file_commit(cf, 0, err + 256, sizeof err - 256);
        if (rank == 0 && trace) cli_atomic_abort(&tr);
        cli_fail(prog, "%s", err);
    }
    double seconds = cli_now() - ctx.t0;

    if (w) {
        if (cfpo_engine_write(E, w, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        const char *tmp = pf_writer_tmpname(w);
        char tmpcopy[4096];
        snprintf(tmpcopy, sizeof tmpcopy, "%s", tmp);
        if (pf_writer_commit(w, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        cli_unguard_tmp(tmpcopy);
    }
    if (cf) {
        char tmpcopy[4096];
        snprintf(tmpcopy, sizeof tmpcopy, "%s", comm_file_tmpname(cf));
        unsigned char hdr[PF_HEADER_MAX];
        size_t hl = pf_header(fmt, (size_t)n, hdr, sizeof hdr);
        int ok = 1;
        if (rank == 0 && hl) ok = comm_file_write_at(cf, 0, hdr, hl) == 0;
        if (cfpo_engine_write_points(E, cf, hl, err, sizeof err) != 0) ok = 0;
        if (comm_file_commit(cf, ok, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        cli_unguard_tmp(tmpcopy);
    }
    if (trace && rank == 0 && cli_atomic_commit(&tr, err, sizeof err) != 0) cli_fail(prog, "%s", err);

    int64_t peak = (int64_t)cli_peak_rss(), peak_max = peak;
    comm_sum_i64(&peak, 1);
    comm_max_i64(&peak_max, 1);
    cfpo_engine_timing tm;
    cfpo_engine_timing_get(E, &tm);
    if (rank == 0) {
        cli_summary sm = {
            .method = "cfpo",
            .variant = cfpo_variant_name(o.variant),
            .n = n, .seed = o.seed,
            .threads = o.threads > 0 ? o.threads : omp_get_num_procs(),
            .ranks = P, .iterations = res.iterations, .seconds = seconds,
            .delta_min = res.delta_min, .delta_avg = res.delta_avg,
            .converged = res.converged, .peak_bytes = (uint64_t)peak,
            .stop = cfpo_stop_name(res.stop)};
        cli_print_summary(stdout, &sm);
        if (P > 1) {
            const double ph = tm.phases > 0 ? (double)tm.phases : 1;
            printf("RANKS ranks=%d tiles=%dx%d phases=%lld compute_s=%.3f/%.3f/%.3f migrate_s=%.3f/%.3f/%.3f "
                   "halo_s=%.3f/%.3f/%.3f halo_bytes_per_phase=%.0f/%.0f/%.0f "
                   "migrate_bytes_per_phase=%.0f/%.0f/%.0f peak_bytes_per_rank=%lld\n",
                   P, T.px, T.py, (long long)tm.phases, tm.compute[0], tm.compute[1], tm.compute[2],
                   tm.migrate[0], tm.migrate[1], tm.migrate[2], tm.halo[0], tm.halo[1], tm.halo[2],
                   tm.halo_bytes[0] / ph, tm.halo_bytes[1] / ph, tm.halo_bytes[2] / ph,
                   tm.migrate_bytes[0] / ph, tm.migrate_bytes[1] / ph, tm.migrate_bytes[2] / ph,
                   (long long)peak_max);
        }
        if (cfg.check)
            fprintf(stderr, "cfpo: check: %lld migrations and %lld halo refreshes verified on rank 0\n",
                    (long long)tm.checked_migrations, (long long)tm.checked_halos);
        fflush(stdout);
    }
    cfpo_engine_free(E);
    comm_finalize();
    return 0;
}
