/* prog_pgrid.c - see prog_pgrid.h. */
#include "prog_pgrid.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"

#include <omp.h>

int prog_pgrid_init(prog_pgrid *P, const double *xy, const int64_t *sizes, int K, const int *lev, double f)
{
    P->K = K;
    P->sizes = sizes;
    P->lev = lev;
    P->measured = 0;
    for (int g = 0; g < K; g++) {
        const int64_t m = sizes[g];
        const double side = f * cfpo_delta_bound((double)m);
        if (prog_buckets_init_side(&P->G[g], xy, side, m) != 0) return -1;
        const int64_t nb = P->G[g].gs * P->G[g].gs;
        P->stamp[g] = calloc((size_t)nb, sizeof *P->stamp[g]);
        P->nd[g] = malloc((size_t)m * sizeof *P->nd[g]);
        if (!P->stamp[g] || !P->nd[g]) return -1;
        for (int64_t k = m - 1; k >= 0; k--) prog_buckets_link(&P->G[g], k);
        if (g == 0) continue;
        if (prog_buckets_init_side(&P->V[g], xy, side, m) != 0) return -1;
        for (int64_t k = m - 1; k >= sizes[g - 1]; k--) prog_buckets_link(&P->V[g], k);
    }
    return 0;
}

void prog_pgrid_free(prog_pgrid *P)
{
    for (int g = 0; g < P->K; g++) {
        prog_buckets_free(&P->G[g]);
        prog_buckets_free(&P->V[g]);
        free(P->stamp[g]);
        free(P->nd[g]);
        P->stamp[g] = NULL;
        P->nd[g] = NULL;
    }
}

void prog_pgrid_move(prog_pgrid *P, double *xy, int64_t k, double x, double y, uint32_t now)
{
    const int l = P->lev[k];
    for (int g = l; g < P->K; g++) {
        prog_buckets *B = &P->G[g];
        prog_buckets_unlink(B, k);
        P->stamp[g][prog_buckets_of(B, xy[2 * k], xy[2 * k + 1])] = now;
    }
    if (l > 0) prog_buckets_unlink(&P->V[l], k);
    xy[2 * k] = x;
    xy[2 * k + 1] = y;
    if (l > 0) prog_buckets_link(&P->V[l], k);
    for (int g = l; g < P->K; g++) {
        prog_buckets *B = &P->G[g];
        prog_buckets_link(B, k);
        P->stamp[g][prog_buckets_of(B, x, y)] = now;
    }
}

int prog_pgrid_changed(const prog_pgrid *P, int g, double x, double y, double r, uint32_t t)
{
    const prog_buckets *B = &P->G[g];
    const uint32_t *st = P->stamp[g];
    const int64_t gs = B->gs;
    int64_t x0, y0;
    const int64_t span = prog_buckets_window(B, prog_buckets_of(B, x, y), (int64_t)floor(r / B->cs) + 1, &x0, &y0);
    for (int64_t oy = 0; oy < span; oy++) {
        const int64_t row = prog_buckets_wrap(y0 + oy, gs) * gs;
        for (int64_t ox = 0; ox < span; ox++)
            if (st[row + prog_buckets_wrap(x0 + ox, gs)] >= t) return 1;
    }
    return 0;
}

int prog_pgrid_measure(prog_pgrid *P, int nth, uint32_t now, double *dmin, double *davg, double *raw)
{
    const uint32_t since = P->measured;
    for (int g = 0; g < P->K; g++) {
        const prog_buckets *B = &P->G[g];
        const int64_t m = P->sizes[g];
        double *nd = P->nd[g];
        const double *xy = B->xy;
#pragma omp parallel for schedule(static) num_threads(nth)
        for (int64_t i = 0; i < m; i++) {
            const double x = xy[2 * i], y = xy[2 * i + 1];
            if (since == 0 || prog_pgrid_changed(P, g, x, y, nd[i], since + 1))
                nd[i] = sqrt(prog_buckets_nearest2(B, x, y, i, -1.0));
        }
        double lo = INFINITY, sum = 0;
        for (int64_t i = 0; i < m; i++) {
            if (nd[i] < lo) lo = nd[i];
            sum += nd[i];
        }
        const double D = cfpo_delta_bound((double)m);
        dmin[g] = lo / D;
        davg[g] = sum / (double)m / D;
        if (raw) raw[g] = lo;
    }
    P->measured = now;
    return 0;
}

/* ---- the working order */

static uint64_t spread16(uint64_t v)
{
    v &= 0xffff;
    v = (v | (v << 8)) & 0x00ff00ffULL;
    v = (v | (v << 4)) & 0x0f0f0f0fULL;
    v = (v | (v << 2)) & 0x33333333ULL;
    return (v | (v << 1)) & 0x55555555ULL;
}

typedef struct {
    uint64_t key;
    int64_t id;
} zitem;

static int zcmp(const void *a, const void *b)
{
    const zitem *p = a, *q = b;
    if (p->key != q->key) return p->key < q->key ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}

int prog_pgrid_order(const double *xy, const int64_t *sizes, int K, int64_t *perm)
{
    const int64_t n = sizes[K - 1];
    zitem *z = malloc((size_t)n * sizeof *z);
    if (!z) return -1;
    for (int64_t i = 0; i < n; i++) {
        const uint64_t qx = (uint64_t)(xy[2 * i] * 65536.0), qy = (uint64_t)(xy[2 * i + 1] * 65536.0);
        z[i] = (zitem){spread16(qx) | (spread16(qy) << 1), i};
    }
    for (int l = 0; l < K; l++) {
        const int64_t lo = l ? sizes[l - 1] : 0;
        qsort(z + lo, (size_t)(sizes[l] - lo), sizeof *z, zcmp);
    }
    for (int64_t j = 0; j < n; j++) perm[j] = z[j].id;
    free(z);
    return 0;
}
