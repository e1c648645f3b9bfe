/* test_ptree.c - the certificate's point tree (ptree.c) against brute
 * force, on the sets of ptree_sets.h: uniform (1 to 3,000 points),
 * clusters of 1e-3 and 1e-9, lines, points on the torus's edge (0,
 * 2^-1074, 1e-300, 1 - 2^-53), copies of two positions and a lattice.
 * (The walk over images: test_pwalk.)
 *
 * Must hold:
 *  - the tree: every point once, each node's box holding its points, a
 *    leaf of more than 8 points only where they share one position, and a
 *    depth about log2(n / 8) however the points crowd;
 *  - an_ptree_nearest: exactly (==) the least squared distance over every
 *    point but `skip` and its images by -1, 0, 1 (which hold the nearest
 *    one, the query wrapped into [0, 1)), computed as a point's distance
 *    (image first, then the difference); and to within rounding the torus
 *    distance of cfpo_torus_dist2. Queries at the points, at the points
 *    moved by whole periods, between them, outside [0, 1), on the edge;
 *    skip = none, the nearest point, and a few fixed indices;
 *  - an_ptree_count_box: the brute force's count of images in a closed
 *    square (half-sides 0 to 1.2, and through a point's image). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "ptree.h"
#include "ptree_sets.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

/* ---- the tree's shape ---- */

static int depth_of(const an_ptree *T, long k)
{
    const an_pnode *b = &T->node[k];
    if (b->left < 0) return 1;
    const int l = depth_of(T, b->left), r = depth_of(T, b->right);
    return 1 + (l > r ? l : r);
}

/* 1 when some leaf of more than one point holds one position only. */
static int has_one_position_leaf(const an_ptree *T)
{
    for (size_t k = 0; k < T->nodes; k++) {
        const an_pnode *b = &T->node[k];
        if (b->left < 0 && b->hi - b->lo > 1 && b->x0 == b->x1 && b->y0 == b->y1) return 1;
    }
    return 0;
}

static void shape(const char *what, const an_ptree *T, const double *xy, size_t n)
{
    char *seen = calloc(n + 1, 1);
    int ok_perm = T->n == n, ok_box = 1, ok_leaf = 1, ok_split = 1;
    for (size_t t = 0; t < n && ok_perm; t++) {
        const size_t i = T->id[t];
        ok_perm = i < n && !seen[i] && T->x[t] == xy[2 * i] && T->y[t] == xy[2 * i + 1];
        if (ok_perm) seen[i] = 1;
    }
    for (size_t k = 0; k < T->nodes; k++) {
        const an_pnode *b = &T->node[k];
        for (size_t t = b->lo; t < b->hi; t++)
            if (T->x[t] < b->x0 || T->x[t] > b->x1 || T->y[t] < b->y0 || T->y[t] > b->y1) ok_box = 0;
        if (b->left < 0) {
            if (b->hi - b->lo > 8 && !(b->x0 == b->x1 && b->y0 == b->y1)) ok_leaf = 0;
        } else {
            const an_pnode *l = &T->node[b->left], *r = &T->node[b->right];
            if (l->lo != b->lo || l->hi != r->lo || r->hi != b->hi || l->hi <= l->lo || r->hi <= r->lo) ok_split = 0;
        }
    }
    CHECK(ok_perm, "%s: the tree does not hold each point once, as given", what);
    CHECK(n == 0 || (T->node[0].lo == 0 && T->node[0].hi == n), "%s: the root does not span the points", what);
    CHECK(ok_box, "%s: a point outside its node's box", what);
    CHECK(ok_leaf, "%s: a leaf of more than 8 points of several positions", what);
    CHECK(ok_split, "%s: children do not split their parent's range", what);
    if (n > 0) {
        const int d = depth_of(T, 0);
        const int bound = 2 + (int)ceil(log2((double)n / 8 + 1));
        CHECK(d <= bound, "%s: depth %d above %d", what, d, bound);
    }
    free(seen);
}

/* ---- nearest ---- */

/* In the tree's arithmetic: the query wrapped, each image's coordinate
 * formed first, then the difference. */
static double brute_nearest(const double *xy, size_t n, double qx, double qy, size_t skip)
{
    qx -= floor(qx);
    qy -= floor(qy);
    double best = INFINITY;
    for (size_t j = 0; j < n; j++) {
        if (j == skip) continue;
        for (int oy = -1; oy <= 1; oy++)
            for (int ox = -1; ox <= 1; ox++) {
                const double dx = (xy[2 * j] + ox) - qx, dy = (xy[2 * j + 1] + oy) - qy;
                best = fmin(best, dx * dx + dy * dy);
            }
    }
    return best;
}

static double torus_nearest(const double *xy, size_t n, double qx, double qy, size_t skip, size_t *arg)
{
    double best = INFINITY;
    *arg = n;
    for (size_t j = 0; j < n; j++) {
        if (j == skip) continue;
        const double d2 = cfpo_torus_dist2(qx, qy, xy[2 * j], xy[2 * j + 1]);
        if (d2 < best) { best = d2; *arg = j; }
    }
    return best;
}

static int nn_fail_exact, nn_fail_torus, nn_queries;

static void one_nearest(const char *what, const an_ptree *T, const double *xy, size_t n, double qx, double qy,
                        size_t skip)
{
    const double got = an_ptree_nearest(T, qx, qy, skip);
    const double want = brute_nearest(xy, n, qx, qy, skip);
    size_t arg;
    const double tor = torus_nearest(xy, n, qx, qy, skip, &arg);
    nn_queries++;
    if (!(got == want)) {
        if (nn_fail_exact++ < 5)
            fprintf(stderr, "%s: nearest to (%.17g, %.17g) skip %zu: %.17g, brute force %.17g\n", what, qx, qy, skip,
                    got, want);
    }
    /* The two brute forces round differently (the query wrapped or not,
     * the image moved before or after the difference): a few ulps of the
     * query's coordinates. */
    if (!(got == tor || fabs(sqrt(got) - sqrt(tor)) <= 4 * 0x1p-52 * (fabs(qx) + fabs(qy) + 1)))
        if (nn_fail_torus++ < 5)
            fprintf(stderr, "%s: nearest to (%.17g, %.17g) skip %zu: %.17g, torus distance %.17g\n", what, qx, qy,
                    skip, got, tor);
}

static void nearest(const char *what, const an_ptree *T, const double *xy, size_t n, uint64_t seed)
{
    nn_fail_exact = nn_fail_torus = nn_queries = 0;
    const size_t fixed[] = {0, n / 2, n > 0 ? n - 1 : 0};
    double q[2 * 64];
    int nq = 0;
    /* At points, at points moved by whole periods, between, outside, on
     * the edge. */
    for (int k = 0; k < 12 && n > 0; k++) {
        const size_t i = (size_t)(cfpo_rand01(seed, 1, (uint64_t)k) * n);
        q[2 * nq] = xy[2 * i]; q[2 * nq + 1] = xy[2 * i + 1]; nq++;
        if (k < 4) { q[2 * nq] = xy[2 * i] + (k - 2); q[2 * nq + 1] = xy[2 * i + 1] - 3 * k; nq++; }
    }
    for (int k = 0; k < 14; k++) {
        const double u = cfpo_rand01(seed, 2, 2 * (uint64_t)k), v = cfpo_rand01(seed, 2, 2 * (uint64_t)k + 1);
        if (k < 6) { q[2 * nq] = u; q[2 * nq + 1] = v; }
        else if (k < 10) { q[2 * nq] = 7 * u - 3; q[2 * nq + 1] = 5 * v - 2; }
        else if (n > 0) { /* near a point, at the scale of the tightest set */
            const size_t i = (size_t)(u * n);
            q[2 * nq] = xy[2 * i] + 3e-9 * (v - 0.5);
            q[2 * nq + 1] = xy[2 * i + 1] + 3e-9 * (u - 0.5);
        } else { q[2 * nq] = u; q[2 * nq + 1] = v; }
        nq++;
    }
    const double edge[][2] = {{0, 0}, {-0.0, 1}, {1, 1}, {0x1p-1074, 1 - 0x1p-53}, {-1e-300, 0.5},
                              {1 - 0x1p-53, -0x1p-60}, {-1, 2}, {0.5, 0.25}};
    for (size_t k = 0; k < sizeof edge / sizeof edge[0]; k++) {
        q[2 * nq] = edge[k][0];
        q[2 * nq + 1] = edge[k][1];
        nq++;
    }
    for (int k = 0; k < nq; k++) {
        const double qx = q[2 * k], qy = q[2 * k + 1];
        one_nearest(what, T, xy, n, qx, qy, n);
        for (size_t f = 0; f < 3; f++) one_nearest(what, T, xy, n, qx, qy, fixed[f]);
        size_t arg;
        torus_nearest(xy, n, qx, qy, n, &arg); /* the nearest itself skipped */
        if (arg < n) one_nearest(what, T, xy, n, qx, qy, arg);
    }
    CHECK(nn_fail_exact == 0, "%s: %d of %d nearest queries differ from brute force", what, nn_fail_exact, nn_queries);
    CHECK(nn_fail_torus == 0, "%s: %d of %d nearest queries differ from the torus distance", what, nn_fail_torus,
          nn_queries);
}

/* ---- counting in a square ---- */

/* Images with both differences, computed as written, within h: offsets
 * two periods past the square on each side. */
static size_t brute_count(const double *xy, size_t n, double cx, double cy, double h)
{
    size_t count = 0;
    for (size_t j = 0; j < n; j++)
        for (double oy = floor(cy - h) - 2; oy <= floor(cy + h) + 2; oy++)
            for (double ox = floor(cx - h) - 2; ox <= floor(cx + h) + 2; ox++)
                count += fabs((xy[2 * j] + ox) - cx) <= h && fabs((xy[2 * j + 1] + oy) - cy) <= h;
    return count;
}

/* an_ptree_count_box against brute force: squares of half-side 0, small,
 * 0.3, 0.5 and 1.2 (images of a point more than once), and squares whose
 * side passes exactly through a point's image (closed). */
static void count_box(const char *what, const an_ptree *T, const double *xy, size_t n, uint64_t seed)
{
    int bad = 0, runs = 0;
    for (int k = 0; k < 10; k++) {
        const double u = cfpo_rand01(seed, 7, 2 * (uint64_t)k), v = cfpo_rand01(seed, 7, 2 * (uint64_t)k + 1);
        const size_t i = (size_t)(u * n), j = (size_t)(v * n);
        double cx = 3 * u - 1, cy = 3 * v - 1;
        if (k % 3 == 0 && n > 0) { cx = xy[2 * i]; cy = xy[2 * i + 1]; }
        const double h[] = {0, n > 0 ? 2.0 / sqrt((double)n) : 0.1, 0.3, 0.5, 1.2,
                            n > 0 ? fabs((xy[2 * j] + 1) - cx) : 0.2, n > 0 ? fabs(xy[2 * j + 1] - cy) : 0.2};
        for (size_t a = 0; a < sizeof h / sizeof h[0]; a++) {
            const size_t got = an_ptree_count_box(T, cx, cy, h[a]), want = brute_count(xy, n, cx, cy, h[a]);
            runs++;
            if (got != want && bad++ < 3)
                fprintf(stderr, "%s: count in the square of (%.17g, %.17g) half-side %.17g: %zu, brute force %zu\n",
                        what, cx, cy, h[a], got, want);
        }
    }
    CHECK(bad == 0, "%s: %d of %d counts in a square differ from brute force", what, bad, runs);
}

static void one_set(const char *what, const double *xy, size_t n, int kind)
{
    an_ptree T;
    CHECK(an_ptree_build(&T, xy, n) == 0, "%s: build failed", what);
    shape(what, &T, xy, n);
    nearest(what, &T, xy, n, 31 + (uint64_t)kind);
    count_box(what, &T, xy, n, 71 + (uint64_t)kind);
    const int one = has_one_position_leaf(&T);
    CHECK(one == (kind == COPIES || kind == UNEVEN), "%s: a leaf of one position %s", what,
          one ? "where none was expected" : "missing");
    an_ptree_free(&T);
}

int main(void)
{
    double *xy = malloc(2 * 3000 * sizeof *xy);
    ptree_sets_each(xy, one_set);
    /* No point, and one point skipped: infinity. */
    an_ptree T;
    CHECK(an_ptree_build(&T, xy, 0) == 0 && an_ptree_nearest(&T, 0.5, 0.5, 0) == INFINITY, "no points");
    an_ptree_free(&T);
    CHECK(an_ptree_build(&T, xy, 1) == 0 && an_ptree_nearest(&T, xy[0], xy[1], 0) == INFINITY,
          "one point skipped: not infinity");
    an_ptree_free(&T);
    free(xy);
    return test_report(passed_, failed_);
}
