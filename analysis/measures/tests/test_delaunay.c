/* test_delaunay.c - the measures of the periodic Delaunay triangulation:
 * on a hexagonal lattice (stretched to fit the square torus: 26 x 30
 * sites) psi6, the covering radius and the mesh ratio against their values
 * from the lattice's geometry, the Voronoi area variance 0; the covering
 * radius and delta_min on small sets against the brute force (the largest
 * empty circumcircle over all triples of points and their periodic
 * images); white noise against the published and known values (psi6 0.365
 * as psa publishes; Voronoi area variance 0.280, the Poisson-Voronoi
 * value); duplicates refused. */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "delaunay.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

/* Largest empty circumcircle and smallest distance, by brute force. */
static void brute(const double *xy, size_t n, double *cover, double *dmin)
{
    const size_t m = 9 * n;
    double *im = malloc(2 * m * sizeof *im);
    for (size_t i = 0; i < n; i++)
        for (int s = 0; s < 9; s++) {
            im[2 * (9 * i + s)] = xy[2 * i] + (s % 3 - 1);
            im[2 * (9 * i + s) + 1] = xy[2 * i + 1] + (s / 3 - 1);
        }
    double best = 0, d2min = INFINITY;
    for (size_t i = 0; i < n; i++) {
        const double px = xy[2 * i], py = xy[2 * i + 1];
        for (size_t j = 0; j < m; j++) {
            const double ax = im[2 * j] - px, ay = im[2 * j + 1] - py;
            const double a2 = ax * ax + ay * ay;
            if (a2 == 0 || a2 > 0.25) continue;
            if (a2 < d2min) d2min = a2;
            for (size_t k = j + 1; k < m; k++) {
                const double bx = im[2 * k] - px, by = im[2 * k + 1] - py, b2 = bx * bx + by * by;
                if (b2 == 0 || b2 > 0.25) continue;
                const double d = 2 * (ax * by - ay * bx);
                if (fabs(d) < 1e-14) continue;
                const double ux = (by * a2 - ay * b2) / d, uy = (ax * b2 - bx * a2) / d, r2 = ux * ux + uy * uy;
                if (r2 <= best * best || r2 > 0.0625) continue;
                int empty = 1;
                for (size_t q = 0; q < m && empty; q++) {
                    const double qx = im[2 * q] - px - ux, qy = im[2 * q + 1] - py - uy;
                    if (qx * qx + qy * qy < r2 * (1 - 1e-12)) empty = 0;
                }
                if (empty) best = sqrt(r2);
            }
        }
    }
    *cover = best;
    *dmin = sqrt(d2min);
    free(im);
}

int main(void)
{
    char err[256];
    an_delaunay D;

    /* the lattice: columns of a = 1/26, rows of b = 1/30, odd rows shifted by a/2 */
    const int cols = 26, rows = 30;
    const size_t nl = (size_t)cols * rows;
    double *xy = malloc(2 * 65536 * sizeof *xy);
    for (int j = 0; j < rows; j++)
        for (int i = 0; i < cols; i++) {
            xy[2 * (j * cols + i)] = (i + 0.5 * (j % 2)) / cols;
            xy[2 * (j * cols + i) + 1] = (double)j / rows;
        }
    CHECK(an_delaunay_compute(xy, nl, &D, err, sizeof err) == 0, "lattice: %s", err);
    const double a = 1.0 / cols, b = 1.0 / rows;
    const double e[6][2] = {{a, 0}, {a / 2, b}, {-a / 2, b}, {-a, 0}, {-a / 2, -b}, {a / 2, -b}};
    double complex z = 0;
    for (int k = 0; k < 6; k++) z += cexp(6 * I * atan2(e[k][1] - e[(k + 1) % 6][1], e[k][0] - e[(k + 1) % 6][0]));
    const double psi = cabs(z) / 6, side = sqrt(a * a / 4 + b * b);
    const double R = side * side / (2 * b), dmin = side < a ? side : a;
    CHECK(fabs(D.psi6 - psi) < 1e-12 && psi > 0.9999, "lattice psi6 %.15g, geometry %.15g", D.psi6, psi);
    CHECK(fabs(D.covering - R) < 1e-12 * R, "lattice covering %.15g, geometry %.15g", D.covering, R);
    CHECK(fabs(D.delta_min - dmin) < 1e-12, "lattice delta_min %.15g, geometry %.15g", D.delta_min, dmin);
    CHECK(fabs(D.mesh_ratio - 2 * R / dmin) < 1e-11 && fabs(D.mesh_ratio - 2 / sqrt(3)) < 2e-3,
          "lattice mesh ratio %.15g, geometry %.15g (hexagonal 2/sqrt 3)", D.mesh_ratio, 2 * R / dmin);
    CHECK(fabs(D.area_var) < 1e-12, "lattice Voronoi area variance %.3g", D.area_var);
    printf("lattice 26 x 30: psi6 %.12f (geometry %.12f), mesh ratio %.12f (geometry %.12f; 2/sqrt3 %.6f), "
           "area var %.1e\n", D.psi6, psi, D.mesh_ratio, 2 * R / dmin, 2 / sqrt(3), D.area_var);

    /* small sets against the brute force */
    for (int t = 0; t < 3; t++) {
        size_t n = 36;
        if (t == 0) set_jittered(xy, 6, 41);
        if (t == 1) set_jittered(xy, 7, 42), n = 49;
        if (t == 2) {
            cfpo_options o;
            cfpo_options_init(&o);
            o.seed = 43;
            o.threads = 1;
            cfpo_result res;
            n = 50;
            CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
        }
        double cover, dm;
        brute(xy, n, &cover, &dm);
        CHECK(an_delaunay_compute(xy, n, &D, err, sizeof err) == 0, "set %d: %s", t, err);
        CHECK(fabs(D.covering - cover) < 1e-12 && fabs(D.delta_min - dm) < 1e-13,
              "set %d (n %zu): covering %.15g brute %.15g, delta_min %.15g brute %.15g", t, n, D.covering, cover,
              D.delta_min, dm);
        CHECK(fabs(D.mesh_ratio - 2 * cover / dm) < 1e-11, "set %d: mesh ratio", t);
        printf("set %d (n %2zu): covering radius %.12f (brute force %.12f), delta_min %.12f (%.12f)\n", t, n,
               D.covering, cover, D.delta_min, dm);
    }

    /* white noise, 4 sets of 65,536 points */
    double psi6 = 0, av = 0;
    for (int s = 0; s < 4; s++) {
        set_white(xy, 65536, 60 + (uint64_t)s);
        CHECK(an_delaunay_compute(xy, 65536, &D, err, sizeof err) == 0, "white: %s", err);
        psi6 += D.psi6 / 4;
        av += D.area_var / 4;
    }
    CHECK(fabs(psi6 - 0.365) < 0.003, "white noise psi6 %.4f, published 0.365", psi6);
    CHECK(fabs(av - 0.280) < 0.005, "white noise Voronoi area variance %.4f, Poisson-Voronoi 0.280", av);
    printf("white noise (4 x 65,536): psi6 %.4f (psa: 0.365), Voronoi area variance %.4f (Poisson-Voronoi 0.280)\n",
           psi6, av);

    /* bad input */
    xy[2] = xy[0];
    xy[3] = xy[1];
    CHECK(an_delaunay_compute(xy, 100, &D, err, sizeof err) != 0, "duplicates accepted");
    printf("duplicates: %s\n", err);
    set_white(xy, 5, 1);
    CHECK(an_delaunay_compute(xy, 5, &D, err, sizeof err) != 0, "5 points accepted");
    printf("5 points: %s\n", err);
    free(xy);
    return test_report(passed_, failed_);
}
