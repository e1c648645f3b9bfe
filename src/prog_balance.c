/* prog_balance.c - see prog_balance.h. */
#include "prog_balance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "prog_buckets.h"
#include "prog_order.h"
#include "rng.h"

#define BALANCE_SALT 0x62616c616e6365ULL /* the draws of the rounding and the order */

static int64_t cell_of(double v, int64_t g)
{
    int64_t c = (int64_t)(v * (double)g);
    return c < 0 ? 0 : c >= g ? g - 1 : c;
}

/* Q new points to four children of ideal shares t[0..3]: into a[]. */
static void split4(int64_t Q, const double *ideal, uint64_t seed, uint64_t stream, uint64_t node, int64_t *a)
{
    double t[4];
    int on[4] = {1, 1, 1, 1};
    for (int pass = 0; pass < 4; pass++) { /* equal shift of the excess; a child below zero out */
        double s = 0;
        int na = 0;
        for (int i = 0; i < 4; i++)
            if (on[i]) s += ideal[i], na++;
        const double shift = ((double)Q - s) / na;
        int cut = 0;
        for (int i = 0; i < 4; i++) {
            t[i] = on[i] ? ideal[i] + shift : 0;
            if (on[i] && t[i] < 0) on[i] = 0, cut = 1;
        }
        if (!cut) break;
        for (int i = 0; i < 4; i++)
            if (!on[i]) t[i] = 0;
    }
    int64_t left = Q;
    double frac[4], tie[4];
    for (int i = 0; i < 4; i++) {
        a[i] = t[i] > 0 ? (int64_t)floor(t[i]) : 0;
        if (a[i] > left) a[i] = left;
        left -= a[i];
        frac[i] = t[i] - (double)a[i];
        tie[i] = cfpo_rand01(seed, stream, 4 * node + (uint64_t)i);
    }
    while (left > 0) { /* the largest remainders, ties by the draw */
        int b = -1;
        for (int i = 0; i < 4; i++)
            if (b < 0 || frac[i] > frac[b] || (frac[i] == frac[b] && tie[i] < tie[b])) b = i;
        a[b]++, frac[b] -= 1.0, left--;
    }
}

int cfpo_prog_balance_quota(const double *xy, int64_t m0, int64_t m1, int per_cell, uint64_t seed, uint64_t stream,
                            int *depth, int64_t **quota)
{
    int L = 0;
    while (L < 15 && (double)m1 / pow(4.0, L + 1) >= (double)per_cell) L++;
    *depth = L;
    const int64_t G = (int64_t)1 << L;
    int64_t **cnt = calloc((size_t)L + 1, sizeof *cnt); /* cnt[l]: the points at m0 in each cell of depth l */
    int64_t *q = NULL, *nq = NULL;
    int rc = cnt ? 0 : -1;
    for (int l = 0; rc == 0 && l <= L; l++)
        if (!(cnt[l] = calloc((size_t)((int64_t)1 << (2 * l)), sizeof **cnt))) rc = -1;
    if (rc == 0) {
        for (int64_t i = 0; i < m0; i++) cnt[L][cell_of(xy[2 * i + 1], G) * G + cell_of(xy[2 * i], G)]++;
        for (int l = L - 1; l >= 0; l--) {
            const int64_t g = (int64_t)1 << l;
            for (int64_t y = 0; y < 2 * g; y++)
                for (int64_t x = 0; x < 2 * g; x++) cnt[l][(y / 2) * g + x / 2] += cnt[l + 1][y * 2 * g + x];
        }
        q = malloc(sizeof *q);
        if (!q) rc = -1;
        else q[0] = m1 - m0;
    }
    for (int l = 0; rc == 0 && l < L; l++) { /* the quotas of depth l + 1 from those of depth l */
        const int64_t g = (int64_t)1 << l, g2 = 2 * g;
        const double share = (double)m1 / (double)(g2 * g2);
        if (!(nq = malloc((size_t)(g2 * g2) * sizeof *nq))) {
            rc = -1;
            break;
        }
        for (int64_t y = 0; y < g; y++)
            for (int64_t x = 0; x < g; x++) {
                int64_t ci[4];
                double ideal[4];
                int64_t a[4];
                for (int c = 0; c < 4; c++) {
                    ci[c] = (2 * y + c / 2) * g2 + 2 * x + c % 2;
                    ideal[c] = share - (double)cnt[l + 1][ci[c]];
                }
                const uint64_t node = ((uint64_t)1 << (2 * l)) + (uint64_t)(y * g + x); /* unique over depths */
                split4(q[y * g + x], ideal, seed, stream, node, a);
                for (int c = 0; c < 4; c++) nq[ci[c]] = a[c];
            }
        free(q);
        q = nq;
        nq = NULL;
    }
    for (int l = 0; cnt && l <= L; l++) free(cnt[l]);
    free(cnt);
    if (rc != 0) {
        free(q);
        q = NULL;
    }
    *quota = q;
    return rc;
}

int cfpo_prog_insert_balanced(double *xy, int64_t m0, int64_t m1, int cand, int per_cell, uint64_t seed,
                              uint64_t stream, char *err, size_t errlen)
{
    const uint64_t st = stream ^ BALANCE_SALT;
    int L;
    int64_t *quota = NULL, *slot = NULL;
    prog_buckets B = {0};
    int rc = cfpo_prog_balance_quota(xy, m0, m1, per_cell, seed, st, &L, &quota);
    const int64_t G = (int64_t)1 << L, q = m1 - m0;
    if (rc == 0 && (!(slot = malloc((size_t)(q > 0 ? q : 1) * sizeof *slot)) || prog_buckets_init(&B, xy, m1, m1) != 0))
        rc = -1;
    if (rc == 0) {
        int64_t s = 0;
        for (int64_t c = 0; c < G * G; c++)
            for (int64_t j = 0; j < quota[c]; j++) slot[s++] = c;
        for (int64_t i = q - 1; i > 0; i--) { /* a seeded shuffle: the cells in a random order */
            const int64_t j = (int64_t)(cfpo_rand64(seed, st + 1, (uint64_t)i) % (uint64_t)(i + 1));
            const int64_t t = slot[i];
            slot[i] = slot[j], slot[j] = t;
        }
        for (int64_t k = 0; k < m0; k++) prog_buckets_link(&B, k);
        uint64_t counter = 0;
        const double side = 1.0 / (double)G;
        for (int64_t t = 0; t < q; t++) {
            const int64_t k = m0 + t, c = slot[t];
            const double ox = (double)(c % G) * side, oy = (double)(c / G) * side;
            double bx = 0, by = 0, bd = -1;
            for (int d = 0; d < cand; d++) {
                const double x = ox + side * cfpo_rand01(seed, stream, counter++);
                const double y = oy + side * cfpo_rand01(seed, stream, counter++);
                const double d2 = k > 0 ? prog_buckets_nearest2(&B, x, y, -1, bd) : 1.0;
                if (d2 > bd) bx = x, by = y, bd = d2;
            }
            xy[2 * k] = bx < 1.0 ? bx : 0.0;
            xy[2 * k + 1] = by < 1.0 ? by : 0.0;
            prog_buckets_link(&B, k);
        }
    }
    if (rc != 0) snprintf(err, errlen, "out of memory");
    prog_buckets_free(&B);
    free(slot);
    free(quota);
    return rc;
}

typedef struct {
    double t;
    int64_t i;
} timed;

static int by_time(const void *a, const void *b)
{
    const timed *x = a, *y = b;
    return x->t < y->t ? -1 : x->t > y->t ? 1 : (x->i > y->i) - (x->i < y->i);
}

int cfpo_prog_order_balanced(double *xy, int64_t m0, int64_t m1, int per_cell, uint64_t seed, uint64_t stream,
                             char *err, size_t errlen)
{
    const int64_t q = m1 - m0;
    if (cfpo_prog_order(xy, m0, m1, err, errlen) != 0) return -1;
    if (q <= 1) return 0;
    int L = 0;
    while (L < 15 && (double)m1 / pow(4.0, L + 1) >= (double)per_cell) L++;
    const int64_t G = (int64_t)1 << L;
    const uint64_t st = stream ^ BALANCE_SALT ^ 0x6f72646572ULL;
    int64_t *count = calloc((size_t)(G * G), sizeof *count), *seen = calloc((size_t)(G * G), sizeof *seen);
    timed *T = malloc((size_t)q * sizeof *T);
    double *w = malloc(2 * (size_t)q * sizeof *w);
    int rc = count && seen && T && w ? 0 : -1;
    if (rc == 0) {
        for (int64_t j = 0; j < q; j++) count[cell_of(xy[2 * (m0 + j) + 1], G) * G + cell_of(xy[2 * (m0 + j)], G)]++;
        for (int64_t j = 0; j < q; j++) { /* a cell's j-th point (greedy order) at (j + u) / its count */
            const int64_t c = cell_of(xy[2 * (m0 + j) + 1], G) * G + cell_of(xy[2 * (m0 + j)], G);
            const double u = cfpo_rand01(seed, st, (uint64_t)c);
            T[j] = (timed){((double)seen[c]++ + u) / (double)count[c], j};
        }
        qsort(T, (size_t)q, sizeof *T, by_time);
        for (int64_t j = 0; j < q; j++) w[2 * j] = xy[2 * (m0 + T[j].i)], w[2 * j + 1] = xy[2 * (m0 + T[j].i) + 1];
        for (int64_t j = 0; j < 2 * q; j++) xy[2 * m0 + j] = w[j];
    } else
        snprintf(err, errlen, "out of memory");
    free(count);
    free(seen);
    free(T);
    free(w);
    return rc;
}
