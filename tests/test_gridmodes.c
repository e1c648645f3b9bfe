/* test_gridmodes.c - the grid's print on a set and the field that removes
 * it (gridmodes.h; issue 44).
 *
 * The vectors: (mx, my) g / 3 with |mx|, |my| <= 4 in the half plane where
 * 3 divides g (40, each once, none the negative of another), the cells'
 * four otherwise. The modes: against direct sums in double precision on a
 * random set, and exact in the integers: two parts' sums add to the
 * whole's, and one thread or three give the same bits. The field: a
 * jittered set given a density wave at three of the vectors (relative
 * size 5%) and moved along the field once loses at least 99.9% of P there
 * (the linearisation and the table leave second order), and the other
 * vectors do not gain; moved against the field, P grows (a sign error
 * fails). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gridmodes.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

static void test_vectors(void)
{
    cfpo_gridmodes M;
    CHECK(cfpo_gridmodes_init(&M, 459, 262144) == 0, "g 459: out of memory");
    CHECK(M.count == 40 && M.q == 153, "g 459: %d vectors of step %d, not 40 of 153", M.count, M.q);
    int bad = 0;
    for (int i = 0; i < M.count; i++) {
        if (abs(M.mx[i]) > 4 || M.my[i] < 0 || M.my[i] > 4 || (M.my[i] == 0 && M.mx[i] <= 0)) bad++;
        for (int j = 0; j < i; j++)
            if ((M.mx[i] == M.mx[j] && M.my[i] == M.my[j]) || (M.mx[i] == -M.mx[j] && M.my[i] == -M.my[j])) bad++;
    }
    CHECK(bad == 0, "g 459: %d vectors outside the half plane or repeated", bad);
    cfpo_gridmodes_free(&M);
    cfpo_gridmodes_init(&M, 460, 262144);
    CHECK(M.count == 4 && M.q == 460, "g 460: %d vectors of step %d, not the cells' 4", M.count, M.q);
    cfpo_gridmodes_free(&M);
    cfpo_gridmodes_init(&M, 2, 16);
    CHECK(M.count == 0, "g 2: %d vectors, not 0", M.count);
    cfpo_gridmodes_free(&M);
}

static double direct_power(const double *x, const double *y, int64_t n, double kx, double ky)
{
    double re = 0, im = 0;
    for (int64_t j = 0; j < n; j++) {
        const double a = -2 * M_PI * (kx * x[j] + ky * y[j]);
        re += cos(a);
        im += sin(a);
    }
    return (re * re + im * im) / (double)n;
}

static void test_modes(void)
{
    const int64_t n = 20000;
    double *x = malloc(2 * (size_t)n * sizeof *x), *y = x + n;
    for (int64_t j = 0; j < n; j++) {
        x[j] = cfpo_rand01(11, 1, (uint64_t)j);
        y[j] = cfpo_rand01(11, 2, (uint64_t)j);
    }
    cfpo_gridmodes M, A, B, T;
    cfpo_gridmodes_init(&M, 126, n);
    cfpo_gridmodes_sum(&M, x, y, n, 1);
    double worst = 0;
    for (int i = 0; i < M.count; i++) {
        const double P = cfpo_gridmodes_power(&M, i, n);
        const double D = direct_power(x, y, n, (double)M.mx[i] * M.q, (double)M.my[i] * M.q);
        const double e = fabs(P - D) / fmax(D, 1e-3);
        if (e > worst) worst = e;
    }
    CHECK(worst < 1e-7, "modes against direct sums: relative error %.3g", worst);
    T = M;
    cfpo_gridmodes_sum(&T, x, y, n, 3);
    CHECK(memcmp(T.acc, M.acc, sizeof M.acc) == 0, "1 and 3 threads: the sums differ");
    A = M, B = M;
    cfpo_gridmodes_sum(&A, x, y, 7001, 2);
    cfpo_gridmodes_sum(&B, x + 7001, y + 7001, n - 7001, 2);
    int differ = 0;
    for (int i = 0; i < 2 * M.count; i++) differ += A.acc[i] + B.acc[i] != M.acc[i];
    CHECK(differ == 0, "two parts' sums: %d of %d values differ from the whole's", differ, 2 * M.count);
    cfpo_gridmodes_free(&M); /* A, B and T share its table */
    free(x);
}

/* The largest P over the vectors of M, and over the ones marked. */
static void powers(cfpo_gridmodes *M, const double *x, const double *y, int64_t n, const int *planted, double *pl,
                   double *other)
{
    cfpo_gridmodes_sum(M, x, y, n, 2);
    *pl = *other = 0;
    for (int i = 0; i < M->count; i++) {
        const double P = cfpo_gridmodes_power(M, i, n);
        if (planted[i]) *pl = fmax(*pl, P);
        else *other = fmax(*other, P);
    }
}

static void test_field(void)
{
    const int side = 240, g = 3 * 64; /* n = 57,600 points, g/3 = 64 */
    const int64_t n = (int64_t)side * side;
    double *x = malloc(4 * (size_t)n * sizeof *x), *y = x + n, *x0 = y + n, *y0 = x0 + n;
    for (int64_t j = 0; j < n; j++) {
        x[j] = ((double)(j % side) + cfpo_rand01(5, 1, (uint64_t)j)) / side;
        y[j] = ((double)(j / side) + cfpo_rand01(5, 2, (uint64_t)j)) / side;
    }
    cfpo_gridmodes M;
    cfpo_gridmodes_init(&M, g, n);
    /* density waves of relative size 5% at (0, g), (g, 0) and (-g/3, 2g/3):
     * a displacement along k of amplitude e / (2 pi |k|) */
    const int wave[3][2] = {{0, 3}, {3, 0}, {-1, 2}};
    int planted[CFPO_GRIDMODES_MAX] = {0};
    for (int w = 0; w < 3; w++)
        for (int i = 0; i < M.count; i++)
            if (M.mx[i] == wave[w][0] && M.my[i] == wave[w][1]) planted[i] = 1;
    for (int64_t j = 0; j < n; j++)
        for (int w = 0; w < 3; w++) {
            const double kx = (double)wave[w][0] * M.q, ky = (double)wave[w][1] * M.q, k = sqrt(kx * kx + ky * ky);
            const double s = 0.05 / (2 * M_PI * k) * sin(2 * M_PI * (kx * x[j] + ky * y[j]) + w);
            x[j] += s * kx / k;
            y[j] += s * ky / k;
        }
    for (int64_t j = 0; j < n; j++) {
        x[j] -= floor(x[j]);
        y[j] -= floor(y[j]);
    }
    memcpy(x0, x, 2 * (size_t)n * sizeof *x);
    double pl0, ot0, pl1, ot1, pl2, ot2;
    powers(&M, x, y, n, planted, &pl0, &ot0);
    cfpo_gridmodes_finish(&M, n);
    for (int64_t j = 0; j < n; j++) {
        double ux, uy;
        cfpo_gridmodes_field(&M, x0[j], y0[j], &ux, &uy);
        x[j] = x0[j] + ux - floor(x0[j] + ux);
        y[j] = y0[j] + uy - floor(y0[j] + uy);
        x0[j] = x0[j] - ux - floor(x0[j] - ux);
        y0[j] = y0[j] - uy - floor(y0[j] - uy);
    }
    powers(&M, x, y, n, planted, &pl1, &ot1);
    powers(&M, x0, y0, n, planted, &pl2, &ot2);
    printf("planted P %.1f (others %.2f); along the field %.3f (%.2f); against it %.1f\n", pl0, ot0, pl1, ot1, pl2);
    CHECK(pl0 > 20, "the planted waves' P is %.1f, not above 20", pl0);
    CHECK(pl1 < 0.001 * pl0, "along the field the planted P fell from %.1f to %.3f only", pl0, pl1);
    CHECK(ot1 < 2 * ot0 + 1, "along the field the other vectors' P rose from %.2f to %.2f", ot0, ot1);
    CHECK(pl2 > 2 * pl0, "against the field the planted P went from %.1f to %.1f", pl0, pl2);
    cfpo_gridmodes_free(&M);
    free(x);
}

int main(void)
{
    test_vectors();
    test_modes();
    test_field();
    return test_report(passed_, failed_);
}
