/* test_bnot.c - blue noise through optimal transport (bnot.h):
 *  - capacities: after the start's solve and after every iteration of a
 *    random run every power cell has area 1/n within 1e-6 (relative; the
 *    solver aims at 1e-8), and still at a converged run's end;
 *  - the power diagram is valid: CGAL's is_valid(), no original site
 *    hidden or with an empty cell, cell areas summing to 1 within 1e-12;
 *  - the power cells are the torus's: the areas and centroids equal a
 *    brute-force assignment of a fine grid of samples to the site (any of
 *    its 9 copies) of least power distance |x - p|^2 - w, for a 40-site
 *    diagram with non-zero weights and for 7 sites (every copy inserted);
 *  - the transport energy does not increase: with tight capacities
 *    (1e-11), the Lloyd step lowers it on fixed cells (energy_moved <=
 *    energy) and the solve for the moved sites finds cells no costlier
 *    (energy after <= energy_moved, within 1e-10 relative), so it never
 *    rises over the run;
 *  - a square lattice is a fixed point: equal square cells with zero
 *    weights, no site moves, normalised second moment 1/12;
 *  - the same seed gives the same points, another seed other points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bnot.h"
#include "power_brute.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

/* n uniform random sites (any n >= 2; the command's minimum is cfpo's) */
static bnot_engine *random_engine(int64_t n, uint64_t seed, double tol, double cap_tol, char *err, size_t errlen)
{
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    for (int64_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(seed, 1, (uint64_t)i);
    bnot_engine *E = bnot_create_from(n, xy, 1.0 / sqrt((double)n), tol, cap_tol, err, errlen);
    free(xy);
    return E;
}

/* capacity and validity checks of E's current diagram; returns failures */
static int diagram_ok(const bnot_engine *E, int64_t n, const char *when)
{
    int bad = 0;
    bnot_check_info c;
    bnot_check(E, &c);
    const double *A = bnot_areas(E);
    double worst = 0;
    for (int64_t i = 0; i < n; i++) worst = fmax(worst, fabs(A[i] * (double)n - 1));
    if (worst > 1e-6) { bad++; fprintf(stderr, "%s: capacity error %.3g\n", when, worst); }
    if (!bnot_solve_ok(E)) { bad++; fprintf(stderr, "%s: the capacity solve failed\n", when); }
    if (!c.valid) { bad++; fprintf(stderr, "%s: CGAL is_valid() fails\n", when); }
    if (c.empty) { bad++; fprintf(stderr, "%s: %lld empty cells\n", when, (long long)c.empty); }
    if (fabs(c.area_sum - 1) > 1e-12) { bad++; fprintf(stderr, "%s: areas sum to 1 %+.3g\n", when, c.area_sum - 1); }
    return bad;
}

static void run_checked(int64_t n, int iters)
{
    char err[256], when[64];
    bnot_engine *E = random_engine(n, 3, 1e-4, BNOT_CAP_TOL, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    int bad = diagram_ok(E, n, "start");
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 1; it <= iters; it++) {
        bnot_iterate(E, &s);
        snprintf(when, sizeof when, "n=%lld iteration %d", (long long)n, it);
        bad += diagram_ok(E, n, when);
    }
    CHECK(bad == 0, "n=%lld: %d capacity/validity failures in %d iterations", (long long)n, bad, iters);
    CHECK(s.delta_min > 0.6, "n=%lld: delta_min %.3f after %d iterations", (long long)n, s.delta_min, iters);
    bnot_free(E);
}

/* A run to convergence: converged, capacities held at the end. */
static void converge(int64_t n)
{
    char err[256];
    bnot_engine *E = bnot_create(n, 5, 1e-3, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    int it;
    for (it = 1; it <= 5000; it++) {
        bnot_iterate(E, &s);
        if (s.converged) break;
    }
    CHECK(s.converged, "n=%lld: not converged in 5000 iterations", (long long)n);
    CHECK(diagram_ok(E, n, "converged") == 0, "n=%lld: capacities or validity at convergence", (long long)n);
    CHECK(bnot_cap_err(E) <= BNOT_CAP_TOL, "n=%lld: capacity error %.3g at convergence", (long long)n, bnot_cap_err(E));
    CHECK(s.delta_min > 0.7, "n=%lld: converged delta_min %.3f", (long long)n, s.delta_min);
    printf("n=%lld converged in %d iterations: delta_min %.4f delta_avg %.4f, capacity error %.2g\n", (long long)n,
           it, s.delta_min, s.delta_avg, bnot_cap_err(E));
    bnot_free(E);
}

/* Brute force: a g x g grid of sample points, each to the site copy of
 * least power distance; areas and centroids against the engine's. */
static void brute_force(int64_t n, int iters, int g)
{
    if (n < 2 || n > 100000) return;
    char err[256];
    bnot_engine *E = random_engine(n, 11, 1e-4, BNOT_CAP_TOL, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < iters; it++) bnot_iterate(E, &s);
    const double *p = bnot_points(E), *w = bnot_weights(E), *A = bnot_areas(E), *C = bnot_centroids(E);
    double wspread = 0;
    for (int64_t i = 0; i < n; i++) wspread = fmax(wspread, fabs(w[i]) * (double)n);
    double *cnt = calloc((size_t)n, sizeof *cnt), *sx = calloc((size_t)n, sizeof *sx), *sy = calloc((size_t)n, sizeof *sy);
    for (int a = 0; a < g; a++)
        for (int b = 0; b < g; b++) {
            const double x = (a + 0.5) / g, y = (b + 0.5) / g;
            double bx, by;
            const int64_t bi = power_cell_brute(p, w, n, x, y, &bx, &by);
            cnt[bi] += 1;
            sx[bi] += bx; /* the sample in the frame of the site itself */
            sy[bi] += by;
        }
    const double h = 1.0 / g;
    int bad_a = 0, bad_c = 0;
    for (int64_t i = 0; i < n; i++) {
        const double a = cnt[i] * h * h;
        if (fabs(a - A[i]) > 3e-3 * A[i]) bad_a++;
        const double cx = sx[i] / cnt[i], cy = sy[i] / cnt[i];
        if (hypot(cx - C[2 * i], cy - C[2 * i + 1]) > 2 * h) bad_c++;
    }
    CHECK(wspread > 0.01, "n=%lld: the weights are all about 0 (%.3g): a Voronoi diagram tests little", (long long)n, wspread);
    CHECK(bad_a == 0, "n=%lld: %d cell areas differ from the brute force", (long long)n, bad_a);
    CHECK(bad_c == 0, "n=%lld: %d cell centroids differ from the brute force", (long long)n, bad_c);
    printf("brute force n=%lld, %dx%d samples, largest |w| n = %.3g: areas and centroids agree\n", (long long)n, g, g,
           wspread);
    free(cnt);
    free(sx);
    free(sy);
    bnot_free(E);
}

/* Energy: with capacities solved to 1e-11, E_k >= moved_k >= E_{k+1}. */
static void energy(int64_t n, int iters)
{
    char err[256];
    bnot_engine *E = random_engine(n, 21, 0, 1e-11, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    double e = bnot_energy(E), worst_lloyd = 0, worst_solve = 0;
    const double e0 = e;
    int bad_lloyd = 0, bad_solve = 0, bad_solver = 0;
    for (int it = 1; it <= iters; it++) {
        bnot_iterate(E, &s);
        const double m = bnot_energy_moved(E), a = bnot_energy(E);
        worst_lloyd = fmax(worst_lloyd, (m - e) / e);
        worst_solve = fmax(worst_solve, (a - m) / m);
        if (m > e * (1 + 1e-12)) bad_lloyd++;
        if (a > m * (1 + 1e-10)) bad_solve++;
        if (!bnot_solve_ok(E) || bnot_cap_err(E) > 1e-11) bad_solver++;
        e = a;
    }
    CHECK(bad_solver == 0, "n=%lld: %d solves missed the capacity tolerance 1e-11", (long long)n, bad_solver);
    CHECK(bad_lloyd == 0, "n=%lld: the Lloyd step raised the energy in %d iterations (worst %+.3g)", (long long)n, bad_lloyd, worst_lloyd);
    CHECK(bad_solve == 0, "n=%lld: the capacity solve raised the energy in %d iterations (worst %+.3g)", (long long)n, bad_solve, worst_solve);
    CHECK(e < 0.5 * e0, "n=%lld: energy %.4g -> %.4g only", (long long)n, e0, e);
    printf("energy n=%lld: %.6g -> %.6g over %d iterations; worst relative rise: Lloyd %+.2g, solve %+.2g\n",
           (long long)n, e0, e, iters, worst_lloyd, worst_solve);
    bnot_free(E);
}

static void square_lattice(int k)
{
    const int64_t n = (int64_t)k * k;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    for (int j = 0; j < k; j++)
        for (int i = 0; i < k; i++) {
            xy[2 * (j * k + i)] = (i + 0.5) / k;
            xy[2 * (j * k + i) + 1] = (j + 0.5) / k;
        }
    char err[256];
    bnot_engine *E = bnot_create_from(n, xy, 1.0 / k, 1e-4, BNOT_CAP_TOL, err, sizeof err);
    CHECK(E != NULL, "lattice create: %s", err);
    if (!E) { free(xy); return; }
    CHECK(bnot_newton_steps(E) == 0, "lattice %dx%d: %d Newton steps for equal cells", k, k, bnot_newton_steps(E));
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    bnot_iterate(E, &s);
    CHECK(s.moved == 0 && s.converged, "lattice %dx%d: %lld sites moved (largest %.3g L)", k, k, (long long)s.moved, s.max_disp);
    CHECK(fabs(bnot_energy_nsm(E) - 1.0 / 12) < 1e-12, "lattice %dx%d: normalised energy %.15g, want 1/12", k, k, bnot_energy_nsm(E));
    CHECK(diagram_ok(E, n, "lattice") == 0, "lattice %dx%d: capacities or validity", k, k);
    bnot_free(E);
    free(xy);
}

static void determinism(void)
{
    char err[256];
    bnot_engine *A = bnot_create(400, 1, 1e-4, err, sizeof err), *B = bnot_create(400, 1, 1e-4, err, sizeof err);
    bnot_engine *C = bnot_create(400, 2, 1e-4, err, sizeof err);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < 5; it++) {
        bnot_iterate(A, &s);
        bnot_iterate(B, &s);
        bnot_iterate(C, &s);
    }
    CHECK(memcmp(bnot_points(A), bnot_points(B), 800 * sizeof(double)) == 0, "same seed, different points");
    CHECK(memcmp(bnot_weights(A), bnot_weights(B), 400 * sizeof(double)) == 0, "same seed, different weights");
    CHECK(memcmp(bnot_points(A), bnot_points(C), 800 * sizeof(double)) != 0, "seeds 1 and 2 give the same points");
    bnot_free(A);
    bnot_free(B);
    bnot_free(C);
}

int main(void)
{
    run_checked(300, 40);
    run_checked(7, 20);
    converge(128);
    brute_force(40, 3, 700);
    brute_force(7, 2, 500);
    energy(200, 60);
    square_lattice(8);
    determinism();
    return test_report(passed_, failed_);
}
