/* test_cuda_solver.c - the device solver gives the host solver's bits:
 * 20,000 local problems (random, clustered, collinear, duplicated points;
 * squares of every size; with and without a floor) solved by
 * cfpo_local_solve on the host and by cfpo_cuda_solve_batch on the device,
 * compared byte for byte. Without a CUDA device it says so and exits 77,
 * which CTest reports as skipped, not passed. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "rng.h"
#include "solver_device.h"

enum { B = 20000, MMAX = 40 };

static double u01(uint64_t *k) { return cfpo_rand01(0x5eedULL, (*k)++, 0); }

/* Problem b's points into yx/yy from index a; returns the count. */
static int make_points(int b, uint64_t *k, double *yx, double *yy)
{
    const int m = 1 + (int)(u01(k) * MMAX);
    const int kind = b % 4;
    for (int i = 0; i < m; i++) {
        double x = 3 * u01(k) - 1, y = 3 * u01(k) - 1;
        if (kind == 1) { x = 0.5 + 0.01 * u01(k); y = 0.5 + 0.01 * u01(k); }          /* clustered */
        if (kind == 2) { const double t = 3 * u01(k) - 1; x = t; y = 0.25 + 0.5 * t; } /* collinear */
        if (kind == 3 && i > 0 && u01(k) < 0.3) { x = yx[i - 1]; y = yy[i - 1]; }       /* duplicates */
        yx[i] = x;
        yy[i] = y;
    }
    return m;
}

int main(void)
{
    if (cfpo_cuda_devices() == 0) {
        printf("SKIPPED: no CUDA device\n");
        return 77;
    }
    int *off = malloc((B + 1) * sizeof *off), *skip = malloc(B * sizeof *skip);
    double *yx = malloc((size_t)B * MMAX * sizeof *yx), *yy = malloc((size_t)B * MMAX * sizeof *yy);
    double *hx = malloc(B * sizeof *hx), *hy = malloc(B * sizeof *hy), *fl = malloc(B * sizeof *fl);
    double *v1 = malloc(B * sizeof *v1), *x1 = malloc(B * sizeof *x1), *y1 = malloc(B * sizeof *y1);
    double *v2 = malloc(B * sizeof *v2), *x2 = malloc(B * sizeof *x2), *y2 = malloc(B * sizeof *y2);
    cfpo_square *S = malloc(B * sizeof *S);
    double *scratch = malloc(cfpo_solver_scratch(MMAX) * sizeof *scratch);
    uint64_t k = 0;
    off[0] = 0;
    for (int b = 0; b < B; b++) {
        const int m = make_points(b, &k, yx + off[b], yy + off[b]);
        off[b + 1] = off[b] + m;
        skip[b] = u01(&k) < 0.2 ? -1 : (int)(u01(&k) * m);
        const double e = 0.5 * u01(&k);
        S[b] = (cfpo_square){-e, -e, 1 + e, 1 + e};
        hx[b] = u01(&k);
        hy[b] = u01(&k);
        fl[b] = u01(&k) < 0.5 ? -1 : 0.05 * u01(&k);
        v1[b] = cfpo_local_solve(yx + off[b], yy + off[b], m, skip[b], S[b], hx[b], hy[b], fl[b], &x1[b], &y1[b],
                                 scratch);
    }
    char err[256];
    if (cfpo_cuda_solve_batch(B, off, yx, yy, skip, S, hx, hy, fl, v2, x2, y2, err, sizeof err) != 0) {
        printf("FAIL: %s\n", err);
        return 1;
    }
    int bad = 0;
    for (int b = 0; b < B; b++)
        if (memcmp(&v1[b], &v2[b], 8) || memcmp(&x1[b], &x2[b], 8) || memcmp(&y1[b], &y2[b], 8)) {
            if (bad++ < 5)
                printf("FAIL: problem %d (m = %d): host %.17g at (%.17g, %.17g), device %.17g at (%.17g, %.17g)\n", b,
                       off[b + 1] - off[b], v1[b], x1[b], y1[b], v2[b], x2[b], y2[b]);
        }
    printf("%d of %d problems differ\n", bad, B);
    return bad != 0;
}
