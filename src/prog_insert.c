/* prog_insert.c - see prog_insert.h. */
#include "prog_insert.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_buckets.h"
#include "rng.h"

int cfpo_prog_insert(double *xy, int64_t m0, int64_t m1, int cand, uint64_t seed, uint64_t stream, char *err,
                     size_t errlen)
{
    prog_buckets B = {0};
    if (prog_buckets_init(&B, xy, m1, m1) != 0) {
        prog_buckets_free(&B);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int64_t k = 0; k < m0; k++) prog_buckets_link(&B, k);
    uint64_t counter = 0;
    for (int64_t k = m0; k < m1; k++) {
        double bx = 0, by = 0, bd = -1;
        for (int c = 0; c < cand; c++) {
            const double x = cfpo_rand01(seed, stream, counter++), y = cfpo_rand01(seed, stream, counter++);
            const double d2 = k > 0 ? prog_buckets_nearest2(&B, x, y, -1, bd) : 1.0;
            if (d2 > bd) bx = x, by = y, bd = d2;
        }
        xy[2 * k] = bx;
        xy[2 * k + 1] = by;
        prog_buckets_link(&B, k);
    }
    prog_buckets_free(&B);
    return 0;
}

/* ---- the greedy order of a level's points */

typedef struct {
    double d;
    int64_t i;
} hitem;

static int above(const hitem *a, const hitem *b) { return a->d > b->d || (a->d == b->d && a->i < b->i); }

static void hpush(hitem *h, int64_t *n, hitem v)
{
    int64_t k = (*n)++;
    while (k > 0 && above(&v, &h[(k - 1) / 2])) {
        h[k] = h[(k - 1) / 2];
        k = (k - 1) / 2;
    }
    h[k] = v;
}

static hitem hpop(hitem *h, int64_t *n)
{
    const hitem top = h[0], v = h[--(*n)];
    int64_t k = 0;
    for (;;) {
        int64_t c = 2 * k + 1;
        if (c >= *n) break;
        if (c + 1 < *n && above(&h[c + 1], &h[c])) c++;
        if (!above(&h[c], &v)) break;
        h[k] = h[c];
        k = c;
    }
    if (*n > 0) h[k] = v;
    return top;
}

int cfpo_prog_order(double *xy, int64_t m0, int64_t m1, char *err, size_t errlen)
{
    const int64_t q = m1 - m0;
    if (q <= 1) return 0;
    prog_buckets P = {0}, Q = {0};
    double *d = malloc((size_t)q * sizeof *d), *out = malloc(2 * (size_t)q * sizeof *out);
    unsigned char *taken = calloc((size_t)q, 1);
    const int64_t hcap = 8 * q + 16;
    hitem *h = malloc((size_t)hcap * sizeof *h);
    int rc = -1;
    if (!d || !out || !taken || !h || prog_buckets_init(&P, xy, m1, m1) != 0 || prog_buckets_init(&Q, xy, m1, m1) != 0) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    for (int64_t k = 0; k < m0; k++) prog_buckets_link(&P, k);
    int64_t hn = 0;
    for (int64_t j = 0; j < q; j++) { /* each new point's distance to the prefix */
        d[j] = m0 > 0 ? prog_buckets_nearest2(&P, xy[2 * (m0 + j)], xy[2 * (m0 + j) + 1], -1, -1.0) : INFINITY;
        prog_buckets_link(&Q, m0 + j);
        hpush(h, &hn, (hitem){d[j], j});
    }
    for (int64_t t = 0; t < q; t++) {
        hitem top;
        do top = hpop(h, &hn); /* stale entries (a distance lowered since) are skipped */
        while (taken[top.i] || top.d != d[top.i]);
        const int64_t p = top.i;
        taken[p] = 1;
        const double px = xy[2 * (m0 + p)], py = xy[2 * (m0 + p) + 1];
        out[2 * t] = px;
        out[2 * t + 1] = py;
        /* the untaken points nearer to p than to the set so far: within the
         * largest such distance, sqrt(top.d), of p */
        const double r = sqrt(top.d);
        const int64_t reach = isinf(r) ? Q.gs : (int64_t)ceil(r / Q.cs) + 1;
        int64_t x0, y0;
        const int64_t span = prog_buckets_window(&Q, prog_buckets_of(&Q, px, py), reach, &x0, &y0);
        for (int64_t oy = 0; oy < span; oy++)
            for (int64_t ox = 0; ox < span; ox++) {
                for (int64_t k = prog_buckets_first(&Q, x0 + ox, y0 + oy); k >= 0; k = Q.next[k]) {
                    const int64_t j = k - m0;
                    if (taken[j]) continue;
                    const double d2 = prog_torus_d2(px, py, xy[2 * k], xy[2 * k + 1]);
                    if (d2 >= d[j]) continue;
                    d[j] = d2;
                    if (hn == hcap) { /* compact: one live entry per untaken point */
                        hn = 0;
                        for (int64_t i = 0; i < q; i++)
                            if (!taken[i]) hpush(h, &hn, (hitem){d[i], i});
                    }
                    hpush(h, &hn, (hitem){d2, j});
                }
            }
    }
    for (int64_t t = 0; t < 2 * q; t++) xy[2 * m0 + t] = out[t];
    rc = 0;
done:
    prog_buckets_free(&P);
    prog_buckets_free(&Q);
    free(d);
    free(out);
    free(taken);
    free(h);
    return rc;
}
