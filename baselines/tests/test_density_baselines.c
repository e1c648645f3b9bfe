/* test_density_baselines.c - the baselines under a density (--density):
 *  - the draws (dens_draw.h): proportional to rho (counts per column of a
 *    ramp against the columns' mass, a chi-square bound), never on a zero
 *    pixel, and for rho = 1 the uniform numbers themselves;
 *  - the measure grid (mgrid.h): its smallest measure, with exclusions and
 *    removals, equals brute force; its conflict test equals brute force;
 *  - adaptive dart throwing: exactly n points, every pair at measure
 *    >= REL by brute force, counts per block following the density, the
 *    same points as dart throwing for rho = 1;
 *  - FPO and LFPO under a density: after every iteration the triangulation
 *    and its bookkeeping hold (fpo_check), the brute-force smallest
 *    measure over all pairs never falls and equals the reported delta_min,
 *    the run raises it, counts per 2 x 2 block follow the density better
 *    than the start (drawn from rho, independent) and, for global FPO,
 *    within 6%; for rho = 1 the same bytes as without a density, and
 *    --start grid refused;
 *  - CCVT under a density: the capacity points follow it, the converged
 *    sites per 2 x 2 block within 6%, rho = 1 gives --point-set random's
 *    run. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ccvt.h"
#include "dens_draw.h"
#include "fpo.h"
#include "geom.h"
#include "mgrid.h"
#include "pd.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static void load(const char *spec, cfpo_density *d)
{
    char err[512];
    if (cfpo_density_load(spec, d, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", spec, err);
        exit(1);
    }
}

/* Brute force: min over pairs of d^2 q_i q_j, as a measure (/ Delta). */
static double brute_min(const cfpo_density *d, const double *xy, size_t n)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            const double qi = sqrt(cfpo_density_at(d, xy[2 * i], xy[2 * i + 1]));
            const double qj = sqrt(cfpo_density_at(d, xy[2 * j], xy[2 * j + 1]));
            const double v = cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]) * (qi * qj);
            if (v < best) best = v;
        }
    return sqrt(best) / cfpo_delta_bound((double)n);
}

/* The largest relative error of the points per block (B x B) against n
 * times the block's mass. */
static double count_error(const cfpo_density *d, const double *xy, size_t n, int B)
{
    double *mass = calloc((size_t)(B * B), sizeof *mass), *cnt = calloc((size_t)(B * B), sizeof *cnt);
    for (int64_t j = 0; j < d->h; j++)
        for (int64_t i = 0; i < d->w; i++) {
            const int bx = (int)((i * B) / d->w), by = (int)((j * B) / d->h);
            mass[by * B + bx] += d->rho[j * d->w + i] / (double)(d->w * d->h);
        }
    for (size_t k = 0; k < n; k++) {
        int bx = (int)(xy[2 * k] * B), by = (int)(xy[2 * k + 1] * B);
        bx = bx >= B ? B - 1 : bx;
        by = by >= B ? B - 1 : by;
        cnt[by * B + bx] += 1;
    }
    double worst = 0;
    for (int b = 0; b < B * B; b++) {
        const double e = fabs(cnt[b] - (double)n * mass[b]) / ((double)n * mass[b]);
        if (e > worst) worst = e;
    }
    free(mass);
    free(cnt);
    return worst;
}

static void check_draws(void)
{
    cfpo_density d;
    load("ramp:contrast=16,res=64", &d);
    dens_draw s;
    CHECK(dens_draw_init(&s, &d) == 0, "dens_draw_init");
    enum { N = 400000, C = 8 };
    double cnt[C] = {0}, mass[C] = {0};
    for (int64_t i = 0; i < d.w; i++)
        for (int64_t j = 0; j < d.h; j++) mass[i * C / d.w] += d.rho[j * d.w + i] / (double)(d.w * d.h);
    for (uint64_t k = 0; k < N; k++) {
        double u[6], x, y;
        for (int t = 0; t < 6; t++) u[t] = cfpo_rand01(7, 99, 6 * k + (uint64_t)t);
        dens_draw_point(&s, u, &x, &y);
        cnt[(int)(x * C)] += 1;
    }
    double chi2 = 0;
    for (int c = 0; c < C; c++) chi2 += (cnt[c] - N * mass[c]) * (cnt[c] - N * mass[c]) / (N * mass[c]);
    CHECK(chi2 < 24.3, "draws against the ramp's column masses: chi2 = %.2f with 7 degrees of freedom", chi2);
    dens_draw_free(&s);
    cfpo_density_free(&d);

    /* zero pixels: the left half of a 4 x 2 array is empty */
    const double v[8] = {0, 0, 1, 3, 0, 0, 2, 5};
    char err[256];
    CHECK(cfpo_density_from_values(v, 4, 2, "test", &d, err, sizeof err) == 0, "from_values: %s", err);
    dens_draw_init(&s, &d);
    int off = 0;
    for (uint64_t k = 0; k < 100000; k++) {
        double u[6], x, y;
        for (int t = 0; t < 6; t++) u[t] = cfpo_rand01(8, 99, 6 * k + (uint64_t)t);
        dens_draw_point(&s, u, &x, &y);
        off += !(cfpo_density_at(&d, x, y) > 0) || !(x >= 0 && x < 1 && y >= 0 && y < 1);
    }
    CHECK(off == 0, "%d draws off the support", off);
    dens_draw_free(&s);
    cfpo_density_free(&d);
    /* the top of the CDF when the last pixels are empty: u3 just below 1 */
    const double w[8] = {1, 3, 0, 0, 2, 5, 0, 0};
    CHECK(cfpo_density_from_values(w, 4, 2, "test", &d, err, sizeof err) == 0, "from_values: %s", err);
    dens_draw_init(&s, &d);
    const double top[6] = {0.9, 0.9, 0.5, 0x1.fffffffffffffp-1, 0.999999, 0.999999};
    double tx, ty;
    dens_draw_point(&s, top, &tx, &ty);
    CHECK(cfpo_density_at(&d, tx, ty) > 0, "the draw at the CDF's top lands on an empty pixel (%g, %g)", tx, ty);
    dens_draw_free(&s);
    cfpo_density_free(&d);

    load("cos:a=0,res=16", &d);
    dens_draw_init(&s, &d);
    int same = 1;
    for (uint64_t k = 0; k < 10000; k++) {
        double u[6], x, y;
        for (int t = 0; t < 6; t++) u[t] = cfpo_rand01(9, 99, 6 * k + (uint64_t)t);
        dens_draw_point(&s, u, &x, &y);
        same &= x == u[0] && y == u[1];
    }
    CHECK(same, "a uniform density's draws are not the uniform numbers");
    dens_draw_free(&s);
    cfpo_density_free(&d);
}

static void check_mgrid(void)
{
    cfpo_density d;
    load("ramp:contrast=16,res=32", &d);
    enum { N = 700 };
    double xy[2 * N], q[N];
    for (int i = 0; i < N; i++) {
        xy[2 * i] = cfpo_rand01(5, 1, 2 * (uint64_t)i);
        xy[2 * i + 1] = cfpo_rand01(5, 1, 2 * (uint64_t)i + 1);
        q[i] = sqrt(cfpo_density_at(&d, xy[2 * i], xy[2 * i + 1]));
    }
    mgrid M;
    CHECK(mgrid_init(&M, N, N, xy, q, sqrt(d.rho_min)) == 0, "mgrid_init");
    for (int i = 0; i < N; i++) mgrid_insert(&M, i);
    for (int i = 0; i < N; i += 3) mgrid_remove(&M, i); /* every third point out */
    int wrong = 0, wrongc = 0;
    for (int t = 0; t < 300; t++) {
        const double x = cfpo_rand01(6, 1, 2 * (uint64_t)t), y = cfpo_rand01(6, 1, 2 * (uint64_t)t + 1);
        const double qx = sqrt(cfpo_density_at(&d, x, y));
        const int64_t ex[3] = {t % N, (7 * t + 1) % N, (13 * t + 2) % N};
        double want = INFINITY;
        for (int j = 0; j < N; j++) {
            if (j % 3 == 0 || j == ex[0] || j == ex[1] || j == ex[2]) continue;
            const double v = cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]) * (qx * q[j]);
            if (v < want) want = v;
        }
        wrong += mgrid_min(&M, x, y, qx, ex, 3, INFINITY) != want;
        const double bound = want * 1.5;
        wrong += mgrid_min(&M, x, y, qx, ex, 3, bound) != want;
        wrong += mgrid_min(&M, x, y, qx, ex, 3, want * 0.5) != want * 0.5;
        /* the conflict test without exclusions */
        double all = INFINITY;
        for (int j = 0; j < N; j++)
            if (j % 3) all = fmin(all, cfpo_torus_dist2(x, y, xy[2 * j], xy[2 * j + 1]) * (qx * q[j]));
        wrongc += mgrid_conflict(&M, x, y, qx, all * 1.0001) != 1 || mgrid_conflict(&M, x, y, qx, all) != 0;
    }
    CHECK(wrong == 0, "mgrid_min differs from brute force %d times", wrong);
    CHECK(wrongc == 0, "mgrid_conflict differs from brute force %d times", wrongc);
    mgrid_free(&M);
    cfpo_density_free(&d);
}

static void check_dart(void)
{
    cfpo_density d;
    load("ramp:contrast=16,res=64", &d);
    const int64_t n = 3000;
    pd_params p = {.seed = 4, .r = 0.75 * cfpo_delta_bound((double)n), .target = n, .max_fails = 1000000,
                   .report_step = n, .density = &d};
    pd_result res;
    char err[256];
    CHECK(dart_density_sample(&p, &res, err, sizeof err) == 0 && !res.saturated && res.n == n,
          "adaptive dart: %lld of %lld points", (long long)res.n, (long long)n);
    const double m = brute_min(&d, res.xy, (size_t)res.n);
    CHECK(m >= 0.75, "adaptive dart: smallest measure %.6f < 0.75", m);
    const double e = count_error(&d, res.xy, (size_t)res.n, 4);
    CHECK(e < 0.12, "adaptive dart: counts per block off by %.3f", e);
    free(res.xy);
    cfpo_density_free(&d);

    /* rho = 1: dart throwing's points */
    load("cos:a=0,res=16", &d);
    pd_result a, b;
    p.density = &d;
    dart_density_sample(&p, &a, err, sizeof err);
    p.density = NULL;
    dart_sample(&p, &b, err, sizeof err);
    CHECK(a.n == b.n && memcmp(a.xy, b.xy, 2 * (size_t)a.n * sizeof(double)) == 0,
          "adaptive dart under rho = 1 differs from dart throwing");
    free(a.xy);
    free(b.xy);
    cfpo_density_free(&d);
}

static void check_fpo(int local, const char *spec, int64_t n, int iters)
{
    cfpo_density d;
    load(spec, &d);
    fpo_options o;
    fpo_options_init(&o);
    o.local = local;
    o.seed = 2;
    o.density = &d;
    char err[256];
    fpo_engine *E = fpo_create(n, &o, err, sizeof err);
    CHECK(E != NULL, "fpo create: %s", err);
    if (!E) return;
    const double m0 = brute_min(&d, fpo_points(E), (size_t)n);
    const double e0 = count_error(&d, fpo_points(E), (size_t)n, 2);
    double prev = m0;
    int valid = 1, monotone = 1, agree = 1, it;
    cfpo_iter_stats s;
    for (it = 1; it <= iters; it++) {
        fpo_iterate(E, &s);
        valid &= fpo_check(E);
        const double m = brute_min(&d, fpo_points(E), (size_t)n);
        if (m < prev) {
            monotone = 0;
            fprintf(stderr, "%s %s iteration %d: min measure %.17g < %.17g\n", local ? "lfpo" : "fpo", spec, it, m, prev);
        }
        agree &= fabs(m - s.delta_min) <= 1e-12;
        prev = m;
        if (s.converged) break;
    }
    const char *name = local ? "lfpo" : "fpo";
    CHECK(valid, "%s %s: triangulation or bookkeeping invalid after an iteration", name, spec);
    CHECK(monotone, "%s %s: the smallest measure fell", name, spec);
    CHECK(agree, "%s %s: delta_min is not the brute-force smallest measure", name, spec);
    CHECK(prev > m0 + 0.3, "%s %s: smallest measure only %.4f -> %.4f", name, spec, m0, prev);
    const double e = count_error(&d, fpo_points(E), (size_t)n, 2);
    /* global FPO evens the counts out; LFPO's moves are local and slower */
    CHECK(e < e0 && (local || e < 0.06), "%s %s: counts per block off by %.3f (start %.3f)", name, spec, e, e0);
    fpo_free(E);
    cfpo_density_free(&d);
}

static void check_fpo_uniform(int local)
{
    cfpo_density d;
    load("cos:a=0,res=16", &d);
    fpo_options o;
    fpo_options_init(&o);
    o.local = local;
    o.seed = 5;
    char err[256];
    fpo_engine *A = fpo_create(500, &o, err, sizeof err);
    o.density = &d;
    fpo_engine *B = fpo_create(500, &o, err, sizeof err);
    cfpo_iter_stats s;
    for (int it = 0; it < 10; it++) {
        fpo_iterate(A, &s);
        fpo_iterate(B, &s);
    }
    CHECK(memcmp(fpo_points(A), fpo_points(B), 1000 * sizeof(double)) == 0,
          "%s under rho = 1 differs from %s", local ? "lfpo" : "fpo", local ? "lfpo" : "fpo");
    fpo_free(A);
    fpo_free(B);
    /* --start grid is refused under a density */
    o.start = FPO_START_GRID;
    CHECK(fpo_create(500, &o, err, sizeof err) == NULL && strstr(err, "--start grid"), "grid start: '%s'", err);
    cfpo_density_free(&d);
}

static void check_ccvt(void)
{
    cfpo_density d;
    load("ramp:contrast=16,res=64", &d);
    ccvt_options o;
    ccvt_options_init(&o);
    o.seed = 3;
    o.m = 64;
    o.density = &d;
    char err[256];
    ccvt_engine *E = ccvt_create(400, &o, err, sizeof err);
    CHECK(E != NULL, "ccvt create: %s", err);
    if (!E) return;
    const double ep = count_error(&d, ccvt_points(E), 400 * 64, 2), e0 = count_error(&d, ccvt_sites(E), 400, 2);
    CHECK(ep < 0.05, "ccvt: the capacity points off the density by %.3f (4 standard deviations: 0.05)", ep);
    cfpo_iter_stats s;
    for (int it = 0; it < 300; it++) {
        ccvt_iterate(E, &s);
        if (s.converged) break;
    }
    const double e = count_error(&d, ccvt_sites(E), 400, 2);
    CHECK(s.converged && e < 0.06 && e < e0, "ccvt: sites per block off by %.3f (start %.3f), converged %d", e, e0,
          s.converged);
    ccvt_free(E);
    cfpo_density_free(&d);
    /* rho = 1: the random point set's run */
    load("cos:a=0,res=16", &d);
    ccvt_engine *A = ccvt_create(300, &o, err, sizeof err);
    o.density = NULL;
    o.points = CCVT_POINTS_RANDOM;
    ccvt_engine *B = ccvt_create(300, &o, err, sizeof err);
    for (int it = 0; it < 10; it++) {
        ccvt_iterate(A, &s);
        ccvt_iterate(B, &s);
    }
    CHECK(memcmp(ccvt_sites(A), ccvt_sites(B), 600 * sizeof(double)) == 0,
          "ccvt under rho = 1 differs from --point-set random");
    ccvt_free(A);
    ccvt_free(B);
    cfpo_density_free(&d);
}

int main(void)
{
    check_ccvt();
    check_draws();
    check_mgrid();
    check_dart();
    check_fpo(0, "cos:a=0.9,res=64", 400, 40);
    check_fpo(1, "cos:a=0.9,res=64", 400, 40);
    check_fpo(0, "ramp:contrast=16,res=64", 400, 40);
    check_fpo(1, "ramp:contrast=16,res=64", 400, 40);
    check_fpo_uniform(0);
    check_fpo_uniform(1);
    return test_report(passed_, failed_);
}
