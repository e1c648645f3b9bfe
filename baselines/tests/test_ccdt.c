/* test_ccdt.c - capacity-constrained Delaunay triangulation (ccdt.h):
 *  - after every iteration of a random run the triangulation is valid
 *    (CGAL's is_valid()), has n vertices whose points are the engine's,
 *    and 2n triangles (ccdt_check);
 *  - the area energy never increases: the energy tracked move by move
 *    (accepted moves only) equals the energy recomputed from every
 *    triangle, and it decreases from one iteration to the next;
 *  - a perturbed lattice of equal triangles returns to equal areas;
 *  - the same seed gives the same points, another seed other points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ccdt.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static void run_checked(int64_t n, int iters)
{
    char err[256];
    ccdt_engine *E = ccdt_create(n, 3, 1e-4, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    CHECK(ccdt_check(E), "start: invalid triangulation");
    double e = ccdt_energy_recomputed(E);
    int bad_valid = 0, bad_track = 0, bad_mono = 0;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 1; it <= iters; it++) {
        s.iteration = it;
        ccdt_iterate(E, &s);
        if (!ccdt_check(E)) bad_valid++;
        double r = ccdt_energy_recomputed(E), t = ccdt_energy(E);
        if (fabs(r - t) > 1e-9 * r) bad_track++;
        if (r > e * (1 + 1e-12)) bad_mono++;
        e = r;
    }
    CHECK(bad_valid == 0, "n=%lld: %d iterations left an invalid triangulation", (long long)n, bad_valid);
    CHECK(bad_track == 0, "n=%lld: tracked energy differs from the recomputed one in %d iterations", (long long)n, bad_track);
    CHECK(bad_mono == 0, "n=%lld: the energy rose in %d iterations", (long long)n, bad_mono);
    CHECK(ccdt_area_cv(E) < 0.5, "n=%lld: area cv %.3g after %d iterations (random start: ~0.9)", (long long)n, ccdt_area_cv(E), iters);
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
    for (int it = 0; it < 3; it++) {
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

int main(void)
{
    run_checked(300, 30);
    lattice(8, 0.2);
    lattice(12, 0.3);
    determinism();
    return test_report(passed_, failed_);
}
