/* test_poisson.c - properties of the Poisson-disk baselines, each able to
 * fail:
 *  - DT, BS, Bridson: every pair of points at least r apart on the torus
 *    (all pairs, brute force, the periodic distance);
 *  - BS and Bridson: maximal, i.e. covering radius (the largest empty
 *    circle, exactly, from CGAL's periodic Delaunay triangulation) at most
 *    r up to PD_RHO_EPS; the checker itself rejects a maximal set with one
 *    point taken out, and a square lattice has the known covering radius;
 *  - DT places exactly n points, and stops with saturated = 1 past the
 *    jamming limit;
 *  - the same seed gives the same points, another seed other points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coverage.h"
#include "geom.h"
#include "pd.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

typedef int (*sampler)(const pd_params *, pd_result *, char *, size_t);

static double min_pair_dist2(const double *xy, int64_t n)
{
    double best = INFINITY;
    for (int64_t i = 0; i < n; i++)
        for (int64_t j = i + 1; j < n; j++) {
            double d2 = cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]);
            if (d2 < best) best = d2;
        }
    return best;
}

static pd_result run(sampler f, double r, int64_t target, uint64_t seed, int plain)
{
    pd_params p;
    memset(&p, 0, sizeof p);
    p.seed = seed;
    p.r = r;
    p.target = target;
    p.max_fails = 1000000;
    p.k = 30;
    p.plain = plain;
    p.report_step = 1 << 30;
    pd_result res;
    char err[256];
    if (f(&p, &res, err, sizeof err) != 0) {
        fprintf(stderr, "sampler failed: %s\n", err);
        res.xy = NULL;
        res.n = 0;
    }
    return res;
}

static void check_set(const char *name, sampler f, double rel, int64_t n, uint64_t seed, int maximal)
{
    const double r = rel * cfpo_delta_bound((double)n);
    pd_result a = run(f, r, n, seed, 0);
    CHECK(a.xy && a.n > 1, "%s n=%lld seed=%llu: no set", name, (long long)n, (unsigned long long)seed);
    if (!a.xy) return;
    double d2 = min_pair_dist2(a.xy, a.n);
    CHECK(d2 >= r * r, "%s n=%lld seed=%llu: two points %.17g apart, r = %.17g", name,
          (long long)a.n, (unsigned long long)seed, sqrt(d2), r);
    if (maximal) {
        double R = bl_covering_radius(a.xy, (size_t)a.n);
        CHECK(R > 0 && R <= r * (1.0 + 1e-8), "%s n=%lld seed=%llu: covering radius %.17g > r %.17g",
              name, (long long)a.n, (unsigned long long)seed, R, r);
        /* The checker can fail: without its last point the set is not maximal. */
        double R2 = bl_covering_radius(a.xy, (size_t)a.n - 1);
        CHECK(R2 > r * (1.0 + 1e-6), "%s: covering radius without the last point %.17g <= r %.17g", name, R2, r);
    } else {
        CHECK(a.n == n, "%s: %lld points, wanted %lld", name, (long long)a.n, (long long)n);
    }
    pd_result b = run(f, r, n, seed, 0), c = run(f, r, n, seed + 1, 0);
    CHECK(b.n == a.n && memcmp(a.xy, b.xy, 2 * (size_t)a.n * sizeof(double)) == 0,
          "%s: seed %llu twice gives different sets", name, (unsigned long long)seed);
    CHECK(c.n != a.n || memcmp(a.xy, c.xy, 2 * (size_t)a.n * sizeof(double)) != 0,
          "%s: seeds %llu and %llu give the same set", name, (unsigned long long)seed,
          (unsigned long long)seed + 1);
    free(a.xy);
    free(b.xy);
    free(c.xy);
}

static void check_lattice(void)
{
    const int k = 16;
    double xy[2 * 16 * 16];
    for (int j = 0; j < k; j++)
        for (int i = 0; i < k; i++) xy[2 * (j * k + i)] = (i + 0.5) / k, xy[2 * (j * k + i) + 1] = (j + 0.5) / k;
    double R = bl_covering_radius(xy, (size_t)(k * k)), want = sqrt(0.5) / k;
    CHECK(fabs(R - want) < 1e-12, "square lattice covering radius %.17g, want %.17g", R, want);
}

int main(void)
{
    check_lattice();
    for (uint64_t seed = 1; seed <= 3; seed++) {
        check_set("dart", dart_sample, 0.75, 1500, seed, 0);
        check_set("bs", bs_sample, 0.85, 1500, seed, 1);
        check_set("bridson", bridson_sample, 0.775, 1500, seed, 1);
    }
    /* Few points: the grid windows wrap around the torus. */
    check_set("dart", dart_sample, 0.6, 12, 5, 0);
    check_set("bs", bs_sample, 0.85, 40, 5, 1);
    check_set("bridson", bridson_sample, 0.775, 40, 5, 1);

    /* Past the jamming limit (about 0.777) dart throwing saturates. */
    pd_params p;
    memset(&p, 0, sizeof p);
    p.seed = 1;
    p.target = 2000;
    p.r = 0.82 * cfpo_delta_bound(2000.0);
    p.max_fails = 200000;
    p.report_step = 1 << 30;
    pd_result s;
    char err[256];
    CHECK(dart_sample(&p, &s, err, sizeof err) == 0 && s.saturated == 1 && s.n < 2000 && s.n > 1000,
          "saturation: saturated=%d n=%lld", s.saturated, (long long)s.n);
    CHECK(min_pair_dist2(s.xy, s.n) >= p.r * p.r, "saturated set too close");
    free(s.xy);

    /* Bridson 2007 as published (--plain) still keeps the spacing. */
    pd_result q = run(bridson_sample, 0.775 * cfpo_delta_bound(1500.0), 1500, 7, 1);
    CHECK(min_pair_dist2(q.xy, q.n) >= pow(0.775 * cfpo_delta_bound(1500.0), 2), "plain Bridson spacing");
    free(q.xy);
    return test_report(passed_, failed_);
}
