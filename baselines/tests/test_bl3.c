/* test_bl3.c - the 3-D baselines (bl3.h) against brute force: weighted
 * sample elimination's kept set (wse3.h) against an O(M^3) elimination
 * that recomputes every weight from all pairs and all periodic images at
 * every step, on sets whose d_max takes the grid path and the all-images
 * path, with and without weight limiting; dart throwing's and Bridson's
 * disk property (no pair closer than r, all pairs checked); the jittered
 * set's one point per box; every method seeded (same seed, same bytes). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl3.h"
#include "nn3.h"
#include "rng.h"
#include "solve3.h"
#include "testutil.h"
#include "wse.h"
#include "wse3.h"

static int passed_, failed_;

extern const bl3_method bl3_white, bl3_jitter, bl3_dart, bl3_bridson, bl3_wse;

static int64_t pair_all_images(const double *p, const double *q, double dmax, double dmin, double alpha)
{
    int64_t w = 0;
    for (int oz = -2; oz <= 2; oz++)
        for (int oy = -2; oy <= 2; oy++)
            for (int ox = -2; ox <= 2; ox++) {
                const double dx = p[0] - q[0] + ox, dy = p[1] - q[1] + oy, dz = p[2] - q[2] + oz;
                w += wse_pair_weight(dx * dx + dy * dy + dz * dz, dmax, dmin, alpha);
            }
    return w;
}

static void brute_wse(const double *p, size_t M, size_t n, int limit, char *dead)
{
    const double dmax = cbrt(sqrt(2.0) / (double)n); /* the paper's 2 r_max, written out */
    const double dmin = limit ? dmax * (1 - pow((double)n / (double)M, 1.5)) * 0.65 : 0;
    int64_t *pw = malloc(M * M * sizeof *pw); /* every pair's weight, all images */
    for (size_t a = 0; a < M; a++)
        for (size_t b = 0; b < M; b++) pw[a * M + b] = a == b ? 0 : pair_all_images(p + 3 * a, p + 3 * b, dmax, dmin, 8.0);
    memset(dead, 0, M);
    for (size_t e = 0; e + n < M; e++) { /* every weight summed again at every step */
        size_t best = 0;
        int64_t bw = -1;
        for (size_t a = 0; a < M; a++) {
            if (dead[a]) continue;
            int64_t w = 0;
            for (size_t b = 0; b < M; b++)
                if (!dead[b]) w += pw[a * M + b];
            if (w >= bw) bw = w, best = a; /* ties: the larger index */
        }
        dead[best] = 1;
    }
    free(pw);
}

static void compare_wse(const char *name, size_t n, size_t M, int limit, uint64_t seed)
{
    double *p = malloc(3 * M * sizeof *p);
    size_t *keep = malloc(n * sizeof *keep);
    char *dead = malloc(M);
    for (size_t i = 0; i < 3 * M; i++) p[i] = cfpo_rand01(seed, 77, i);
    CHECK(wse3_order(p, M, n, 8.0, limit, keep) == 0, "%s: wse3_order", name);
    brute_wse(p, M, n, limit, dead);
    size_t k = 0, same = 0;
    for (size_t a = 0; a < M; a++)
        if (!dead[a]) same += k < n && keep[k++] == a;
    CHECK(same == n && k == n, "%s: kept set differs from brute force (%zu of %zu agree)", name, same, n);
    free(p), free(keep), free(dead);
}

static double brute_min_dist(const double *p, int64_t n)
{
    double m = INFINITY;
    for (int64_t i = 0; i < n; i++)
        for (int64_t j = i + 1; j < n; j++) {
            const double dx = cfpo3_pdiff(p[3 * i], p[3 * j]), dy = cfpo3_pdiff(p[3 * i + 1], p[3 * j + 1]),
                         dz = cfpo3_pdiff(p[3 * i + 2], p[3 * j + 2]);
            m = fmin(m, sqrt(dx * dx + dy * dy + dz * dz));
        }
    return m;
}

static int run(const bl3_method *m, int64_t n, uint64_t seed, const double *opt, double **p, int64_t *got)
{
    char err[256];
    bl3_info info = {.iterations = -1};
    double o[BL3_MAX_OPTIONS];
    for (int i = 0; i < m->noptions; i++) o[i] = opt ? opt[i] : m->options[i].def;
    const int rc = m->run(n, seed, o, NULL, NULL, p, got, &info, err, sizeof err);
    if (rc != 0) fprintf(stderr, "%s: %s\n", m->name, err);
    return rc;
}

static void check_seeded(const bl3_method *m, int64_t n)
{
    double *a = NULL, *b = NULL, *c = NULL;
    int64_t na = 0, nb = 0, nc = 0;
    CHECK(run(m, n, 5, NULL, &a, &na) == 0 && run(m, n, 5, NULL, &b, &nb) == 0 && run(m, n, 6, NULL, &c, &nc) == 0,
          "%s runs", m->name);
    CHECK(na == nb && memcmp(a, b, 3 * (size_t)na * sizeof *a) == 0, "%s: same seed, same bytes", m->name);
    CHECK(na != nc || memcmp(a, c, 3 * (size_t)na * sizeof *a) != 0, "%s: another seed, another set", m->name);
    for (int64_t i = 0; i < 3 * na; i++)
        if (!(a[i] >= 0 && a[i] < 1)) {
            CHECK(0, "%s: coordinate %g outside [0, 1)", m->name, a[i]);
            break;
        }
    free(a), free(b), free(c);
}

int main(void)
{
    /* d_max = Delta3(n): 0.49 at n = 12 (all images), 0.26 at 80 (grid of 3^3) */
    compare_wse("n 12 of 60, limited", 12, 60, 1, 1);
    compare_wse("n 12 of 60, no limit", 12, 60, 0, 2);
    compare_wse("n 80 of 400, limited (grid)", 80, 400, 1, 3);
    compare_wse("n 100 of 300, no limit (grid)", 100, 300, 0, 4);
    compare_wse("n 2 of 9", 2, 9, 1, 5);
    CHECK(fabs(wse3_dmax(1000) - 2 * cbrt(1.0 / (4 * sqrt(2.0) * 1000))) < 1e-15, "d_max = 2 r_max of the paper");

    /* dart throwing and Bridson: no pair within r */
    double *p;
    int64_t got;
    const double dopt[2] = {0.78, 1e5};
    CHECK(run(&bl3_dart, 1500, 3, dopt, &p, &got) == 0, "dart runs");
    CHECK(got == 1500, "dart places n = 1500 at REL 0.78 (placed %lld)", (long long)got);
    CHECK(brute_min_dist(p, got) >= 0.78 * cfpo3_delta_bound(1500), "dart: a pair closer than r");
    free(p);
    const double sat[2] = {0.9, 2e4}; /* past the saturation limit: stops short of n */
    CHECK(run(&bl3_dart, 800, 4, sat, &p, &got) == 0 && got < 800 && got > 400, "dart saturates (placed %lld)",
          (long long)got);
    CHECK(brute_min_dist(p, got) >= 0.9 * cfpo3_delta_bound(800), "saturated dart: a pair closer than r");
    free(p);
    CHECK(run(&bl3_bridson, 1500, 3, NULL, &p, &got) == 0, "bridson runs");
    CHECK(got > 1000 && got < 2200, "bridson: about n points (%lld)", (long long)got);
    CHECK(brute_min_dist(p, got) >= bl3_bridson.options[0].def * cfpo3_delta_bound(1500), "bridson: a pair closer than r");
    free(p);

    /* jittered: 4^3 boxes of a 64-point set hold one point each */
    CHECK(run(&bl3_jitter, 64, 7, NULL, &p, &got) == 0 && got == 64, "jitter runs");
    int box[64] = {0};
    for (int64_t i = 0; i < got; i++)
        box[(int)(p[3 * i + 2] * 4) * 16 + (int)(p[3 * i + 1] * 4) * 4 + (int)(p[3 * i] * 4)]++;
    int ones = 0;
    for (int b = 0; b < 64; b++) ones += box[b] == 1;
    CHECK(ones == 64, "jitter: one point per box (%d of 64)", ones);
    free(p);
    CHECK(run(&bl3_jitter, 1001, 7, NULL, &p, &got) == 0 && got == 1001, "jitter: exact n for any n");
    free(p);

    check_seeded(&bl3_white, 500);
    check_seeded(&bl3_jitter, 500);
    check_seeded(&bl3_dart, 500);
    check_seeded(&bl3_bridson, 500);
    check_seeded(&bl3_wse, 300);
    return test_report(passed_, failed_);
}
