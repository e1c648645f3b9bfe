/* test_prog_balance.c - the balanced insertion of a progressive level
 * (src/prog_balance.c) against counts by brute force:
 *  - the quotas: none negative, their sum the level's new points; with
 *    the earlier points under every cell's share, every quadtree cell at
 *    every depth holds its share of the prefix within 4/3 of a point
 *    (each depth's rounding is within 1, the error above shrinks by 4);
 *    a cell whose earlier points are over its share gets no new point;
 *  - the insertion: every new point lies in the unit square and in its
 *    leaf cell (the counts of old plus new per leaf are old plus quota);
 *    the earlier points unchanged; the same bytes twice, other bytes for
 *    another seed;
 *  - the check can fail: the plain best-candidate insertion
 *    (prog_insert.c) misses the shares by more than 4/3;
 *  - the balanced order of a level: the same points; at every partial
 *    level of t of its q points, each leaf cell holds t q_c / q of them
 *    within 2 (q_c its points in the level); the greedy order misses
 *    that (the check can fail). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prog_balance.h"
#include "prog_order.h"
#include "prog_insert.h"
#include "rng.h"
#include "test_spread.h"
#include "testutil.h"

static int passed_, failed_;

static int cmp_pt(const void *a, const void *b)
{
    const double *p = a, *q = b;
    return p[0] < q[0] ? -1 : p[0] > q[0] ? 1 : p[1] < q[1] ? -1 : p[1] > q[1];
}

static int64_t cell_of(double v, int64_t g)
{
    int64_t c = (int64_t)(v * (double)g);
    return c < 0 ? 0 : c >= g ? g - 1 : c;
}

/* The largest |count - share| over the cells of every depth 0..L for the
 * first m points of xy, share = m / 4^depth. */
static double worst_share(const double *xy, int64_t m, int L)
{
    double worst = 0;
    for (int d = 0; d <= L; d++) {
        const int64_t g = (int64_t)1 << d;
        int64_t *c = calloc((size_t)(g * g), sizeof *c);
        for (int64_t i = 0; i < m; i++) c[cell_of(xy[2 * i + 1], g) * g + cell_of(xy[2 * i], g)]++;
        for (int64_t k = 0; k < g * g; k++) worst = fmax(worst, fabs((double)c[k] - (double)m / (double)(g * g)));
        free(c);
    }
    return worst;
}

/* The largest |count - t q_c / q| over the partial levels t and the leaf
 * cells (2^L a side) of the points m0 .. m0 + q - 1 in their order. */
static double worst_partial(const double *xy, int64_t m0, int64_t q, int L)
{
    const int64_t g = (int64_t)1 << L;
    int64_t *qc = calloc((size_t)(g * g), sizeof *qc), *c = calloc((size_t)(g * g), sizeof *c);
    for (int64_t j = 0; j < q; j++) qc[cell_of(xy[2 * (m0 + j) + 1], g) * g + cell_of(xy[2 * (m0 + j)], g)]++;
    double worst = 0;
    for (int64_t t = 1; t <= q; t++) {
        c[cell_of(xy[2 * (m0 + t - 1) + 1], g) * g + cell_of(xy[2 * (m0 + t - 1)], g)]++;
        for (int64_t k = 0; k < g * g; k++) worst = fmax(worst, fabs((double)c[k] - (double)t * (double)qc[k] / (double)q));
    }
    free(qc);
    free(c);
    return worst;
}

int main(void)
{
    char err[256];
    enum { M0 = 2025, M1 = 4096, PER = 16 };
    double *xy = malloc(2 * M1 * sizeof *xy), *again = malloc(2 * M1 * sizeof *again), *old = malloc(2 * M0 * sizeof *old);
    tu_spread(xy, M0, 7); /* m0 earlier points, under every cell's share of 2 m0 */
    memcpy(old, xy, 2 * M0 * sizeof *old);
    int L;
    int64_t *q = NULL;
    CHECK(cfpo_prog_balance_quota(xy, M0, M1, PER, 3, 4, &L, &q) == 0, "quota failed");
    CHECK(L == 4, "depth %d for %d points at %d a cell (want 4: 4096 / 256 = 16)", L, M1, PER);
    const int64_t G = (int64_t)1 << L;
    int64_t sum = 0, neg = 0;
    for (int64_t c = 0; c < G * G; c++) sum += q[c], neg += q[c] < 0;
    CHECK(sum == M1 - M0 && neg == 0, "quotas: sum %lld (want %d), %lld negative", (long long)sum, M1 - M0, (long long)neg);
    CHECK(cfpo_prog_insert_balanced(xy, M0, M1, 16, PER, 3, 4, err, sizeof err) == 0, "insert failed: %s", err);
    CHECK(memcmp(xy, old, 2 * M0 * sizeof *old) == 0, "the earlier points changed");
    int64_t *cnt = calloc((size_t)(G * G), sizeof *cnt), *cnt0 = calloc((size_t)(G * G), sizeof *cnt0), bad = 0, out = 0;
    for (int64_t i = 0; i < M1; i++) {
        out += !(xy[2 * i] >= 0 && xy[2 * i] < 1 && xy[2 * i + 1] >= 0 && xy[2 * i + 1] < 1);
        const int64_t c = cell_of(xy[2 * i + 1], G) * G + cell_of(xy[2 * i], G);
        (i < M0 ? cnt0 : cnt)[c]++;
    }
    for (int64_t c = 0; c < G * G; c++) bad += cnt[c] != q[c];
    CHECK(out == 0, "%lld points outside the unit square", (long long)out);
    CHECK(bad == 0, "%lld leaf cells whose new points are not their quota", (long long)bad);
    const double w = worst_share(xy, M1, L);
    CHECK(w < 4.0 / 3.0, "a cell misses its share by %.3f (>= 4/3)", w);
    memcpy(again, old, 2 * M0 * sizeof *again);
    cfpo_prog_insert_balanced(again, M0, M1, 16, PER, 3, 4, err, sizeof err);
    CHECK(memcmp(again, xy, 2 * M1 * sizeof *xy) == 0, "not the same bytes twice");
    memcpy(again, old, 2 * M0 * sizeof *again);
    cfpo_prog_insert_balanced(again, M0, M1, 16, PER, 5, 4, err, sizeof err);
    CHECK(memcmp(again, xy, 2 * M1 * sizeof *xy) != 0, "another seed, the same bytes");
    /* the plain insertion misses the shares */
    memcpy(again, old, 2 * M0 * sizeof *again);
    CHECK(cfpo_prog_insert(again, M0, M1, 16, 3, 4, err, sizeof err) == 0, "plain insert failed: %s", err);
    const double wp = worst_share(again, M1, L);
    CHECK(wp >= 4.0 / 3.0, "the plain insertion meets the shares too (%.3f): the check is empty", wp);
    /* the balanced order of the level (cells of 16 of the 4,096 points: L = 4) */
    memcpy(again, xy, 2 * M1 * sizeof *again);
    CHECK(cfpo_prog_order_balanced(again, M0, M1, PER, 3, 4, err, sizeof err) == 0, "order failed: %s", err);
    CHECK(memcmp(again, xy, 2 * M0 * sizeof *xy) == 0, "the order moved an earlier point");
    double *sa = malloc(2 * M1 * sizeof *sa), *sb = malloc(2 * M1 * sizeof *sb);
    memcpy(sa, xy + 2 * M0, 2 * (M1 - M0) * sizeof *sa);
    memcpy(sb, again + 2 * M0, 2 * (M1 - M0) * sizeof *sb);
    qsort(sa, M1 - M0, 2 * sizeof *sa, cmp_pt);
    qsort(sb, M1 - M0, 2 * sizeof *sb, cmp_pt);
    CHECK(memcmp(sa, sb, 2 * (M1 - M0) * sizeof *sa) == 0, "the order changed the level's points");
    const double wo = worst_partial(again, M0, M1 - M0, L);
    CHECK(wo <= 2.0, "a partial level misses a cell's share by %.3f (> 2)", wo);
    memcpy(sa, xy, 2 * M1 * sizeof *sa);
    CHECK(cfpo_prog_order(sa, M0, M1, err, sizeof err) == 0, "greedy order failed: %s", err);
    const double wg = worst_partial(sa, M0, M1 - M0, L);
    CHECK(wg > 2.0, "the greedy order keeps the shares too (%.3f): the check is empty", wg);
    free(sa);
    free(sb);
    free(q);
    /* a quadrant over its share: its cells get nothing, the rest take the level */
    for (int64_t i = 0; i < M0; i++) xy[2 * i] *= 0.5, xy[2 * i + 1] *= 0.5; /* all in [0, 1/2)^2 */
    CHECK(cfpo_prog_balance_quota(xy, M0, M1, PER, 3, 4, &L, &q) == 0, "quota failed");
    int64_t inq = 0, sum2 = 0;
    for (int64_t y = 0; y < G; y++)
        for (int64_t x = 0; x < G; x++) {
            sum2 += q[y * G + x];
            if (x < G / 2 && y < G / 2) inq += q[y * G + x];
        }
    CHECK(inq == 0 && sum2 == M1 - M0, "the full quadrant got %lld new points (sum %lld)", (long long)inq, (long long)sum2);
    free(q);
    free(cnt);
    free(cnt0);
    free(xy);
    free(again);
    free(old);
    return test_report(passed_, failed_);
}
