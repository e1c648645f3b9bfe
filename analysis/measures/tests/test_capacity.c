/* test_capacity.c - capacities (analysis/capacity.h) from the periodic
 * Delaunay triangulation's Voronoi cells (delaunay.h):
 *  - a polygon's integral: an axis-parallel rectangle against the exact
 *    sum of pixel overlaps, a triangle crossing the torus' edges against
 *    a 4000 x 4000 midpoint rule of the wrapped density;
 *  - the cells tile the torus: the capacities sum to 1 to 1e-12, on a
 *    random density with random and jittered sets;
 *  - rho = 1: every capacity is its cell's area and the deviation is
 *    sqrt(Voronoi area variance) of the Delaunay measures, to 1e-9;
 *  - brute force: 60 points on an 8 x 6 random density, each of 2000 x
 *    2000 sample points assigned to its nearest point (torus), rho summed:
 *    every capacity within 2e-4 of it (the sampling's own error, about
 *    the cells' perimeter over 2000 samples, is near 3e-5). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "capacity.h"
#include "delaunay.h"
#include "density.h"
#include "geom.h"
#include "sets.h"
#include "testdensity.h"
#include "testutil.h"

static int passed_, failed_;

static double wrapped_rho(const cfpo_density *d, double x, double y)
{
    return cfpo_density_at(d, cfpo_wrap01(x), cfpo_wrap01(y));
}

static void test_polygons(void)
{
    cfpo_density d;
    test_density_random(&d, 7, 5, 1);
    /* rectangle [0.13, 0.71] x [0.22, 0.9]: sum of overlaps */
    const double x0 = 0.13, x1 = 0.71, y0 = 0.22, y1 = 0.9, rect[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    double want = 0;
    for (int j = 0; j < d.h; j++)
        for (int i = 0; i < d.w; i++) {
            const double ox = fmin(x1, (i + 1.0) / d.w) - fmax(x0, (double)i / d.w);
            const double oy = fmin(y1, (j + 1.0) / d.h) - fmax(y0, (double)j / d.h);
            if (ox > 0 && oy > 0) want += d.rho[j * d.w + i] * ox * oy;
        }
    const double got = an_capacity_polygon(&d, rect, 4);
    CHECK(fabs(got - want) < 1e-14, "rectangle: %.17g, overlaps %.17g", got, want);
    /* clockwise: the negative */
    const double cw[8] = {x0, y0, x0, y1, x1, y1, x1, y0};
    CHECK(fabs(an_capacity_polygon(&d, cw, 4) + want) < 1e-14, "clockwise rectangle");
    /* a triangle across both edges */
    const double tri[6] = {-0.2, -0.1, 0.35, 0.05, 0.1, 0.4};
    const int N = 4000;
    double s = 0;
    for (int b = 0; b < N; b++)
        for (int a = 0; a < N; a++) {
            const double x = -0.25 + 0.65 * (a + 0.5) / N, y = -0.15 + 0.6 * (b + 0.5) / N;
            int in = 1;
            for (int e = 0; e < 3 && in; e++) {
                const double *p = tri + 2 * e, *q = tri + 2 * ((e + 1) % 3);
                in = (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]) >= 0;
            }
            if (in) s += wrapped_rho(&d, x, y);
        }
    s *= 0.65 * 0.6 / ((double)N * N);
    const double t = an_capacity_polygon(&d, tri, 3);
    CHECK(fabs(t - s) < 2e-4 * s, "triangle across the edges: %.9g, midpoint rule %.9g", t, s);
    cfpo_density_free(&d);
}

static double *capacities(const cfpo_density *d, const double *xy, size_t n, an_delaunay *dt)
{
    an_vcells c;
    char err[256];
    if (an_delaunay_compute_cells(xy, n, dt, &c, err, sizeof err) != 0) {
        CHECK(0, "%s", err);
        return NULL;
    }
    double *cap = malloc(n * sizeof *cap);
    CHECK(an_capacity_compute(d, &c, cap) == 0, "out of memory");
    an_vcells_free(&c);
    return cap;
}

static void test_tiling(void)
{
    cfpo_density d;
    test_density_random(&d, 64, 48, 2);
    double xy[2 * 4096];
    for (int k = 0; k < 2; k++) {
        const size_t n = k ? 4096 : 1000;
        if (k) set_jittered(xy, 64, 3);
        else set_white(xy, n, 4);
        an_delaunay dt;
        double *cap = capacities(&d, xy, n, &dt), s = 0;
        if (!cap) continue;
        for (size_t i = 0; i < n; i++) s += cap[i];
        CHECK(fabs(s - 1) < 1e-12, "%s: capacities sum to 1 + %.3g", k ? "jittered" : "white", s - 1);
        free(cap);
    }
    cfpo_density_free(&d);
}

static void test_uniform(void)
{
    cfpo_density d;
    const double one = 1;
    char err[256];
    CHECK(cfpo_density_from_values(&one, 1, 1, "one", &d, err, sizeof err) == 0, "%s", err);
    double xy[2 * 2000];
    set_white(xy, 2000, 5);
    an_delaunay dt;
    double *cap = capacities(&d, xy, 2000, &dt);
    if (cap) {
        const double dev = an_capacity_deviation(cap, 2000);
        CHECK(fabs(dev - sqrt(dt.area_var)) < 1e-9 * dev, "rho = 1: deviation %.12g, sqrt(area variance) %.12g",
              dev, sqrt(dt.area_var));
    }
    free(cap);
    cfpo_density_free(&d);
}

static void test_brute(void)
{
    cfpo_density d;
    test_density_random(&d, 8, 6, 6);
    enum { n = 60, N = 2000 };
    double xy[2 * n], bf[n] = {0};
    set_white(xy, n, 7);
    for (int b = 0; b < N; b++)
        for (int a = 0; a < N; a++) {
            const double x = (a + 0.5) / N, y = (b + 0.5) / N;
            int best = 0;
            double bd = INFINITY;
            for (int i = 0; i < n; i++) {
                const double d2 = cfpo_torus_dist2(x, y, xy[2 * i], xy[2 * i + 1]);
                if (d2 < bd) bd = d2, best = i;
            }
            bf[best] += cfpo_density_at(&d, x, y) / ((double)N * N);
        }
    an_delaunay dt;
    double *cap = capacities(&d, xy, n, &dt), mx = 0;
    if (cap) {
        for (int i = 0; i < n; i++) mx = fmax(mx, fabs(cap[i] - bf[i]));
        CHECK(mx < 2e-4, "brute force: largest difference %.3g", mx);
    }
    free(cap);
    cfpo_density_free(&d);
}

int main(void)
{
    test_polygons();
    test_tiling();
    test_uniform();
    test_brute();
    return test_report(passed_, failed_);
}
