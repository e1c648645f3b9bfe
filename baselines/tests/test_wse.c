/* test_wse.c - weighted sample elimination (wse.h) against a brute-force
 * elimination that recomputes every weight from all pairs and all periodic
 * images at every step (O(M^3)), plain and progressive, with and without
 * weight limiting, on sets whose stages take both the grid path (d_max <= 1/3)
 * and the all-images path; and the greedy farthest-point order (fporder.h)
 * against an O(n^2) greedy loop. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fporder.h"
#include "jitter.h"
#include "testutil.h"
#include "wse.h"

static int passed_, failed_;

static int64_t pair_all_images(const double *p, const double *q, double dmax, double dmin, double alpha)
{
    int64_t w = 0;
    for (int oy = -2; oy <= 2; oy++)
        for (int ox = -2; ox <= 2; ox++) {
            const double dx = p[0] - q[0] + ox, dy = p[1] - q[1] + oy;
            w += wse_pair_weight(dx * dx + dy * dy, dmax, dmin, alpha);
        }
    return w;
}

/* ids[0..c) -> t kept (their order), then the eliminated, later first */
static void brute_stage(const double *xy, size_t *ids, size_t c, size_t t, const wse_params *p)
{
    const double dmax = wse_dmax(t);
    const double dmin = p->weight_limit ? dmax * (1 - pow((double)t / (double)c, WSE_GAMMA)) * WSE_BETA : 0;
    int64_t *pw = malloc(c * c * sizeof *pw);
    char *dead = calloc(c, 1);
    size_t *gone = malloc(c * sizeof *gone);
    for (size_t a = 0; a < c; a++)
        for (size_t b = 0; b < c; b++)
            pw[a * c + b] = a == b ? 0 : pair_all_images(xy + 2 * ids[a], xy + 2 * ids[b], dmax, dmin, p->alpha);
    for (size_t e = 0; e < c - t; e++) {
        size_t best = 0;
        int64_t bw = -1;
        for (size_t a = 0; a < c; a++) {
            if (dead[a]) continue;
            int64_t w = 0;
            for (size_t b = 0; b < c; b++)
                if (!dead[b]) w += pw[a * c + b];
            if (w > bw || (w == bw && ids[a] > ids[best])) bw = w, best = a;
        }
        dead[best] = 1;
        gone[e] = ids[best];
    }
    size_t k = 0;
    for (size_t a = 0; a < c; a++)
        if (!dead[a]) ids[k++] = ids[a];
    for (size_t e = c - t; e-- > 0;) ids[k++] = gone[e];
    free(pw), free(dead), free(gone);
}

static void compare(const char *name, size_t n, double ratio, int progressive, int limit, uint64_t seed)
{
    const size_t M = (size_t)ceil(ratio * (double)n);
    double *xy = malloc(2 * M * sizeof *xy);
    size_t *got = malloc(n * sizeof *got), *ids = malloc(M * sizeof *ids);
    white_points((int64_t)M, seed, xy);
    const wse_params p = {.alpha = WSE_ALPHA, .weight_limit = limit, .progressive = progressive};
    CHECK(wse_order(xy, M, n, &p, got) == 0, "%s: wse_order", name);
    for (size_t i = 0; i < M; i++) ids[i] = i;
    brute_stage(xy, ids, M, n, &p);
    for (size_t c = n; progressive && c > 1; c /= 2) brute_stage(xy, ids, c, c / 2, &p);
    size_t same = 0;
    while (same < n && got[same] == ids[same]) same++;
    CHECK(same == n, "%s: the order differs from brute force at %zu of %zu", name, same, n);
    free(xy), free(got), free(ids);
}

static double d2(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    dx = fmin(dx, 1 - dx), dy = fmin(dy, 1 - dy);
    return dx * dx + dy * dy;
}

static void check_fporder(const char *name, const double *xy, size_t n, size_t first)
{
    size_t *got = malloc(n * sizeof *got), *want = malloc(n * sizeof *want);
    double *best = malloc(n * sizeof *best);
    char *used = calloc(n, 1);
    CHECK(fp_order(xy, n, first, got) == 0, "%s: fp_order", name);
    for (size_t i = 0; i < n; i++) best[i] = INFINITY;
    size_t cur = first;
    for (size_t k = 0; k < n; k++) {
        want[k] = cur;
        used[cur] = 1;
        size_t nx = 0;
        double far = -1;
        for (size_t i = 0; i < n; i++) {
            if (used[i]) continue;
            best[i] = fmin(best[i], d2(xy + 2 * i, xy + 2 * cur));
            if (best[i] > far) far = best[i], nx = i;
        }
        cur = nx;
    }
    size_t same = 0;
    while (same < n && got[same] == want[same]) same++;
    CHECK(same == n, "%s: greedy order differs from brute force at %zu of %zu", name, same, n);
    free(got), free(want), free(best), free(used);
}

int main(void)
{
    compare("plain n = 60", 60, WSE_RATIO, 0, 1, 1);
    compare("progressive n = 64", 64, WSE_RATIO, 1, 1, 2);
    compare("progressive n = 45", 45, WSE_RATIO, 1, 1, 3);
    compare("progressive, no weight limit", 50, WSE_RATIO, 1, 0, 4);
    compare("n = 3 (all images)", 3, WSE_RATIO, 1, 1, 5);
    compare("n = 1", 1, 3.0, 1, 1, 6);
    compare("ratio 2.5", 80, 2.5, 1, 1, 7);

    /* the same seed, the same points; another seed, others */
    const wse_params p = {.alpha = WSE_ALPHA, .weight_limit = 1, .progressive = 1};
    double a[400], b[400], c[400];
    char err[256];
    CHECK(wse_points(200, 9, WSE_RATIO, &p, a, err, sizeof err) == 0 &&
              wse_points(200, 9, WSE_RATIO, &p, b, err, sizeof err) == 0 &&
              wse_points(200, 10, WSE_RATIO, &p, c, err, sizeof err) == 0,
          "wse_points: %s", err);
    CHECK(memcmp(a, b, sizeof a) == 0 && memcmp(a, c, sizeof a) != 0, "seeded");

    /* the greedy farthest-point order */
    double *xy = malloc(2 * 2000 * sizeof *xy);
    white_points(2000, 11, xy);
    check_fporder("white 2000", xy, 2000, 0);
    check_fporder("white 500 from 17", xy, 500, 17);
    jitter_points(1024, 12, xy);
    check_fporder("jittered 1024", xy, 1024, 5);
    for (int i = 0; i < 300; i++) xy[2 * (300 + i)] = xy[2 * i], xy[2 * (300 + i) + 1] = xy[2 * i + 1];
    check_fporder("duplicates", xy, 600, 0);
    check_fporder("one point", xy, 1, 0);
    free(xy);
    return test_report(passed_, failed_);
}
