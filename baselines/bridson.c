/* bridson.c - Bridson's fast Poisson-disk sampling (SIGGRAPH sketch 2007)
 * on the unit torus.
 *
 * Active list; a uniformly random active sample s draws up to k candidates
 * uniformly (by area) in the annulus rho <= |c - s| <= 2 rho and the first
 * one with no point within r is accepted and made active. When all k fail,
 * the 2007 algorithm retires s. That leaves rare holes (the set is not
 * maximal), so before retiring s this version computes the free arcs of
 * C(s, rho) exactly (arcs.h, from its neighbours) and, if any are left,
 * places a sample uniformly on them and keeps s active: s is retired only
 * when its circle is covered, so the result is maximal (see arcs.h).
 * plain = 1 skips that check and gives the 2007 algorithm exactly.
 * Randomness: stream BRIDSON_STREAM, one counter for all draws. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "pd.h"
#include "pdset.h"
#include "rng.h"

#define BRIDSON_STREAM 0x425249444eULL /* "BRIDN" */

static const double TWO_PI = 6.283185307179586476925286766559;

/* A sample on the free arcs of s, or 0 when its circle is covered. */
static int fill_point(const pdset *S, uint32_t s, double u, double *x, double *y)
{
    arcs A;
    pdset_free_arcs(S, s, &A);
    if (A.m == 0) return 0;
    const double phi = arcs_pick(&A, u);
    *x = cfpo_wrap01(S->xy[2 * s] + S->rho * cos(phi));
    *y = cfpo_wrap01(S->xy[2 * s + 1] + S->rho * sin(phi));
    return 1;
}

int bridson_sample(const pd_params *p, pd_result *res, char *err, size_t errlen)
{
    res->xy = NULL;
    res->n = 0;
    res->trials = 0;
    res->saturated = 0;
    pdset S;
    if (pdset_init(&S, p->r, p->target, 0) != 0) goto oom;
    uint64_t ctr = 0, trials = 0;
    double x0 = cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++);
    double y0 = cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++);
    if (pdset_add(&S, x0, y0) < 0) goto oom_set;
    while (S.nactive > 0) {
        const int64_t k = (int64_t)(cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++) * (double)S.nactive);
        const uint32_t s = S.active[k];
        const double sx = S.xy[2 * s], sy = S.xy[2 * s + 1];
        int found = 0;
        double x = 0, y = 0;
        for (int j = 0; j < p->k && !found; j++) {
            const double u = cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++);
            const double v = cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++);
            const double rad = S.rho * sqrt(1.0 + 3.0 * u), ang = TWO_PI * v;
            x = cfpo_wrap01(sx + rad * cos(ang));
            y = cfpo_wrap01(sy + rad * sin(ang));
            trials++;
            if ((trials & ((1u << 22) - 1)) == 0 && p->report)
                p->report(p->user, S.n, trials, S.nactive);
            found = !pdgrid_conflict(&S.G, x, y);
        }
        if (!found && !p->plain) {
            found = fill_point(&S, s, cfpo_rand01(p->seed, BRIDSON_STREAM, ctr++), &x, &y);
            /* Rounding at an arc's end could conflict; never seen, but then
             * retire s rather than loop (the maximality test would tell). */
            if (found && pdgrid_conflict(&S.G, x, y)) found = 0;
        }
        if (!found) {
            pdset_retire(&S, k);
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
