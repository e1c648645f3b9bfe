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
 *    printed (the straight lines stand in for Apollonius circles). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "dens_solve.h"
#include "density.h"
#include "testutil.h"

static int passed_, failed_;

static double urand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

#define G 300 /* enumeration grid a side */

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
        for (int j = 0; j < k; j++) {
            double x = (2 * urand(&seed) - 1) * 2 * s, y = (2 * urand(&seed) - 1) * 2 * s;
            int at = j; /* nearest first (to the box's centre) */
            const double dj = x * x + y * y;
            while (at > 0 && dd[at - 1] > dj) {
                dd[at] = dd[at - 1]; yx[at] = yx[at - 1]; yy[at] = yy[at - 1];
                at--;
            }
            dd[at] = dj; yx[at] = x; yy[at] = y;
        }
        for (int j = 0; j < k; j++) yr[j] = cfpo_dens_local_q(&d, ox, oy, yx[j], yy[j]);
        cfpo_square S = {-s, -s, s, s};
        double cx, cy, f;
        if (!cfpo_dens_solve(yx, yy, yr, k, S, &d, ox, oy, -1, &cx, &cy, &f, scratch)) continue;
        n++;
        /* a floor below the best gives the same vertex; at or above it, none */
        const double floors[4] = {0, 0.5 * f, f * (1 - 1e-9), f};
        for (int q = 0; q < 4; q++) {
            double fx, fy, ff;
            const int got = cfpo_dens_solve(yx, yy, yr, k, S, &d, ox, oy, floors[q], &fx, &fy, &ff, scratch);
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

int main(void)
{
    trials("cos:a=0,res=16", 1, 300);
    trials("cos:a=0.9,res=64", 0, 300);
    trials("ramp:contrast=16,res=64", 0, 300);
    trials("balzer:res=64", 0, 300);
    return test_report(passed_, failed_);
}
