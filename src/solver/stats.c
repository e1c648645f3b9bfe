/* stats.c - see stats.h. Grid of about 2 points per cell; each point looks
 * at rings of cells outward until no unvisited cell can hold a closer
 * point; past half the torus it falls back to all points. */
#include "stats.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "geom.h"

static size_t coord(double v, size_t g)
{
    size_t c = (size_t)(v * (double)g);
    return c >= g ? g - 1 : c;
}

int cfpo_nn_stats(const double *xy, size_t n, double *nn, double *delta_min, double *delta_avg)
{
    if (n < 2) return -1;
    size_t g = (size_t)floor(sqrt((double)n / 2.0));
    if (g < 1) g = 1;
    const size_t cells = g * g;
    size_t *start = calloc(cells + 1, sizeof *start);
    size_t *idx = malloc(n * sizeof *idx);
    double *rowsum = malloc(g * sizeof *rowsum), *rowmin = malloc(g * sizeof *rowmin);
    if (!start || !idx || !rowsum || !rowmin) {
        free(start); free(idx); free(rowsum); free(rowmin);
        return -1;
    }
    for (size_t i = 0; i < n; i++) start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g) + 1]++;
    for (size_t c = 0; c < cells; c++) start[c + 1] += start[c];
    for (size_t i = 0; i < n; i++) idx[start[coord(xy[2 * i + 1], g) * g + coord(xy[2 * i], g)]++] = i;
    for (size_t c = cells; c > 0; c--) start[c] = start[c - 1];
    start[0] = 0;
    const double L = 1.0 / (double)g;
    const long gg = (long)g;
#pragma omp parallel for schedule(dynamic, 4)
    for (long cy = 0; cy < gg; cy++) {
        double sum = 0, mn = INFINITY;
        for (long cx = 0; cx < gg; cx++)
            for (size_t k = start[cy * gg + cx]; k < start[cy * gg + cx + 1]; k++) {
                const size_t i = idx[k];
                const double x = xy[2 * i], y = xy[2 * i + 1];
                const double lx = x - (double)cx * L, ly = y - (double)cy * L;
                double edge = fmin(fmin(lx, L - lx), fmin(ly, L - ly));
                if (edge < 0) edge = 0;
                double best = INFINITY;
                for (long r = 0;; r++) {
                    if (2 * r + 1 > gg) {
                        for (size_t j = 0; j < n; j++)
                            if (j != i) best = fmin(best, cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]));
                        break;
                    }
                    for (long dy = -r; dy <= r; dy++)
                        for (long dx = -r; dx <= r; dx++) {
                            if (dy != -r && dy != r && dx != -r && dx != r) continue;
                            size_t c = (size_t)(((cy + dy + gg) % gg) * gg + (cx + dx + gg) % gg);
                            for (size_t q = start[c]; q < start[c + 1]; q++) {
                                size_t j = idx[q];
                                if (j == i) continue;
                                double d2 = cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]);
                                if (d2 < best) best = d2;
                            }
                        }
                    double reach = (double)r * L + edge;
                    if (best <= reach * reach) break;
                }
                double d = sqrt(best);
                if (nn) nn[i] = d;
                sum += d;
                if (d < mn) mn = d;
            }
        rowsum[cy] = sum;
        rowmin[cy] = mn;
    }
    double sum = 0, mn = INFINITY;
    for (size_t cy = 0; cy < g; cy++) {
        sum += rowsum[cy];
        if (rowmin[cy] < mn) mn = rowmin[cy];
    }
    const double D = cfpo_delta_bound((double)n);
    *delta_min = mn / D;
    *delta_avg = sum / (double)n / D;
    free(start); free(idx); free(rowsum); free(rowmin);
    return 0;
}
