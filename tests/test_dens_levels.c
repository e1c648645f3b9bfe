/* test_dens_levels.c - cells sized to the local spacing
 * (src/density/dens_levels.c), against brute force:
 *  - the levels' count: one on a flat density (the one grid, nothing
 *    held), several at contrast 1:256, each level's cells at least 1.25
 *    times the densest spacing;
 *  - every tier's q is at most q at every point of the torus within its
 *    square of cells (the cell's own grown by 2^(k-1) + 1 cells each side),
 *    read as the engine reads it (the point's pixel), on a random density
 *    with zero pixels and under random offsets: the outside bound rests on
 *    it;
 *  - the tiers' test of a spot (cfpo_dens_levels_clear) against its
 *    definition written out for each tier;
 *  - a point's level: its cells are at least 1.25 of its spacing, a finer
 *    level would not be, or would fail the tiers for a spot one cell from
 *    the block's edge; on zero density, level 0. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "dens_dist.h"
#include "dens_levels.h"
#include "dens_qbound.h"
#include "density.h"
#include "geom.h"
#include "testutil.h"

static int passed_, failed_;

static double urand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static int load(const char *spec, cfpo_density *d)
{
    char err[256];
    if (cfpo_density_load(spec, d, err, sizeof err) != 0) {
        CHECK(0, "%s: %s", spec, err);
        return -1;
    }
    return 0;
}

static void counts(void)
{
    cfpo_density d;
    if (load("cos:a=0.000001,res=64", &d) != 0) return;
    const int64_t n = 65536;
    const double D = cfpo_delta_bound((double)n);
    cfpo_dens_levels V;
    CHECK(cfpo_dens_levels_init(&V, &d, 189, D, 1.25) == 0 && V.n == 1 && !V.work, "flat: %d levels", V.n);
    cfpo_dens_levels_free(&V);
    cfpo_density_free(&d);
    if (load("ramp:contrast=256,res=256", &d) != 0) return;
    const double densest = D / sqrt(d.rho_max);
    CHECK(cfpo_dens_levels_init(&V, &d, 15, D, 1.25) == 0 && V.n >= 4, "ramp 1:256: %d levels", V.n);
    for (int l = 0; l < V.n; l++)
        CHECK(1.0 / (double)(V.g0 << l) >= 1.25 * densest, "level %d: cells %g under 1.25 x the densest spacing %g", l,
              1.0 / (double)(V.g0 << l), densest);
    CHECK(1.0 / (double)(V.g0 << V.n) < 1.25 * densest || V.n == CFPO_DENS_LEVELS_MAX, "one more level would fit");
    printf("levels: flat 1, ramp 1:256 %d (g0 15 .. %lld) at %lld points\n", V.n, (long long)(V.g0 << (V.n - 1)),
           (long long)n);
    cfpo_dens_levels_free(&V);
    cfpo_density_free(&d);
}

/* q at the torus point (x, y) as the engine reads it */
static double q_at(const cfpo_density *d, double x, double y) { return sqrt(cfpo_density_at(d, cfpo_wrap01(x), cfpo_wrap01(y))); }

static void tiers_bound(void)
{
    unsigned long long seed = 99;
    /* a random 37 x 23 raster, a fifth of it zero, contrast up to 1:251 */
    const int W = 37, H = 23;
    double *v = malloc((size_t)(W * H) * sizeof *v);
    if (!v) return;
    for (int i = 0; i < W * H; i++) v[i] = urand(&seed) < 0.2 ? 0 : 0.004 + urand(&seed);
    cfpo_density d;
    char err[256];
    if (cfpo_density_from_values(v, W, H, "random", &d, err, sizeof err) != 0) { CHECK(0, "%s", err); free(v); return; }
    free(v);
    cfpo_dens_qbound ql;
    if (cfpo_dens_qbound_build_min(&ql, &d) != 0) { CHECK(0, "pyramid"); cfpo_density_free(&d); return; }
    const int64_t n = 20000;
    cfpo_dens_levels V;
    CHECK(cfpo_dens_levels_init(&V, &d, 6, cfpo_delta_bound((double)n), 1.25) == 0 && V.n >= 3, "random: %d levels",
          V.n);
    int64_t checked = 0, bad = 0;
    for (int rep = 0; rep < 3 && V.n > 1; rep++) {
        const double L0 = 1.0 / 6, sx = urand(&seed) * L0, sy = urand(&seed) * L0;
        if (cfpo_dens_levels_place(&V, &ql, sx, sy) != 0) { CHECK(0, "place"); break; }
        for (int l = 0; l < V.n; l++) {
            const int64_t g = V.g0 << l;
            const double L = 1.0 / (double)g;
            for (int s = 0; s < 40; s++) {
                const int64_t cx = (int64_t)(urand(&seed) * (double)g) % g, cy = (int64_t)(urand(&seed) * (double)g) % g;
                double t[CFPO_DENS_TIERS];
                const int nt = cfpo_dens_levels_tiers(&V, l, cx, cy, t);
                for (int k = 1; k <= nt; k++) {
                    const double h = (double)(((int64_t)1 << (k - 1)) + 1);
                    const double ext = fmin((2 * h + 1) * L, 1.0);
                    /* points spread over the square, its edges and corners
                     * included */
                    for (int p = 0; p < 200; p++) {
                        const double u = p < 4 ? (p & 1) : urand(&seed), w = p < 4 ? (p >> 1) : urand(&seed);
                        const double x = sx + ((double)cx - h) * L + u * ext * (1 - 1e-12);
                        const double y = sy + ((double)cy - h) * L + w * ext * (1 - 1e-12);
                        const double q = q_at(&d, x, y);
                        if (!(q > 0)) continue;
                        checked++;
                        if (!(t[k - 1] <= q)) bad++;
                    }
                }
            }
        }
    }
    CHECK(bad == 0 && checked > 10000, "tiers above q at %lld of %lld points", (long long)bad, (long long)checked);
    printf("tiers: %lld points of their squares, none below its tier's q\n", (long long)checked);

    /* the test of a spot, tier by tier as written in dens_levels.h */
    int64_t agree = 0, disagree = 0;
    for (int s = 0; s < 20000; s++) {
        double t[CFPO_DENS_TIERS];
        for (int k = 0; k < CFPO_DENS_TIERS; k++) t[k] = urand(&seed) < 0.1 ? 0 : urand(&seed) * 2;
        const double L = 0.01 + urand(&seed) * 0.05, e = L * (1 + urand(&seed) * 0.5), rc = urand(&seed) * 2,
                     qmin = urand(&seed) * 0.1, oldf = urand(&seed) * 1e-3;
        /* every point beyond the block: tier k's at distance e + r_(k-1)
         * with q t[k-1], past the last qmin at e + r_nt */
        int want = 1;
        double r = 0;
        for (int k = 1; k <= CFPO_DENS_TIERS; k++) {
            if (!((e + r) * (e + r) * fmin(t[k - 1], 1e300) * rc >= oldf) && !((e + r) * (e + r) * qmin * rc >= oldf))
                want = 0;
            if ((e + r) * (e + r) * qmin * rc >= oldf) break;
            r = ldexp(L, k - 1);
            if (k == CFPO_DENS_TIERS && !((e + r) * (e + r) * qmin * rc >= oldf)) want = 0;
        }
        const int got = cfpo_dens_levels_clear(t, CFPO_DENS_TIERS, qmin, L, e, rc, oldf);
        if (got == want) agree++;
        else disagree++;
    }
    CHECK(disagree == 0, "the tiers' test disagrees with its definition %lld times", (long long)disagree);

    /* levels of points: room for their spacing, a finer level not usable */
    int64_t pts = 0, badl = 0;
    const double D = cfpo_delta_bound((double)n);
    for (int s = 0; s < 4000 && V.n > 1; s++) {
        const double x = urand(&seed), y = urand(&seed), q = q_at(&d, x, y);
        const int l = cfpo_dens_levels_of(&V, x, y, q, D, 1.25, 1.1);
        if (!(q > 0)) {
            badl += l != 0;
            continue;
        }
        pts++;
        const double L = 1.0 / (double)(V.g0 << l);
        if (l > 0 && L < 1.25 * D / q) badl++;
        if (l + 1 < V.n) { /* the next finer level: too small, or failing the tiers */
            const int64_t g = V.g0 << (l + 1), c = cfpo_dens_cell_of(g, V.sx, V.sy, x, y);
            const double Lf = 1.0 / (double)g;
            double t[CFPO_DENS_TIERS];
            const int nt = cfpo_dens_levels_tiers(&V, l + 1, c % g, c / g, t);
            if (Lf >= 1.25 * D / q && cfpo_dens_levels_clear(t, nt, V.qmin, Lf, Lf, q, (1.1 * D) * (1.1 * D))) badl++;
        }
    }
    CHECK(badl == 0 && pts > 1000, "%lld of %lld points on a wrong level", (long long)badl, (long long)pts);
    cfpo_dens_levels_free(&V);
    cfpo_dens_qbound_free(&ql);
    cfpo_density_free(&d);
}

int main(void)
{
    counts();
    tiers_bound();
    return test_report(passed_, failed_);
}
