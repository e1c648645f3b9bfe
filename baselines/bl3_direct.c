/* bl3_direct.c - white noise and the jittered set on the unit 3-torus, as
 * 3-D baselines (bl3.h): the commands cfpo3d-white and cfpo3d-jitter.
 *
 * White noise: 3n uniform coordinates, point i = (u(3i), u(3i+1), u(3i+2))
 * of stream WHITE3.
 * Jittered (stratified) sampling (Cook 1986) for any n: h = round(cbrt n)
 * slabs in z, slab k holding floor((k+1) n / h) - floor(k n / h) points;
 * within a slab the 2-D jittered layout of the 2-D baseline (jitter.h:
 * round(sqrt c) rows of near-equal counts); one uniform point in each of
 * the resulting boxes. For n = h^3 it is the h x h x h jittered grid. */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>

#include "bl3.h"
#include "jitter.h"
#include "rng.h"

#define WHITE3_STREAM 0x5748495433ULL  /* "WHIT3" */
#define JITTER3_STREAM 0x4a49545433ULL /* "JITT3" */

static int64_t icbrt_round(int64_t n)
{
    int64_t h = (int64_t)llround(cbrt((double)n));
    return h < 1 ? 1 : h;
}

static double below1(double x) { return x >= 1.0 ? nextafter(1.0, 0.0) : x; }

static int alloc_out(int64_t n, double **xyz, char *err, size_t errlen)
{
    *xyz = malloc(3 * (size_t)n * sizeof **xyz);
    if (!*xyz) snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
    return *xyz ? 0 : -1;
}

static int run_white(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                     int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    (void)opt, (void)cb, (void)user, (void)info;
    if (alloc_out(n, xyz, err, errlen) != 0) return -1;
    for (int64_t i = 0; i < 3 * n; i++) (*xyz)[i] = cfpo_rand01(seed, WHITE3_STREAM, (uint64_t)i);
    *n_out = n;
    return 0;
}

static int run_jitter(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                      int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    (void)opt, (void)cb, (void)user, (void)info;
    if (alloc_out(n, xyz, err, errlen) != 0) return -1;
    double *p = *xyz;
    const int64_t h = icbrt_round(n);
    int64_t i = 0;
    for (int64_t k = 0; k < h; k++) {
        const int64_t c = (int64_t)((__int128)(k + 1) * n / h - (__int128)k * n / h);
        if (c == 0) continue;
        const int64_t rows = jitter_rows(c);
        for (int64_t r = 0; r < rows; r++) {
            int64_t first, cnt;
            jitter_row(c, r, &first, &cnt);
            for (int64_t a = 0; a < cnt; a++, i++) {
                const uint64_t b = 3 * (uint64_t)i;
                p[3 * i] = below1(((double)a + cfpo_rand01(seed, JITTER3_STREAM, b)) / (double)cnt);
                p[3 * i + 1] = below1(((double)r + cfpo_rand01(seed, JITTER3_STREAM, b + 1)) / (double)rows);
                p[3 * i + 2] = below1(((double)k + cfpo_rand01(seed, JITTER3_STREAM, b + 2)) / (double)h);
            }
        }
    }
    *n_out = i;
    return 0;
}

const bl3_method bl3_white = {
    .name = "white3d", .prog = "cfpo3d-white", .min_n = 2, .run = run_white,
    .about = "White noise on the unit 3-torus: n independent uniform points. Direct."};

const bl3_method bl3_jitter = {
    .name = "jitter3d", .prog = "cfpo3d-jitter", .min_n = 2, .run = run_jitter,
    .about = "Jittered (stratified) sampling on the unit 3-torus: round(cbrt n) slabs in z,\n"
             "each cut as the 2-D jittered set into boxes of near-equal size, one uniform\n"
             "point in each box (for n = h^3 the h x h x h jittered grid). Direct."};
