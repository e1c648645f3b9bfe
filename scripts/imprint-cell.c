/* imprint-cell.c - where a set's grid print sits inside the cells
 * (docs/results/2026-11-29-imprint8.md): the histogram of the points'
 * positions within the cells of the grid cfpo used in iteration K (the
 * default variant's offsets for that seed, asked of the engine's own
 * policy), on each axis, relative to a uniform set (1 = uniform); then
 * the print on each axis, P = |sum_j exp(2 pi i m Y_j / 3)|^2 / n with
 * Y_j the point's position over the colours' period 3 L in cells, for
 * m = 1..4 (m = 3: (g, 0) or (0, g)), split into the part of the points
 * within W cells of the two lines where a square of margin E cells ends
 * (E and 1 - E within the cell) and the rest.
 *
 * Build: cc -O2 -Isrc -Isrc/common -Isrc/engine -Isrc/solver -o imprint-cell \
 *            scripts/imprint-cell.c build/libcfpo_core.a -lm
 * Use:   imprint-cell FILE.npy SEED K [BINS [E W]]
 *        (K: the iteration whose grid to use, 1 for a --max-iter 1 set;
 *        E: the margin over L, e.g. 0.328 at 1,048,576 points early on) */
#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "policy.h"

static double *read_npy(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char pre[10];
    if (fread(pre, 1, 10, f) != 10 || memcmp(pre, "\x93NUMPY", 6) != 0 || pre[6] != 1) return fclose(f), NULL;
    const size_t hl = pre[8] | (size_t)pre[9] << 8;
    char *h = calloc(hl + 1, 1);
    if (!h || fread(h, 1, hl, f) != hl) return fclose(f), free(h), NULL;
    const int f4 = strstr(h, "<f4") != NULL;
    const char *s = strstr(h, "'shape': (");
    if (!s) return fclose(f), free(h), NULL;
    *n = strtoull(s + 10, NULL, 10);
    free(h);
    double *p = malloc(*n * 2 * sizeof *p);
    int ok = p != NULL;
    if (ok && f4) {
        float *q = malloc(*n * 2 * sizeof *q);
        ok = q && fread(q, sizeof *q, *n * 2, f) == *n * 2;
        for (size_t i = 0; ok && i < *n * 2; i++) p[i] = q[i];
        free(q);
    } else if (ok) {
        ok = fread(p, sizeof *p, *n * 2, f) == *n * 2;
    }
    fclose(f);
    if (!ok) free(p);
    return ok ? p : NULL;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: imprint-cell FILE.npy SEED K [BINS [E W]]\n");
        return 2;
    }
    size_t n;
    double *p = read_npy(argv[1], &n);
    if (!p) {
        fprintf(stderr, "imprint-cell: cannot read %s\n", argv[1]);
        return 1;
    }
    const uint64_t seed = strtoull(argv[2], NULL, 10);
    const int k = atoi(argv[3]), B = argc > 4 ? atoi(argv[4]) : 20;
    const double E = argc > 6 ? atof(argv[5]) : 0.328, W = argc > 6 ? atof(argv[6]) : 0.01;
    cfpo_grid G;
    char err[200];
    if (B < 1 || B > 1000 || cfpo_grid_init(&G, (int64_t)n, CFPO_VARIANT_ADAPTIVE, seed, err, sizeof err) != 0) {
        fprintf(stderr, "imprint-cell: bad arguments\n");
        return 1;
    }
    const double g = (double)G.g;
    double sh[2], walk[2];
    for (int a = 0; a < 2; a++) sh[a] = cfpo_policy_shift(&G, k, a), walk[a] = cfpo_policy_walk(&G, k, a);
    printf("n=%zu g=%lld iteration %d: offsets %.4f %.4f cells, walk %.4f %.4f\n", n, (long long)G.g, k, sh[0] * g,
           sh[1] * g, walk[0], walk[1]);
    long *h = calloc((size_t)B * 2, sizeof *h);
    double complex c[2][4] = {{0}}, ce[2][4] = {{0}};
    long ne[2] = {0, 0};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 2; a++) {
            double v = (p[2 * i + a] - sh[a]) * g; /* cells from the grid's line 0 */
            v -= floor(v / g) * g;
            const double fr = v - floor(v), Y = fmod(v, 3.0);
            int b = (int)(fr * B);
            h[a * B + (b < B ? b : B - 1)]++;
            const int edge = fabs(fr - E) < W || fabs(fr - (1 - E)) < W;
            ne[a] += edge;
            for (int m = 1; m <= 4; m++) {
                const double complex z = cexp(2 * M_PI * I * m * Y / 3);
                c[a][m - 1] += z;
                if (edge) ce[a][m - 1] += z;
            }
        }
    printf("position within the cell (bin of %d), x, y, 1 = uniform\n", B);
    for (int b = 0; b < B; b++)
        printf("%6.3f %7.4f %7.4f\n", (b + 0.5) / B, h[b] * (double)B / n, h[B + b] * (double)B / n);
    for (int a = 0; a < 2; a++) {
        printf("axis %c: %.4f of the points within %.3f of %.3f or %.3f (uniform: %.4f)\n", a ? 'y' : 'x',
               (double)ne[a] / n, W, E, 1 - E, 4 * W);
        for (int m = 1; m <= 4; m++) {
            const double complex r = c[a][m - 1] - ce[a][m - 1];
            printf("  m=%d P=%.1f edge part %.1f rest %.1f\n", m, creal(c[a][m - 1] * conj(c[a][m - 1])) / n,
                   creal(ce[a][m - 1] * conj(ce[a][m - 1])) / n, creal(r * conj(r)) / n);
        }
    }
    free(h);
    free(p);
    return 0;
}
