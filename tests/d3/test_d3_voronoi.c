/* test_d3_voronoi.c - the 3-D Voronoi cells (measures3_vor.h) on lattices
 * whose cells are known: FCC (rhombic dodecahedra, 12 faces), BCC
 * (truncated octahedra, 14 faces), simple cubic (cubes, 6 faces; its
 * Delaunay cells are degenerate, the zero-area faces not counted), each of
 * volume 1/n, centroid the point itself; on random sets the volumes sum to
 * 1, the mean face count is about 15.54 (Poisson-Voronoi), and a cell's
 * centroid lies within its own cell (nearer its point than any other).
 * The FPD certificate (measures3_fpd.h): every point of FCC and BCC passes
 * (violation 0 to rounding); one FCC point moved by 3% of the spacing
 * fails it, and so does white noise, whose worst point can move far. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "measures3_fpd.h"
#include "measures3_vor.h"
#include "nn3.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

static size_t lattice(double *p, int kind, int side, double shift)
{
    static const double fcc[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    static const double bcc[2][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}};
    const int nb = kind == 0 ? 4 : kind == 1 ? 2 : 1;
    size_t n = 0;
    for (int z = 0; z < side; z++)
        for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++)
                for (int b = 0; b < nb; b++) {
                    const double *o = kind == 0 ? fcc[b] : kind == 1 ? bcc[b] : fcc[0];
                    p[3 * n] = (x + o[0] + shift) / side, p[3 * n + 1] = (y + o[1] + shift) / side;
                    p[3 * n + 2] = (z + o[2] + shift) / side;
                    n++;
                }
    return n;
}

static void check_lattice(const char *name, int kind, int side, int want)
{
    double *p = malloc(3 * 4 * (size_t)side * side * side * sizeof *p);
    const size_t n = lattice(p, kind, side, 0.25);
    int *f = malloc(n * sizeof *f);
    double *v = malloc(n * sizeof *v), *c = malloc(3 * n * sizeof *c);
    char err[200];
    CHECK(cfpo3_voronoi(p, n, f, v, c, err, sizeof err) == 0, "%s: %s", name, err);
    int badf = 0;
    double dv = 0, dc = 0;
    for (size_t i = 0; i < n; i++) {
        badf += f[i] != want;
        dv = fmax(dv, fabs(v[i] * (double)n - 1));
        for (int a = 0; a < 3; a++) dc = fmax(dc, fabs(cfpo3_pdiff(c[3 * i + a], p[3 * i + a])));
    }
    CHECK(badf == 0, "%s: %d cells without %d faces (first %d)", name, badf, want, f[0]);
    CHECK(dv < 1e-9, "%s: cell volumes off 1/n by %.3g relative", name, dv);
    CHECK(dc < 1e-9, "%s: centroids off their points by %.3g", name, dc);
    printf("%s (%zu points): %d faces, volume n V - 1 = %.2g\n", name, n, f[0], dv);
    free(p), free(f), free(v), free(c);
}

int main(void)
{
    check_lattice("FCC", 0, 4, 12);
    check_lattice("BCC", 1, 5, 14);
    check_lattice("SC", 2, 6, 6);
    const size_t n = 2000;
    double *p = malloc(3 * n * sizeof *p), *v = malloc(n * sizeof *v), *c = malloc(3 * n * sizeof *c);
    int *f = malloc(n * sizeof *f);
    for (size_t i = 0; i < 3 * n; i++) p[i] = cfpo_rand01(7, 11, i);
    char err[200];
    CHECK(cfpo3_voronoi(p, n, f, v, c, err, sizeof err) == 0, "white: %s", err);
    double sv = 0, sf = 0;
    for (size_t i = 0; i < n; i++) sv += v[i], sf += f[i];
    CHECK(fabs(sv - 1) < 1e-9, "white: volumes sum to %.12f", sv);
    CHECK(fabs(sf / n - 15.535) < 0.3, "white: mean faces %.3f, Poisson-Voronoi 15.535", sf / n);
    /* the centroid lies in its own cell: no other point nearer to it */
    int outside = 0;
    for (size_t i = 0; i < n; i += 7) {
        double di = 0;
        for (int a = 0; a < 3; a++) di += pow(cfpo3_pdiff(c[3 * i + a], p[3 * i + a]), 2);
        for (size_t j = 0; j < n; j++) {
            double dj = 0;
            for (int a = 0; a < 3; a++) dj += pow(cfpo3_pdiff(c[3 * i + a], p[3 * j + a]), 2);
            if (j != i && dj < di - 1e-15) {
                outside++;
                break;
            }
        }
    }
    CHECK(outside == 0, "white: %d centroids outside their cells", outside);
    /* the certificate */
    {
        double *q = malloc(3 * 256 * sizeof *q);
        cfpo3_fpd_result fr;
        size_t m = lattice(q, 0, 4, 0.25);
        CHECK(cfpo3_fpd_certify(q, m, &fr, NULL, err, sizeof err) == 0 && fr.passed == m && fabs(fr.max_violation) < 1e-9,
              "FCC certified (%zu of %zu, violation %.3g)", fr.passed, m, fr.max_violation);
        m = lattice(q, 1, 5, 0.25);
        CHECK(cfpo3_fpd_certify(q, m, &fr, NULL, err, sizeof err) == 0 && fr.passed == m && fr.max_violation < 1e-9,
              "BCC certified (%zu of %zu, violation %.3g)", fr.passed, m, fr.max_violation);
        m = lattice(q, 0, 4, 0.25);
        q[3 * 17] += 0.03 * 0.25 / sqrt(2.0);
        double each[256], top = -INFINITY;
        int far_bad = 0;
        CHECK(cfpo3_fpd_certify(q, m, &fr, each, err, sizeof err) == 0 && fr.passed < m && fr.max_violation > 1e-3,
              "FCC with a moved point: %zu of %zu pass, violation %.3g", fr.passed, m, fr.max_violation);
        /* every point's violation: the largest is the summary's; the moved
         * point's is above 1e-3; a point farther than 0.3 from it keeps its
         * lattice hole (radius = its distance) and its violation is 0 */
        for (size_t i = 0; i < m; i++) {
            if (each[i] > top) top = each[i];
            double d2 = 0;
            for (int a = 0; a < 3; a++) d2 += pow(cfpo3_pdiff(q[3 * i + a], q[3 * 17 + a]), 2);
            if (d2 > 0.09 && !(fabs(each[i]) < 1e-9)) far_bad++;
        }
        CHECK(top == fr.max_violation && each[17] > 1e-3 && far_bad == 0,
              "per point: max %.3g (summary %.3g), moved point %.3g, %d far points off 0", top, fr.max_violation,
              each[17], far_bad);
        CHECK(cfpo3_fpd_certify(p, n, &fr, NULL, err, sizeof err) == 0 && fr.passed < n / 10 && fr.max_violation > 0.3,
              "white: %zu of %zu pass, violation %.3g", fr.passed, n, fr.max_violation);
        free(q);
    }
    double dup[6] = {0.1, 0.2, 0.3, 0.1, 0.2, 0.3};
    CHECK(cfpo3_voronoi(dup, 2, NULL, NULL, NULL, err, sizeof err) == -1, "duplicates refused");
    free(p), free(v), free(c), free(f);
    return test_report(passed_, failed_);
}
