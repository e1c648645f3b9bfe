/* grid3.c - see grid3.h. */
#include "grid3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rng.h"
#include "solve3.h"

#define START_SALT 0x3d5bd1e995a1c3b7ULL

int64_t cfpo3_icbrt(int64_t n)
{
    int64_t h = (int64_t)cbrt((double)n);
    while (h > 0 && h * h * h > n) h--;
    while ((h + 1) * (h + 1) * (h + 1) <= n) h++;
    return h;
}

int64_t cfpo3_grid_min_n(void)
{
    int64_t n = 1;
    while (1.0 / 3.0 <= cfpo3_delta_bound((double)n)) n++;
    return n;
}

int cfpo3_grid_choose(int64_t n, cfpo3_grid *G, char *err, size_t errlen)
{
    const int64_t nmin = cfpo3_grid_min_n();
    if (n < nmin) {
        snprintf(err, errlen, "n = %lld is too small: at least %lld points are needed in 3-D "
                 "(a 3x3x3 grid with cells wider than Delta3(n))", (long long)n, (long long)nmin);
        return -1;
    }
    const double want = (double)n / 1.5;
    int64_t g = 3 * (int64_t)floor(cbrt(want) / 3.0);
    if (g < 3) g = 3;
    const double a = fabs((double)(g * g * g) - want), b = fabs((double)((g + 3) * (g + 3) * (g + 3)) - want);
    if (b < a) g += 3;
    const double d3 = cfpo3_delta_bound((double)n);
    while (g > 3 && 1.0 / (double)g <= d3) g -= 3;
    if (g > 1290) { /* g^3 must index cells in 32 bits */
        snprintf(err, errlen, "n = %lld is too large for one 3-D grid", (long long)n);
        return -1;
    }
    G->n = n;
    G->g = (int)g;
    G->L = 1.0 / (double)g;
    G->delta3 = d3;
    return 0;
}

int cfpo3_start(int64_t n, uint64_t seed, double *pos)
{
    const int64_t h = cfpo3_icbrt(n), h3 = h * h * h, extra = n - h3;
    unsigned char *two = calloc((size_t)h3, 1);
    int64_t *first = malloc(sizeof(int64_t) * (size_t)h3);
    if (!two || !first) {
        free(two);
        free(first);
        return -1;
    }
    const uint64_t key = cfpo_mix64(seed ^ START_SALT);
    for (int64_t r = 0; r < extra; r++) two[cfpo_permute((uint64_t)r, (uint64_t)h3, key)] = 1;
    int64_t id = 0;
    for (int64_t c = 0; c < h3; c++) {
        first[c] = id;
        id += 1 + two[c];
    }
#pragma omp parallel for schedule(static)
    for (int64_t c = 0; c < h3; c++) {
        const int64_t i = c % h, j = (c / h) % h, k = c / (h * h);
        for (int p = 0; p <= two[c]; p++) {
            double *x = pos + 3 * (first[c] + p);
            const uint64_t s = 2 * (uint64_t)c + 1;
            x[0] = ((double)i + cfpo_rand01(seed, s, 3 * (uint64_t)p + 0)) / (double)h;
            x[1] = ((double)j + cfpo_rand01(seed, s, 3 * (uint64_t)p + 1)) / (double)h;
            x[2] = ((double)k + cfpo_rand01(seed, s, 3 * (uint64_t)p + 2)) / (double)h;
            for (int a = 0; a < 3; a++)
                if (x[a] >= 1.0) x[a] = 0.0;
        }
    }
    free(two);
    free(first);
    return 0;
}
