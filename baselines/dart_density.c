/* dart_density.c - adaptive dart throwing under a density: dart_sample
 * (dart.c) with candidates drawn proportional to rho and a conflict radius
 * that follows the local spacing.
 *
 * Local spacing r(x) = r / sqrt(rho(x)), r = REL Delta(n) the uniform
 * radius. Two points conflict when |x_i - x_j| < sqrt(r(x_i) r(x_j)),
 * i.e. d^2 q_i q_j < r^2 with q = sqrt(rho): the symmetric radius of the
 * pair measure m(i, j) = |x_i - x_j| / sqrt(r_i r_j) of cfpo's density
 * path (src/density/dens_measure.h), so every pair of the result has m >= REL in
 * those units. This is the adaptive conflict rule of Wei's parallel
 * Poisson-disk sampling and of Wei and Wang's differential domain analysis
 * (a pair conflicts when closer than a radius symmetric in the two
 * samples' local radii) with the geometric mean for the symmetric radius:
 * Wei (2008) takes the larger radius, Wei and Wang (2011) normalise by the
 * arithmetic mean; the geometric mean is the one whose measure never falls
 * under farthest-point moves (docs/method.md, "Density"), the measure the
 * suite reports.
 * Dart k is drawn by dens_draw.h from the uniform dart k of dart.c
 * (rand01(seed, DART_STREAM, 2k), 2k + 1) and four numbers of its own
 * stream; for a uniform density the darts, the conflicts (d^2 * 1 < r^2)
 * and so the points are dart.c's, byte for byte. Saturation as dart.c:
 * max_fails consecutive rejected darts. */
#include <stdio.h>
#include <stdlib.h>

#include "dens_draw.h"
#include "mgrid.h"
#include "pd.h"
#include "rng.h"

#include <math.h>

#define DART_STREAM 0x4441525453ULL       /* "DARTS", dart.c's */
#define DART_DENS_STREAM 0x444152545344ULL /* "DARTSD" */

int dart_density_sample(const pd_params *p, pd_result *res, char *err, size_t errlen)
{
    const cfpo_density *d = p->density;
    res->xy = NULL;
    res->n = 0;
    res->trials = 0;
    res->saturated = 0;
    double *xy = malloc(2 * (size_t)p->target * sizeof *xy), *q = malloc((size_t)p->target * sizeof *q);
    dens_draw s = {0};
    mgrid M = {0};
    if (!xy || !q || dens_draw_init(&s, d) != 0 ||
        mgrid_init(&M, (size_t)p->target, (size_t)p->target, xy, q, sqrt(d->rho_min)) != 0) {
        free(xy);
        free(q);
        dens_draw_free(&s);
        snprintf(err, errlen, "out of memory for %lld points at radius %g", (long long)p->target, p->r);
        return -1;
    }
    const double r2 = p->r * p->r;
    int64_t placed = 0;
    uint64_t dart = 0, fails = 0;
    while (placed < p->target) {
        double x = cfpo_rand01(p->seed, DART_STREAM, 2 * dart), y = cfpo_rand01(p->seed, DART_STREAM, 2 * dart + 1);
        dens_draw_at(&s, p->seed, DART_DENS_STREAM, dart, &x, &y);
        dart++;
        if ((dart & ((1u << 22) - 1)) == 0 && p->report) p->report(p->user, placed, dart, (int64_t)fails);
        const double qx = sqrt(cfpo_density_at(d, x, y));
        if (mgrid_conflict(&M, x, y, qx, r2)) {
            if (++fails >= p->max_fails) {
                res->saturated = 1;
                break;
            }
            continue;
        }
        fails = 0;
        xy[2 * placed] = x;
        xy[2 * placed + 1] = y;
        q[placed] = qx;
        mgrid_insert(&M, placed);
        placed++;
        if (p->report && placed % p->report_step == 0) p->report(p->user, placed, dart, 0);
    }
    mgrid_free(&M);
    dens_draw_free(&s);
    free(q);
    res->xy = xy;
    res->n = placed;
    res->trials = dart;
    return 0;
}
