/* test_lloyd.c - Lloyd's algorithm (lloyd.h):
 *  - the Voronoi cells from the periodic Delaunay triangulation: areas
 *    positive and summing to 1 (1e-12), and areas and centroids equal to a
 *    brute-force assignment of 800 x 800 samples to the nearest site over
 *    the torus (40 sites, after 0 and 3 iterations);
 *  - the centroid condition at convergence: a 64-site run that converges
 *    (no move of tol * L) leaves every site within 2 tol L of its cell's
 *    centroid; delta_min rose from the random start;
 *  - the same seed the same sites, another seed other sites. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "lloyd.h"
#include "testutil.h"

static int passed_, failed_;

static double wrapd(double d) { return d - floor(d + 0.5); }

static void brute(const lloyd_engine *E, int64_t n)
{
    const double *xy = lloyd_points(E);
    double *area = calloc((size_t)n, sizeof *area), *cx = calloc((size_t)n, sizeof *cx),
           *cy = calloc((size_t)n, sizeof *cy);
    double *ba = calloc((size_t)n, sizeof *ba), *bx = calloc((size_t)n, sizeof *bx),
           *by = calloc((size_t)n, sizeof *by);
    CHECK(lloyd_cells(E, area, cx, cy) == 0, "lloyd_cells failed");
    const int S = 800;
    for (int a = 0; a < S; a++)
        for (int b = 0; b < S; b++) {
            const double x = (a + 0.5) / S, y = (b + 0.5) / S;
            double best = 1e300, bdx = 0, bdy = 0;
            int64_t k = -1;
            for (int64_t i = 0; i < n; i++) {
                const double dx = wrapd(x - xy[2 * i]), dy = wrapd(y - xy[2 * i + 1]);
                if (dx * dx + dy * dy < best) {
                    best = dx * dx + dy * dy;
                    k = i;
                    bdx = dx;
                    bdy = dy;
                }
            }
            ba[k] += 1.0 / ((double)S * S);
            bx[k] += bdx / ((double)S * S);
            by[k] += bdy / ((double)S * S);
        }
    double sum = 0, worst_a = 0, worst_c = 0;
    int positive = 1;
    for (int64_t i = 0; i < n; i++) {
        sum += area[i];
        if (!(area[i] > 0)) positive = 0;
        worst_a = fmax(worst_a, fabs(area[i] - ba[i]) * (double)n);
        const double ex = xy[2 * i] + bx[i] / ba[i], ey = xy[2 * i + 1] + by[i] / ba[i];
        worst_c = fmax(worst_c, hypot(cx[i] - ex, cy[i] - ey) * sqrt((double)n));
    }
    CHECK(positive && fabs(sum - 1) < 1e-12, "lloyd cells: areas sum to %.15g", sum);
    /* the samples' resolution: 1/800 against a spacing of 1/sqrt(40) */
    CHECK(worst_a < 0.02, "lloyd cells: an area differs from brute force by %g of 1/n", worst_a);
    CHECK(worst_c < 0.01, "lloyd cells: a centroid differs from brute force by %g of n^-1/2", worst_c);
    free(area), free(cx), free(cy), free(ba), free(bx), free(by);
}

int main(void)
{
    char err[256];
    cfpo_iter_stats s;
    lloyd_engine *E = lloyd_create(40, 3, 1e-4, 0, err, sizeof err);
    CHECK(E != NULL, "lloyd_create(40): %s", err);
    if (E) {
        brute(E, 40);
        for (int i = 0; i < 3; i++) lloyd_iterate(E, &s);
        brute(E, 40);
        lloyd_free(E);
    }
    const int64_t n = 64;
    const double tol = 1e-4;
    E = lloyd_create(n, 5, tol, 0, err, sizeof err);
    CHECK(E != NULL, "lloyd_create(64): %s", err);
    if (!E) return test_report(passed_, failed_);
    double d0min, d0avg;
    lloyd_deltas(E, &d0min, &d0avg);
    int it = 0;
    do lloyd_iterate(E, &s);
    while (!s.converged && ++it < 20000);
    CHECK(s.converged, "lloyd: 64 sites not converged after %d iterations", it);
    double *area = malloc((size_t)n * sizeof *area), *cx = malloc((size_t)n * sizeof *cx),
           *cy = malloc((size_t)n * sizeof *cy);
    lloyd_cells(E, area, cx, cy);
    cfpo_grid G;
    cfpo_grid_init(&G, n, CFPO_VARIANT_FULL, 1, err, sizeof err);
    double worst = 0;
    const double *xy = lloyd_points(E);
    for (int64_t i = 0; i < n; i++)
        worst = fmax(worst, hypot(wrapd(cx[i] - xy[2 * i]), wrapd(cy[i] - xy[2 * i + 1])));
    CHECK(worst < 2 * tol * G.L, "lloyd: at convergence a site is %g L from its centroid", worst / G.L);
    CHECK(s.delta_min > d0min + 0.3, "lloyd: delta_min %g from %g", s.delta_min, d0min);
    printf("lloyd n=64 converged after %d iterations: delta_min %.4f delta_avg %.4f\n", it + 1, s.delta_min,
           s.delta_avg);
    free(area), free(cx), free(cy);
    lloyd_engine *A = lloyd_create(n, 5, tol, 0, err, sizeof err), *B = lloyd_create(n, 6, tol, 0, err, sizeof err);
    CHECK(A && B && memcmp(lloyd_points(A), lloyd_points(B), 2 * (size_t)n * sizeof(double)) != 0,
          "lloyd: seeds 5 and 6 give the same start");
    lloyd_engine *C = lloyd_create(n, 5, tol, 0, err, sizeof err);
    for (int i = 0; i < 5; i++) lloyd_iterate(A, &s), lloyd_iterate(C, &s);
    CHECK(memcmp(lloyd_points(A), lloyd_points(C), 2 * (size_t)n * sizeof(double)) == 0, "lloyd: same seed, other sites");
    lloyd_free(A), lloyd_free(B), lloyd_free(C), lloyd_free(E);
    return test_report(passed_, failed_);
}
