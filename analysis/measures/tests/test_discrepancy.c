/* test_discrepancy.c - an_discrepancy_compute (O(n log n)) against the
 * definitions summed over all n^2 pairs in binary128 (to 1e-9 relative, at
 * n = 4,096 and on tiny, tied and edge sets), against scipy and UTK, and
 * the torus-invariant two under a toroidal shift.
 *
 * scipy 1.17.1 values, for the golden-ratio set of sets.h at n = 1,000:
 *   python3 -c 'import numpy as np; from scipy.stats import qmc;
 *     i = np.arange(1000.0); x = np.stack([np.fmod(i * 0.6180339887498949, 1.0),
 *     np.fmod(i * 1.4142135623730951, 1.0)], axis=1);
 *     print([repr(qmc.discrepancy(x, method=m)) for m in ("L2-star", "CD", "WD")])'
 *   L2-star 0.0014807548635774968 (rooted), CD 2.4887555440944453e-06 and
 *   WD 3.1080256259752304e-06 (both squared). scipy sums the million WD
 *   terms in double, which leaves 5e-7 of the result: the same sum in
 *   numpy's long double (x = x.astype(np.longdouble); d = np.abs(x[:, None]
 *   - x[None]); np.prod(1.5 - d * (1 - d), axis=2).sum() / n**2 - 16/9)
 *   gives 3.1080272147299657648e-06, ours to 1e-12.
 * UTK's documentation (sources-doc/discrepancy_generalized_l2_disc.md,
 * GeneralizedL2Discrepancy_fromfile_2dd on sobol_1024.dat, sobol_4096.dat):
 * generalised L2 of the first 1,024 and 4,096 Sobol' points 0.00117859 and
 * 0.000307601 (six digits printed). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "discrepancy.h"
#include "quad.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

/* The five definitions, literally, over all ordered pairs. */
static void brute(const double *xy, size_t n, an_discrepancy *d)
{
    const an_quad pi = (an_quad)3.14159265358979323846264338327950288L, N = (an_quad)n;
    an_quad wd = 0, dia = 0, star = 0, gen = 0, cen = 0, s_star = 0, s_gen = 0, s_cen = 0;
    for (size_t i = 0; i < n; i++) {
        an_quad u[2], ui[2];
        for (int k = 0; k < 2; k++) { u[k] = xy[2 * i + k]; ui[k] = u[k] - (an_quad)0.5; if (ui[k] < 0) ui[k] = -ui[k]; }
        s_star += (1 - u[0] * u[0]) * (1 - u[1] * u[1]);
        s_gen += (3 - u[0] * u[0]) / 2 * (3 - u[1] * u[1]) / 2;
        s_cen += (1 + ui[0] / 2 - ui[0] * ui[0] / 2) * (1 + ui[1] / 2 - ui[1] * ui[1] / 2);
        for (size_t j = i; j < n; j++) { /* i < j twice, i = j once */
            const an_quad wgt = j == i ? 1 : 2;
            an_quad pw = 1, ph = 1, ps = 1, pg = 1, pc = 1;
            for (int k = 0; k < 2; k++) {
                const an_quad xi = xy[2 * i + k], xj = xy[2 * j + k];
                const an_quad dd = xi - xj, ad = dd < 0 ? -dd : dd;
                an_quad t = dd < 0 ? dd + 1 : dd; /* {d} */
                pw *= (an_quad)1.5 - ad * (1 - ad);
                ph *= 1 + 2 * pi * pi * (t * t - t + (an_quad)1 / 6);
                const an_quad mx = xi > xj ? xi : xj;
                ps *= 1 - mx;
                pg *= 2 - mx;
                an_quad ai = xi - (an_quad)0.5, aj = xj - (an_quad)0.5, dij = ai - aj;
                if (ai < 0) ai = -ai;
                if (aj < 0) aj = -aj;
                if (dij < 0) dij = -dij;
                pc *= 1 + ai / 2 + aj / 2 - dij / 2;
            }
            wd += wgt * pw; dia += wgt * (ph - 1); star += wgt * ps; gen += wgt * pg; cen += wgt * pc;
        }
    }
    const an_quad N2 = N * N, h0 = 1 + pi * pi / 3;
    const an_quad v[5] = {wd / N2 - (an_quad)16 / 9, dia / (N2 * (h0 * h0 - 1)),
                          (an_quad)1 / 9 - s_star / (2 * N) + star / N2,
                          (an_quad)16 / 9 - 2 * s_gen / N + gen / N2,
                          (an_quad)169 / 144 - 2 * s_cen / N + cen / N2};
    double r[5];
    for (int k = 0; k < 5; k++) r[k] = v[k] > 0 ? sqrt((double)v[k]) : 0;
    d->wrap_l2 = r[0]; d->diaphony = r[1]; d->l2_star = r[2]; d->generalized_l2 = r[3]; d->centred_l2 = r[4];
}

static const char *names[5] = {"wrap-around L2", "diaphony", "L2-star", "generalised L2", "centred L2"};

static void values(const an_discrepancy *d, double v[5])
{
    v[0] = d->wrap_l2; v[1] = d->diaphony; v[2] = d->l2_star; v[3] = d->generalized_l2; v[4] = d->centred_l2;
}

static double worst_;

static void against_brute(const char *what, const double *xy, size_t n)
{
    an_discrepancy f, b;
    char err[256];
    CHECK(an_discrepancy_compute(xy, n, &f, err, sizeof err) == 0, "%s: %s", what, err);
    brute(xy, n, &b);
    double vf[5], vb[5];
    values(&f, vf);
    values(&b, vb);
    for (int k = 0; k < 5; k++) {
        const double rel = fabs(vf[k] - vb[k]) / (vb[k] > 1e-300 ? vb[k] : 1);
        if (rel > worst_) worst_ = rel;
        CHECK(rel <= 1e-9 && isfinite(vf[k]), "%s (n = %zu): %s %.17g, brute force %.17g", what, n, names[k],
              vf[k], vb[k]);
    }
}

static void near(const char *what, double got, double want, double rel)
{
    CHECK(fabs(got - want) <= rel * fabs(want), "%s: %.12g, reference %.12g (within %g)", what, got, want, rel);
}

int main(void)
{
    const size_t N = 4096;
    double *xy = malloc(2 * N * sizeof *xy), *sh = malloc(2 * N * sizeof *sh);

    set_white(xy, N, 7);
    against_brute("white noise", xy, N);
    set_sobol(xy, N);
    against_brute("Sobol'", xy, N);
    set_jittered(xy, 32, 3);
    against_brute("jittered 32 x 32", xy, 1024);
    for (size_t n = 1; n <= 9; n++) {
        set_white(xy, n, 100 + n);
        against_brute("tiny white noise", xy, n);
    }
    const double edge[] = {0, 0.5, 0.25, nextafter(1.0, 0.0), 5e-324, nextafter(0.5, 0.0)};
    for (size_t i = 0; i < 36; i++) { xy[2 * i] = edge[i % 6]; xy[2 * i + 1] = edge[i / 6]; }
    against_brute("coordinates at 0, 1/2 and 1^-", xy, 36);
    for (size_t i = 0; i < 500; i++) { xy[2 * i] = (double)(i % 7) / 7; xy[2 * i + 1] = (double)(i % 5) / 8; }
    against_brute("repeated points (ties on both axes)", xy, 500);
    for (size_t i = 0; i < 300; i++) { xy[2 * i] = 0; xy[2 * i + 1] = cfpo_rand01(9, 3, i); }
    against_brute("every x at 0", xy, 300);
    for (size_t i = 0; i < 4; i++) xy[i] = 0;
    against_brute("two points at the origin", xy, 2);
    printf("largest relative difference to the brute-force sums: %.3g\n", worst_);

    /* one thread or two: the same bits */
#ifdef _OPENMP
    {
        an_discrepancy t1, t2;
        char e[256];
        set_white(xy, N, 8);
        omp_set_num_threads(1);
        CHECK(an_discrepancy_compute(xy, N, &t1, e, sizeof e) == 0, "one thread: %s", e);
        omp_set_num_threads(2);
        CHECK(an_discrepancy_compute(xy, N, &t2, e, sizeof e) == 0, "two threads: %s", e);
        CHECK(memcmp(&t1, &t2, sizeof t1) == 0, "one and two threads differ");
    }
#endif

    /* an empty set is refused */
    an_discrepancy d;
    char err[256];
    CHECK(an_discrepancy_compute(xy, 0, &d, err, sizeof err) != 0, "n = 0 accepted");

    /* scipy (see the top of the file) */
    set_golden(xy, 1000);
    CHECK(an_discrepancy_compute(xy, 1000, &d, err, sizeof err) == 0, "golden: %s", err);
    near("L2-star against scipy", d.l2_star, 0.0014807548635774968, 1e-9);
    near("centred L2^2 against scipy's CD", d.centred_l2 * d.centred_l2, 2.4887555440944453e-06, 1e-8);
    near("wrap-around L2^2 against scipy's WD", d.wrap_l2 * d.wrap_l2, 3.1080256259752304e-06, 1e-6);
    near("wrap-around L2^2 against numpy's long double sum", d.wrap_l2 * d.wrap_l2, 3.1080272147299657648e-06, 1e-12);

    /* UTK's generalised L2 of the Sobol' points, to its six printed digits */
    set_sobol(xy, 4096);
    CHECK(an_discrepancy_compute(xy, 1024, &d, err, sizeof err) == 0, "sobol 1024: %s", err);
    near("generalised L2, Sobol' 1,024, against UTK", d.generalized_l2, 0.00117859, 5e-6);
    CHECK(an_discrepancy_compute(xy, 4096, &d, err, sizeof err) == 0, "sobol 4096: %s", err);
    near("generalised L2, Sobol' 4,096, against UTK", d.generalized_l2, 0.000307601, 5e-6);

    /* the torus-invariant two do not move under a toroidal shift; the
     * others do (a shifted Sobol' set is no longer anchored at 0) */
    an_discrepancy s;
    for (size_t i = 0; i < N; i++) {
        sh[2 * i] = fmod(xy[2 * i] + 0.3125, 1.0);
        sh[2 * i + 1] = fmod(xy[2 * i + 1] + 0.71875, 1.0);
    }
    CHECK(an_discrepancy_compute(sh, N, &s, err, sizeof err) == 0, "shifted: %s", err);
    near("wrap-around L2 under a shift", s.wrap_l2, d.wrap_l2, 1e-9);
    near("diaphony under a shift", s.diaphony, d.diaphony, 1e-9);
    CHECK(fabs(s.l2_star - d.l2_star) > 1e-3 * d.l2_star, "L2-star did not move under a shift (%.12g)", s.l2_star);

    /* white noise: E[WD^2] = ((4/3)^2 + ... ) is 1/n ((3/2)^2 - (4/3)^2) */
    double mean = 0;
    for (uint64_t seed = 0; seed < 20; seed++) {
        set_white(xy, 1024, 1000 + seed);
        an_discrepancy_compute(xy, 1024, &d, err, sizeof err);
        mean += d.wrap_l2 * d.wrap_l2 / 20;
    }
    near("mean wrap-around L2^2 of white noise", mean, (2.25 - 16.0 / 9) / 1024, 0.15);
    free(xy);
    free(sh);
    return test_report(passed_, failed_);
}
