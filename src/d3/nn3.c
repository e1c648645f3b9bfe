/* nn3.c - see nn3.h. The grid has about two points a cell; point i's
 * search visits the shells of cells at Chebyshev distance r = 0, 1, ...
 * and stops once its k-th distance is at most r cell sides (every point of
 * a farther shell is farther than that), or once the shells cover the
 * torus. */
#include "nn3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solve3.h"

static int cell_of(double x, int g)
{
    int c = (int)(x * g);
    return c < 0 ? 0 : (c >= g ? g - 1 : c);
}

/* Insert (d, j) into the sorted list of at most k. */
static void push(double *bd, int64_t *bi, int *cnt, int k, double d, int64_t j)
{
    int c = *cnt;
    if (c == k && (d > bd[k - 1] || (d == bd[k - 1] && j > bi[k - 1]))) return;
    int at = c == k ? k - 1 : c;
    while (at > 0 && (bd[at - 1] > d || (bd[at - 1] == d && bi[at - 1] > j))) {
        bd[at] = bd[at - 1];
        bi[at] = bi[at - 1];
        at--;
    }
    bd[at] = d;
    bi[at] = j;
    if (c < k) (*cnt)++;
}

int cfpo3_knn(const double *p, size_t n, int k, int64_t *idx, double *d2)
{
    int g = (int)floor(cbrt((double)n / 2.0));
    if (g < 1) g = 1;
    const size_t G3 = (size_t)g * g * g;
    size_t *start = calloc(G3 + 1, sizeof *start);
    size_t *ids = malloc(n * sizeof *ids);
    int *cell = malloc(n * sizeof *cell);
    double *bdall = malloc((size_t)k * n * sizeof *bdall);
    int64_t *biall = malloc((size_t)k * n * sizeof *biall);
    if (!start || !ids || !cell || !bdall || !biall) {
        free(start), free(ids), free(cell), free(bdall), free(biall);
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        const int c = (cell_of(p[3 * i + 2], g) * g + cell_of(p[3 * i + 1], g)) * g + cell_of(p[3 * i], g);
        cell[i] = c;
        start[c + 1]++;
    }
    for (size_t c = 0; c < G3; c++) start[c + 1] += start[c];
    {
        size_t *fill = malloc(G3 * sizeof *fill);
        if (!fill) {
            free(start), free(ids), free(cell), free(bdall), free(biall);
            return -1;
        }
        memcpy(fill, start, G3 * sizeof *fill);
        for (size_t i = 0; i < n; i++) ids[fill[cell[i]]++] = i;
        free(fill);
    }
    const double Lc = 1.0 / g;
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t i = 0; i < n; i++) {
        double *bd = bdall + (size_t)k * i;
        int64_t *bi = biall + (size_t)k * i;
        int cnt = 0;
        const int c = cell[i], ci = c % g, cj = (c / g) % g, ck = c / (g * g);
        for (int r = 0;; r++) {
            const int lo = -r, hi = r;
            const int wide = 2 * r + 1 >= g; /* this shell wraps onto cells already seen */
            for (int dz = lo; dz <= hi; dz++)
                for (int dy = lo; dy <= hi; dy++)
                    for (int dx = lo; dx <= hi; dx++) {
                        const int m = abs(dx) > abs(dy) ? abs(dx) : abs(dy);
                        if ((m > abs(dz) ? m : abs(dz)) != r) continue;
                        if (wide) { /* visit each cell once: offsets in [-(g-1)/2 .. g/2] only */
                            if (dx < -(g - 1) / 2 || dx > g / 2 || dy < -(g - 1) / 2 || dy > g / 2 ||
                                dz < -(g - 1) / 2 || dz > g / 2)
                                continue;
                        }
                        const int x = ((ci + dx) % g + g) % g, y = ((cj + dy) % g + g) % g,
                                  z = ((ck + dz) % g + g) % g;
                        const size_t cc = ((size_t)z * g + y) * g + x;
                        for (size_t s = start[cc]; s < start[cc + 1]; s++) {
                            const size_t j = ids[s];
                            if (j == i) continue;
                            const double ex = cfpo3_pdiff(p[3 * j], p[3 * i]);
                            const double ey = cfpo3_pdiff(p[3 * j + 1], p[3 * i + 1]);
                            const double ez = cfpo3_pdiff(p[3 * j + 2], p[3 * i + 2]);
                            push(bd, bi, &cnt, k, ex * ex + ey * ey + ez * ez, (int64_t)j);
                        }
                    }
            if (2 * r + 1 >= g) break; /* every cell seen */
            const double reach = r * Lc;
            if (cnt == k && bd[k - 1] <= reach * reach) break;
        }
    }
    if (idx) memcpy(idx, biall, (size_t)k * n * sizeof *idx);
    if (d2) memcpy(d2, bdall, (size_t)k * n * sizeof *d2);
    free(start), free(ids), free(cell), free(bdall), free(biall);
    return 0;
}

int cfpo3_nn_stats(const double *p, size_t n, double *nn, double *delta_min, double *delta_avg)
{
    double *d2 = malloc(n * sizeof *d2);
    if (!d2 || cfpo3_knn(p, n, 1, NULL, d2) != 0) {
        free(d2);
        return -1;
    }
    double mn = INFINITY, sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double d = sqrt(d2[i]);
        if (nn) nn[i] = d;
        if (d < mn) mn = d;
        sum += d;
    }
    const double D = cfpo3_delta_bound((double)n);
    *delta_min = mn / D;
    *delta_avg = sum / (double)n / D;
    free(d2);
    return 0;
}
