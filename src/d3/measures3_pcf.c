/* measures3_pcf.c - see measures3_pcf.h. */
#include "measures3_pcf.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nn3.h"
#include "solve3.h"

static long cell1(double x, long G)
{
    long c = (long)(x * (double)G);
    return c < 0 ? 0 : (c >= G ? G - 1 : c);
}

int cfpo3_pcf(const double *p, size_t n, double rmax, double dr, double *g, int bins)
{
    const double D = cfpo3_delta_bound((double)n), R = rmax * D, R2 = R * R;
    if (!(R < 0.5) || n < 2 || bins < 1) return -1;
    long G = (long)floor(1.0 / R);
    if (G < 3) G = 1; /* every pair, one image each: cells of the whole box */
    if (G > 512) G = 512;
    const size_t cells = (size_t)G * (size_t)G * (size_t)G;
    size_t *start = calloc(cells + 2, sizeof *start), *idx = malloc(n * sizeof *idx);
    uint64_t *h = calloc((size_t)bins, sizeof *h);
    if (!start || !idx || !h) {
        free(start), free(idx), free(h);
        return -1;
    }
#define CELL(i) ((size_t)((cell1(p[3 * (i) + 2], G) * G + cell1(p[3 * (i) + 1], G)) * G + cell1(p[3 * (i)], G)))
    for (size_t i = 0; i < n; i++) start[CELL(i) + 2]++;
    for (size_t c = 2; c < cells + 2; c++) start[c] += start[c - 1];
    for (size_t i = 0; i < n; i++) idx[start[CELL(i) + 1]++] = i;
    const long reach = G == 1 ? 0 : 1;
    for (size_t i = 0; i < n; i++) {
        const long cx = cell1(p[3 * i], G), cy = cell1(p[3 * i + 1], G), cz = cell1(p[3 * i + 2], G);
        for (long oz = -reach; oz <= reach; oz++)
            for (long oy = -reach; oy <= reach; oy++)
                for (long ox = -reach; ox <= reach; ox++) {
                    const size_t c = (size_t)((((cz + oz + G) % G) * G + (cy + oy + G) % G) * G + (cx + ox + G) % G);
                    for (size_t k = start[c]; k < start[c + 1]; k++) {
                        const size_t j = idx[k];
                        if (j <= i) continue;
                        const double dx = cfpo3_pdiff(p[3 * i], p[3 * j]), dy = cfpo3_pdiff(p[3 * i + 1], p[3 * j + 1]),
                                     dz = cfpo3_pdiff(p[3 * i + 2], p[3 * j + 2]);
                        const double q = dx * dx + dy * dy + dz * dz;
                        if (q >= R2) continue;
                        const long b = (long)(sqrt(q) / D / dr);
                        if (b < bins) h[b]++;
                    }
                }
    }
#undef CELL
    const double pairs = (double)n * (double)(n - 1) / 2;
    for (int b = 0; b < bins; b++) {
        const double lo = b * dr * D, hi = (b + 1) * dr * D;
        g[b] = (double)h[b] / (pairs * 4.0 / 3.0 * M_PI * (hi * hi * hi - lo * lo * lo));
    }
    free(start), free(idx), free(h);
    return 0;
}

int cfpo3_pcf_bins(size_t n, double rmax, double dr)
{
    const double D = cfpo3_delta_bound((double)n);
    while (rmax * D >= 0.5) rmax -= dr;
    return (int)floor(rmax / dr + 1e-9);
}
