/* dens_buckets.c - layer 2: the bucket grid of a density block (dens_buckets.h). */
#include "dens_buckets.h"

#include <math.h>
#include <stdlib.h>

static int axis(const cfpo_dens_buckets *b, double v, double origin)
{
    const double t = floor((v - origin) / b->h);
    if (b->wrap) {
        long long i = (long long)t % b->B;
        return (int)(i < 0 ? i + b->B : i);
    }
    return t < 0 ? 0 : t >= b->B ? b->B - 1 : (int)t;
}

int cfpo_dens_bucket_of(const cfpo_dens_buckets *b, double x, double y)
{
    if (b->B == 1) return 0; /* one bucket: every position (axis() gives 0 on both axes) */
    return axis(b, y, b->y0) * b->B + axis(b, x, b->x0);
}

int cfpo_dens_buckets_build(cfpo_dens_buckets *b, const double *x, const double *y, int m, double x0, double y0,
                            double side, int wrap, double per)
{
    int B = (int)ceil(sqrt((double)m / per));
    if (B < 1) B = 1;
    if (B > 4096) B = 4096;
    const size_t nb = (size_t)B * (size_t)B;
    if (nb > b->cap_b) {
        free(b->head);
        b->head = malloc(nb * sizeof *b->head);
        b->cap_b = b->head ? nb : 0;
        if (!b->head) return -1;
    }
    if ((size_t)m > b->cap_m) {
        free(b->next);
        const size_t cap = (size_t)m + (size_t)m / 2 + 16;
        b->next = malloc(cap * sizeof *b->next);
        b->cap_m = b->next ? cap : 0;
        if (!b->next) return -1;
    }
    b->B = B;
    b->wrap = wrap;
    b->x0 = x0;
    b->y0 = y0;
    b->h = side / (double)B;
    for (size_t i = 0; i < nb; i++) b->head[i] = -1;
    if (B == 1) { /* the points in order, no position read */
        for (int p = 0; p < m; p++) b->next[p] = p + 1 < m ? p + 1 : -1;
        if (m > 0) b->head[0] = 0;
        return 0;
    }
    for (int p = m - 1; p >= 0; p--) {
        const int c = cfpo_dens_bucket_of(b, x[p], y[p]);
        b->next[p] = b->head[c];
        b->head[c] = p;
    }
    return 0;
}

void cfpo_dens_buckets_move(cfpo_dens_buckets *b, int p, int from, int to)
{
    if (from == to) return;
    int *q = &b->head[from];
    while (*q != p) q = &b->next[*q];
    *q = b->next[p];
    b->next[p] = b->head[to];
    b->head[to] = p;
}

int cfpo_dens_ring(const cfpo_dens_buckets *b, int c, int k, int *out)
{
    const int B = b->B, cx = c % B, cy = c / B;
    if (k == 0) {
        out[0] = c;
        return 1;
    }
    if (b->wrap) {
        if (2 * (k - 1) + 1 >= B) return -1;
    } else if (cx - k < 0 && cx + k >= B && cy - k < 0 && cy + k >= B) {
        return -1;
    }
    int n = 0;
    for (int dy = -k; dy <= k; dy++) {
        const int step = (dy == -k || dy == k) ? 1 : 2 * k;
        for (int dx = -k; dx <= k; dx += step) {
            int x = cx + dx, y = cy + dy;
            if (b->wrap) {
                x = ((x % B) + B) % B;
                y = ((y % B) + B) % B;
            } else if (x < 0 || x >= B || y < 0 || y >= B) {
                continue;
            }
            out[n++] = y * B + x;
        }
    }
    return n;
}

void cfpo_dens_span(const cfpo_dens_buckets *b, double lo, double hi, double origin, int *first, int *count)
{
    if (b->B == 1) { /* one bucket: it covers every span (both branches below give 0, 1) */
        *first = 0;
        *count = 1;
        return;
    }
    const double t0 = floor((lo - origin) / b->h), t1 = floor((hi - origin) / b->h);
    if (b->wrap) {
        const double w = t1 - t0 + 1;
        *count = w >= b->B ? b->B : (int)w;
        long long i = (long long)t0 % b->B;
        *first = (int)(i < 0 ? i + b->B : i);
        return;
    }
    const int a = t0 < 0 ? 0 : t0 >= b->B ? b->B - 1 : (int)t0;
    const int z = t1 < 0 ? 0 : t1 >= b->B ? b->B - 1 : (int)t1;
    *first = a;
    *count = z - a + 1;
}

void cfpo_dens_buckets_free(cfpo_dens_buckets *b)
{
    free(b->head);
    free(b->next);
    b->head = b->next = NULL;
    b->cap_b = b->cap_m = 0;
}
