/* test_certify.c - the FPD certificate.
 *
 * Must pass: square lattices (x removed leaves a hole of radius exactly
 * d(x), every other hole is smaller), two antipodal points, and a set
 * polished by global FPO moves (each failing point moved to the farthest
 * point of the others, the certificate's own `target`) until converged.
 * Must fail: a lattice with one point moved (that point, by about the move),
 * a lattice with two neighbours removed (every point, through the far hole),
 * a jittered lattice, uniform random points, a dart-throwing set, two close
 * points. Exactness against brute force: no sampled point of the torus is
 * farther from X \ {x} than the certificate's radius, and its target point
 * reaches that radius. The two tests (farthest point, Local Characterization
 * Theorem) must reach the same verdict. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certify.h"
#include "cfpo.h"
#include "rng.h"
#include "testsets.h"
#include "testutil.h"

static int passed_, failed_;

static int cert(const double *xy, size_t n, an_certificate *c, double *viol, double *target)
{
    char err[256];
    int r = an_certify(xy, n, AN_CERT_TOL, c, viol, target, err, sizeof err);
    if (r) fprintf(stderr, "%s\n", err);
    return r;
}

static double dist_rest(const double *xy, size_t n, size_t i, double px, double py)
{
    double m = INFINITY;
    for (size_t j = 0; j < n; j++)
        if (j != i) m = fmin(m, cfpo_torus_dist2(px, py, xy[2 * j], xy[2 * j + 1]));
    return sqrt(m);
}

/* The largest empty circle of X \ {x_i} on the torus, from the core's
 * exact solver on the unit square with the 3 x 3 images of the other
 * points (enough while that circle's radius is below 1/2); -1 when it is
 * not. Independent of the certificate's own solvers. */
static double exact_radius(const double *xy, size_t n, size_t i)
{
    const size_t m = 9 * (n - 1);
    double *yx = malloc(m * sizeof *yx), *yy = malloc(m * sizeof *yy);
    double *scratch = malloc(cfpo_solver_scratch(m) * sizeof *scratch);
    size_t k = 0;
    for (size_t j = 0; j < n; j++)
        for (int oy = -1; oy <= 1 && j != i; oy++)
            for (int ox = -1; ox <= 1; ox++) { yx[k] = xy[2 * j] + ox; yy[k] = xy[2 * j + 1] + oy; k++; }
    const cfpo_square S = {0, 0, 1, 1};
    double cx, cy;
    const double r = sqrt(cfpo_local_solve(yx, yy, (int)k, -1, S, 0.5, 0.5, -1, &cx, &cy, scratch));
    free(yx);
    free(yy);
    free(scratch);
    return r < 0.5 ? r : -1;
}

/* Brute force for point i: a G x G grid over the torus must not beat the
 * certificate's radius d(x) + viol, and the target must reach it; for
 * n <= 300, the radius must be the exact one (exact_radius). */
static void brute(const char *what, const double *xy, size_t n, size_t i, double viol, const double *target)
{
    const double D = cfpo_delta_bound((double)n), di = dist_rest(xy, n, i, xy[2 * i], xy[2 * i + 1]);
    const double radius = di + viol * D;
    if (n <= 300) {
        const double r = exact_radius(xy, n, i);
        CHECK(r < 0 || fabs(r - radius) <= 1e-12, "%s point %zu: radius %.17g, exact %.17g", what, i, radius, r);
    }
    const int G = 96;
    double best = 0;
    for (int a = 0; a < G; a++)
        for (int b = 0; b < G; b++) best = fmax(best, dist_rest(xy, n, i, (a + 0.5) / G, (b + 0.5) / G));
    double at = dist_rest(xy, n, i, target[2 * i], target[2 * i + 1]);
    CHECK(best <= radius + 1e-12, "%s point %zu: sampled %g beats the certificate's %g", what, i, best, radius);
    CHECK(fabs(at - radius) <= 1e-9 * D, "%s point %zu: target reaches %g, radius %g", what, i, at, radius);
}

static void expect(const char *what, const double *xy, size_t n, int fpd, double max_pass)
{
    an_certificate c;
    double *viol = malloc(n * sizeof *viol), *target = malloc(2 * n * sizeof *target);
    CHECK(cert(xy, n, &c, viol, target) == 0, "%s: certify failed", what);
    double frac = (double)c.fp_pass / n;
    printf("%-18s n=%-5zu fpd=%d pass %.4f lct %.4f max violation %.4g (P1 %.3g, P2 %.3g)\n", what, n,
           c.fpd, frac, (double)c.lct_pass / n, c.fp_max_violation, c.p1_max_violation, c.p2_max_violation);
    CHECK(c.fpd == fpd, "%s: fpd = %d", what, c.fpd);
    CHECK(frac <= max_pass, "%s: pass fraction %g above %g", what, frac, max_pass);
    CHECK((c.fp_pass == n) == (c.lct_pass == n), "%s: the two tests disagree (%zu vs %zu)", what, c.fp_pass, c.lct_pass);
    brute(what, xy, n, c.fp_worst, viol[c.fp_worst], target);
    brute(what, xy, n, 0, viol[0], target);
    brute(what, xy, n, n - 1, viol[n - 1], target);
    free(viol);
    free(target);
}

static void lattices(void)
{
    double *xy = ts_lattice(12, 0.3, 0.6);
    expect("lattice", xy, 144, 1, 1.0);
    xy[2 * 50] = cfpo_wrap01(xy[2 * 50] + 0.2 / 12);
    an_certificate c;
    double viol[144], target[288];
    cert(xy, 144, &c, viol, target);
    CHECK(!c.fpd && viol[50] > 0.1 && c.fp_worst == 50, "moved point: fpd %d, violation %g, worst %zu", c.fpd, viol[50], c.fp_worst);
    brute("moved point", xy, 144, 50, viol[50], target);
    free(xy);
    /* Two neighbours removed: a hole of radius 1.118 spacing far from most
     * points, which every point could move into (T2, the far field). */
    xy = ts_lattice(12, 0.3, 0.6);
    memmove(xy + 2 * 70, xy + 2 * 72, 2 * (144 - 72) * sizeof *xy);
    expect("lattice with a gap", xy, 142, 0, 0.0);
    free(xy);
    xy = ts_lattice(20, 0.5, 0.5);
    ts_jitter(xy, 400, 0.1 / 20, 3);
    expect("jittered lattice", xy, 400, 0, 0.5);
    free(xy);
}

static void random_sets(void)
{
    double *xy = ts_uniform(500, 8);
    expect("uniform", xy, 500, 0, 0.05);
    free(xy);
    size_t n;
    xy = ts_dart(0.75 * cfpo_delta_bound(600), 20000, 4, &n);
    expect("dart throwing", xy, n, 0, 0.9);
    free(xy);
    double two[4] = {0.1, 0.2, 0.6, 0.7};
    expect("antipodal pair", two, 2, 1, 1.0);
    double close[4] = {0.1, 0.2, 0.15, 0.2};
    expect("close pair", close, 2, 0, 0.0);
}

/* CFPO, then global FPO moves on the failing points until none is left. */
static void polished(void)
{
    const size_t n = 300;
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 5;
    o.threads = 1; /* tiny phases: spinning OpenMP barriers only cost time */
    char err[256];
    cfpo_result res;
    double *xy = malloc(2 * n * sizeof *xy), *viol = malloc(n * sizeof *viol), *target = malloc(2 * n * sizeof *target);
    CHECK(cfpo_sample((int64_t)n, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
    an_certificate c;
    int rounds = 0;
    for (; rounds < 300; rounds++) {
        cert(xy, n, &c, viol, target);
        if (c.fpd) break;
        size_t w = c.fp_worst; /* one move at a time: sequential FPO */
        xy[2 * w] = target[2 * w];
        xy[2 * w + 1] = target[2 * w + 1];
    }
    printf("FPO polish: %d moves\n", rounds);
    expect("FPO-polished", xy, n, 1, 1.0);
    free(xy); free(viol); free(target);
}

/* The theorem's two properties for every point by the core's solver on
 * D(x) and D(x) \ {x} (images collected here, D(x) and S(x) as certify.h
 * defines them): the largest violations / Delta(n) and the pass counts
 * must be the certificate's. Independent of analysis/farthest.c,
 * farsub.c and lct.c's shortcuts. */
static void lct_reference(const char *what, const double *xy, size_t n)
{
    an_certificate c;
    CHECK(cert(xy, n, &c, NULL, NULL) == 0, "%s: certify failed", what);
    const double Dn = cfpo_delta_bound((double)n), tol = AN_CERT_TOL * Dn;
    double *nn = malloc(n * sizeof *nn), *yx = malloc(9 * n * sizeof *yx), *yy = malloc(9 * n * sizeof *yy);
    double *scratch = malloc(cfpo_solver_scratch(9 * n) * sizeof *scratch);
    double delta = INFINITY;
    for (size_t i = 0; i < n; i++) {
        nn[i] = dist_rest(xy, n, i, xy[2 * i], xy[2 * i + 1]);
        delta = fmin(delta, nn[i]);
    }
    double p1max = -INFINITY, p2max = -INFINITY;
    size_t p1pass = 0, p2pass = 0;
    for (size_t i = 0; i < n; i++) {
        const double x = xy[2 * i], y = xy[2 * i + 1];
        const double h = fmax(fmax(3 * delta, delta + nn[i]), Dn) * (1 + 1e-9), e = h - delta;
        const cfpo_square S = {x - e, y - e, x + e, y + e};
        int m = 0, self = -1;
        for (size_t j = 0; j < n; j++)
            for (int oy = -1; oy <= 1; oy++)
                for (int ox = -1; ox <= 1; ox++) {
                    const double X = xy[2 * j] + ox, Y = xy[2 * j + 1] + oy;
                    if (fabs(X - x) > h || fabs(Y - y) > h) continue;
                    if (j == i && ox == 0 && oy == 0) self = m;
                    yx[m] = X;
                    yy[m] = Y;
                    m++;
                }
        double cx, cy;
        const double p1 = sqrt(cfpo_local_solve(yx, yy, m, -1, S, x, y, -1, &cx, &cy, scratch)) - delta;
        const double dY = sqrt(cfpo_min_dist2(x, y, yx, yy, m, self));
        const double p2 = sqrt(cfpo_local_solve(yx, yy, m, self, S, x, y, -1, &cx, &cy, scratch)) - dY;
        p1max = fmax(p1max, p1 / Dn);
        p2max = fmax(p2max, p2 / Dn);
        p1pass += p1 <= tol;
        p2pass += p2 <= tol;
    }
    CHECK(fabs(c.p1_max_violation - p1max) <= 1e-9 && fabs(c.p2_max_violation - p2max) <= 1e-9,
          "%s: theorem's violations %.12g, %.12g; the core's solver %.12g, %.12g", what, c.p1_max_violation,
          c.p2_max_violation, p1max, p2max);
    CHECK(c.p1_pass == p1pass && c.p2_pass == p2pass, "%s: passes %zu, %zu; the core's solver %zu, %zu", what,
          c.p1_pass, c.p2_pass, p1pass, p2pass);
    free(nn);
    free(yx);
    free(yy);
    free(scratch);
}

/* Degenerate sets: exact (brute force agrees). The clustered set and the
 * one of 150 copies of each of two positions put more than AN_FAR_SMALL
 * points in a neighbourhood, so they check the certificate's own solver
 * path (analysis/farthest.c); 1,000 collinear points are refused. */
static void degenerate(void)
{
    const size_t n = 200;
    double *xy = malloc(2 * 1000 * sizeof *xy);
    for (size_t i = 0; i < n; i++) { xy[2 * i] = (double)i / n; xy[2 * i + 1] = 0.5; }
    expect("collinear", xy, n, 0, 0.0);
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = 0.5 + 1e-3 * cfpo_rand01(7, i, 0);
        xy[2 * i + 1] = 0.5 + 1e-3 * cfpo_rand01(7, i, 1);
    }
    expect("clustered", xy, n, 0, 0.0);
    for (size_t i = 0; i < n; i++) { xy[2 * i] = i % 2 ? 0.7 : 0.1; xy[2 * i + 1] = 0.3; }
    expect("duplicated", xy, n, 0, 0.0);
    for (size_t i = 0; i < 300; i++) { xy[2 * i] = i % 2 ? 0.7 : 0.1; xy[2 * i + 1] = 0.3; }
    expect("150 copies of two positions", xy, 300, 0, 0.0);
    /* A diagonal segment that does not wrap: 300 points 1.7e-3 apart in
     * each coordinate (0.51 of the torus). Every point fails (fpd 0, pass
     * 0): d(x) is 2.4e-3, while X \ {x} leaves an empty circle of radius
     * about 0.44 (7.0 Delta(n)) off the gap that the segment leaves on its
     * diagonal, whichever x is taken out. The endpoints' Voronoi cells
     * have a vertex for each point of the segment (the bisectors fan out:
     * about 295), more than VMAX_DIRECT (64) touching points: the
     * hole_radius path of vmax.c, checked against brute force at both
     * ends. */
    for (size_t i = 0; i < 300; i++) { xy[2 * i] = 0.1 + 1.7e-3 * i; xy[2 * i + 1] = 0.3 + 1.7e-3 * i; }
    expect("diagonal segment", xy, 300, 0, 0.0);
    /* A vertical segment, x = 0.5, y from 0.3 to 0.7: the largest empty
     * circle is centred at the torus point (0, 0) and touches the two end
     * points (and their images), so leaving an end point out grows it
     * (T > rho, unlike the diagonal), and the end points' cells reach
     * along the segment's images on both sides (many touching points):
     * vmax.c's hole_radius decides the value at both ends. */
    for (size_t i = 0; i < 200; i++) { xy[2 * i] = 0.5; xy[2 * i + 1] = 0.3 + 0.4 * (double)i / 199; }
    expect("vertical segment", xy, 200, 0, 0.0);
    /* Neighbourhoods of more than AN_FAR_SMALL (128) points that differ
     * from point to point: the theorem by the certificate's own solvers
     * (a few points, property 2 from property 1's answer, the tree)
     * against the core's solver on every D(x). */
    double *big = malloc(2 * 4000 * sizeof *big);
    for (size_t i = 0; i < 4000; i++) { big[2 * i] = (double)i / 4000; big[2 * i + 1] = 0.5; }
    lct_reference("collinear, 4,000", big, 4000);
    for (size_t i = 0; i < 1000; i++) {
        big[2 * i] = 0.5 + 0.03 * cos(6.283185307179586 * (double)i / 1000);
        big[2 * i + 1] = 0.5 + 0.03 * sin(6.283185307179586 * (double)i / 1000);
    }
    lct_reference("circle, 1,000", big, 1000);
    for (size_t i = 0; i < 3000; i++) { big[2 * i] = 0.1 + 1.5e-4 * (double)i; big[2 * i + 1] = 0.3 + 1e-4 * (double)i; }
    lct_reference("segment, 3,000", big, 3000);
    for (size_t i = 0; i < 800; i++) { /* a dense patch: D(x) differs from point to point */
        big[2 * i] = 0.45 + 0.1 * cfpo_rand01(9, i, 0);
        big[2 * i + 1] = 0.45 + 0.1 * cfpo_rand01(9, i, 1);
    }
    lct_reference("uniform patch, 800", big, 800);
    free(big);
    for (size_t i = 0; i < 1000; i++) { xy[2 * i] = (double)i / 1000; xy[2 * i + 1] = 0.5; }
    an_certificate c;
    CHECK(cert(xy, 1000, &c, NULL, NULL) == 0 && !c.fpd && c.fp_pass == 0, "1,000 collinear points");
    free(xy);
}

int main(void)
{
    degenerate();
    lattices();
    random_sets();
    polished();
    return test_report(passed_, failed_);
}
