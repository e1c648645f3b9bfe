/* bridson3.c - Bridson's fast Poisson-disk sampling (SIGGRAPH sketch 2007)
 * on the unit 3-torus, the command cfpo3d-bridson (bl3.h): the 2007
 * algorithm as published, in three dimensions.
 *
 * One uniform first sample, made active. While samples are active: pick
 * one, s, uniformly among them; draw up to k candidates uniformly (by
 * volume) in the spherical shell r <= |c - s| <= 2r; the first with no
 * point within r (pd3grid.h) is added and made active; when all k fail, s
 * is retired. The set is not exactly maximal (rare holes remain, as the
 * paper says). r = REL * Delta3(N); REL's default is measured so that the
 * set has about N points (the exact count is in SUMMARY). Randomness: stream
 * BRIDSON3, one counter for all draws. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bl3.h"
#include "pd3grid.h"
#include "rng.h"
#include "solve3.h"

#define BRIDSON3_STREAM 0x4252494433ULL /* "BRID3" */

enum { REL, CAND };

static double wrap01(double x)
{
    x -= floor(x);
    return x >= 1.0 ? 0.0 : x;
}

static int run_bridson(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                       int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    (void)cb, (void)user;
    const double r = opt[REL] * cfpo3_delta_bound((double)n);
    const int k = (int)opt[CAND];
    /* a set with minimum distance r holds fewer than 0.7405 / (pi/6 r^3) points */
    const size_t cap = (size_t)(0.7405 / (M_PI / 6 * r * r * r)) + 16;
    double *p = calloc(3 * cap, sizeof *p);
    uint32_t *active = malloc(cap * sizeof *active);
    pd3grid G;
    if (!p || !active || cap > INT32_MAX || pd3grid_init(&G, r, p) != 0) {
        free(p), free(active);
        snprintf(err, errlen, "out of memory at radius %g", r);
        return -1;
    }
    uint64_t ctr = 0, trials = 0;
    size_t m = 0, na = 0;
    for (int a = 0; a < 3; a++) p[a] = cfpo_rand01(seed, BRIDSON3_STREAM, ctr++);
    pd3grid_put(&G, p, 0);
    active[na++] = 0;
    m = 1;
    while (na > 0) {
        const size_t j = (size_t)(cfpo_rand01(seed, BRIDSON3_STREAM, ctr++) * (double)na);
        const double *s = p + 3 * (size_t)active[j];
        int found = 0;
        double c[3];
        for (int t = 0; t < k && !found; t++) {
            const double u = cfpo_rand01(seed, BRIDSON3_STREAM, ctr++);
            const double v = cfpo_rand01(seed, BRIDSON3_STREAM, ctr++);
            const double w = cfpo_rand01(seed, BRIDSON3_STREAM, ctr++);
            const double rad = r * cbrt(1.0 + 7.0 * u); /* uniform by volume in [r, 2r] */
            const double cz = 2.0 * v - 1.0, sz = sqrt(fmax(0.0, 1.0 - cz * cz)), ph = 2.0 * M_PI * w;
            c[0] = wrap01(s[0] + rad * sz * cos(ph));
            c[1] = wrap01(s[1] + rad * sz * sin(ph));
            c[2] = wrap01(s[2] + rad * cz);
            trials++;
            found = !pd3grid_conflict(&G, c);
        }
        if (!found) {
            active[j] = active[--na];
            continue;
        }
        if (m >= cap) break; /* cannot happen: the packing bound */
        for (int a = 0; a < 3; a++) p[3 * m + a] = c[a];
        pd3grid_put(&G, c, (int32_t)m);
        active[na++] = (uint32_t)m;
        m++;
    }
    pd3grid_free(&G);
    free(active);
    info->trials = (int64_t)trials;
    *xyz = p;
    *n_out = (int64_t)m;
    return 0;
}

const bl3_method bl3_bridson = {
    .name = "bridson3d", .prog = "cfpo3d-bridson", .min_n = 2, .run = run_bridson, .noptions = 2,
    .options = {{"rel-radius", 0.741, 0.05, 1.0,
                 "      --rel-radius REL r = REL * Delta3(N), Delta3(N) = (sqrt(2)/N)^(1/3); the default\n"
                 "                       %g is measured so that the set has about N points\n"},
                {"candidates", 30, 1, 1000, "      --candidates K   candidates per active sample (default %g, the paper's)\n"}},
    .about = "Bridson's fast Poisson-disk sampling (2007) on the unit 3-torus: an active list,\n"
             "k candidates uniform in the shell [r, 2r] around a random active sample, the\n"
             "first one with no point within r kept; a sample is retired after k failures.\n"
             "Direct. SUMMARY n is the count placed (about N)."};
