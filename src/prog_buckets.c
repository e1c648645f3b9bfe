/* prog_buckets.c - see prog_buckets.h. */
#include "prog_buckets.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"

int prog_buckets_init(prog_buckets *B, const double *xy, int64_t m, int64_t cap)
{
    return prog_buckets_init_side(B, xy, cfpo_delta_bound((double)m), cap);
}

int prog_buckets_build(prog_buckets *B, const double *xy, int64_t m)
{
    if (prog_buckets_init(B, xy, m, m) != 0) return -1;
    for (int64_t k = m - 1; k >= 0; k--) prog_buckets_link(B, k);
    return 0;
}

int prog_buckets_init_side(prog_buckets *B, const double *xy, double side, int64_t cap)
{
    B->gs = (int64_t)floor(1.0 / side);
    if (B->gs < 1) B->gs = 1;
    B->cs = 1.0 / (double)B->gs;
    B->xy = xy;
    B->head = malloc((size_t)(B->gs * B->gs) * sizeof *B->head);
    B->next = malloc((size_t)(cap > 0 ? cap : 1) * sizeof *B->next);
    if (!B->head || !B->next) return -1;
    for (int64_t b = 0; b < B->gs * B->gs; b++) B->head[b] = -1;
    return 0;
}

void prog_buckets_free(prog_buckets *B)
{
    free(B->head);
    free(B->next);
    B->head = B->next = NULL;
}

int64_t prog_buckets_of(const prog_buckets *B, double x, double y)
{
    int64_t bx = (int64_t)(x * (double)B->gs), by = (int64_t)(y * (double)B->gs);
    if (bx >= B->gs) bx = B->gs - 1;
    if (by >= B->gs) by = B->gs - 1;
    if (bx < 0) bx = 0;
    if (by < 0) by = 0;
    return by * B->gs + bx;
}

void prog_buckets_link(prog_buckets *B, int64_t k)
{
    const int64_t b = prog_buckets_of(B, B->xy[2 * k], B->xy[2 * k + 1]);
    B->next[k] = B->head[b];
    B->head[b] = k;
}

void prog_buckets_unlink(prog_buckets *B, int64_t k)
{
    const int64_t b = prog_buckets_of(B, B->xy[2 * k], B->xy[2 * k + 1]);
    int64_t *p = &B->head[b];
    while (*p != k) p = &B->next[*p];
    *p = B->next[k];
}

double prog_buckets_nearest2(const prog_buckets *B, double x, double y, int64_t skip, double stop2)
{
    const int64_t gs = B->gs, b = prog_buckets_of(B, x, y), bx = b % gs, by = b / gs;
    double best = INFINITY;
    for (int64_t r = 0; r <= gs / 2 + 1; r++) {
        /* ring r; once it spans the grid, every bucket once */
        const int64_t span = 2 * r + 1 >= gs ? gs : 2 * r + 1, lo = span == gs ? 0 : r;
        for (int64_t oy = 0; oy < span; oy++)
            for (int64_t ox = 0; ox < span; ox++) {
                if (span != gs && ox != 0 && ox != span - 1 && oy != 0 && oy != span - 1) continue;
                const int64_t cx = prog_buckets_wrap(bx - lo + ox, gs), cy = prog_buckets_wrap(by - lo + oy, gs);
                for (int64_t k = B->head[cy * gs + cx]; k >= 0; k = B->next[k]) {
                    if (k == skip) continue;
                    const double d2 = prog_torus_d2(x, y, B->xy[2 * k], B->xy[2 * k + 1]);
                    if (d2 < best) best = d2;
                    if (best <= stop2) return best; /* (the caller's place wins: no need for the nearest) */
                }
            }
        if (span == gs) break; /* every bucket seen */
        const double reach = (double)r * B->cs; /* every point beyond ring r is farther */
        if (best <= reach * reach) break;
    }
    return best;
}
