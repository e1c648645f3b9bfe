/* test_pcf.c - the pair correlation g(r): the cell-grid sum against the
 * O(n^2) double loop with a direct exp per term at 4,096 points (1e-9
 * relative, several sigma and rmax, and on small sets where the plain loop
 * or a 3 x 3 grid is used); the same bytes for 1 and 2 threads; white
 * noise: g = 1 within its statistical error (the mean over r in [1, 3]
 * Delta of 8 sets); a CFPO set: g = 0 exactly below delta_min - 6 sigma,
 * and a peak above 1 near delta_min. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "nnhist.h"
#include "omp_compat.h"
#include "pcf.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

static void against_brute(const char *what, const double *xy, size_t n, double sigma, double rmax)
{
    const int B = an_pcf_bins(n, sigma, rmax);
    CHECK(B > 0, "%s: no bins", what);
    if (B <= 0) return;
    double *g = malloc((size_t)B * sizeof *g), *ref = malloc((size_t)B * sizeof *ref);
    CHECK(an_pcf_compute(xy, n, sigma, rmax, B, g) == 0, "%s: out of memory", what);
    an_pcf_brute(xy, n, sigma, B, ref);
    double worst = 0, gmax = 0;
    for (int b = 0; b < B; b++) {
        if (ref[b] > gmax) gmax = ref[b];
        const double d = fabs(g[b] - ref[b]) / (fabs(ref[b]) > 1e-3 ? fabs(ref[b]) : 1e-3);
        if (d > worst) worst = d;
    }
    CHECK(worst <= 1e-9 && gmax > 0.5, "%s (n %zu, sigma %g, rmax %g, %d bins): largest relative difference %.3g",
          what, n, sigma, rmax, B, worst);
    printf("%-10s n %5zu sigma %.3f rmax %.1f bins %4d: max rel diff to brute force %.2e\n", what, n, sigma, rmax, B,
           worst);
    free(g);
    free(ref);
}

int main(void)
{
    const size_t n = 4096;
    double *xy = malloc(2 * n * sizeof *xy);
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 5;
    o.threads = 1;
    cfpo_result res;
    char err[256];
    CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
    against_brute("cfpo", xy, n, AN_PCF_SIGMA, AN_PCF_RMAX);
    against_brute("cfpo", xy, n, 0.1, 5);
    set_white(xy, n, 3);
    against_brute("white", xy, n, AN_PCF_SIGMA, AN_PCF_RMAX);
    against_brute("white", xy, 40, 0.05, 3);  /* plain loop, r cut at 1/2 - 6 sigma */
    against_brute("white", xy, 200, 0.05, 3); /* a 3 x 3 grid */
    /* n = 2: Delta = 0.76, the bins stop below 1/2 / Delta - 6 sigma = 0.358 Delta: 35 */
    CHECK(an_pcf_bins(1, 0.05, 3) == 0 && an_pcf_bins(2, 0.05, 3) == 35, "bins for n = 1, 2: %d, %d",
          an_pcf_bins(1, 0.05, 3), an_pcf_bins(2, 0.05, 3));
    CHECK(an_pcf_bins(4096, 0.05, 3) == 300, "bins for 4096: %d", an_pcf_bins(4096, 0.05, 3));

    /* same bytes for any number of threads */
    const int B = an_pcf_bins(n, AN_PCF_SIGMA, AN_PCF_RMAX);
    double *g1 = malloc((size_t)B * sizeof *g1), *g2 = malloc((size_t)B * sizeof *g2);
    omp_set_num_threads(1);
    an_pcf_compute(xy, n, AN_PCF_SIGMA, AN_PCF_RMAX, B, g1);
    omp_set_num_threads(2);
    an_pcf_compute(xy, n, AN_PCF_SIGMA, AN_PCF_RMAX, B, g2);
    CHECK(memcmp(g1, g2, (size_t)B * sizeof *g1) == 0, "1 and 2 threads differ");

    /* white noise: E g(r) = 1 for r >= 6 sigma; the mean over r in [1, 3]
     * Delta of 8 sets of 4,096 points. Its standard error: the bins share
     * pairs, so it is taken from the scatter of the 8 set means. */
    double m[8], mm = 0, sd = 0;
    for (int s = 0; s < 8; s++) {
        set_white(xy, n, 100 + (uint64_t)s);
        an_pcf_compute(xy, n, AN_PCF_SIGMA, AN_PCF_RMAX, B, g1);
        m[s] = 0;
        int c = 0;
        for (int b = 100; b <= 300; b++) { m[s] += g1[b - 1]; c++; }
        m[s] /= c;
        mm += m[s] / 8;
    }
    for (int s = 0; s < 8; s++) sd += (m[s] - mm) * (m[s] - mm) / 7;
    const double se = sqrt(sd / 8);
    CHECK(fabs(mm - 1) <= 4 * se && se < 0.01, "white noise: mean g over [1, 3] Delta %.5f +- %.5f", mm, se);
    printf("white noise: mean g(r) over r in [1, 3] Delta, 8 sets: %.5f +- %.5f\n", mm, se);

    /* CFPO: no pair closer than delta_min */
    CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
    an_nn nn;
    uint64_t hist[AN_NN_BINS] = {0};
    CHECK(an_nn_compute(xy, n, &nn, hist) == 0, "nn");
    an_pcf_compute(xy, n, AN_PCF_SIGMA, AN_PCF_RMAX, B, g1);
    const double h = AN_PCF_SIGMA / 5;
    int zero = 1, below = 0;
    double peak = 0, peak_r = 0;
    for (int b = 1; b <= B; b++) {
        const double r = b * h;
        if (r < nn.delta_min - AN_PCF_CUT * AN_PCF_SIGMA) { below++; zero &= g1[b - 1] == 0; }
        if (g1[b - 1] > peak) { peak = g1[b - 1]; peak_r = r; }
    }
    CHECK(zero && below > 50, "cfpo: g not 0 below delta_min %.4f - 6 sigma (%d bins)", nn.delta_min, below);
    CHECK(peak > 1.5 && fabs(peak_r - nn.delta_min) < 0.2, "cfpo: peak %.3f at %.3f, delta_min %.4f", peak, peak_r,
          nn.delta_min);
    printf("cfpo: g = 0 on %d bins below delta_min %.4f - 6 sigma; peak %.3f at r = %.2f Delta\n", below,
           nn.delta_min, peak, peak_r);
    free(nn.nn);
    free(g1);
    free(g2);
    free(xy);
    return test_report(passed_, failed_);
}
