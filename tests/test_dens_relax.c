/* test_dens_relax.c - the density start's relaxation (src/density/dens_relax.c)
 * against a brute-force step of the rule in dens_relax.h: every pair of
 * points, pushed apart when nearer than Delta(n) / sqrt(q_i q_j), each end
 * by (r - d) / 4 along their line, the sum capped at Delta(n) / (2 q_i),
 * a move onto zero density not made. On a random density of contrast
 * about 1:20 with a zero-density square, 3,000 points from the density's
 * start: one step and four steps agree with the reference to rounding (the
 * binned sum runs in another order), and one step with a crowd of 12
 * points at one spot (where the cap binds). The check fails when the binned
 * search misses pairs (a reach of the point's own spacing only: the pairs
 * with a sparser partner are lost), when the cap or the zero-density rule
 * is dropped.
 * Also: 32 steps give the same bytes on 1, 2 and 3 threads; no point ends
 * on zero density; the smallest local measure rises; the counts in 8 x 8
 * blocks still follow the density (rms within half a Poisson process's). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dens_relax.h"
#include "dens_start.h"
#include "geom.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

#define N 3000

static double q_at(const cfpo_density *d, double x, double y) { return sqrt(cfpo_density_at(d, x, y)); }

/* One step of the rule over every pair, from the places `a` into `b`. */
static void reference_step(const cfpo_density *d, int64_t n, const double *a, double *b)
{
    const double r0 = cfpo_delta_bound((double)n);
    for (int64_t i = 0; i < n; i++) {
        const double px = a[2 * i], py = a[2 * i + 1], qi = q_at(d, px, py);
        double fx = 0, fy = 0;
        for (int64_t j = 0; j < n; j++) {
            if (j == i) continue;
            double ex = px - a[2 * j], ey = py - a[2 * j + 1];
            ex -= rint(ex);
            ey -= rint(ey);
            const double dd = sqrt(ex * ex + ey * ey), r = r0 / sqrt(qi * q_at(d, a[2 * j], a[2 * j + 1]));
            if (dd < r && dd > 0) {
                fx += 0.5 * (r - dd) / dd * ex;
                fy += 0.5 * (r - dd) / dd * ey;
            }
        }
        const double len = 0.5 * sqrt(fx * fx + fy * fy), lim = 0.5 * r0 / qi;
        const double s = len > lim ? 0.5 * lim / len : 0.5;
        double u = px + s * fx, v = py + s * fy;
        u -= floor(u);
        v -= floor(v);
        if (!(u < 1.0)) u = 0.0;
        if (!(v < 1.0)) v = 0.0;
        const int ok = cfpo_density_at(d, u, v) > 0;
        b[2 * i] = ok ? u : px;
        b[2 * i + 1] = ok ? v : py;
    }
}

/* The largest torus distance between the two sets' places. */
static double max_diff(const double *a, const double *b, int64_t n)
{
    double m = 0;
    for (int64_t i = 0; i < 2 * n; i++) {
        double e = fabs(a[i] - b[i]);
        if (e > 0.5) e = 1 - e;
        if (e > m) m = e;
    }
    return m;
}

/* The smallest d sqrt(q_i q_j) / Delta(n) over the pairs. */
static double smallest_measure(const cfpo_density *d, int64_t n, const double *xy)
{
    double m = INFINITY;
    for (int64_t i = 0; i < n; i++)
        for (int64_t j = i + 1; j < n; j++) {
            double ex = xy[2 * i] - xy[2 * j], ey = xy[2 * i + 1] - xy[2 * j + 1];
            ex -= rint(ex);
            ey -= rint(ey);
            const double v = sqrt(ex * ex + ey * ey) * sqrt(q_at(d, xy[2 * i], xy[2 * i + 1]) *
                                                            q_at(d, xy[2 * j], xy[2 * j + 1]));
            if (v < m) m = v;
        }
    return m / cfpo_delta_bound((double)n);
}

/* The rms of (count - expected) / expected over 8 x 8 blocks. */
static double block_rms(const cfpo_density *d, int64_t n, const double *xy)
{
    double mass[64] = {0}, cnt[64] = {0}, tot = 0;
    for (int64_t j = 0; j < d->h; j++)
        for (int64_t i = 0; i < d->w; i++) {
            mass[(j * 8 / d->h) * 8 + i * 8 / d->w] += d->rho[j * d->w + i];
            tot += d->rho[j * d->w + i];
        }
    for (int64_t p = 0; p < n; p++) cnt[(int)(xy[2 * p + 1] * 8) * 8 + (int)(xy[2 * p] * 8)] += 1;
    double s = 0;
    for (int b = 0; b < 64; b++) {
        const double e = mass[b] / tot * (double)n;
        s += (cnt[b] - e) * (cnt[b] - e) / (e * e);
    }
    return sqrt(s / 64);
}

int main(void)
{
    /* 64 x 64 pixels of 0.05 + U[0, 1), a zero square of 8 x 8 pixels */
    double *v = malloc(64 * 64 * sizeof *v);
    for (int i = 0; i < 64 * 64; i++) v[i] = 0.05 + cfpo_rand01(11, 7, (uint64_t)i);
    for (int j = 20; j < 28; j++)
        for (int i = 40; i < 48; i++) v[j * 64 + i] = 0;
    cfpo_density d;
    char err[256];
    if (cfpo_density_from_values(v, 64, 64, "test", &d, err, sizeof err) != 0) { printf("%s\n", err); return 1; }
    free(v);
    double *s0 = malloc(2 * N * sizeof *s0), *a = malloc(2 * N * sizeof *a), *r = malloc(2 * N * sizeof *r),
           *t = malloc(2 * N * sizeof *t);
    CHECK(cfpo_dens_start(&d, N, 5, s0) == 0, "start");

    /* one step, then four, against the reference; then one step with a
     * crowd of 12 points within 1e-4 of one spot, where the cap binds */
    double *crowd = malloc(2 * N * sizeof *crowd);
    memcpy(crowd, s0, 2 * N * sizeof *crowd);
    for (int i = 0; i < 12; i++) {
        crowd[2 * i] = 0.3 + 1e-4 * cfpo_rand01(3, 1, (uint64_t)i);
        crowd[2 * i + 1] = 0.6 + 1e-4 * cfpo_rand01(3, 2, (uint64_t)i);
    }
    for (int c = 0; c < 3; c++) {
        const int steps = c == 1 ? 4 : 1;
        const double *from = c == 2 ? crowd : s0;
        memcpy(a, from, 2 * N * sizeof *a);
        memcpy(r, from, 2 * N * sizeof *r);
        CHECK(cfpo_dens_relax(&d, N, a, steps, 2, 0, 1, NULL, NULL) == 0, "relax %d", steps);
        for (int k = 0; k < steps; k++) {
            reference_step(&d, N, r, t);
            memcpy(r, t, 2 * N * sizeof *r);
        }
        const double e = max_diff(a, r, N), moved = max_diff(from, r, N);
        CHECK(e < 1e-12 && moved > 1e-4, "%s, %d step(s): the binned relaxation is %.3g from the brute-force rule "
              "(the points moved up to %.3g)", c == 2 ? "a crowd" : "the start", steps, e, moved);
    }
    free(crowd);

    /* the default's steps on 1, 2 and 3 threads */
    const int steps = cfpo_dens_relax_steps(N);
    CHECK(steps > 0, "steps for %d points: %d", N, steps);
    memcpy(a, s0, 2 * N * sizeof *a);
    CHECK(cfpo_dens_relax(&d, N, a, steps, 1, 0, 1, NULL, NULL) == 0, "relax");
    for (int th = 2; th <= 3; th++) {
        memcpy(t, s0, 2 * N * sizeof *t);
        CHECK(cfpo_dens_relax(&d, N, t, steps, th, 0, 1, NULL, NULL) == 0, "relax");
        CHECK(memcmp(a, t, 2 * N * sizeof *a) == 0, "%d steps: %d threads give other bytes than one", steps, th);
    }
    int64_t off = 0;
    for (int64_t i = 0; i < N; i++) off += !(cfpo_density_at(&d, a[2 * i], a[2 * i + 1]) > 0);
    CHECK(off == 0, "%lld points on zero density after the relaxation", (long long)off);
    const double m0 = smallest_measure(&d, N, s0), m1 = smallest_measure(&d, N, a);
    CHECK(m1 > m0 && m1 > 0.2, "the smallest local measure went from %.4f to %.4f", m0, m1);
    const double f0 = block_rms(&d, N, s0), f1 = block_rms(&d, N, a), poisson = 1 / sqrt((double)N / 64);
    CHECK(f1 < 0.5 * poisson, "8 x 8 block counts: rms %.4f after (%.4f before; a Poisson process about %.4f)", f1, f0,
          poisson);
    printf("%d steps: smallest measure %.4f -> %.4f, block rms %.4f -> %.4f\n", steps, m0, m1, f0, f1);

    /* too few points for the density: nothing moves */
    memcpy(a, s0, 2 * 16 * sizeof *a);
    CHECK(cfpo_dens_relax(&d, 16, a, 4, 1, 0, 1, NULL, NULL) == 0 && memcmp(a, s0, 2 * 16 * sizeof *a) == 0,
          "16 points: the relaxation should leave them");

    free(s0); free(a); free(r); free(t);
    cfpo_density_free(&d);
    printf("%d passed, %d failed\n", passed_, failed_);
    return failed_ != 0;
}
