/* test_quality.c - converged CFPO sets reach the quality of FPO.
 *
 * Five seeds of 4096 points, default tolerance: each must converge with
 * delta_min >= 0.92 and delta_avg >= 0.928 (measured independently of the
 * engine, by brute force over all pairs). The simplified variant is
 * reported, not held to those numbers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "geom.h"
#include "testutil.h"

static int passed_, failed_;

static void brute(const double *xy, int n, double *dmin, double *davg)
{
    double mn = INFINITY, sum = 0;
    for (int i = 0; i < n; i++) {
        double b = INFINITY;
        for (int j = 0; j < n; j++)
            if (j != i) b = fmin(b, cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]));
        mn = fmin(mn, sqrt(b));
        sum += sqrt(b);
    }
    *dmin = mn / cfpo_delta_bound(n);
    *davg = sum / n / cfpo_delta_bound(n);
}

int main(void)
{
    const int n = 4096;
    double *xy = malloc(2 * n * sizeof *xy);
    for (int variant = 0; variant < 3; variant++)
        for (int seed = 1; seed <= 5; seed++) {
            cfpo_options o;
            cfpo_options_init(&o);
            o.seed = (uint64_t)seed;
            o.variant = variant;
            char err[256];
            cfpo_result r;
            if (cfpo_sample(n, &o, xy, &r, err, sizeof err) != 0) {
                fprintf(stderr, "%s\n", err);
                return 1;
            }
            double dmin, davg;
            brute(xy, n, &dmin, &davg);
            printf("%-10s seed %d: %4d iterations, converged %s, delta_min %.4f, delta_avg %.4f\n",
                   cfpo_variant_name(variant), seed, r.iterations, r.converged ? "yes" : "no",
                   dmin, davg);
            if (variant != CFPO_VARIANT_SIMPLIFIED) {
                CHECK(r.converged, "seed %d did not converge", seed);
                CHECK(dmin >= 0.92, "seed %d: delta_min %.4f < 0.92", seed, dmin);
                CHECK(davg >= 0.928, "seed %d: delta_avg %.4f < 0.928", seed, davg);
                /* delta_avg is an exact sum in units of Delta / 2^24 */
                CHECK(fabs(dmin - r.delta_min) < 1e-12 && fabs(davg - r.delta_avg) < 4e-8,
                      "seed %d: engine reports %.6f/%.6f, brute force %.6f/%.6f", seed,
                      r.delta_min, r.delta_avg, dmin, davg);
            }
        }
    free(xy);
    return test_report(passed_, failed_);
}
