/* bench_contrast.c - layer 5: `cfpo-bench contrast` (bench_contrast.h): an
 * iteration under one density against one under another, through the
 * library, interleaved so that a machine's drift falls on both. */
#include "bench_contrast.h"

#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "cli.h"
#include "density.h"
#include "engines.h"

#define FIRST_IT 3
#define LAST_IT 22

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the q-quantile of v[0..k) (sorted in place), by linear interpolation */
static double quantile(double *v, int k, double q)
{
    qsort(v, (size_t)k, sizeof *v, cmp_double);
    const double at = q * (double)(k - 1);
    const int i = (int)at;
    return i + 1 < k ? v[i] + (at - (double)i) * (v[i + 1] - v[i]) : v[i];
}

static int on_iter(const cfpo_iter_stats *s, void *user)
{
    if (s->iteration >= FIRST_IT && s->iteration <= LAST_IT) *(double *)user += s->seconds;
    return 0;
}

/* The command's default tolerance under density `spec` (a flat one runs
 * the uniform engine at the uniform default). */
static double default_tol(const char *prog, const char *spec)
{
    cfpo_options o;
    cfpo_options_init(&o);
    cfpo_density d;
    char err[512];
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    const double tol = cfpo_engines_default_tol(o.variant, &d);
    cfpo_density_free(&d);
    return tol;
}

/* seconds of iterations FIRST_IT..LAST_IT of one run */
static double one_run(const char *prog, int64_t n, int threads, uint64_t seed, const char *spec, double tol,
                      double *xy)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.threads = threads;
    o.seed = seed;
    o.tol = tol;
    o.max_iter = LAST_IT;
    o.lazy_measure = 1; /* as the command measures when it shows no progress */
    double sum = 0;
    o.progress = on_iter;
    o.user = &sum;
    cfpo_result r;
    char err[512];
    if (cfpo_sample_density(n, &o, spec, xy, &r, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    if (r.iterations < LAST_IT)
        cli_fail(prog, "the run on '%s' stopped after %d iterations, before iteration %d", spec, r.iterations, LAST_IT);
    return sum;
}

int bench_contrast(const char *prog, int64_t n, int threads, int rounds, int seeds, const char *density,
                   const char *reference)
{
    double *xy = malloc((size_t)n * 2 * sizeof *xy), *a = malloc((size_t)rounds * sizeof *a);
    double *b = malloc((size_t)rounds * sizeof *b), *ratio = malloc((size_t)rounds * sizeof *ratio);
    if (!xy || !a || !b || !ratio) cli_fail(prog, "out of memory for %lld points", (long long)n);
    const double its = (double)(seeds * (LAST_IT - FIRST_IT + 1));
    const double tol_d = default_tol(prog, density), tol_r = default_tol(prog, reference);
    for (int k = 0; k < rounds; k++) {
        a[k] = b[k] = 0;
        for (int s = 1; s <= seeds; s++) {
            /* alternate which density runs first: a drift of the machine's
             * speed within a round falls on both alike */
            const int first = (k + s) % 2;
            for (int w = 0; w < 2; w++) {
                const int dens = w == first;
                const double t = one_run(prog, n, threads, (uint64_t)s, dens ? density : reference,
                                         dens ? tol_d : tol_r, xy);
                if (dens) a[k] += t;
                else b[k] += t;
            }
        }
        ratio[k] = a[k] / b[k];
        fprintf(stderr, "cfpo-bench: contrast round %d of %d: %.4f ms against %.4f ms an iteration, ratio %.4f\n",
                k + 1, rounds, a[k] / its * 1e3, b[k] / its * 1e3, ratio[k]);
    }
    /* quantile() sorts: the minima (the runs least disturbed by the
     * machine, which can only add time) are the first after it */
    const double ma = quantile(a, rounds, 0.5) / its * 1e3, mb = quantile(b, rounds, 0.5) / its * 1e3;
    const double ba = a[0] / its * 1e3, bb = b[0] / its * 1e3;
    const double q1 = quantile(ratio, rounds, 0.25), q2 = quantile(ratio, rounds, 0.5), q3 = quantile(ratio, rounds, 0.75);
    printf("RESULT contrast n=%lld threads=%d rounds=%d seeds=%d iterations=%d-%d density=%s reference=%s "
           "ms_per_iteration=%.4f reference_ms_per_iteration=%.4f ratio=%.4f ratio_q1=%.4f ratio_q3=%.4f "
           "best_ms_per_iteration=%.4f best_reference_ms_per_iteration=%.4f ratio_of_best=%.4f\n",
           (long long)n, threads, rounds, seeds, FIRST_IT, LAST_IT, density, reference, ma, mb, q2, q1, q3, ba, bb,
           ba / bb);
    free(xy);
    free(a);
    free(b);
    free(ratio);
    return 0;
}
