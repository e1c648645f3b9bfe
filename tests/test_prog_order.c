/* test_prog_order.c - the start and the order of a progressive level's
 * points (src/prog_insert.c) against brute force on the torus:
 *  - cfpo_prog_insert: each new point is the best of its candidates (its
 *    distance to every point before it, by brute force, is at least every
 *    candidate's), the first m0 points untouched, the same bytes twice;
 *  - cfpo_prog_order: the points after m0 are a permutation of the level's
 *    points, the first m0 untouched, and the order is exactly the brute-force
 *    greedy farthest-point order (next: the farthest from all before it,
 *    ties to the lower index), on uniform sets, a jittered grid with exact
 *    ties, and with m0 = 0. A shuffled order fails the same check. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "prog_insert.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

static double d2t(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    if (dx > 0.5) dx = 1 - dx;
    if (dy > 0.5) dy = 1 - dy;
    return dx * dx + dy * dy;
}

/* Nearest squared distance from p to xy[0..k). */
static double near2(const double *xy, int64_t k, const double *p)
{
    double b = INFINITY;
    for (int64_t i = 0; i < k; i++) {
        const double d = d2t(xy + 2 * i, p);
        if (d < b) b = d;
    }
    return b;
}

/* Brute-force greedy order of in[m0..m1) after in[0..m0) into out. */
static void greedy(const double *in, int64_t m0, int64_t m1, double *out)
{
    memcpy(out, in, 2 * (size_t)m0 * sizeof *out);
    const int64_t q = m1 - m0;
    unsigned char *used = calloc((size_t)q, 1);
    for (int64_t t = 0; t < q; t++) {
        int64_t best = -1;
        double bd = -1;
        for (int64_t j = 0; j < q; j++) {
            if (used[j]) continue;
            const double d = near2(out, m0 + t, in + 2 * (m0 + j));
            if (d > bd) bd = d, best = j;
        }
        used[best] = 1;
        out[2 * (m0 + t)] = in[2 * (m0 + best)];
        out[2 * (m0 + t) + 1] = in[2 * (m0 + best) + 1];
    }
    free(used);
}

static void uniform(double *xy, int64_t n, uint64_t seed)
{
    for (int64_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(seed, 7, (uint64_t)i);
}

static void check_order(const double *in, int64_t m0, int64_t m1, const char *what)
{
    double *a = malloc(2 * (size_t)m1 * sizeof *a), *b = malloc(2 * (size_t)m1 * sizeof *b);
    char err[128];
    memcpy(a, in, 2 * (size_t)m1 * sizeof *a);
    CHECK(cfpo_prog_order(a, m0, m1, err, sizeof err) == 0, "%s: order failed: %s", what, err);
    greedy(in, m0, m1, b);
    CHECK(memcmp(a, b, 2 * (size_t)m1 * sizeof *a) == 0, "%s: not the brute-force greedy order", what);
    /* a permutation of the level's points (sorted x then y compare) */
    int perm = 1;
    for (int64_t j = m0; j < m1 && perm; j++) {
        int found = 0;
        for (int64_t i = m0; i < m1 && !found; i++) found = a[2 * i] == in[2 * j] && a[2 * i + 1] == in[2 * j + 1];
        perm = found;
    }
    CHECK(perm, "%s: not a permutation", what);
    free(a);
    free(b);
}

int main(void)
{
    char err[128];
    /* insertion: best of its candidates, deterministic */
    {
        const int64_t m0 = 50, m1 = 400;
        double *xy = malloc(2 * (size_t)m1 * sizeof *xy), *again = malloc(2 * (size_t)m1 * sizeof *again);
        uniform(xy, m0, 3);
        memcpy(again, xy, 2 * (size_t)m0 * sizeof *xy);
        CHECK(cfpo_prog_insert(xy, m0, m1, 16, 9, 2, err, sizeof err) == 0, "insert: %s", err);
        CHECK(cfpo_prog_insert(again, m0, m1, 16, 9, 2, err, sizeof err) == 0, "insert again: %s", err);
        CHECK(memcmp(xy, again, 2 * (size_t)m1 * sizeof *xy) == 0, "insert: not the same bytes twice");
        double pre[100];
        uniform(pre, m0, 3);
        CHECK(memcmp(xy, pre, 2 * (size_t)m0 * sizeof *xy) == 0, "insert: the first m0 points changed");
        int best = 1;
        uint64_t counter = 0;
        for (int64_t k = m0; k < m1; k++) {
            const double got = near2(xy, k, xy + 2 * k);
            for (int c = 0; c < 16; c++) {
                double p[2];
                p[0] = cfpo_rand01(9, 2, counter++);
                p[1] = cfpo_rand01(9, 2, counter++);
                if (near2(xy, k, p) > got) best = 0;
            }
        }
        CHECK(best, "insert: a candidate was farther than the point chosen");
        free(xy);
        free(again);
    }
    /* greedy order against brute force */
    {
        double *in = malloc(2 * 700 * sizeof *in);
        uniform(in, 700, 11);
        check_order(in, 100, 700, "uniform, m0 = 100");
        check_order(in, 0, 300, "uniform, m0 = 0");
        check_order(in, 699, 700, "one point");
        /* a jittered 16 x 16 grid's centres: exact ties everywhere */
        for (int i = 0; i < 256; i++) in[2 * i] = (i % 16 + 0.5) / 16, in[2 * i + 1] = (i / 16 + 0.5) / 16;
        check_order(in, 0, 256, "a grid (ties)");
        check_order(in, 17, 256, "a grid after 17 of its points");
        /* the check can fail: a shuffled order is not the greedy one */
        uniform(in, 300, 5);
        double *a = malloc(2 * 300 * sizeof *a), *b = malloc(2 * 300 * sizeof *b);
        memcpy(a, in, 2 * 300 * sizeof *a);
        greedy(in, 20, 300, b);
        CHECK(memcmp(a, b, 2 * 300 * sizeof *a) != 0, "the input order passed as greedy");
        free(a);
        free(b);
        free(in);
    }
    return test_report(passed_, failed_);
}
