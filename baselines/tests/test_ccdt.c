/* test_ccdt.c - capacity-constrained Delaunay triangulation (ccdt.h),
 * the alternating scheme:
 *  - geometry phase: with the connectivity fixed, no sweep raises the
 *    energy of that connectivity (measured from all its triangles), no
 *    triangle inverts (smallest signed area > 0) and the signed areas still
 *    sum to 1 (the copy's offsets are consistent);
 *  - Delaunay phase: it moves no point (positions equal to the wrapped ones
 *    bit for bit), the triangulation is valid (CGAL's is_valid(), n
 *    vertices, 2n triangles, ccdt_check), the copied connectivity's energy
 *    equals the energy of CGAL's triangles, and a second Delaunay phase
 *    changes no edge and no energy;
 *  - the step rule: the next step is half the last one when the energy of
 *    the Delaunay triangulation rose over an iteration, else 1.25 times it
 *    (at most 1); a run converges under tol and evens the areas out;
 *  - a perturbed lattice of equal triangles returns to equal areas;
 *  - the same seed gives the same points, another seed other points;
 *  - the reference schedule (ccdt_set_reference K): every iteration one
 *    sweep at the full step 1, the run converged exactly at iteration K,
 *    the triangulation valid after each, the areas evened out over the
 *    run, the points other than the damped schedule's, and the same for
 *    the same seed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ccdt.h"
#include "geom.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

/* Phases one at a time on a random start: sweeps, then a Delaunay phase. */
static void phases(int64_t n, int rounds, int sweeps)
{
    char err[256];
    ccdt_engine *E = ccdt_create(n, 3, 1e-4, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    CHECK(ccdt_check(E), "start: invalid triangulation");
    int bad_mono = 0, bad_inv = 0, bad_sum = 0, bad_still = 0, bad_valid = 0, bad_copy = 0, bad_idem = 0, flips = 0;
    double *before = malloc(2 * (size_t)n * sizeof *before);
    const double cv0 = ccdt_area_cv(E);
    for (int r = 0; r < rounds; r++) {
        double e = ccdt_energy(E);
        for (int k = 0; k < sweeps; k++) {
            ccdt_sweep(E);
            const double e1 = ccdt_energy(E);
            if (e1 > e * (1 + 1e-12)) bad_mono++;
            if (!(ccdt_area_min(E) > 0)) bad_inv++;
            if (fabs(ccdt_area_sum(E) - 1) > 1e-9) bad_sum++;
            e = e1;
        }
        CHECK(!ccdt_check(E), "ccdt_check holds between a sweep and the Delaunay phase");
        memcpy(before, ccdt_points(E), 2 * (size_t)n * sizeof *before);
        const int64_t fl = ccdt_delaunay(E);
        flips += fl > 0;
        const double *p = ccdt_points(E);
        for (int64_t i = 0; i < 2 * n; i++)
            if (p[i] != cfpo_wrap01(before[i])) {
                bad_still++;
                break;
            }
        if (fl < 0 || !ccdt_check(E)) bad_valid++;
        const double ec = ccdt_energy(E), er = ccdt_energy_recomputed(E);
        if (fabs(ec - er) > 1e-12 * er) bad_copy++;
        if (ccdt_delaunay(E) != 0 || ccdt_energy(E) != ec) bad_idem++;
    }
    CHECK(bad_mono == 0, "n=%lld: a sweep raised the energy of the fixed connectivity %d times", (long long)n, bad_mono);
    CHECK(bad_inv == 0, "n=%lld: a triangle inverted in %d sweeps", (long long)n, bad_inv);
    CHECK(bad_sum == 0, "n=%lld: the signed areas do not sum to 1 after %d sweeps", (long long)n, bad_sum);
    CHECK(bad_still == 0, "n=%lld: the Delaunay phase moved points in %d rounds", (long long)n, bad_still);
    CHECK(bad_valid == 0, "n=%lld: %d Delaunay phases left an invalid triangulation", (long long)n, bad_valid);
    CHECK(bad_copy == 0, "n=%lld: the copy's energy differs from CGAL's in %d rounds", (long long)n, bad_copy);
    CHECK(bad_idem == 0, "n=%lld: a second Delaunay phase changed something in %d rounds", (long long)n, bad_idem);
    CHECK(flips > 0, "n=%lld: no Delaunay phase changed an edge (the test proves nothing)", (long long)n);
    CHECK(ccdt_area_cv(E) < 0.25 * cv0, "n=%lld: area cv %.3g after %d rounds (start %.3g)", (long long)n,
          ccdt_area_cv(E), rounds, cv0);
    free(before);
    ccdt_free(E);
}

/* Whole iterations: the step rule, validity, convergence. */
static void run_checked(int64_t n, int max_iter)
{
    char err[256];
    ccdt_engine *E = ccdt_create(n, 5, 1e-4, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    double e = ccdt_energy(E), step = 1;
    int bad_valid = 0, bad_step = 0, rose = 0, fell = 0, it;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (it = 1; it <= max_iter; it++) {
        s.iteration = it;
        ccdt_iterate(E, &s);
        if (!ccdt_check(E)) bad_valid++;
        const double e1 = ccdt_energy(E);
        if (ccdt_step(E) != step) bad_step++;
        if (e1 > e) {
            rose++;
            step = 0.5 * step;
        } else {
            fell++;
            step = fmin(1.0, 1.25 * step);
        }
        e = e1;
        if (s.converged) break;
    }
    CHECK(bad_valid == 0, "n=%lld: %d iterations left an invalid triangulation", (long long)n, bad_valid);
    CHECK(bad_step == 0, "n=%lld: the step broke the rule in %d iterations", (long long)n, bad_step);
    CHECK(rose > 0 && fell > 0, "n=%lld: the energy rose %d and fell %d times (the rule untested)", (long long)n, rose, fell);
    CHECK(s.converged, "n=%lld: not converged in %d iterations", (long long)n, max_iter);
    CHECK(ccdt_area_cv(E) < 0.05, "n=%lld: area cv %.3g at the end (random start: ~0.9)", (long long)n, ccdt_area_cv(E));
    CHECK(s.delta_min > 0.5, "n=%lld: delta_min %.3f at the end", (long long)n, s.delta_min);
    printf("n=%lld: converged=%d after %d iterations, area cv %.4f, delta_min %.3f, delta_avg %.3f\n", (long long)n,
           s.converged, it, ccdt_area_cv(E), s.delta_min, s.delta_avg);
    ccdt_free(E);
}

/* k columns x k rows, odd rows shifted by half a column: every Delaunay
 * triangle has area 1 / (2 k^2). */
static void lattice(int k, double amp)
{
    const int n = k * k;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    for (int j = 0; j < k; j++)
        for (int i = 0; i < k; i++) {
            int id = j * k + i;
            double x = (i + 0.25 + 0.5 * (j & 1)) / k, y = (j + 0.5) / k;
            x += amp / k * (cfpo_rand01(9, 1, 2 * (uint64_t)id) - 0.5);
            y += amp / k * (cfpo_rand01(9, 1, 2 * (uint64_t)id + 1) - 0.5);
            xy[2 * id] = x - floor(x);
            xy[2 * id + 1] = y - floor(y);
        }
    char err[256];
    ccdt_engine *E = ccdt_create_from(n, xy, 1.0 / k, 0, err, sizeof err);
    CHECK(E != NULL, "lattice create: %s", err);
    if (!E) { free(xy); return; }
    double dev0 = ccdt_area_maxdev(E);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    int it;
    for (it = 1; it <= 1000; it++) {
        s.iteration = it;
        ccdt_iterate(E, &s);
        if (ccdt_area_maxdev(E) < 1e-3) break;
    }
    double dev = ccdt_area_maxdev(E);
    CHECK(dev0 > 0.05, "lattice %dx%d: the perturbation left the areas equal (%.3g)", k, k, dev0);
    CHECK(dev < 1e-3, "lattice %dx%d perturbed by %.2f: largest area deviation %.3g (start %.3g) after %d iterations",
          k, k, amp, dev, dev0, it - 1);
    CHECK(ccdt_check(E), "lattice: invalid triangulation");
    printf("lattice %dx%d perturbed by %.2f: largest area deviation %.3g -> %.3g in %d iterations\n", k, k, amp, dev0, dev, it);
    ccdt_free(E);
    free(xy);
}

static void determinism(void)
{
    char err[256];
    ccdt_engine *A = ccdt_create(400, 1, 1e-4, err, sizeof err), *B = ccdt_create(400, 1, 1e-4, err, sizeof err);
    ccdt_engine *C = ccdt_create(400, 2, 1e-4, err, sizeof err);
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < 5; it++) {
        ccdt_iterate(A, &s);
        ccdt_iterate(B, &s);
        ccdt_iterate(C, &s);
    }
    CHECK(memcmp(ccdt_points(A), ccdt_points(B), 800 * sizeof(double)) == 0, "same seed, different points");
    CHECK(memcmp(ccdt_points(A), ccdt_points(C), 800 * sizeof(double)) != 0, "seeds 1 and 2 give the same points");
    ccdt_free(A);
    ccdt_free(B);
    ccdt_free(C);
}

static void reference(int64_t n, int K)
{
    char err[256];
    ccdt_engine *A = ccdt_create(n, 3, 1e-4, err, sizeof err), *B = ccdt_create(n, 3, 1e-4, err, sizeof err);
    ccdt_engine *D = ccdt_create(n, 3, 1e-4, err, sizeof err);
    CHECK(A && B && D, "create: %s", err);
    if (!A || !B || !D) return;
    ccdt_set_reference(A, K);
    ccdt_set_reference(B, K);
    const double cv0 = ccdt_area_cv(A);
    cfpo_iter_stats s, t;
    memset(&s, 0, sizeof s);
    memset(&t, 0, sizeof t);
    int bad_step = 0, bad_conv = 0, bad_valid = 0;
    for (int it = 1; it <= K; it++) {
        ccdt_iterate(A, &s);
        ccdt_iterate(B, &t);
        ccdt_iterate(D, &t);
        if (ccdt_sweeps(A) != 1 || ccdt_step(A) != 1) bad_step++;
        if (s.converged != (it == K)) bad_conv++;
        if (!ccdt_check(A)) bad_valid++;
    }
    CHECK(bad_step == 0, "reference n=%lld: %d iterations not one sweep at step 1", (long long)n, bad_step);
    CHECK(bad_conv == 0, "reference n=%lld: %d iterations with converged != (iteration == %d)", (long long)n, bad_conv, K);
    CHECK(bad_valid == 0, "reference n=%lld: %d invalid triangulations", (long long)n, bad_valid);
    CHECK(ccdt_area_cv(A) < 0.5 * cv0, "reference n=%lld: area cv %.3f -> %.3f only", (long long)n, cv0, ccdt_area_cv(A));
    CHECK(memcmp(ccdt_points(A), ccdt_points(B), 2 * (size_t)n * sizeof(double)) == 0, "reference: same seed, other points");
    CHECK(memcmp(ccdt_points(A), ccdt_points(D), 2 * (size_t)n * sizeof(double)) != 0,
          "reference: the same points as the damped schedule");
    ccdt_free(A);
    ccdt_free(B);
    ccdt_free(D);
}

int main(void)
{
    phases(300, 12, 4);
    phases(1000, 4, 8);
    run_checked(300, 2000);
    lattice(8, 0.2);
    lattice(12, 0.3);
    determinism();
    reference(500, 12);
    return test_report(passed_, failed_);
}
