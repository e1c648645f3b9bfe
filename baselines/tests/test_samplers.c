/* test_samplers.c - the direct samplers (jitter.h, sobol.h) and Gaussian
 * blue noise (gbn.h):
 *  - white noise: uniform by a chi-square test over 16 x 16 cells and by
 *    the means of x and y (65,536 points, three seeds);
 *  - jittered: for square and other n, the rows' counts are floor or ceil
 *    of n / r and sum to n, and every stratum holds exactly one point;
 *  - Sobol': the unscrambled second coordinate at i = 2^k is the known
 *    direction number m_{k+1} / 2^{k+1} (m = 1, 3, 5, 15, 17, 51, 85, 255,
 *    the recurrence of x + 1), the first is the bit reversal of i; at
 *    n = 2^m (m <= 12) every elementary interval of area 2^-m holds one
 *    point, unscrambled and scrambled (three seeds); a prefix of 1000
 *    points: its first 512 and its points 512..767 are nets;
 *  - Owen's scramble: nested (values that share j leading digits map to
 *    values that share j leading digits), not linear (a linear scramble
 *    with a digital shift has s(a)^s(b)^s(c)^s(a^b^c) = 0 for all a, b, c:
 *    here it fails for most triples (75%)); other seeds other points; point 5's
 *    coordinates over 4000 seeds are uniform (chi-square, 16 bins);
 *  - GBN: the truncated cell-list sum equals the all-pairs sum to 1e-6 of
 *    the kernel's width; the points are the same bytes on 1, 2 and 3
 *    threads; from the same start, the authors' kernel (float, every pair,
 *    nearest image, their step, 1000 iterations) gives delta_min and
 *    delta_avg within 0.01 of ours. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gbn.h"
#include "jitter.h"
#include "sobol.h"
#include "stats.h"
#include "testutil.h"

static int passed_, failed_;

static void test_white(void)
{
    const int64_t n = 65536;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        white_points(n, seed, xy);
        int count[256] = {0};
        double mx = 0, my = 0;
        for (int64_t i = 0; i < n; i++) {
            count[(int)(xy[2 * i] * 16) + 16 * (int)(xy[2 * i + 1] * 16)]++;
            mx += xy[2 * i];
            my += xy[2 * i + 1];
        }
        double chi2 = 0, e = n / 256.0;
        for (int c = 0; c < 256; c++) chi2 += (count[c] - e) * (count[c] - e) / e;
        /* 255 degrees of freedom: mean 255, sd 22.6 */
        CHECK(chi2 < 255 + 6 * 22.6, "white seed %llu: chi2 %g", (unsigned long long)seed, chi2);
        const double sd = sqrt(1.0 / 12 / n);
        CHECK(fabs(mx / n - 0.5) < 5 * sd && fabs(my / n - 0.5) < 5 * sd, "white means %g %g", mx / n, my / n);
    }
    free(xy);
}

static void test_jitter(void)
{
    const int64_t ns[] = {1, 2, 17, 100, 101, 1000, 4096, 4097, 65535};
    for (size_t t = 0; t < sizeof ns / sizeof ns[0]; t++) {
        const int64_t n = ns[t], r = jitter_rows(n);
        CHECK(llabs(r * r - n) <= r, "n %lld: %lld rows", (long long)n, (long long)r);
        int64_t total = 0, lo = n, hi = 0;
        for (int64_t k = 0; k < r; k++) {
            int64_t first, count;
            jitter_row(n, k, &first, &count);
            CHECK(first == total, "n %lld row %lld starts at %lld", (long long)n, (long long)k, (long long)first);
            total += count;
            lo = count < lo ? count : lo;
            hi = count > hi ? count : hi;
        }
        CHECK(total == n && hi - lo <= 1 && lo >= 1, "n %lld: rows hold %lld (%lld..%lld)", (long long)n,
              (long long)total, (long long)lo, (long long)hi);
        double *xy = malloc(2 * (size_t)n * sizeof *xy);
        char *seen = calloc((size_t)n, 1);
        jitter_points(n, 7, xy);
        int ok = 1;
        for (int64_t i = 0; i < n; i++) {
            const double x = xy[2 * i], y = xy[2 * i + 1];
            if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) ok = 0;
            const int64_t k = (int64_t)(y * (double)r);
            int64_t first, count;
            jitter_row(n, k < r ? k : r - 1, &first, &count);
            const int64_t c = (int64_t)(x * (double)count);
            const int64_t s = first + (c < count ? c : count - 1);
            if (seen[s]++) ok = 0;
        }
        CHECK(ok, "n %lld: a stratum holds two points or one lies outside", (long long)n);
        free(xy);
        free(seen);
    }
}

/* 1 when every elementary interval [a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), ..)
 * of points xy[first..first+2^m) holds exactly one point. */
static int is_net(const double *xy, int64_t first, int m)
{
    const int64_t N = (int64_t)1 << m;
    int *count = malloc((size_t)N * sizeof *count);
    int ok = 1;
    for (int k = 0; k <= m && ok; k++) {
        memset(count, 0, (size_t)N * sizeof *count);
        for (int64_t i = first; i < first + N; i++) {
            const int64_t a = (int64_t)(xy[2 * i] * (double)((int64_t)1 << k));
            const int64_t b = (int64_t)(xy[2 * i + 1] * (double)((int64_t)1 << (m - k)));
            count[(a << (m - k)) | b]++;
        }
        for (int64_t c = 0; c < N; c++)
            if (count[c] != 1) ok = 0;
    }
    free(count);
    return ok;
}

static void test_sobol(void)
{
    const unsigned mk[] = {1, 3, 5, 15, 17, 51, 85, 255};
    for (int k = 0; k < 8; k++) {
        uint32_t x, y;
        sobol_point(1u << k, &x, &y);
        CHECK(y == (uint32_t)mk[k] << (31 - k), "sobol y(2^%d) = %u, not m = %u", k, y, mk[k]);
        CHECK(x == 1u << (31 - k), "sobol x(2^%d)", k);
    }
    uint32_t x, y;
    sobol_point(6, &x, &y); /* v1 ^ v2 = 0.75 ^ 0.625 = 0.375 */
    CHECK(x == 3u << 29 && y == 3u << 29, "sobol point 6: %u %u", x, y);
    const int M = 12;
    double *xy = malloc(2 * ((size_t)1 << M) * sizeof *xy);
    for (int m = 0; m <= M; m++) {
        sobol_points((int64_t)1 << m, 1, 0, xy);
        CHECK(is_net(xy, 0, m), "plain sobol 2^%d is not a (0,%d,2)-net", m, m);
        for (uint64_t seed = 1; seed <= 3; seed++) {
            sobol_points((int64_t)1 << m, seed, 1, xy);
            CHECK(is_net(xy, 0, m), "owen sobol 2^%d seed %llu is not a net", m, (unsigned long long)seed);
        }
    }
    free(xy);
    xy = malloc(2 * 1000 * sizeof *xy);
    sobol_points(1000, 9, 1, xy);
    CHECK(is_net(xy, 0, 9) && is_net(xy, 512, 8), "the prefix of 1000 points: its aligned blocks are not nets");
    double *other = malloc(2 * 1000 * sizeof *other);
    sobol_points(1000, 10, 1, other);
    int same = 0;
    for (int i = 0; i < 2000; i++) same += xy[i] == other[i];
    CHECK(same == 0, "seeds 9 and 10 share %d coordinates", same);
    free(other);
    free(xy);

    /* nested: a shared prefix of j digits maps to a shared prefix of j digits */
    int nested = 1, nonlinear = 0;
    for (uint32_t t = 0; t < 2000; t++) {
        const uint32_t a = (uint32_t)(t * 2654435761u), b = a ^ ((t * 40503u) >> (t % 31));
        const int j = a == b ? 32 : __builtin_clz(a ^ b);
        const uint32_t sa = sobol_owen(a, 5, t & 1), sb = sobol_owen(b, 5, t & 1);
        const int js = sa == sb ? 32 : __builtin_clz(sa ^ sb);
        if (js != j) nested = 0;
        const uint32_t c = t * 97u + 13u;
        if ((sa ^ sb ^ sobol_owen(c, 5, t & 1) ^ sobol_owen(a ^ b ^ c, 5, t & 1)) != 0) nonlinear++;
    }
    CHECK(nested, "the scramble is not nested");
    CHECK(nonlinear > 1000, "the scramble looks linear: %d of 2000 triples", nonlinear);

    /* point 5 over 4000 seeds: uniform */
    int bins[2][16] = {{0}};
    double p[12], mean[2] = {0, 0};
    for (uint64_t seed = 1; seed <= 4000; seed++) {
        sobol_points(6, seed, 1, p);
        for (int d = 0; d < 2; d++) {
            bins[d][(int)(p[10 + d] * 16)]++;
            mean[d] += p[10 + d] / 4000;
        }
    }
    for (int d = 0; d < 2; d++) {
        double chi2 = 0;
        for (int b = 0; b < 16; b++) chi2 += (bins[d][b] - 250.0) * (bins[d][b] - 250.0) / 250.0;
        /* 15 degrees of freedom: mean 15, sd 5.5 */
        CHECK(chi2 < 15 + 6 * 5.5, "point 5, coordinate %d over seeds: chi2 %g", d, chi2);
        CHECK(fabs(mean[d] - 0.5) < 5 * sqrt(1.0 / 12 / 4000), "point 5 mean %g", mean[d]);
    }
}

/* The authors' toroidal kernel as published (every pair, nearest image,
 * float arithmetic, x += step * sum d exp(-|d|^2 n / (2 sigma^2)), sigma 1). */
static void authors_gbn(float *p, int n, int iterations)
{
    float *q = malloc(2 * (size_t)n * sizeof *q);
    const float ss2InvNeg = -(float)n / 2.0f, scale = 0.25f;
    for (int it = 0; it < iterations; it++) {
        for (int i = 0; i < n; i++) {
            float gx = 0, gy = 0;
            for (int j = 0; j < n; j++) {
                if (j == i) continue;
                float x = p[2 * i] - p[2 * j], y = p[2 * i + 1] - p[2 * j + 1];
                if (x < -0.5f) x += 1.0f;
                if (x >= 0.5f) x -= 1.0f;
                if (y < -0.5f) y += 1.0f;
                if (y >= 0.5f) y -= 1.0f;
                const float g = expf(ss2InvNeg * (x * x + y * y));
                gx += x * g;
                gy += y * g;
            }
            float x = p[2 * i] + scale * gx, y = p[2 * i + 1] + scale * gy;
            if (x < 0) x += 1;
            if (x >= 1) x -= 1;
            if (y < 0) y += 1;
            if (y >= 1) y -= 1;
            q[2 * i] = x;
            q[2 * i + 1] = y;
        }
        memcpy(p, q, 2 * (size_t)n * sizeof *q);
    }
    free(q);
}

static void test_gbn(void)
{
    gbn_options o;
    gbn_options_init(&o);
    char err[256];
    const int64_t n = 576; /* s = 1/24, cutoff 0.25: 4 x 4 cells */
    gbn_engine *E[3];
    for (int t = 0; t < 3; t++) {
        o.threads = t + 1;
        E[t] = gbn_create(n, &o, err, sizeof err);
        CHECK(E[t] != NULL, "gbn_create: %s", err);
        if (!E[t]) return;
    }
    float *ref = malloc(2 * (size_t)n * sizeof *ref);
    for (int64_t i = 0; i < 2 * n; i++) ref[i] = (float)gbn_points(E[0])[i];
    cfpo_iter_stats s;
    double worst = 0;
    for (int it = 1; it <= o.iterations; it++) {
        for (int t = 0; t < 3; t++) gbn_iterate(E[t], &s);
        if (it == 1 || it == 50 || it == o.iterations) {
            for (int64_t i = 0; i < n; i++) {
                double cx, cy, fx, fy;
                gbn_cell_gradient(E[0], i, &cx, &cy);
                gbn_full_gradient(E[0], i, &fx, &fy);
                worst = fmax(worst, hypot(cx - fx, cy - fy) * sqrt((double)n));
            }
        }
    }
    CHECK(s.converged, "gbn: not converged after its %d iterations", o.iterations);
    CHECK(worst < 1e-6, "gbn: the cell sum differs from the full sum by %g s", worst);
    const size_t bytes = 2 * (size_t)n * sizeof(double);
    CHECK(memcmp(gbn_points(E[0]), gbn_points(E[1]), bytes) == 0 &&
              memcmp(gbn_points(E[0]), gbn_points(E[2]), bytes) == 0,
          "gbn: other bytes on 2 or 3 threads");
    authors_gbn(ref, (int)n, o.iterations);
    double *rd = malloc(bytes);
    for (int64_t i = 0; i < 2 * n; i++) rd[i] = ref[i];
    double amin, aavg, bmin, bavg;
    cfpo_nn_stats(rd, (size_t)n, NULL, &amin, &aavg);
    gbn_deltas(E[0], &bmin, &bavg);
    printf("gbn n=%lld: ours %.4f %.4f, the authors' kernel %.4f %.4f\n", (long long)n, bmin, bavg, amin, aavg);
    CHECK(fabs(amin - bmin) < 0.01 && fabs(aavg - bavg) < 0.01, "gbn: %g %g against the authors' %g %g", bmin,
          bavg, amin, aavg);
    free(rd);
    free(ref);
    for (int t = 0; t < 3; t++) gbn_free(E[t]);
}

int main(void)
{
    test_white();
    test_jitter();
    test_sobol();
    test_gbn();
    return test_report(passed_, failed_);
}
