/* test_nufft.c - the FFTW path against exact summation: random sets and
 * optimised sets (CFPO from the core library, a jittered lattice), several
 * n and K, must agree within 1e-6 (|P - P_exact| / max(P_exact, 1), and
 * pointwise relative wherever P_exact >= 1e-4); a narrow kernel (width 4)
 * must not, which shows the comparison can fail; the result must not depend
 * on the number of threads, and P(-k) = P(k), P(0) = n. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "omp_compat.h"
#include "power.h"
#include "testsets.h"
#include "testutil.h"

static int passed_, failed_;

static double pointwise(const double *P, const double *Q, int K)
{
    double worst = 0;
    for (size_t t = 0; t < an_side(K) * an_side(K); t++)
        if (Q[t] >= 1e-4) worst = fmax(worst, fabs(P[t] - Q[t]) / Q[t]);
    return worst;
}

static void compare(const char *what, const double *xy, size_t n, int K)
{
    char err[256];
    const size_t N = an_side(K) * an_side(K);
    double *P = malloc(N * sizeof *P), *Q = malloc(N * sizeof *Q);
    int ok = an_power_nufft(xy, n, K, 0, P, NULL, err, sizeof err) == 0 &&
             an_power_exact(xy, n, K, Q, NULL, NULL, err, sizeof err) == 0;
    CHECK(ok, "%s: %s", what, err);
    double d = an_power_maxdiff(P, Q, K), pw = pointwise(P, Q, K);
    printf("%-22s n=%-5zu K=%-3d maxdiff %.2e pointwise %.2e\n", what, n, K, d, pw);
    CHECK(d <= 1e-6 && pw <= 1e-6, "%s n=%zu K=%d: maxdiff %g pointwise %g", what, n, K, d, pw);
    CHECK(fabs(Q[an_pidx(K, 0, 0)] - (double)n) <= 1e-9 * n, "%s: P(0) = %g", what, Q[an_pidx(K, 0, 0)]);
    int sym = 1;
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) sym &= P[an_pidx(K, kx, ky)] == P[an_pidx(K, -kx, -ky)];
    CHECK(sym, "%s: P(-k) != P(k)", what);
    free(P);
    free(Q);
}

static void narrow_kernel_fails(void)
{
    char err[256];
    const int K = 40;
    const size_t n = 2000, N = an_side(K) * an_side(K);
    double *xy = ts_uniform(n, 77), *P = malloc(N * sizeof *P), *Q = malloc(N * sizeof *Q);
    an_power_nufft(xy, n, K, 4, P, NULL, err, sizeof err);
    an_power_exact(xy, n, K, Q, NULL, NULL, err, sizeof err);
    double d = an_power_maxdiff(P, Q, K);
    CHECK(d > 1e-6, "width 4 should be visibly less accurate, maxdiff %g", d);
    free(xy); free(P); free(Q);
}

static void threads_do_not_matter(void)
{
    char err[256];
    const int K = 60;
    const size_t n = 3000, N = an_side(K) * an_side(K);
    double *xy = ts_uniform(n, 5), *P1 = malloc(N * sizeof *P1), *P2 = malloc(N * sizeof *P2);
    int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    an_power_nufft(xy, n, K, 0, P1, NULL, err, sizeof err);
    omp_set_num_threads(3);
    an_power_nufft(xy, n, K, 0, P2, NULL, err, sizeof err);
    omp_set_num_threads(saved);
    CHECK(memcmp(P1, P2, N * sizeof *P1) == 0, "NUFFT result depends on the thread count");
    free(xy); free(P1); free(P2);
}

int main(void)
{
    static const size_t ns[] = {1, 3, 100, 1000, 3000};
    static const int Ks[] = {1, 7, 32, 64};
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 4; b++) {
            double *xy = ts_uniform(ns[a], 10 * a + b);
            compare("uniform", xy, ns[a], Ks[b]);
            free(xy);
        }
    /* Optimised sets: little power at low frequencies is the hard case. */
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 11;
    o.threads = 1; /* tiny phases: spinning OpenMP barriers only cost time */
    char err[256];
    cfpo_result res;
    double *xy = malloc(2 * 400 * sizeof *xy);
    CHECK(cfpo_sample(400, &o, xy, &res, err, sizeof err) == 0, "cfpo_sample: %s", err);
    compare("cfpo", xy, 400, 20);
    compare("cfpo", xy, 400, 80);
    free(xy);
    xy = ts_lattice(40, 0.5, 0.5);
    ts_jitter(xy, 1600, 0.3 / 40, 9);
    compare("jittered lattice", xy, 1600, 50);
    free(xy);
    narrow_kernel_fails();
    threads_do_not_matter();
    return test_report(passed_, failed_);
}
