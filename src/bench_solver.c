/* bench_solver.c - `cfpo-bench capture` and `cfpo-bench replay`: the local
 * solver's calls of a real run, recorded and played back through the plain
 * and the AVX2 solver (solver_simd.h), which must give the same bits on
 * every call. Never a test: the benchmark of the solver alone. Times are
 * the replaying thread's CPU time, the best of the rounds. Calls made in
 * the adaptive variant's near phase (cfpo_near_solve) are captured too,
 * and replayed, like every call, as full LocalCFPO problems.
 *
 * File: "CFPOCALLS1\n", then per call: int32 m, int32 skip, 7 doubles
 * (S.x0, S.y0, S.x1, S.y1, hx, hy, floor2), then m doubles x, m doubles y. */
#include "bench_solver.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cfpo.h"
#include "cli.h"
#include "engine.h"
#include "readall.h"
#include "solver_simd.h"

static const char MAGIC[] = "CFPOCALLS1\n";
static FILE *cap_out;
static long cap_calls;

static void record(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                   double floor2)
{
    int32_t h[2] = {m, skip};
    double d[7] = {S.x0, S.y0, S.x1, S.y1, hx, hy, floor2};
#pragma omp critical(cfpo_capture)
    {
        fwrite(h, sizeof h, 1, cap_out);
        fwrite(d, sizeof d, 1, cap_out);
        fwrite(yx, sizeof *yx, (size_t)m, cap_out);
        fwrite(yy, sizeof *yy, (size_t)m, cap_out);
        cap_calls++;
    }
}

int bench_capture(const char *prog, int64_t n, uint64_t seed, const int *its, int nits, const char *path)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.threads = 1;
    o.seed = seed;
    char err[256];
    cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
    if (!E) cli_fail(prog, "%s", err);
    cap_out = fopen(path, "wb");
    if (!cap_out) cli_fail(prog, "cannot write '%s'", path);
    fwrite(MAGIC, 1, sizeof MAGIC - 1, cap_out);
    int last = 0;
    for (int i = 0; i < nits; i++)
        if (its[i] > last) last = its[i];
    for (int it = 1; it <= last; it++) {
        int want = 0;
        for (int i = 0; i < nits; i++) want |= its[i] == it;
        long before = cap_calls;
        cfpo_solve_observer = want ? record : NULL;
        int64_t moved, solved;
        cfpo_engine_sweep(E, &moved, &solved);
        cfpo_solve_observer = NULL;
        if (want) printf("iteration %d: %ld calls, %lld moved\n", it, cap_calls - before, (long long)moved);
    }
    if (fclose(cap_out) != 0) cli_fail(prog, "cannot write '%s'", path);
    printf("RESULT capture n=%lld calls=%ld file=%s\n", (long long)n, cap_calls, path);
    cfpo_engine_free(E);
    return 0;
}

typedef struct {
    int m, skip;
    cfpo_square S;
    double hx, hy, floor2;
    const double *x, *y;
} call;

static unsigned char *slurp(const char *prog, const char *path, size_t *len)
{
    unsigned char *b = NULL;
    switch (readall(path, 0, &b, len)) {
    case READALL_OK: break;
    case READALL_OPEN: cli_fail(prog, "cannot read '%s'", path);
    case READALL_MEMORY:
    case READALL_LARGE: cli_fail(prog, "out of memory reading '%s'", path);
    case READALL_READ: cli_fail(prog, "read error in '%s'", path);
    }
    return b;
}

/* The calls of a capture file (pointers into buf). */
static call *parse(const char *prog, const char *path, unsigned char *buf, size_t len, long *ncalls)
{
    const size_t ml = sizeof MAGIC - 1;
    if (len < ml || memcmp(buf, MAGIC, ml) != 0) cli_fail(prog, "'%s' is not a capture file", path);
    long cap = 1024, n = 0;
    call *c = malloc((size_t)cap * sizeof *c);
    size_t p = ml;
    while (p < len) {
        int32_t h[2];
        double d[7];
        if (len - p < sizeof h + sizeof d) cli_fail(prog, "'%s': truncated call %ld", path, n);
        memcpy(h, buf + p, sizeof h);
        memcpy(d, buf + p + sizeof h, sizeof d);
        p += sizeof h + sizeof d;
        if (h[0] < 0 || h[0] > 100000 || h[1] < -1 || h[1] >= h[0] || len - p < 2 * (size_t)h[0] * sizeof(double))
            cli_fail(prog, "'%s': bad call %ld", path, n);
        if (n == cap) c = realloc(c, (size_t)(cap *= 2) * sizeof *c);
        if (!c) cli_fail(prog, "out of memory");
        /* the doubles are 8-byte aligned: the header is 11 bytes, so copy */
        double *xy = malloc(2 * (size_t)h[0] * sizeof(double) + 1);
        if (!xy) cli_fail(prog, "out of memory");
        memcpy(xy, buf + p, 2 * (size_t)h[0] * sizeof(double));
        p += 2 * (size_t)h[0] * sizeof(double);
        c[n++] = (call){h[0], h[1], {d[0], d[1], d[2], d[3]}, d[4], d[5], d[6], xy, xy + h[0]};
    }
    *ncalls = n;
    return c;
}

typedef double (*solver_fn)(const double *, const double *, int, int, cfpo_square, double, double, double, double *,
                            double *, double *);

/* Seconds of CPU time of this thread: time the machine gives to other
 * processes does not count. */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* All calls through f, their results into v, cx, cy; returns CPU seconds. */
static double run_all(solver_fn f, const call *c, long n, double *scratch, double *v, double *cx, double *cy)
{
    double t0 = cpu_now();
    for (long i = 0; i < n; i++)
        v[i] = f(c[i].x, c[i].y, c[i].m, c[i].skip, c[i].S, c[i].hx, c[i].hy, c[i].floor2, &cx[i], &cy[i], scratch);
    return cpu_now() - t0;
}

int bench_replay(const char *prog, const char *path, const char *only, int rounds)
{
    size_t len;
    unsigned char *buf = slurp(prog, path, &len);
    long n;
    call *c = parse(prog, path, buf, len, &n);
    free(buf);
    int maxm = 0;
    for (long i = 0; i < n; i++)
        if (c[i].m > maxm) maxm = c[i].m;
    double *scratch = malloc(cfpo_solver_scratch((size_t)maxm) * sizeof(double));
    double *r = malloc(9 * (size_t)(n + 1) * sizeof(double));
    if (!scratch || !r) cli_fail(prog, "out of memory");
    /* The routes: each one's results in r[3 n q ...], its best time in t[q]. */
    const solver_fn fn[3] = {cfpo_local_solve_plain, cfpo_local_solve_avx2, cfpo_local_solve_avx512};
    static const char *const name[3] = {"plain", "avx2", "avx512"};
    const int usable[3] = {1, cfpo_solver_avx2_usable(), cfpo_solver_avx512_usable()};
    int run[3];
    double t[3] = {1e300, 1e300, 1e300};
    for (int q = 0; q < 3; q++) run[q] = usable[q] && (!only || strcmp(only, name[q]) == 0);
    for (int k = 0; k < rounds; k++)
        for (int q = 0; q < 3; q++)
            if (run[q]) {
                double *rq = r + 3 * (size_t)n * (size_t)q;
                double s = run_all(fn[q], c, n, scratch, rq, rq + n, rq + 2 * n);
                if (s < t[q]) t[q] = s;
            }
    /* Every route run against the first one run: the same bits? */
    long differ = 0;
    int first = -1;
    for (int q = 0; q < 3; q++) {
        if (!run[q]) continue;
        if (first < 0) {
            first = q;
            continue;
        }
        const double *a = r + 3 * (size_t)n * (size_t)first, *b = r + 3 * (size_t)n * (size_t)q;
        for (long i = 0; i < n; i++)
            differ += memcmp(&a[i], &b[i], 8) || memcmp(&a[n + i], &b[n + i], 8) ||
                      memcmp(&a[2 * n + i], &b[2 * n + i], 8);
    }
    double ns[3];
    for (int q = 0; q < 3; q++) ns[q] = run[q] ? t[q] / (double)n * 1e9 : 0.0;
    printf("RESULT replay calls=%ld avx2=%s avx512=%s plain_ns_per_call=%.1f avx2_ns_per_call=%.1f "
           "avx512_ns_per_call=%.1f speedup=%.3f speedup_avx512=%.3f differing_calls=%ld\n",
           n, usable[1] ? "yes" : "no", usable[2] ? "yes" : "no", ns[0], ns[1], ns[2],
           run[0] && run[1] ? t[0] / t[1] : 0.0, run[0] && run[2] ? t[0] / t[2] : 0.0, differ);
    for (long i = 0; i < n; i++) free((void *)c[i].x);
    free(c);
    free(scratch);
    free(r);
    return differ ? 1 : 0;
}
