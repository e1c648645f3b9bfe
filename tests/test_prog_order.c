/* test_prog_order.c - the start and the order of a progressive level's
 * points (src/prog_insert.c, src/prog_order.c) against brute force on the
 * torus:
 *  - cfpo_prog_insert: each new point is the best of its candidates (its
 *    distance to every point before it, by brute force, is at least every
 *    candidate's), the first m0 points untouched, the same bytes twice;
 *  - cfpo_prog_order: the points after m0 are a permutation of the level's
 *    points, the first m0 untouched, and the order is exactly the brute-force
 *    greedy farthest-point order (next: the farthest from all before it,
 *    ties to the lower index), on uniform sets, a jittered grid with exact
 *    ties, and with m0 = 0. A shuffled order fails the same check;
 *  - cfpo_prog_order_paced: exactly the brute-force paced order (next: the
 *    farthest point none of whose quadtree cells has given floor((t + 1)
 *    c / q) + tol of its c points after t picks), and, checked on the
 *    output alone, every cell within that allowance after every pick; the
 *    greedy order breaks the allowance on the same set; a tol below 1 is
 *    refused;
 *  - cfpo_prog_herd_kernel: the direct sum of its Fourier series;
 *  - cfpo_prog_order_herded: exactly the brute-force herded order (each
 *    step from scratch: the free points by the same allowances, the
 *    candidates at least min(floor Delta(m), the farthest free one's
 *    distance) from the points before them, next the least kernel sum over
 *    every point before it), within the allowance after
 *    every pick, and different from the paced order on the same set. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "prog_herd.h"
#include "prog_insert.h"
#include "prog_order.h"
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

/* The cell at level l (1 .. depth) of a point, over all levels. */
static int64_t cell_at(const double *p, int depth, int l)
{
    const int64_t G = (int64_t)1 << l;
    int64_t x = (int64_t)(p[0] * (double)((int64_t)1 << depth)), y = (int64_t)(p[1] * (double)((int64_t)1 << depth));
    const int64_t F = (int64_t)1 << depth;
    x = x < 0 ? 0 : x >= F ? F - 1 : x;
    y = y < 0 ? 0 : y >= F ? F - 1 : y;
    return (G * G - 1) / 3 - 1 + (y >> (depth - l)) * G + (x >> (depth - l));
}

/* Brute force of the paced order of in[m0..m1) into out (depth, tol). */
static void paced(const double *in, int64_t m0, int64_t m1, int depth, int tol, double *out)
{
    memcpy(out, in, 2 * (size_t)m0 * sizeof *out);
    const int64_t q = m1 - m0, cells = (((int64_t)1 << (2 * (depth + 1))) - 1) / 3;
    unsigned char *used = calloc((size_t)q, 1);
    double *nd = malloc((size_t)q * sizeof *nd);
    int64_t *count = calloc((size_t)cells + 1, sizeof *count), *took = calloc((size_t)cells + 1, sizeof *took);
    for (int64_t j = 0; j < q; j++) {
        nd[j] = near2(in, m0, in + 2 * (m0 + j));
        for (int l = 1; l <= depth; l++) count[cell_at(in + 2 * (m0 + j), depth, l)]++;
    }
    for (int64_t t = 0; t < q; t++) {
        int64_t best = -1;
        for (int64_t j = 0; j < q; j++) {
            if (used[j] || (best >= 0 && !(nd[j] > nd[best]))) continue;
            int ok = 1;
            for (int l = 1; l <= depth && ok; l++) {
                const int64_t c = cell_at(in + 2 * (m0 + j), depth, l);
                ok = took[c] < (t + 1) * count[c] / q + tol;
            }
            if (ok) best = j;
        }
        used[best] = 1;
        for (int l = 1; l <= depth; l++) took[cell_at(in + 2 * (m0 + best), depth, l)]++;
        out[2 * (m0 + t)] = in[2 * (m0 + best)];
        out[2 * (m0 + t) + 1] = in[2 * (m0 + best) + 1];
        for (int64_t j = 0; j < q; j++) {
            const double d = d2t(in + 2 * (m0 + j), in + 2 * (m0 + best));
            if (d < nd[j]) nd[j] = d;
        }
    }
    free(used);
    free(nd);
    free(count);
    free(took);
}

/* Whether every cell of the level's points a[m0..m1) kept within its
 * allowance after every pick. */
static int within_allowance(const double *a, int64_t m0, int64_t m1, int depth, int tol)
{
    const int64_t q = m1 - m0, cells = (((int64_t)1 << (2 * (depth + 1))) - 1) / 3;
    int64_t *count = calloc((size_t)cells + 1, sizeof *count), *took = calloc((size_t)cells + 1, sizeof *took);
    int ok = 1;
    for (int64_t j = 0; j < q; j++)
        for (int l = 1; l <= depth; l++) count[cell_at(a + 2 * (m0 + j), depth, l)]++;
    for (int64_t t = 0; t < q && ok; t++)
        for (int l = 1; l <= depth && ok; l++) {
            const int64_t c = cell_at(a + 2 * (m0 + t), depth, l);
            ok = ++took[c] <= (t + 1) * count[c] / q + tol;
        }
    free(count);
    free(took);
    return ok;
}

static void check_paced(const double *in, int64_t m0, int64_t m1, double per_cell, int tol, const char *what)
{
    double *a = malloc(2 * (size_t)m1 * sizeof *a), *b = malloc(2 * (size_t)m1 * sizeof *b);
    char err[128];
    const int depth = cfpo_prog_order_depth(m1, per_cell);
    memcpy(a, in, 2 * (size_t)m1 * sizeof *a);
    CHECK(cfpo_prog_order_paced(a, m0, m1, per_cell, tol, err, sizeof err) == 0, "%s: paced order failed: %s", what, err);
    paced(in, m0, m1, depth, tol, b);
    CHECK(memcmp(a, b, 2 * (size_t)m1 * sizeof *a) == 0, "%s: not the brute-force paced order (depth %d)", what, depth);
    CHECK(within_allowance(a, m0, m1, depth, tol), "%s: a cell past its allowance", what);
    CHECK(memcmp(a, in, 2 * (size_t)m0 * sizeof *a) == 0, "%s: the first m0 points changed", what);
    free(a);
    free(b);
}


/* The kernel's Fourier series summed directly over every k in the disk. */
static double kernel_direct(const double *a, const double *b, double R)
{
    double s = 0;
    const int kc = (int)floor(R);
    for (int kx = -kc; kx <= kc; kx++)
        for (int ky = -kc; ky <= kc; ky++) {
            const double k2 = (double)(kx * kx + ky * ky);
            if (k2 == 0 || k2 > R * R) continue;
            s += cos(2 * M_PI * (kx * (a[0] - b[0]) + ky * (a[1] - b[1]))) / (k2 * sqrt(k2));
        }
    return s;
}

/* Brute force of the herded order (prog_herd.h) of in[m0..m1) into out:
 * every distance and kernel sum from scratch at every step. */
static void herded(const double *in, int64_t m0, int64_t m1, int depth, int tol, double dfloor, double R, double *out)
{
    cfpo_prog_herd_tab *K = malloc(sizeof *K);
    cfpo_prog_herd_table(R, K);
    memcpy(out, in, 2 * (size_t)m0 * sizeof *out);
    const int64_t q = m1 - m0, cells = (((int64_t)1 << (2 * (depth + 1))) - 1) / 3;
    unsigned char *used = calloc((size_t)q, 1), *free_ = calloc((size_t)q, 1);
    double *nd = malloc((size_t)q * sizeof *nd), *phi = malloc((size_t)q * sizeof *phi);
    int64_t *count = calloc((size_t)cells + 1, sizeof *count), *took = calloc((size_t)cells + 1, sizeof *took);
    for (int64_t j = 0; j < q; j++)
        for (int l = 1; l <= depth; l++) count[cell_at(in + 2 * (m0 + j), depth, l)]++;
    for (int64_t t = 0; t < q; t++) {
        double far = -1;
        for (int64_t j = 0; j < q; j++) {
            free_[j] = 0;
            if (used[j]) continue;
            const double *p = in + 2 * (m0 + j);
            nd[j] = near2(out, m0 + t, p);
            phi[j] = 0;
            for (int64_t i = 0; i < m0 + t; i++) phi[j] += cfpo_prog_herd_kernel(p, out + 2 * i, K);
            int ok = 1;
            for (int l = 1; l <= depth && ok; l++) {
                const int64_t c = cell_at(p, depth, l);
                ok = took[c] < (t + 1) * count[c] / q + tol;
            }
            free_[j] = (unsigned char)ok;
            if (ok && nd[j] > far) far = nd[j];
        }
        int64_t best = -1;
        const double delta2 = 2 / (sqrt(3.0) * (double)(m0 + t + 1)), floor2 = dfloor * dfloor * delta2;
        for (int64_t j = 0; j < q; j++) {
            if (!free_[j] || !(nd[j] >= (floor2 < far ? floor2 : far))) continue;
            if (best < 0 || phi[j] < phi[best] || (phi[j] == phi[best] && nd[j] > nd[best])) best = j;
        }
        used[best] = 1;
        for (int l = 1; l <= depth; l++) took[cell_at(in + 2 * (m0 + best), depth, l)]++;
        out[2 * (m0 + t)] = in[2 * (m0 + best)];
        out[2 * (m0 + t) + 1] = in[2 * (m0 + best) + 1];
    }
    free(K);
    free(used);
    free(free_);
    free(nd);
    free(phi);
    free(count);
    free(took);
}

static void check_herded(const double *in, int64_t m0, int64_t m1, double dfloor, double freq, const char *what)
{
    double *a = malloc(2 * (size_t)m1 * sizeof *a), *b = malloc(2 * (size_t)m1 * sizeof *b);
    char err[128];
    const int depth = cfpo_prog_order_depth(m1, CFPO_PROG_ORDER_CELL);
    memcpy(a, in, 2 * (size_t)m1 * sizeof *a);
    CHECK(cfpo_prog_order_herded(a, m0, m1, CFPO_PROG_ORDER_CELL, CFPO_PROG_ORDER_TOL, dfloor, freq, err, sizeof err) == 0,
          "%s: herded order failed: %s", what, err);
    herded(in, m0, m1, depth, CFPO_PROG_ORDER_TOL, dfloor, cfpo_prog_herd_radius(m1, freq), b);
    CHECK(memcmp(a, b, 2 * (size_t)m1 * sizeof *a) == 0, "%s: not the brute-force herded order (depth %d)", what, depth);
    CHECK(within_allowance(a, m0, m1, depth, CFPO_PROG_ORDER_TOL), "%s: a cell past its allowance", what);
    CHECK(memcmp(a, in, 2 * (size_t)m0 * sizeof *a) == 0, "%s: the first m0 points changed", what);
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
    /* the paced order against brute force, and its allowance */
    {
        const int64_t n = 1200;
        double *in = malloc(2 * (size_t)n * sizeof *in), *g = malloc(2 * (size_t)n * sizeof *g);
        uniform(in, n, 13);
        CHECK(cfpo_prog_order_depth(1200, 2) == 4 && cfpo_prog_order_depth(7, 2) == 0, "paced: the quadtree's depth");
        check_paced(in, 100, 1200, 2, 1, "paced, m0 = 100, leaves of 2, tol 1");
        check_paced(in, 300, 1200, 8, 2, "paced, m0 = 300, leaves of 8, tol 2");
        check_paced(in, 0, 600, 2, 1, "paced, m0 = 0");
        check_paced(in, 0, 7, 2, 1, "paced, no quadtree (the greedy order)");
        {
            double *big = malloc(2 * 6000 * sizeof *big);
            uniform(big, 6000, 17);
            check_paced(big, 1500, 6000, 2, 1, "paced, 6,000 points after 1,500");
            /* a prefix that leaves one quarter empty: that quarter's points
             * stay far while its allowance holds them back, and the picks
             * beside it must still lower their distances */
            int64_t m = 0;
            for (int64_t i = 0; i < 1500; i++)
                if (!(big[2 * i] < 0.5 && big[2 * i + 1] < 0.5)) big[2 * m] = big[2 * i], big[2 * m + 1] = big[2 * i + 1], m++;
            memmove(big + 2 * m, big + 2 * 1500, 2 * 4500 * sizeof *big);
            check_paced(big, m, m + 4500, 2, 1, "paced, a prefix with an empty quarter");
            check_paced(big, m, m + 4500, 8, 1, "paced, a prefix with an empty quarter, leaves of 8");
            free(big);
        }
        /* the allowance can fail: the greedy order breaks it here */
        memcpy(g, in, 2 * (size_t)n * sizeof *g);
        CHECK(cfpo_prog_order(g, 100, 1200, err, sizeof err) == 0, "greedy: %s", err);
        CHECK(!within_allowance(g, 100, 1200, 3, 1), "the greedy order kept the paced allowance");
        CHECK(cfpo_prog_order_paced(g, 100, 1200, 2, 0, err, sizeof err) != 0, "paced: tol 0 accepted");
        CHECK(cfpo_prog_order_paced(g, 100, 1200, 0, 1, err, sizeof err) != 0, "paced: per_cell 0 accepted");
        free(in);
        free(g);
    }
    /* the herded order against brute force */
    {
        double *in = malloc(2 * 512 * sizeof *in), *a = malloc(2 * 512 * sizeof *a), *b = malloc(2 * 512 * sizeof *b);
        uniform(in, 512, 19);
        double worst = 0;
        cfpo_prog_herd_tab *K = malloc(sizeof *K);
        for (int i = 0; i < 40; i++) {
            const double R = 1 + 0.37 * i;
            cfpo_prog_herd_table(R, K);
            const double e =
                fabs(cfpo_prog_herd_kernel(in + 2 * i, in + 2 * i + 2, K) - kernel_direct(in + 2 * i, in + 2 * i + 2, R));
            if (e > worst) worst = e;
        }
        free(K);
        CHECK(worst < 1e-9, "herd kernel: %g from its Fourier series", worst);
        check_herded(in, 128, 256, CFPO_PROG_HERD_FLOOR, CFPO_PROG_HERD_FREQ, "herded, 256 after 128");
        check_herded(in, 200, 400, CFPO_PROG_HERD_FLOOR, CFPO_PROG_HERD_FREQ, "herded, 400 after 200");
        check_herded(in, 0, 64, CFPO_PROG_HERD_FLOOR, CFPO_PROG_HERD_FREQ, "herded, m0 = 0");
        check_herded(in, 100, 300, 0.5, 0.8, "herded, floor 0.5, freq 0.8");
        check_herded(in, 100, 300, 0, 0.5, "herded, floor 0 (no distance kept)");
        check_herded(in, 100, 300, 2, 0.5, "herded, floor 2 (the farthest free point only)");
        /* a grid's centres: exact ties of distance and of the kernel */
        for (int i = 0; i < 256; i++) in[2 * i] = (i % 16 + 0.5) / 16, in[2 * i + 1] = (i / 16 + 0.5) / 16;
        check_herded(in, 0, 256, CFPO_PROG_HERD_FLOOR, CFPO_PROG_HERD_FREQ, "herded, a grid (ties)");
        check_herded(in, 17, 256, CFPO_PROG_HERD_FLOOR, CFPO_PROG_HERD_FREQ, "herded, a grid after 17 of its points");
        /* the check can fail: the paced order is another order here */
        uniform(in, 512, 19);
        memcpy(a, in, 2 * 512 * sizeof *a);
        memcpy(b, in, 2 * 512 * sizeof *b);
        CHECK(cfpo_prog_order_paced(a, 128, 256, CFPO_PROG_ORDER_CELL, CFPO_PROG_ORDER_TOL, err, sizeof err) == 0, "%s", err);
        CHECK(cfpo_prog_order_herded(b, 128, 256, CFPO_PROG_ORDER_CELL, CFPO_PROG_ORDER_TOL, CFPO_PROG_HERD_FLOOR,
                                     CFPO_PROG_HERD_FREQ, err, sizeof err) == 0, "%s", err);
        CHECK(memcmp(a, b, 2 * 256 * sizeof *a) != 0, "herded: the same order as the paced one");
        CHECK(cfpo_prog_order_herded(b, 128, 256, 2, 1, -1, 0.5, err, sizeof err) != 0, "herded: floor -1 accepted");
        CHECK(cfpo_prog_order_herded(b, 128, 256, 2, 1, 0.68, 0, err, sizeof err) != 0, "herded: freq 0 accepted");
        free(in);
        free(a);
        free(b);
    }
    return test_report(passed_, failed_);
}
