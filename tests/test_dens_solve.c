/* test_dens_solve.c - the local solve under a density (src/density/dens_solve.c)
 * against enumeration on a fine grid over the box, for random neighbour
 * sets of 1 to 10 points (all of whose polygons the solve looks at):
 *  - the value it returns is the objective at the point it returns (to
 *    1e-12), and the point lies in the box;
 *  - uniform density: the solve is exact, at least the grid's largest
 *    value (the farthest point of a box from a set lies at a vertex of its
 *    Voronoi cells clipped to the box, which the solve evaluates);
 *  - cos a=0.9 and the ramp 1:16 (pixels 1/64, several in the box): never
 *    above the grid's largest value plus the grid's resolution bound (the
 *    solve cannot beat the true maximum); how far below it falls is
 *    printed (the straight lines stand in for Apollonius circles);
 *  - the near phase's solve (the polygons of the 2 nearest only), uniform
 *    density: at least the enumeration's largest value over the grid
 *    points whose nearest neighbour is one of those two (the union of
 *    their Voronoi cells in the box), and never above the full solve's;
 *  - the routes: for random sets of up to 40 neighbours, the plain route,
 *    the AVX-512 route and the AVX2 route (where the CPU has them) give the
 *    same bits (and so does f at the spot found), with
 *    the density's global bound of q and with the tight bound of the box
 *    (dens_qbound.h), at several floors, searching 10 polygons or 2; and
 *    the search resumed after polygon `from` (cfpo_dens_solve_from, as the
 *    engine goes on from the near solve's polygons) gives the bits of the
 *    search in one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dens_qbound.h"
#include "dens_solve.h"
#include "dens_clip.h"
#include "policy.h"
#include "solver_simd.h"
#include "density.h"
#include "testutil.h"

static int passed_, failed_;

static double urand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

#define G 300 /* enumeration grid a side */

/* k sites drawn uniformly in the square of half side r around the
 * origin, sorted nearest first (to the origin) into (yx, yy); dd: k
 * doubles of room. */
static void sites_nearest_first(unsigned long long *seed, int k, double r, double *yx, double *yy, double *dd)
{
    for (int j = 0; j < k; j++) {
        const double x = (2 * urand(seed) - 1) * r, y = (2 * urand(seed) - 1) * r;
        int at = j;
        const double dj = x * x + y * y;
        while (at > 0 && dd[at - 1] > dj) {
            dd[at] = dd[at - 1]; yx[at] = yx[at - 1]; yy[at] = yy[at - 1];
            at--;
        }
        dd[at] = dj; yx[at] = x; yy[at] = y;
    }
}

static void trials(const char *spec, int exact, int count)
{
    cfpo_density d;
    char err[256];
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    unsigned long long seed = 12345;
    const double s = 0.05; /* the box's half side */
    double yx[10], yy[10], yr[10], scratch[200];
    int bad_val = 0, bad_box = 0, bad_exact = 0, bad_above = 0, bad_floor = 0, n = 0;
    double ratio_sum = 0, ratio_min = INFINITY;
    for (int t = 0; t < count; t++) {
        const double ox = urand(&seed), oy = urand(&seed);
        const int k = 1 + (int)(urand(&seed) * 10);
        double dd[10];
        sites_nearest_first(&seed, k, 2 * s, yx, yy, dd);
        for (int j = 0; j < k; j++) yr[j] = cfpo_dens_local_q(&d, ox, oy, yx[j], yy[j]);
        cfpo_square S = {-s, -s, s, s};
        double cx, cy, f;
        if (!cfpo_dens_solve(yx, yy, yr, k, DENS_CELLS, S, &d, sqrt(d.rho_max), ox, oy, -1, &cx, &cy, &f, scratch)) continue;
        n++;
        /* a floor below the best gives the same vertex; at or above it, none */
        const double floors[4] = {0, 0.5 * f, f * (1 - 1e-9), f};
        for (int q = 0; q < 4; q++) {
            double fx, fy, ff;
            const int got = cfpo_dens_solve(yx, yy, yr, k, DENS_CELLS, S, &d, sqrt(d.rho_max), ox, oy, floors[q], &fx, &fy, &ff, scratch);
            if (q < 3 ? !(got && fx == cx && fy == cy && ff == f) : got) bad_floor++;
        }
        const double fv = cfpo_dens_value(yx, yy, yr, k, cfpo_dens_local_q(&d, ox, oy, cx, cy), cx, cy);
        if (!(fabs(fv - f) <= 1e-12 * fabs(f))) bad_val++;
        if (cx < S.x0 || cx > S.x1 || cy < S.y0 || cy > S.y1) bad_box++;
        double best = -1, qmax = 0, ymax = 0;
        for (int j = 0; j < k; j++) {
            if (yr[j] > ymax) ymax = yr[j];
        }
        for (int iy = 0; iy <= G; iy++)
            for (int ix = 0; ix <= G; ix++) {
                const double px = S.x0 + (S.x1 - S.x0) * ix / G, py = S.y0 + (S.y1 - S.y0) * iy / G;
                const double q = cfpo_dens_local_q(&d, ox, oy, px, py);
                if (q > qmax) qmax = q;
                if (!(q > 0)) continue;
                const double v = cfpo_dens_value(yx, yy, yr, k, q, px, py);
                if (v > best) best = v;
            }
        /* within a grid step h of any point the squared distance to a site
         * changes by at most 2 D h + h^2 (D the box's reach to the sites) */
        const double h = 2 * s / G * sqrt(2.0), D = 6 * s, slack = qmax * ymax * (2 * D * h + h * h);
        if (exact && !(f >= best * (1 - 1e-12))) bad_exact++;
        if (!exact && !(f <= best + slack)) bad_above++;
        if (best > 0) {
            ratio_sum += f / best;
            if (f / best < ratio_min) ratio_min = f / best;
        }
    }
    CHECK(n > count / 2, "%s: only %d of %d solves found a vertex", spec, n, count);
    CHECK(bad_val == 0, "%s: %d solves whose value is not the objective at their point", spec, bad_val);
    CHECK(bad_floor == 0, "%s: %d solves where a floor below the best changed the vertex, or one at it found one", spec,
          bad_floor);
    CHECK(bad_box == 0, "%s: %d solves outside the box", spec, bad_box);
    if (exact) CHECK(bad_exact == 0, "%s: %d solves below the enumeration's maximum (uniform: the solve is exact)", spec, bad_exact);
    else CHECK(bad_above == 0, "%s: %d solves above the enumeration's maximum plus its resolution", spec, bad_above);
    printf("%s: %d solves, value over the enumeration's largest: mean %.4f, min %.4f\n", spec, n, ratio_sum / n, ratio_min);
    cfpo_density_free(&d);
}

/* The near phase's solve against enumeration (see the header). */
static void near_trials(int count)
{
    cfpo_density d;
    char err[256];
    if (cfpo_density_load("cos:a=0,res=16", &d, err, sizeof err) != 0) { CHECK(0, "flat: %s", err); return; }
    unsigned long long seed = 4242;
    const double s = 0.05;
    double yx[10], yy[10], yr[10], dd[10], scratch[200];
    int n = 0, below = 0, above_full = 0, strict = 0;
    for (int t = 0; t < count; t++) {
        const double ox = urand(&seed), oy = urand(&seed);
        const int k = 3 + (int)(urand(&seed) * 8);
        sites_nearest_first(&seed, k, 2 * s, yx, yy, dd);
        for (int j = 0; j < k; j++) yr[j] = cfpo_dens_local_q(&d, ox, oy, yx[j], yy[j]);
        const cfpo_square S = {-s, -s, s, s};
        double cx, cy, f, fx, fy, ff;
        const int got = cfpo_dens_solve(yx, yy, yr, k, 2, S, &d, sqrt(d.rho_max), ox, oy, -1, &cx, &cy, &f, scratch);
        const int gfull = cfpo_dens_solve(yx, yy, yr, k, DENS_CELLS, S, &d, sqrt(d.rho_max), ox, oy, -1, &fx, &fy, &ff, scratch);
        double best = -1;
        for (int iy = 0; iy <= G; iy++)
            for (int ix = 0; ix <= G; ix++) {
                const double px = S.x0 + (S.x1 - S.x0) * ix / G, py = S.y0 + (S.y1 - S.y0) * iy / G;
                int nearest = 0;
                double dn = INFINITY;
                for (int j = 0; j < k; j++) {
                    const double e = (px - yx[j]) * (px - yx[j]) + (py - yy[j]) * (py - yy[j]);
                    if (e < dn) { dn = e; nearest = j; }
                }
                if (nearest > 1) continue;
                const double v = cfpo_dens_value(yx, yy, yr, k, cfpo_dens_local_q(&d, ox, oy, px, py), px, py);
                if (v > best) best = v;
            }
        if (best < 0) continue; /* the two cells miss the box */
        n++;
        if (!got || !(f >= best * (1 - 1e-12))) below++;
        if (got && gfull && f > ff) above_full++;
        if (got && gfull && f < ff * (1 - 1e-9)) strict++;
    }
    CHECK(n > count / 2, "near: only %d of %d trials had a grid point in the two cells", n, count);
    CHECK(below == 0, "near: %d of %d solves below the enumeration's largest value over the two nearest's cells", below, n);
    CHECK(above_full == 0, "near: %d solves above the full solve's value", above_full);
    CHECK(strict > 0, "near: the two polygons never missed the full solve's winner in %d trials (the cut is not exercised)", n);
    printf("near (2 polygons), flat: %d solves, %d below the full solve\n", n, strict);
    cfpo_density_free(&d);
}

/* Route r (0 plain, 1 AVX-512, 2 AVX2) over polygons i0 .. m - 1. */
static int route_solve(int r, const double *yx, const double *yy, const double *yr, const double *w, int k, int i0, int m,
                       int found0, cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy,
                       double floor_f, double *cx, double *cy, double *f, double *scratch)
{
    return r == 1 ? cfpo_dens_solve_avx512(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch)
         : r == 2 ? cfpo_dens_solve_avx2(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch)
                  : cfpo_dens_solve_plain(yx, yy, yr, w, k, i0, m, found0, S, d, qhi, ox, oy, floor_f, cx, cy, f, scratch);
}

/* The search in two parts, as the engine resumes it (the near solve's
 * polygons, then the rest: cfpo_dens_solve_from), against the search in
 * one: the same return and bits, on route r; the split after polygon
 * `from`. Returns 1 when they differ. */
static int split_differs(int r, const double *yx, const double *yy, const double *yr, const double *w, int k, int from,
                         int m, cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                         int got, double cx, double cy, double f, double *scratch)
{
    double sx = 0.5 * (S.x0 + S.x1), sy = 0.5 * (S.y0 + S.y1), sf;
    const int first = route_solve(r, yx, yy, yr, w, k, 0, from, 0, S, d, qhi, ox, oy, floor_f, &sx, &sy, &sf, scratch);
    const int two = route_solve(r, yx, yy, yr, w, k, from, m, first, S, d, qhi, ox, oy, first ? sf : floor_f, &sx, &sy,
                                &sf, scratch);
    return two != got || (got && (sx != cx || sy != cy || sf != f));
}

/* The same through the public entry, on the CPU's route. */
static int split_public_differs(const double *yx, const double *yy, const double *yr, int k, int from, int cells,
                                cfpo_square S, const cfpo_density *d, double qhi, double ox, double oy, double floor_f,
                                double *scratch)
{
    double cx, cy, f, sx, sy, sf;
    const int got = cfpo_dens_solve(yx, yy, yr, k, cells, S, d, qhi, ox, oy, floor_f, &cx, &cy, &f, scratch);
    (void)cfpo_dens_solve(yx, yy, yr, k, from, S, d, qhi, ox, oy, floor_f, &sx, &sy, &sf, scratch);
    const int two = cfpo_dens_solve_from(yx, yy, yr, k, from, cells, S, d, qhi, ox, oy, floor_f, &sx, &sy, &sf, scratch);
    return two != got || (got && (sx != cx || sy != cy || sf != f));
}

/* The routes and the bounds against each other (see the header). */
static void routes(const char *spec, int count)
{
    cfpo_density d;
    cfpo_dens_qbound qb;
    char err[256];
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    if (cfpo_dens_qbound_build(&qb, &d) != 0) { CHECK(0, "%s: out of memory", spec); cfpo_density_free(&d); return; }
    const int simd = cfpo_solver_avx512_usable(), avx2 = cfpo_solver_avx2_usable();
    unsigned long long seed = 777;
    double yx[40], yy[40], yr[40], w[40], dd[40], scratch[8 * 48 + 16];
    int differ = 0, tight = 0, n = 0, split_differs_n = 0, split_found = 0, split_n = 0, public_differs = 0;
    for (int t = 0; t < count; t++) {
        const double ox = urand(&seed), oy = urand(&seed), s = 0.01 + 0.04 * urand(&seed);
        const int k = 1 + (int)(urand(&seed) * 40);
        sites_nearest_first(&seed, k, 2 * s, yx, yy, dd);
        for (int j = 0; j < k; j++) {
            yr[j] = cfpo_dens_local_q(&d, ox, oy, yx[j], yy[j]);
            w[j] = sqrt(yr[j]);
        }
        const cfpo_square S = {-s, -s, s, s};
        const double qlo = cfpo_dens_qbound_box(&qb, ox + S.x0, oy + S.y0, ox + S.x1, oy + S.y1);
        const double qhi[2] = {sqrt(d.rho_max), qlo};
        tight += qlo < qhi[0];
        const int m = (t & 1) ? (k < 2 ? k : 2) : (k < DENS_CELLS ? k : DENS_CELLS);
        double ref_x = 0, ref_y = 0, ref_f = 0, floor_f = -1;
        for (int q = 0; q < 3; q++) {
            int ref = -1;
            for (int b = 0; b < 2; b++)
                for (int r = 0; r < 3; r++) {
                    if ((r == 1 && !simd) || (r == 2 && !avx2)) continue;
                    double cx = 0.5 * (S.x0 + S.x1), cy = 0.5 * (S.y0 + S.y1), f;
                    const int got = route_solve(r, yx, yy, yr, w, k, 0, m, 0, S, &d, qhi[b], ox, oy, floor_f, &cx, &cy, &f, scratch);
                    if (m > 1) { /* resumed after polygon `from` */
                        const int from = 1 + (int)((unsigned)t % (unsigned)(m - 1));
                        split_differs_n += split_differs(r, yx, yy, yr, w, k, from, m, S, &d, qhi[b], ox, oy, floor_f, got, cx, cy, f, scratch);
                        split_found += got && f != floor_f;
                        split_n++;
                    }
                    { /* f at the spot found, by the same route */
                        const double q = cfpo_dens_local_q(&d, ox, oy, cx, cy), f0 = cfpo_dens_value_plain(yx, yy, yr, k, q, cx, cy);
                        const double fr = r == 1 ? cfpo_dens_value_avx512(yx, yy, yr, k, q, cx, cy)
                                        : r == 2 ? cfpo_dens_value_avx2(yx, yy, yr, k, q, cx, cy) : f0;
                        differ += memcmp(&fr, &f0, sizeof fr) != 0;
                    }
                    if (ref < 0) {
                        ref = got;
                        ref_x = cx; ref_y = cy; ref_f = f;
                    } else if (got != ref || cx != ref_x || cy != ref_y || f != ref_f) {
                        differ++;
                    }
                }
            n++;
            { /* the engine's fall-back in a steep block: the near solve's polygons, then all */
                int fall;
                const int near = cfpo_policy_density_near(21, 1, 2, DENS_CELLS, &fall); /* an iteration that falls back */
                public_differs += split_public_differs(yx, yy, yr, k, near, fall, S, &d, qhi[1], ox, oy, floor_f, scratch);
            }
            floor_f = ref ? ref_f * (q == 0 ? 0.5 : 1 - 1e-9) : -1;
        }
    }
    CHECK(differ == 0, "%s: %d of %d solves differ between the routes or the bounds of q", spec, differ, n);
    CHECK(split_differs_n == 0, "%s: %d of %d searches resumed after a polygon differ from the search in one", spec,
          split_differs_n, split_n);
    CHECK(split_found > split_n / 4, "%s: only %d of %d split searches found a vertex", spec, split_found, split_n);
    CHECK(public_differs == 0, "%s: %d of %d searches resumed by cfpo_dens_solve_from differ", spec, public_differs, n);
    CHECK(tight > count / 2, "%s: the box's bound of q is below the global one in only %d of %d boxes", spec, tight, count);
    printf("%s: %d solves by the plain route%s%s, same bits with both bounds of q\n", spec, n, simd ? ", the AVX-512 route" : "",
           avx2 ? ", the AVX2 route" : "");
    cfpo_dens_qbound_free(&qb);
    cfpo_density_free(&d);
}

int main(void)
{
    trials("cos:a=0,res=16", 1, 300);
    trials("cos:a=0.9,res=64", 0, 300);
    trials("ramp:contrast=16,res=64", 0, 300);
    trials("balzer:res=64", 0, 300);
    near_trials(300);
    routes("cos:a=0.9,res=256", 400);
    routes("ramp:contrast=16,res=256", 400);
    routes("balzer:res=256", 400);
    return test_report(passed_, failed_);
}
