/* prog_insert.c - see prog_insert.h. */
#include "prog_insert.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "rng.h"

typedef struct {
    int64_t gs;    /* buckets per side */
    double cs;     /* bucket side, 1 / gs */
    int64_t *head; /* first point of each bucket, -1 if none */
    int64_t *next; /* the next point of its bucket */
    const double *xy;
} buckets;

static int64_t bucket_of(const buckets *B, double x, double y)
{
    int64_t bx = (int64_t)(x * (double)B->gs), by = (int64_t)(y * (double)B->gs);
    if (bx >= B->gs) bx = B->gs - 1;
    if (by >= B->gs) by = B->gs - 1;
    return by * B->gs + bx;
}

static void add(buckets *B, int64_t k)
{
    const int64_t b = bucket_of(B, B->xy[2 * k], B->xy[2 * k + 1]);
    B->next[k] = B->head[b];
    B->head[b] = k;
}

static double torus_d2(double ax, double ay, double bx, double by)
{
    double dx = fabs(ax - bx), dy = fabs(ay - by);
    if (dx > 0.5) dx = 1.0 - dx;
    if (dy > 0.5) dy = 1.0 - dy;
    return dx * dx + dy * dy;
}

/* Squared distance from (x, y) to its nearest stored point, searching
 * rings of buckets outwards until no nearer point can remain; stops early
 * (returning a value <= stop2) once the distance falls to stop2. */
static double nearest2(const buckets *B, double x, double y, double stop2)
{
    const int64_t gs = B->gs, b = bucket_of(B, x, y), bx = b % gs, by = b / gs;
    double best = INFINITY;
    for (int64_t r = 0; r <= gs / 2 + 1; r++) {
        for (int64_t dy = -r; dy <= r; dy++)
            for (int64_t dx = -r; dx <= r; dx++) {
                if (dx != -r && dx != r && dy != -r && dy != r) continue; /* the ring only */
                const int64_t cx = ((bx + dx) % gs + gs) % gs, cy = ((by + dy) % gs + gs) % gs;
                for (int64_t k = B->head[cy * gs + cx]; k >= 0; k = B->next[k]) {
                    const double d2 = torus_d2(x, y, B->xy[2 * k], B->xy[2 * k + 1]);
                    if (d2 < best) best = d2;
                }
            }
        if (best <= stop2) return best;
        const double reach = (double)r * B->cs; /* every point beyond ring r is farther */
        if (best <= reach * reach) return best;
        if (2 * r + 1 >= gs) break; /* every bucket seen */
    }
    return best;
}

int cfpo_prog_insert(double *xy, int64_t m0, int64_t m1, int cand, uint64_t seed, uint64_t stream, char *err,
                     size_t errlen)
{
    buckets B = {0};
    B.gs = (int64_t)floor(1.0 / cfpo_delta_bound((double)m1));
    if (B.gs < 1) B.gs = 1;
    B.cs = 1.0 / (double)B.gs;
    B.xy = xy;
    B.head = malloc((size_t)(B.gs * B.gs) * sizeof *B.head);
    B.next = malloc((size_t)m1 * sizeof *B.next);
    if (!B.head || !B.next) {
        free(B.head);
        free(B.next);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int64_t b = 0; b < B.gs * B.gs; b++) B.head[b] = -1;
    for (int64_t k = 0; k < m0; k++) add(&B, k);
    uint64_t counter = 0;
    for (int64_t k = m0; k < m1; k++) {
        double bx = 0, by = 0, bd = -1;
        for (int c = 0; c < cand; c++) {
            const double x = cfpo_rand01(seed, stream, counter++), y = cfpo_rand01(seed, stream, counter++);
            const double d2 = k > 0 ? nearest2(&B, x, y, bd) : 1.0;
            if (d2 > bd) bx = x, by = y, bd = d2;
        }
        xy[2 * k] = bx;
        xy[2 * k + 1] = by;
        add(&B, k);
    }
    free(B.head);
    free(B.next);
    return 0;
}
