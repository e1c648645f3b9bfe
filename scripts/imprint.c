/* imprint.c - the grid imprint of a point set, measured directly (docs/
 * results/2026-11-28-imprint.md): P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n
 * at k = (0, g), (g, 0), (0, 4g/3), (4g/3, 0) (g: cfpo's grid for n, or
 * --grid G), each divided by the mean of P over its own ring: RP_RING (96) integer
 * vectors spread evenly in angle with |k| rounding to the same radius (the
 * four axis vectors of the ring left out). A ratio near 1 is a clean set;
 * white noise gives ratios with an exponential spread (P / mean ~ Exp(1)).
 *
 * Build: cc -O2 -fopenmp -o imprint scripts/imprint.c -lm
 * Use:   imprint FILE.npy G [3|4]   (3: also the colours' period
 *        (0, g/3), (0, 2g/3) and the x ones, and the cells' diagonals
 *        (g, g), (-g, g) over the ring of |k| = g sqrt 2; 4: every
 *        vector (mx, my) g / 3 with |mx|, |my| <= 4 of the half plane,
 *        40 of them, the grid's and its colours' whole print up to the
 *        fourth harmonic; G: cfpo's cells a side, its SUMMARY's
 *        cells_per_side)
 * Prints one line: n g and, per vector, P, ring mean and their ratio
 * (mode 4: the largest ratio first, then every vector's, largest first). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/ring_power.h"

static double *read_npy(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char pre[10];
    if (fread(pre, 1, 10, f) != 10 || memcmp(pre, "\x93NUMPY", 6) != 0) return fclose(f), NULL;
    size_t hl = pre[8] | (size_t)pre[9] << 8;
    if (pre[6] >= 2) {
        unsigned char b[2];
        if (fread(b, 1, 2, f) != 2) return fclose(f), NULL;
        hl = pre[8] | (size_t)pre[9] << 8 | (size_t)b[0] << 16 | (size_t)b[1] << 24;
    }
    char *h = calloc(hl + 1, 1);
    if (!h || fread(h, 1, hl, f) != hl) return fclose(f), free(h), NULL;
    const int f4 = strstr(h, "<f4") != NULL;
    const char *s = strstr(h, "'shape': (");
    if (!s || strstr(h, "True")) return fclose(f), free(h), NULL;
    *n = strtoull(s + 10, NULL, 10);
    free(h);
    double *p = malloc(*n * 2 * sizeof *p);
    if (!p) return fclose(f), NULL;
    if (f4) {
        float *q = malloc(*n * 2 * sizeof *q);
        if (!q || fread(q, sizeof *q, *n * 2, f) != *n * 2) return fclose(f), free(q), free(p), NULL;
        for (size_t i = 0; i < *n * 2; i++) p[i] = q[i];
        free(q);
    } else if (fread(p, sizeof *p, *n * 2, f) != *n * 2) {
        return fclose(f), free(p), NULL;
    }
    fclose(f);
    return p;
}

/* Mode 4: P over its ring's mean at every (mx, my) g / 3, |mx|, |my| <= 4,
 * my > 0 or (my = 0, mx > 0); each ring computed once per radius. */
static int all_vectors(double *p, size_t n, int g)
{
    int vx[40], vy[40], nv = 0, rad[40];
    double ratio[40];
    for (int my = 0; my <= 4; my++)
        for (int mx = -4; mx <= 4; mx++) {
            if (my == 0 && mx <= 0) continue;
            vx[nv] = (int)lround(mx * g / 3.0), vy[nv] = (int)lround(my * g / 3.0);
            rad[nv] = (int)lround(sqrt((double)vx[nv] * vx[nv] + (double)vy[nv] * vy[nv]));
            nv++;
        }
    double rm[40];
    for (int v = 0; v < nv; v++) {
        rm[v] = -1;
        for (int q = 0; q < v; q++)
            if (rad[q] == rad[v]) rm[v] = rm[q];
        if (rm[v] < 0) rm[v] = rp_ring_mean(p, n, rad[v]);
        ratio[v] = rp_power(p, n, vx[v], vy[v]) / rm[v];
    }
    int ord[40];
    for (int v = 0; v < nv; v++) ord[v] = v;
    for (int a = 1; a < nv; a++)
        for (int b = a; b > 0 && ratio[ord[b]] > ratio[ord[b - 1]]; b--) {
            const int t = ord[b];
            ord[b] = ord[b - 1], ord[b - 1] = t;
        }
    printf("n=%zu g=%d largest=%.1f at (%d,%d)g/3 all:", n, g, ratio[ord[0]], (int)lround(3.0 * vx[ord[0]] / g),
           (int)lround(3.0 * vy[ord[0]] / g));
    for (int v = 0; v < nv; v++)
        printf(" (%d,%d)=%.1f", (int)lround(3.0 * vx[ord[v]] / g), (int)lround(3.0 * vy[ord[v]] / g), ratio[ord[v]]);
    printf("\n");
    free(p);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: imprint FILE.npy G\n");
        return 2;
    }
    size_t n = 0;
    double *p = read_npy(argv[1], &n);
    if (!p) {
        fprintf(stderr, "imprint: cannot read %s (a float64 or float32 .npy of shape (n, 2))\n", argv[1]);
        return 1;
    }
    const int g = atoi(argv[2]);
    if (argc > 3 && atoi(argv[3]) == 4) return all_vectors(p, n, g);
    const int g4 = (int)lround(4.0 * g / 3.0);
    const int vec[4][2] = {{0, g}, {g, 0}, {0, g4}, {g4, 0}};
    const char *name[4] = {"0,g", "g,0", "0,4g/3", "4g/3,0"};
    const double mg = rp_ring_mean(p, n, g), m4 = rp_ring_mean(p, n, g4);
    printf("n=%zu g=%d", n, g);
    for (int v = 0; v < 4; v++) {
        const double P = rp_power(p, n, vec[v][0], vec[v][1]), m = v < 2 ? mg : m4;
        printf(" P(%s)=%.3g ring=%.3g ratio=%.1f", name[v], P, m, P / m);
    }
    if (argc > 3) { /* the colours' period, 3 cells: (0, g/3), (0, 2g/3), (g/3, 0), (2g/3, 0) */
        const int g1 = (int)lround(g / 3.0), g2 = (int)lround(2.0 * g / 3.0);
        const double m1 = rp_ring_mean(p, n, g1), m2 = rp_ring_mean(p, n, g2);
        printf(" P(0,g/3)/ring=%.1f P(0,2g/3)/ring=%.1f P(g/3,0)/ring=%.1f P(2g/3,0)/ring=%.1f",
               rp_power(p, n, 0, g1) / m1, rp_power(p, n, 0, g2) / m2, rp_power(p, n, g1, 0) / m1, rp_power(p, n, g2, 0) / m2);
        /* the cells' diagonals: the two axes' walks have the same step,
         * so they do not turn a print at (-g, g) */
        const double md = rp_ring_mean(p, n, (int)lround(g * sqrt(2.0)));
        printf(" P(g,g)/ring=%.1f P(-g,g)/ring=%.1f", rp_power(p, n, g, g) / md, rp_power(p, n, -g, g) / md);
    }
    printf("\n");
    free(p);
    return 0;
}
