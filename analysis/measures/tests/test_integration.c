/* test_integration.c - UTK's integration test with exact ground truth:
 * the Gaussian integrals against a brute-force midpoint rule on 512^2,
 * 1024^2 and 2048^2 grids, Richardson-extrapolated (1e-9); the Heaviside
 * areas against the vertex formula of the literature (1e-13) and against
 * counting the cells of a 4096^2 grid; white noise: the MSE is the mean of
 * (int f^2 - I^2) / n within its statistical error (16 sets); jittered
 * points far below it; the same bytes for 1 and 2 threads. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "integration.h"
#include "omp_compat.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

static double midpoint(const an_integ_fn *f, int N)
{
    double s = 0;
    for (int i = 0; i < N; i++) {
        double r = 0;
        for (int j = 0; j < N; j++) r += an_integ_value(f, (i + 0.5) / N, (j + 0.5) / N);
        s += r;
    }
    return s / ((double)N * N);
}

/* the area below a line: sum over the square's corners v of
 * (-1)^(zeros of v) max(nu.v + r, 0)^2 / (2 nu_x nu_y) */
static double vertex_formula(const an_integ_fn *f)
{
    double s = 0;
    for (int v = 0; v < 4; v++) {
        const int vx = v & 1, vy = v >> 1, zeros = 2 - vx - vy;
        const double e = f->nx * vx + f->ny * vy + f->r;
        if (e > 0) s += (zeros % 2 ? -1 : 1) * e * e;
    }
    return s / (2 * f->nx * f->ny);
}

int main(void)
{
    an_integ_fn f;
    double worst = 0;
    for (int m = 0; m < 8; m++) {
        an_integ_draw(1, AN_INTEG_SEED, m, &f);
        const double I1 = midpoint(&f, 512), I2 = midpoint(&f, 1024), I3 = midpoint(&f, 2048);
        const double R1 = (4 * I2 - I1) / 3, R2 = (4 * I3 - I2) / 3, R = (16 * R2 - R1) / 15;
        const double t = an_integ_truth(&f), d = fabs(t - R);
        if (d > worst) worst = d;
        CHECK(d < 1e-9, "gauss %d: truth %.15g, grid %.15g", m, t, R);
    }
    printf("Gaussian: largest |truth - grid quadrature| over 8 integrands %.2e\n", worst);
    worst = 0;
    for (int m = 0; m < 200; m++) {
        an_integ_draw(0, AN_INTEG_SEED, m, &f);
        if (fabs(f.nx) < 1e-3 || fabs(f.ny) < 1e-3) continue;
        const double d = fabs(an_integ_truth(&f) - vertex_formula(&f));
        if (d > worst) worst = d;
    }
    CHECK(worst < 1e-13, "Heaviside: area against the vertex formula %.3g", worst);
    double gworst = 0;
    for (int m = 0; m < 4; m++) {
        an_integ_draw(0, AN_INTEG_SEED, m, &f);
        const double d = fabs(an_integ_truth(&f) - midpoint(&f, 4096));
        if (d > gworst) gworst = d;
    }
    CHECK(gworst < 1e-5, "Heaviside: area against 4096^2 cells %.3g", gworst);
    printf("Heaviside: against the vertex formula %.2e (200 lines), against 4096^2 cells %.2e\n", worst, gworst);

    /* white noise: E MSE = (1/M) sum_m (int f_m^2 - I_m^2) / n */
    const int M = 256;
    const size_t n = 1024;
    double want[2] = {0, 0};
    for (int m = 0; m < M; m++)
        for (int g = 0; g < 2; g++) {
            an_integ_draw(g, AN_INTEG_SEED, m, &f);
            const double I = an_integ_truth(&f);
            want[g] += (an_integ_truth_sq(&f) - I * I) / (double)n / M;
        }
    double *xy = malloc(2 * n * sizeof *xy);
    double s1[2] = {0, 0}, s2[2] = {0, 0};
    const int sets = 16;
    an_integration r;
    for (int s = 0; s < sets; s++) {
        set_white(xy, n, 500 + (uint64_t)s);
        CHECK(an_integration_compute(xy, n, M, AN_INTEG_SEED, &r) == 0, "memory");
        const double v[2] = {r.heaviside_mse, r.gauss_mse};
        for (int g = 0; g < 2; g++) { s1[g] += v[g] / sets; s2[g] += v[g] * v[g] / sets; }
    }
    for (int g = 0; g < 2; g++) {
        const double se = sqrt((s2[g] - s1[g] * s1[g]) / (sets - 1));
        CHECK(fabs(s1[g] - want[g]) < 4 * se, "%s: white-noise MSE %.5g +- %.2g, expected %.5g",
              g ? "gauss" : "heaviside", s1[g], se, want[g]);
        printf("white noise n %zu, %s: MSE %.5g +- %.2g over %d sets, (int f^2 - I^2)/n %.5g\n", n,
               g ? "gauss" : "heaviside", s1[g], se, sets, want[g]);
    }
    set_jittered(xy, 32, 7);
    an_integration_compute(xy, n, M, AN_INTEG_SEED, &r);
    CHECK(r.gauss_mse < 0.05 * want[1] && r.heaviside_mse < 0.2 * want[0],
          "jittered: MSE gauss %.3g heaviside %.3g, white %.3g %.3g", r.gauss_mse, r.heaviside_mse, want[1], want[0]);
    printf("jittered 32 x 32: MSE gauss %.3g (white %.3g), heaviside %.3g (white %.3g)\n", r.gauss_mse, want[1],
           r.heaviside_mse, want[0]);

    an_integration r1, r2;
    memset(&r1, 0, sizeof r1);
    memset(&r2, 0, sizeof r2);
    omp_set_num_threads(1);
    an_integration_compute(xy, n, 100, 9, &r1);
    omp_set_num_threads(2);
    an_integration_compute(xy, n, 100, 9, &r2);
    CHECK(memcmp(&r1, &r2, sizeof r1) == 0, "1 and 2 threads differ");
    free(xy);
    return test_report(passed_, failed_);
}
