/* jitter.c - see jitter.h. */
#include "jitter.h"

#include <math.h>

#include "rng.h"

static const uint64_t WHITE_STREAM = 0x5748495445000000ULL;  /* "WHITE" */
static const uint64_t JITTER_STREAM = 0x4a49545445520000ULL; /* "JITTER" */

void white_points(int64_t n, uint64_t seed, double *xy)
{
    for (int64_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(seed, WHITE_STREAM, (uint64_t)i);
}

int64_t jitter_rows(int64_t n)
{
    int64_t r = (int64_t)llround(sqrt((double)n));
    while (r > 1 && r * r >= n + r) r--; /* round(sqrt(n)), exact for large n */
    while ((r + 1) * (r + 1) <= n + r) r++;
    return r < 1 ? 1 : r;
}

void jitter_row(int64_t n, int64_t k, int64_t *first, int64_t *count)
{
    const int64_t r = jitter_rows(n);
    /* floor(k n / r) without overflow for n < 2^62 / r */
    const __int128 a = (__int128)k * n / r, b = (__int128)(k + 1) * n / r;
    *first = (int64_t)a;
    *count = (int64_t)(b - a);
}

void jitter_points(int64_t n, uint64_t seed, double *xy)
{
    const int64_t r = jitter_rows(n);
    for (int64_t k = 0; k < r; k++) {
        int64_t first, count;
        jitter_row(n, k, &first, &count);
        for (int64_t c = 0; c < count; c++) {
            const int64_t i = first + c;
            const double u = cfpo_rand01(seed, JITTER_STREAM, 2 * (uint64_t)i);
            const double v = cfpo_rand01(seed, JITTER_STREAM, 2 * (uint64_t)i + 1);
            double x = ((double)c + u) / (double)count, y = ((double)k + v) / (double)r;
            /* rounding may land on the cell's upper edge; keep [0, 1) */
            if (x >= 1.0) x = nextafter(1.0, 0.0);
            if (y >= 1.0) y = nextafter(1.0, 0.0);
            xy[2 * i] = x;
            xy[2 * i + 1] = y;
        }
    }
}
