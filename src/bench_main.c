/* bench_main.c - layer 5: `cfpo-bench`: the core benchmark (never a test).
 *
 *   cfpo-bench sweep    -n N -t T [-k K]  full sweeps (every point solved):
 *                                         seconds per sweep; us per point and per
 *                                         point-update (one local solve) per core
 *   cfpo-bench converge -n N -t T         iterations and seconds until
 *                                         delta_avg >= 0.929, delta_min >= 0.92
 *                                         and convergence; bytes per point
 *   cfpo-bench capture  -n N -i IT,IT,.. -o FILE   records the local solves
 *                                         of those iterations (one thread)
 *   cfpo-bench replay   -o FILE [-k K] [-p plain|avx2|avx512]  replays them
 *                                         through the plain solver and the AVX2
 *                                         and AVX-512 ones the CPU runs: ns per
 *                                         call, and a non-zero exit if any
 *                                         call's bits differ
 *   cfpo-bench plain    -n N -k K [-o FILE]  K iterations of the paper's CFPO
 *                                         in a plain engine (bench_plain.c):
 *                                         the yardstick for the engine's work
 *   cfpo-bench contrast -n N [-k ROUNDS] [-t T] [-d SPEC] [-r SPEC]
 *                                         an iteration under density SPEC
 *                                         (ramp:contrast=256) against one
 *                                         under -r (cos:a=0.000001), seeds
 *                                         1-3, interleaved (bench_contrast.c)
 *
 * Protocol (after the Parallel Research Kernels): one untimed warm-up sweep,
 * then K timed sweeps; the median is reported. Sweep timings exclude the
 * per-iteration statistics, which are timed separately. Each mode ends with
 * one greppable line starting with "RESULT". */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_contrast.h"
#include "bench_plain.h"
#include "bench_solver.h"
#include "cfpo.h"
#include "cli.h"
#include "engine.h"
#include "omp_compat.h"

static const char *prog = "cfpo-bench";

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int k)
{
    qsort(v, (size_t)k, sizeof *v, cmp_double);
    return k % 2 ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

static int sweep(int64_t n, int threads, int k, uint64_t seed)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.threads = threads;
    o.skip = 0;
    o.seed = seed;
    char err[256];
    cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    double *ts = malloc((size_t)k * sizeof *ts), *ss = malloc((size_t)k * sizeof *ss);
    double *solves = malloc((size_t)k * sizeof *solves);
    for (int it = -1; it < k; it++) {
        double t0 = cli_now();
        int64_t moved, solved;
        cfpo_engine_sweep(E, &moved, &solved);
        double t1 = cli_now();
        double dmin, davg;
        cfpo_engine_deltas(E, &dmin, &davg);
        double t2 = cli_now();
        if (it >= 0) {
            ts[it] = t1 - t0;
            ss[it] = t2 - t1;
        }
        /* A point that crosses into a cell of a later colour is solved
         * again in the same sweep, so a sweep solves at least n. */
        if (solved < n) cli_fail(prog, "a full sweep solved %lld of %lld points", (long long)solved, (long long)n);
        if (it >= 0) solves[it] = (double)solved;
    }
    double sw = median(ts, k), st = median(ss, k), sv = median(solves, k);
    printf("RESULT sweep n=%lld threads=%d sweeps=%d seconds_per_sweep=%.4f us_per_point=%.3f "
           "us_per_update=%.3f solves_per_sweep=%.0f stats_seconds=%.4f\n",
           (long long)n, threads, k, sw, sw / (double)n * 1e6, sw * threads / sv * 1e6, sv, st);
    free(solves);
    free(ts);
    free(ss);
    cfpo_engine_free(E);
    return 0;
}

typedef struct {
    int avg_it, min_it;
    double avg_s, min_s, t0;
} conv_ctx;

static int on_iter(const cfpo_iter_stats *s, void *user)
{
    conv_ctx *c = user;
    double el = cli_now() - c->t0;
    if (c->avg_it < 0 && s->delta_avg >= 0.929) { c->avg_it = s->iteration; c->avg_s = el; }
    if (c->min_it < 0 && s->delta_min >= 0.92) { c->min_it = s->iteration; c->min_s = el; }
    return 0;
}

static int converge(int64_t n, int threads, uint64_t seed)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.threads = threads;
    o.seed = seed;
    conv_ctx c = {-1, -1, 0, 0, 0};
    o.progress = on_iter;
    o.user = &c;
    char err[256];
    c.t0 = cli_now();
    cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    cfpo_result r;
    cfpo_engine_run(E, &r, err, sizeof err);
    double total = cli_now() - c.t0;
    uint64_t peak = cli_peak_rss();
    printf("RESULT converge n=%lld threads=%d avg0929_iter=%d avg0929_seconds=%.2f min092_iter=%d "
           "min092_seconds=%.2f converged=%s iterations=%d seconds=%.2f delta_min=%.4f "
           "delta_avg=%.4f peak_bytes=%llu bytes_per_point=%.1f\n",
           (long long)n, threads, c.avg_it, c.avg_s, c.min_it, c.min_s, r.converged ? "yes" : "no",
           r.iterations, total, r.delta_min, r.delta_avg, (unsigned long long)peak,
           (double)peak / (double)n);
    cfpo_engine_free(E);
    return 0;
}

static int is_mode(const char *a)
{
    return strcmp(a, "sweep") == 0 || strcmp(a, "converge") == 0 || strcmp(a, "capture") == 0 ||
           strcmp(a, "replay") == 0 || strcmp(a, "plain") == 0 || strcmp(a, "contrast") == 0;
}

/* "2,20,200" into its[] (at most 16). Returns the count, -1 if bad. */
static int parse_its(const char *s, int *its)
{
    int n = 0;
    while (*s) {
        char *end;
        long v = strtol(s, &end, 10);
        if (end == s || v < 1 || v > 1000000 || n == 16) return -1;
        its[n++] = (int)v;
        if (*end == ',') end++;
        else if (*end) return -1;
        s = end;
    }
    return n ? n : -1;
}

int main(int argc, char **argv)
{
    if (argc < 2 || !is_mode(argv[1])) {
        if (argc >= 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
            printf("Usage: cfpo-bench sweep|converge -n N [-t THREADS] [-k SWEEPS] [-s SEED]\n"
                   "       cfpo-bench capture -n N -i IT[,IT...] -o FILE [-s SEED]\n"
                   "       cfpo-bench replay -o FILE [-k ROUNDS] [-p plain|avx2|avx512]\n"
                   "       cfpo-bench plain -n N -k ITERATIONS [-s SEED] [-o FILE]\n"
                   "       cfpo-bench contrast -n N [-k ROUNDS] [-t THREADS] [-d DENSITY] [-r REFERENCE]\n");
            return 0;
        }
        cli_usage_error(prog, "first argument must be 'sweep', 'converge', 'capture', 'replay', 'plain' or 'contrast'");
    }
    int64_t n = 65536, v;
    int threads = omp_get_num_procs(), k = 5, its[16], nits = 0, threads_given = 0;
    uint64_t seed = 1;
    const char *file = NULL, *only = NULL, *dens = "ramp:contrast=256", *ref = "cos:a=0.000001";
    int ch;
    optind = 2;
    opterr = 0;
    while ((ch = getopt(argc, argv, ":n:t:k:s:i:o:p:d:r:")) != -1) {
        switch (ch) {
        case 'n':
            if (cli_parse_i64(optarg, 11, INT64_MAX, &v) != 0) cli_usage_error(prog, "-n: bad value '%s'", optarg);
            n = v;
            break;
        case 't':
            if (cli_parse_i64(optarg, 1, 4096, &v) != 0) cli_usage_error(prog, "-t: bad value '%s'", optarg);
            threads = (int)v;
            threads_given = 1;
            break;
        case 'k':
            if (cli_parse_i64(optarg, 1, 10000, &v) != 0) cli_usage_error(prog, "-k: bad value '%s'", optarg);
            k = (int)v;
            break;
        case 's':
            if (cli_parse_u64(optarg, &seed) != 0) cli_usage_error(prog, "-s: bad value '%s'", optarg);
            break;
        case 'i':
            if ((nits = parse_its(optarg, its)) < 0) cli_usage_error(prog, "-i: bad iteration list '%s'", optarg);
            break;
        case 'o': file = optarg; break;
        case 'd': dens = optarg; break;
        case 'r': ref = optarg; break;
        case 'p':
            if (strcmp(optarg, "plain") != 0 && strcmp(optarg, "avx2") != 0 && strcmp(optarg, "avx512") != 0)
                cli_usage_error(prog, "-p: bad solver '%s' (plain, avx2 or avx512)", optarg);
            only = optarg;
            break;
        default: cli_usage_error(prog, "unknown or incomplete option '%s'", argv[optind - 1]);
        }
    }
    if (strcmp(argv[1], "capture") == 0) {
        if (!file || !nits) cli_usage_error(prog, "capture needs -i ITERATIONS and -o FILE");
        return bench_capture(prog, n, seed, its, nits, file);
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    if (strcmp(argv[1], "plain") == 0) return bench_plain(prog, n, seed, k, file);
    if (strcmp(argv[1], "contrast") == 0) return bench_contrast(prog, n, threads_given ? threads : 1, k, 3, dens, ref);
    if (strcmp(argv[1], "replay") == 0) {
        if (!file) cli_usage_error(prog, "replay needs -o FILE");
        return bench_replay(prog, file, only, k);
    }
    return strcmp(argv[1], "sweep") == 0 ? sweep(n, threads, k, seed) : converge(n, threads, seed);
}
