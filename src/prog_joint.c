/* prog_joint.c - see prog_joint.h. */
#include "prog_joint.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_buckets.h"
#include "rng.h"

/* Buckets of side about Delta(m) holding points 0 .. m - 1 of xy. */
static int grid_init(prog_buckets *B, const double *xy, int64_t m)
{
    if (prog_buckets_init(B, xy, m, m) != 0) return -1;
    for (int64_t k = m - 1; k >= 0; k--) prog_buckets_link(B, k);
    return 0;
}

static double wrap1(double v)
{
    const double w = v - floor(v);
    return w < 1.0 ? w : 0.0;
}

/* The groups' measures, and (raw, may be NULL) each group's smallest
 * distance itself, the floors' exact values. Groups: the prefixes
 * [0, sizes[k]); with classes, class k [sizes[k - 1], sizes[k]) and then
 * the union [0, sizes[K - 1]) (K + 1 groups). */
static int measure(const double *xy, const int64_t *sizes, int K, int classes, double *dmin, double *davg,
                   double *raw, char *err, size_t errlen)
{
    for (int k = 0; k < K + (classes ? 1 : 0); k++) {
        const int64_t lo0 = classes && k > 0 && k < K ? sizes[k - 1] : 0;
        const int64_t m = (k < K ? sizes[k] : sizes[K - 1]) - lo0;
        xy += 2 * lo0;
        prog_buckets B = {0};
        if (grid_init(&B, xy, m) != 0) {
            prog_buckets_free(&B);
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        double lo = INFINITY, sum = 0;
        for (int64_t i = 0; i < m; i++) {
            const double d = sqrt(prog_buckets_nearest2(&B, xy[2 * i], xy[2 * i + 1], i, -1.0));
            if (d < lo) lo = d;
            sum += d;
        }
        prog_buckets_free(&B);
        const double D = cfpo_delta_bound((double)m);
        dmin[k] = lo / D;
        davg[k] = sum / (double)m / D;
        if (raw) raw[k] = lo;
        xy -= 2 * lo0;
    }
    return 0;
}

int cfpo_prog_measure(const double *xy, const int64_t *sizes, int K, double *dmin, double *davg, char *err,
                      size_t errlen)
{
    return measure(xy, sizes, K, 0, dmin, davg, NULL, err, errlen);
}

/* ---- the moves */

typedef struct {
    prog_buckets B;
    const int *lev;     /* each point's level */
    int K, classes;
    double F[65], G[65]; /* the pair floors (distances) and weights by pair level */
    double Gmax[65];     /* max of G over the pair levels a point of level l can be in */
    double H[65];        /* hold distances: a pair shorter than H_L may not shrink */
    double Fmax[65];     /* the same for F */
    double cap;          /* the measure counted up to this (a mover at or past it has nothing to gain) */
} joint;

/* The pair measure of point i placed at (x, y): its smallest d_ij / G_L
 * over the other points (capped at J->cap), or -1 when some pair falls
 * below its floor. *bind: the binding partner (-1 if none within reach). */
static double measure_at(const joint *J, int64_t i, double x, double y, int64_t *bind)
{
    const prog_buckets *B = &J->B;
    const int l = J->lev[i];
    const double r = fmax(J->Fmax[l], J->cap * J->Gmax[l]);
    double best = J->cap;
    *bind = -1;
    const int64_t gs = B->gs, b = prog_buckets_of(B, x, y), bx = b % gs, by = b / gs;
    int64_t reach = (int64_t)ceil(r / B->cs);
    const int64_t span = 2 * reach + 1 >= gs ? gs : 2 * reach + 1, lo = span == gs ? 0 : reach;
    for (int64_t oy = 0; oy < span; oy++) {
        const int64_t cy = ((by - lo + oy) % gs + gs) % gs;
        for (int64_t ox = 0; ox < span; ox++) {
            const int64_t cx = ((bx - lo + ox) % gs + gs) % gs;
            for (int64_t k = B->head[cy * gs + cx]; k >= 0; k = B->next[k]) {
                if (k == i) continue;
                const double d = sqrt(prog_torus_d2(x, y, B->xy[2 * k], B->xy[2 * k + 1]));
                const int L = J->classes ? (J->lev[k] == l ? l : J->K) : J->lev[k] > l ? J->lev[k] : l;
                if (d < J->F[L]) return -1;
                if (d < J->H[L] && d < sqrt(prog_torus_d2(B->xy[2 * i], B->xy[2 * i + 1], B->xy[2 * k], B->xy[2 * k + 1])))
                    return -1; /* a pair below its hold distance may not shrink */
                const double q = d / J->G[L];
                if (q < best) best = q, *bind = k;
            }
        }
    }
    return best;
}

/* The floors from the groups' smallest distances raw[k] (dmin_k
 * Delta(m_k), exactly as measured): F_L = max over k >= L of raw[k]; with
 * classes, F_c = max(raw[c], raw[K]) (a pair within class c) and F_K =
 * raw[K] (a pair across classes: the union only). */
static void set_floors(joint *J, int K, const double *raw)
{
    if (J->classes) {
        J->F[K] = raw[K];
        for (int c = 0; c < K; c++) J->F[c] = J->Fmax[c] = fmax(raw[c], raw[K]);
        return;
    }
    double f = 0;
    for (int L = K - 1; L >= 0; L--) {
        const double v = raw[L];
        if (v > f) f = v;
        J->F[L] = f;
    }
    for (int l = 0; l < K; l++) {
        J->Fmax[l] = 0;
        for (int L = l; L < K; L++) J->Fmax[l] = fmax(J->Fmax[l], J->F[L]);
    }
}

int cfpo_prog_joint(double *xy, const int64_t *sizes, int K, const cfpo_prog_joint_options *jo, double *dmin,
                    double *davg, char *err, size_t errlen)
{
    if (K > 64) {
        snprintf(err, errlen, "the joint move takes at most 64 levels");
        return -1;
    }
    const int64_t n = sizes[K - 1];
    const int cand = jo->candidates > 0 ? jo->candidates : 12;
    const double tp = jo->target_prefix > 0 ? jo->target_prefix : 0.78;
    const double tf = jo->target_full > 0 ? jo->target_full : 0.90;
    joint J = {0};
    int *lev = malloc((size_t)n * sizeof *lev);
    if (!lev || grid_init(&J.B, xy, n) != 0) {
        free(lev);
        prog_buckets_free(&J.B);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int64_t i = 0, l = 0; i < n; i++) {
        while (i >= sizes[l]) l++;
        lev[i] = (int)l;
    }
    J.lev = lev;
    J.K = K;
    J.classes = jo->classes;
    if (J.classes) { /* class c's size in its own units, the union in Delta(n) */
        for (int c = 0; c < K; c++) {
            const double Dc = cfpo_delta_bound((double)(sizes[c] - (c ? sizes[c - 1] : 0)));
            J.G[c] = tp * Dc;
            J.H[c] = jo->hold * Dc;
        }
        J.G[K] = tf * cfpo_delta_bound((double)n);
        J.H[K] = jo->hold * cfpo_delta_bound((double)n);
        for (int c = 0; c < K; c++) J.Gmax[c] = fmax(J.G[c], J.G[K]);
    } else {
        for (int L = 0; L < K; L++) J.G[L] = (L == K - 1 ? tf : tp) * cfpo_delta_bound((double)sizes[L]);
        for (int l = 0; l < K; l++) {
            J.Gmax[l] = 0;
            for (int L = l; L < K; L++) J.Gmax[l] = fmax(J.Gmax[l], J.G[L]);
        }
        for (int L = 0; L < K; L++) J.H[L] = jo->hold * cfpo_delta_bound((double)sizes[L]);
    }
    J.cap = 1.25;
    const int NG = K + (J.classes ? 1 : 0);
    double raw[65];
    int rc = measure(xy, sizes, K, J.classes, dmin, davg, raw, err, errlen);
    if (rc == 0 && jo->sweep_done) jo->sweep_done(0, 0, dmin, davg, NG, jo->user);
    static const double steps[4] = {0.4, 0.2, 0.08, 0.02}; /* of the nearest neighbour's distance */
    for (int s = 1; rc == 0 && s <= jo->sweeps; s++) {
        set_floors(&J, K, raw);
        int64_t moved = 0;
        for (int64_t i = 0; i < n; i++) {
            const double x0 = xy[2 * i], y0 = xy[2 * i + 1];
            int64_t bind;
            const double q0 = measure_at(&J, i, x0, y0, &bind);
            if (q0 < 0 || q0 >= J.cap || bind < 0) continue; /* (a point at a floor's edge by rounding stays) */
            const double dx = x0 - xy[2 * bind], dy = y0 - xy[2 * bind + 1];
            const double ux = dx - round(dx), uy = dy - round(dy); /* away from the binding partner */
            const double dn = sqrt(ux * ux + uy * uy);
            const double scale = sqrt(prog_torus_d2(x0, y0, xy[2 * bind], xy[2 * bind + 1]));
            double bq = q0, bx = x0, by = y0;
            const uint64_t stream = ((uint64_t)s << 40) ^ (uint64_t)i;
            for (int c = 0; c < cand; c++) {
                const double st = steps[c % 4] * scale;
                double cx, cy;
                if (c < cand / 2 && dn > 0) { /* straight away, with a little sideways jitter */
                    const double j = 0.3 * (2.0 * cfpo_rand01(jo->seed, stream, (uint64_t)c) - 1.0);
                    cx = x0 + st * (ux / dn - j * uy / dn);
                    cy = y0 + st * (uy / dn + j * ux / dn);
                } else { /* uniform in the disk of radius st */
                    const double a = 2.0 * M_PI * cfpo_rand01(jo->seed, stream, 2 * (uint64_t)c + 64);
                    const double r = st * sqrt(cfpo_rand01(jo->seed, stream, 2 * (uint64_t)c + 65));
                    cx = x0 + r * cos(a);
                    cy = y0 + r * sin(a);
                }
                cx = wrap1(cx);
                cy = wrap1(cy);
                int64_t bk;
                const double q = measure_at(&J, i, cx, cy, &bk);
                if (q > bq) bq = q, bx = cx, by = cy;
            }
            if (bq > q0) {
                prog_buckets_unlink(&J.B, i);
                xy[2 * i] = bx;
                xy[2 * i + 1] = by;
                prog_buckets_link(&J.B, i);
                moved++;
            }
        }
        rc = measure(xy, sizes, K, J.classes, dmin, davg, raw, err, errlen);
        if (rc == 0 && jo->sweep_done) jo->sweep_done(s, moved, dmin, davg, NG, jo->user);
        if (moved == 0) break;
    }
    prog_buckets_free(&J.B);
    free(lev);
    return rc;
}
