/* bsample.c - boundary sampling (Dunbar & Humphreys 2006), the paper's BS.
 *
 * A maximal Poisson-disk set grown on the boundary of the union of disks:
 * every active sample keeps the arcs of its circle C(s, rho) that no other
 * disk covers (arcs.h, maintained incrementally by pdset_add: a new point
 * trims the arcs of every sample within 2 rho and retires those left
 * empty). Each step picks a uniformly random active sample and a uniformly
 * random point of its free arcs and places the new sample there, at
 * distance rho from its parent. The front empties exactly when the set is
 * maximal. Randomness: stream BS_STREAM, one counter for all draws. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "pd.h"
#include "pdset.h"
#include "rng.h"

#define BS_STREAM 0x4253414d504cULL /* "BSAMPL" */

int bs_sample(const pd_params *p, pd_result *res, char *err, size_t errlen)
{
    res->xy = NULL;
    res->n = 0;
    res->trials = 0;
    res->saturated = 0;
    pdset S;
    if (pdset_init(&S, p->r, p->target, 1) != 0) goto oom;
    uint64_t ctr = 0;
    double x0 = cfpo_rand01(p->seed, BS_STREAM, ctr++), y0 = cfpo_rand01(p->seed, BS_STREAM, ctr++);
    if (pdset_add(&S, x0, y0) < 0) goto oom_set;
    uint64_t trials = 0;
    while (S.nactive > 0) {
        const int64_t k = (int64_t)(cfpo_rand01(p->seed, BS_STREAM, ctr++) * (double)S.nactive);
        const uint32_t s = S.active[k];
        arcs *A = &S.pool[S.slot[s]];
        const double phi = arcs_pick(A, cfpo_rand01(p->seed, BS_STREAM, ctr++));
        const double x = cfpo_wrap01(S.xy[2 * s] + S.rho * cos(phi));
        const double y = cfpo_wrap01(S.xy[2 * s + 1] + S.rho * sin(phi));
        trials++;
        if ((trials & ((1u << 22) - 1)) == 0 && p->report) p->report(p->user, S.n, trials, S.nactive);
        if (pdgrid_conflict(&S.G, x, y)) {
            /* Only rounding at an arc's end can get here: drop that sliver. */
            arcs_remove(A, phi - ARCS_EPS, phi + ARCS_EPS);
            if (A->m == 0) pdset_retire(&S, k);
            continue;
        }
        if (pdset_add(&S, x, y) < 0) goto oom_set;
        if (p->report && S.n % p->report_step == 0) p->report(p->user, S.n, trials, S.nactive);
    }
    res->n = S.n;
    res->trials = trials;
    res->xy = pdset_take_points(&S);
    pdset_free(&S);
    return 0;
oom_set:
    pdset_free(&S);
oom:
    snprintf(err, errlen, "out of memory at radius %g", p->r);
    return -1;
}
