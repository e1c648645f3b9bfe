/* grid.c - see grid.h. */
#include "grid.h"

#include <math.h>
#include <stdio.h>

#include "rng.h"

/* Stream numbers for the generator: cell c's coordinates use stream 2c+1,
 * the choice of cells with a second point uses a key derived from seed. */
#define PERM_SALT 0x5bd1e9955bd1e995ULL

int64_t cfpo_grid_min_n(int variant)
{
    /* Smallest grid: 3x3 (full) or 4x4 (simplified, an even g >= 4 so that
     * same-colour cells are distinct). L > Delta(n) needs n > 2 g^2/sqrt(3). */
    int64_t g = variant == CFPO_VARIANT_SIMPLIFIED ? 4 : 3;
    int64_t n = (int64_t)floor(2.0 * (double)(g * g) / sqrt(3.0)) + 1;
    while (1.0 / (double)g <= cfpo_delta_bound((double)n)) n++;
    return n;
}

int cfpo_grid_init(cfpo_grid *G, int64_t n, int variant, uint64_t seed, char *err, size_t errlen)
{
    const int period = variant == CFPO_VARIANT_SIMPLIFIED ? 2 : 3;
    const int64_t gmin = variant == CFPO_VARIANT_SIMPLIFIED ? 4 : 3;
    int64_t nmin = cfpo_grid_min_n(variant);
    if (n < nmin) {
        snprintf(err, errlen, "n = %lld is too small for %s: at least %lld points are needed "
                 "(a %lldx%lld grid with cells wider than Delta(n))", (long long)n,
                 variant == CFPO_VARIANT_SIMPLIFIED ? "simplified CFPO" : "CFPO",
                 (long long)nmin, (long long)gmin, (long long)gmin);
        return -1;
    }
    const double delta = cfpo_delta_bound((double)n);
    /* Nearest multiple of the period to sqrt(0.8 n), then down until the
     * cell is wider than Delta(n) and no cell needs more than... g^2 <= n. */
    int64_t g = (int64_t)llround(sqrt(0.8 * (double)n) / period) * period;
    if (g < gmin) g = gmin;
    while (g > gmin && (1.0 / (double)g <= delta || g * g > n)) g -= period;
    G->n = n;
    G->g = g;
    G->L = 1.0 / (double)g;
    G->delta = delta;
    G->variant = variant;
    G->period = period;
    G->margin = variant == CFPO_VARIANT_SIMPLIFIED ? 0.0 : G->L - delta;
    G->seed = seed;
    G->extra = (uint64_t)(n - g * g);
    G->shift_x = G->shift_y = 0;
    return 0;
}

uint64_t cfpo_grid_cell_count(const cfpo_grid *G, uint64_t c)
{
    const uint64_t cells = (uint64_t)(G->g * G->g);
    /* n - g^2 extra points: each cell gets extra / cells more, and the
     * cells whose permuted index falls below the remainder one more. */
    uint64_t base = 1 + G->extra / cells, rem = G->extra % cells;
    if (rem == 0) return base;
    return base + (cfpo_permute(c, cells, cfpo_mix64(G->seed ^ PERM_SALT)) < rem ? 1 : 0);
}

/* A coordinate in cell column (row) i of the unshifted grid. */
static double coord_in_cell(const cfpo_grid *G, int64_t i, double u)
{
    double v = ((double)i + u) * G->L;
    /* Rounding may put v on a neighbour's side of the boundary: step back. */
    while (cfpo_grid_axis(G, v, 0) > i) v = nextafter(v, 0.0);
    while (cfpo_grid_axis(G, v, 0) < i) v = nextafter(v, 1.0);
    return v;
}

void cfpo_grid_cell_point(const cfpo_grid *G, int64_t cx, int64_t cy, uint64_t k, double *x,
                          double *y)
{
    uint64_t stream = 2 * (uint64_t)(cy * G->g + cx) + 1;
    *x = coord_in_cell(G, cx, cfpo_rand01(G->seed, stream, 2 * k));
    *y = coord_in_cell(G, cy, cfpo_rand01(G->seed, stream, 2 * k + 1));
}
