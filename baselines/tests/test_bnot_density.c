/* test_bnot_density.c - BNOT under a density (bnot.h, dens_poly.h):
 *  - the polygon integrals: a pixel-aligned rectangle's mass is the sum
 *    of its pixels (1e-12); random convex polygons (inside and across
 *    the unit square's edges, the density repeating) have the mass,
 *    rho-weighted first and second moments of a fine midpoint sampling
 *    of them; reversing a polygon negates them; segment integrals equal
 *    a fine sampling along the segment;
 *  - the engine's cells under a non-uniform density: their masses sum to
 *    1 (1e-12, the cells partition the torus) and equal, with their
 *    rho-weighted centroids, a brute-force assignment of a fine grid of
 *    samples, each weighted by rho, to the least power distance over
 *    every site and its 8 copies (non-zero weights);
 *  - the Newton solve under cos a = 0.9, a ramp of contrast 16 and a
 *    random density: after the start and after every iteration every
 *    capacity is 1/n within 1e-8 (relative), each solve within 8 Newton
 *    steps (a Hessian that ignored rho would need more);
 *  - the authors' schedule under a density: capacities within 2 tau
 *    (2-norm) after every coarse iteration, exactly n points in [0, 1);
 *  - rho = 1 reduces to BNOT without a density: the same bytes (the
 *    constant density takes the uniform formulas), and the pixel
 *    integrals forced on it give the uniform areas and centroids (1e-12)
 *    and points within 1e-9 after 5 iterations;
 *  - the start follows rho (more sites where rho is larger). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bnot.h"
#include "dens_poly.h"
#include "power_brute.h"
#include "rng.h"
#include "testdensity.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static double rho_at(const cfpo_density *d, double x, double y)
{
    return cfpo_density_at(d, x - floor(x), y - floor(y));
}

/* mass, moments of a convex ccw polygon (absolute vertices) by g x g
 * midpoint samples of its bounding box */
static void sampled(const cfpo_density *d, const double *v, int k, double px, double py, int g, double out[4])
{
    double x0 = v[0], x1 = v[0], y0 = v[1], y1 = v[1];
    for (int a = 1; a < k; a++) {
        x0 = fmin(x0, v[2 * a]), x1 = fmax(x1, v[2 * a]);
        y0 = fmin(y0, v[2 * a + 1]), y1 = fmax(y1, v[2 * a + 1]);
    }
    const double hx = (x1 - x0) / g, hy = (y1 - y0) / g;
    memset(out, 0, 4 * sizeof *out);
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++) {
            const double x = x0 + (i + 0.5) * hx, y = y0 + (j + 0.5) * hy;
            int in = 1;
            for (int a = 0; a < k && in; a++) {
                const int b = (a + 1) % k;
                const double cr = (v[2 * b] - v[2 * a]) * (y - v[2 * a + 1]) - (v[2 * b + 1] - v[2 * a + 1]) * (x - v[2 * a]);
                in = cr >= 0;
            }
            if (!in) continue;
            const double r = rho_at(d, x, y) * hx * hy, u = x - px, w = y - py;
            out[0] += r;
            out[1] += r * u;
            out[2] += r * w;
            out[3] += r * (u * u + w * w);
        }
}

static void polygons(void)
{
    cfpo_density d;
    test_density_random(&d, 7, 5, 3);
    dens_poly t;
    CHECK(dens_poly_init(&t, &d) == 0, "dens_poly_init");
    /* a pixel-aligned rectangle across the torus's edge: pixels 5..8 x 4..6 */
    {
        const double x0 = 5.0 / 7, x1 = 9.0 / 7, y0 = 4.0 / 5, y1 = 7.0 / 5, v[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
        double want = 0, mo[4];
        for (int i = 5; i < 9; i++)
            for (int j = 4; j < 7; j++) want += d.rho[(j % 5) * 7 + i % 7] / 35.0;
        double rel[8];
        for (int a = 0; a < 4; a++) rel[2 * a] = v[2 * a] - 0.9, rel[2 * a + 1] = v[2 * a + 1] - 0.95;
        dens_poly_moments(&t, 0.9, 0.95, rel, 4, mo);
        CHECK(fabs(mo[0] - want) < 1e-12, "rectangle mass %.15g, pixels sum %.15g", mo[0], want);
    }
    /* random convex polygons: k points on an ellipse, some across x = 1, y = 0 */
    int bad = 0;
    double worst = 0;
    for (int trial = 0; trial < 12; trial++) {
        const int k = 3 + trial % 5;
        const double cx = -0.2 + 1.4 * cfpo_rand01(5, 1, trial), cy = -0.2 + 1.4 * cfpo_rand01(5, 2, trial);
        const double ra = 0.05 + 0.3 * cfpo_rand01(5, 3, trial), rb = 0.05 + 0.3 * cfpo_rand01(5, 4, trial);
        double v[16], rel[16], ang[8];
        for (int a = 0; a < k; a++) ang[a] = 2 * M_PI * cfpo_rand01(5, 10 + a, trial);
        for (int a = 1; a < k; a++) /* sort the angles: a convex ccw polygon */
            for (int b = a; b > 0 && ang[b] < ang[b - 1]; b--) { const double s = ang[b]; ang[b] = ang[b - 1]; ang[b - 1] = s; }
        for (int a = 0; a < k; a++) {
            v[2 * a] = cx + ra * cos(ang[a]);
            v[2 * a + 1] = cy + rb * sin(ang[a]);
        }
        const double px = cx + 0.01, py = cy - 0.02;
        for (int a = 0; a < 2 * k; a++) rel[a] = v[a] - (a % 2 ? py : px);
        double mo[4], br[4], rv[16], neg[4];
        dens_poly_moments(&t, px, py, rel, (size_t)k, mo);
        sampled(&d, v, k, px, py, 1500, br);
        const double scale[4] = {br[0], br[0] * (ra + rb), br[0] * (ra + rb), br[0] * (ra + rb) * (ra + rb)};
        for (int q = 0; q < 4; q++) {
            const double e = fabs(mo[q] - br[q]) / scale[q];
            worst = fmax(worst, e);
            if (e > 4e-3) bad++;
        }
        for (int a = 0; a < k; a++) rv[2 * a] = rel[2 * (k - 1 - a)], rv[2 * a + 1] = rel[2 * (k - 1 - a) + 1];
        dens_poly_moments(&t, px, py, rv, (size_t)k, neg);
        for (int q = 0; q < 4; q++)
            if (fabs(neg[q] + mo[q]) > 1e-12 * scale[q] / br[0] + 1e-15) bad++;
    }
    CHECK(bad == 0, "polygon moments: %d differ from sampling (worst %.3g relative)", bad, worst);
    /* segments, across the edges */
    int sbad = 0;
    for (int trial = 0; trial < 20; trial++) {
        const double x0 = -0.3 + 1.6 * cfpo_rand01(6, 1, trial), y0 = -0.3 + 1.6 * cfpo_rand01(6, 2, trial);
        const double x1 = x0 + 0.6 * (cfpo_rand01(6, 3, trial) - 0.5), y1 = trial % 4 ? y0 + 0.6 * (cfpo_rand01(6, 4, trial) - 0.5) : y0;
        const int m = 200000;
        double s = 0;
        for (int q = 0; q < m; q++) {
            const double f = (q + 0.5) / m;
            s += rho_at(&d, x0 + f * (x1 - x0), y0 + f * (y1 - y0));
        }
        const double len = hypot(x1 - x0, y1 - y0);
        s *= len / m;
        if (fabs(dens_poly_segment(&t, x0, y0, x1, y1) - s) > 1e-4 * len) sbad++;
    }
    CHECK(sbad == 0, "segment integrals: %d of 20 differ from sampling", sbad);
    printf("polygons: mass and moments agree with sampling (worst %.2g), segments agree\n", worst);
    dens_poly_free(&t);
    cfpo_density_free(&d);
}

static bnot_engine *tol_engine(int64_t n, const double *xy, uint64_t seed, const cfpo_density *d, int flags)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.epsilon = 0;
    char err[256];
    bnot_engine *E = bnot_create_density(n, xy, seed, 1.0 / sqrt((double)n), 1e-4, &r, d, flags, err, sizeof err);
    if (!E) fprintf(stderr, "create: %s\n", err);
    return E;
}

/* the cells against a brute-force, rho-weighted assignment of samples */
static void brute_force(const cfpo_density *d, int64_t n, int iters, int g)
{
    bnot_engine *E = tol_engine(n, NULL, 11, d, 0);
    CHECK(E != NULL, "create");
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < iters; it++) bnot_iterate(E, &s);
    const double *p = bnot_points(E), *w = bnot_weights(E), *A = bnot_areas(E), *C = bnot_centroids(E);
    double wspread = 0, sum = 0;
    for (int64_t i = 0; i < n; i++) wspread = fmax(wspread, fabs(w[i]) * (double)n), sum += A[i];
    const size_t cnt = n > 0 ? (size_t)n : 1;
    double *ms = calloc(cnt, sizeof *ms), *sx = calloc(cnt, sizeof *sx), *sy = calloc(cnt, sizeof *sy);
    const double h = 1.0 / g;
    for (int a = 0; a < g; a++)
        for (int b = 0; b < g; b++) {
            const double x = (a + 0.5) * h, y = (b + 0.5) * h, r = cfpo_density_at(d, x, y) * h * h;
            double bx, by;
            const int64_t bi = power_cell_brute(p, w, n, x, y, &bx, &by);
            ms[bi] += r;
            sx[bi] += r * bx;
            sy[bi] += r * by;
        }
    int bad_a = 0, bad_c = 0;
    double wa = 0, wc = 0;
    for (int64_t i = 0; i < n; i++) {
        const double ea = fabs(ms[i] - A[i]) / A[i], ec = hypot(sx[i] / ms[i] - C[2 * i], sy[i] / ms[i] - C[2 * i + 1]) / h;
        wa = fmax(wa, ea), wc = fmax(wc, ec);
        if (ea > 5e-3) bad_a++;
        if (ec > 0.4) bad_c++;
    }
    CHECK(fabs(sum - 1) < 1e-12, "n=%lld: the masses sum to 1 %+.3g", (long long)n, sum - 1);
    CHECK(wspread > 0.01, "n=%lld: the weights are all about 0 (%.3g)", (long long)n, wspread);
    CHECK(bad_a == 0, "n=%lld: %d cell masses differ from the brute force", (long long)n, bad_a);
    CHECK(bad_c == 0, "n=%lld: %d weighted centroids differ from the brute force", (long long)n, bad_c);
    printf("brute force n=%lld, %dx%d samples, |w| n up to %.3g: masses (sum 1 %+.1e, worst %.2g relative) and "
           "centroids (worst %.2g samples' side) agree\n", (long long)n, g, g, wspread, sum - 1, wa, wc);
    free(ms);
    free(sx);
    free(sy);
    bnot_free(E);
}

/* every capacity 1/n within 1e-8 after the start and every iteration */
static void newton(const cfpo_density *d, const char *name, int64_t n, int iters)
{
    bnot_engine *E = tol_engine(n, NULL, 5, d, 0);
    CHECK(E != NULL, "%s: create", name);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    int bad = 0, most = bnot_newton_steps(E), fail = !bnot_solve_ok(E) || bnot_cap_err(E) > 1e-8;
    double worst = bnot_cap_err(E);
    for (int it = 0; it < iters; it++) {
        bnot_iterate(E, &s);
        const double *A = bnot_areas(E);
        for (int64_t i = 0; i < n; i++)
            if (fabs(A[i] * (double)n - 1) > 1e-8) bad++;
        worst = fmax(worst, bnot_cap_err(E));
        if (!bnot_solve_ok(E)) fail++;
        if (it > 0 && bnot_newton_steps(E) > most) most = bnot_newton_steps(E);
    }
    CHECK(bad == 0 && fail == 0, "%s: %d capacities off 1/n by more than 1e-8, %d failed solves", name, bad, fail);
    CHECK(most <= 8, "%s: a solve took %d Newton steps", name, most);
    printf("newton %s n=%lld: capacities within %.2g of 1/n over %d iterations, at most %d Newton steps\n", name,
           (long long)n, worst, iters, most);
    bnot_free(E);
}

/* the default schedule under a density */
static void schedule(const cfpo_density *d)
{
    char err[256];
    const int64_t n = 400;
    bnot_engine *E = bnot_create_density(n, NULL, 2, 0, 1e-4, NULL, d, 0, err, sizeof err);
    CHECK(E != NULL, "schedule create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    const double tau = 0.03 * BNOT_DEFAULT_EPSILON / (double)n;
    int bad = 0, it = 0;
    for (; it < 40 && !s.converged; it++) {
        bnot_iterate(E, &s);
        const double *A = bnot_areas(E);
        double r2 = 0;
        for (int64_t i = 0; i < n; i++) r2 += (A[i] - 1.0 / (double)n) * (A[i] - 1.0 / (double)n);
        if (!(sqrt(r2) < 2 * tau)) bad++;
    }
    const double *p = bnot_points(E);
    int out = 0;
    for (int64_t i = 0; i < 2 * n; i++) out += !(p[i] >= 0 && p[i] < 1);
    CHECK(bad == 0, "schedule: %d iterations left |A - 1/n| >= 2 tau", bad);
    CHECK(out == 0 && s.converged, "schedule: %d coordinates outside [0, 1), converged %d", out, s.converged);
    printf("schedule: %d iterations, capacities within 2 tau, delta_min %.4f delta_avg %.4f (measure)\n", it,
           s.delta_min, s.delta_avg);
    bnot_free(E);
}

static void uniform_reduction(void)
{
    cfpo_density one;
    char err[256];
    CHECK(cfpo_density_load("cos:a=0", &one, err, sizeof err) == 0, "cos:a=0: %s", err);
    /* the default schedule and the run to tol: the same bytes */
    for (int tolrun = 0; tolrun < 2; tolrun++) {
        bnot_rule r;
        bnot_rule_init(&r);
        if (tolrun) r.epsilon = 0;
        bnot_engine *A = tolrun ? bnot_create(300, 4, 1e-4, err, sizeof err) : bnot_create_rule(300, NULL, 4, 0, 1e-4, &r, err, sizeof err);
        bnot_engine *B = bnot_create_density(300, NULL, 4, 0, 1e-4, &r, &one, 0, err, sizeof err);
        cfpo_iter_stats s;
        memset(&s, 0, sizeof s);
        for (int it = 0; it < 8; it++) bnot_iterate(A, &s), bnot_iterate(B, &s);
        CHECK(memcmp(bnot_points(A), bnot_points(B), 600 * sizeof(double)) == 0,
              "rho = 1 (%s): not the bytes without a density", tolrun ? "tol run" : "schedule");
        bnot_free(A);
        bnot_free(B);
    }
    /* the pixel integrals on rho = 1 against the uniform formulas */
    const int64_t n = 200;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    for (int64_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(9, 1, (uint64_t)i);
    bnot_engine *U = tol_engine(n, xy, 0, &one, 0), *P = tol_engine(n, xy, 0, &one, BNOT_DENS_PIXELS);
    double ea = 0, ec = 0, ep = 0;
    const double *au = bnot_areas(U), *ap = bnot_areas(P), *cu = bnot_centroids(U), *cp = bnot_centroids(P);
    for (int64_t i = 0; i < n; i++) ea = fmax(ea, fabs(au[i] - ap[i]) * (double)n);
    for (int64_t i = 0; i < 2 * n; i++) ec = fmax(ec, fabs(cu[i] - cp[i]));
    CHECK(ea < 1e-12 && ec < 1e-12, "rho = 1: pixel integrals differ from the uniform cells (areas %.3g n^-1, centroids %.3g)", ea, ec);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < 5; it++) bnot_iterate(U, &s), bnot_iterate(P, &s);
    for (int64_t i = 0; i < 2 * n; i++) ep = fmax(ep, fabs(bnot_points(U)[i] - bnot_points(P)[i]));
    CHECK(ep < 1e-9, "rho = 1: points after 5 iterations differ by %.3g", ep);
    printf("rho = 1: same bytes; pixel integrals vs uniform: areas %.2g / n, centroids %.2g, points after 5 it. %.2g\n",
           ea, ec, ep);
    bnot_free(U);
    bnot_free(P);
    free(xy);
    cfpo_density_free(&one);
}

/* the start follows rho: the sites in the ramp's dense half (x in [1/4,
 * 3/4)) against n times its mass, within 4 standard deviations */
static void start_follows(const cfpo_density *ramp)
{
    char err[256];
    const int64_t n = 2000;
    bnot_rule r;
    bnot_rule_init(&r);
    bnot_engine *E = bnot_create_density(n, NULL, 3, 0, 1e-4, &r, ramp, 0, err, sizeof err);
    CHECK(E != NULL, "start: %s", err);
    if (!E) return;
    double mass = 0;
    for (int64_t i = 0; i < ramp->w; i++)
        if (i * 4 >= ramp->w && i * 4 < 3 * ramp->w) mass += ramp->rho[i] / (double)ramp->w;
    const double *p = bnot_points(E);
    int64_t k = 0;
    for (int64_t i = 0; i < n; i++) k += p[2 * i] >= 0.25 && p[2 * i] < 0.75;
    const double sd = sqrt((double)n * mass * (1 - mass));
    CHECK(fabs((double)k - n * mass) < 4 * sd + 1, "start: %lld sites in the dense half, expected %.1f", (long long)k, n * mass);
    bnot_free(E);
}

int main(void)
{
    polygons();
    cfpo_density cosd, ramp, rnd;
    char err[256];
    if (cfpo_density_load("cos:a=0.9,res=64", &cosd, err, sizeof err) != 0 ||
        cfpo_density_load("ramp:contrast=16,res=64", &ramp, err, sizeof err) != 0) {
        printf("%s\n", err);
        return 1;
    }
    test_density_random(&rnd, 6, 5, 8);
    brute_force(&rnd, 40, 3, 700);
    brute_force(&cosd, 30, 2, 600);
    newton(&cosd, "cos:a=0.9", 300, 15);
    newton(&ramp, "ramp:contrast=16", 300, 15);
    newton(&rnd, "random 6x5", 200, 10);
    schedule(&cosd);
    uniform_reduction();
    start_follows(&ramp);
    cfpo_density_free(&cosd);
    cfpo_density_free(&ramp);
    cfpo_density_free(&rnd);
    return test_report(passed_, failed_);
}
