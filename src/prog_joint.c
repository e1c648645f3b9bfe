/* prog_joint.c - see prog_joint.h. */
#include "prog_joint_int.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"
#include "prog_buckets.h"
#include "prog_measure.h"
#include "prog_pgrid.h"
#include "rng.h"

#include <omp.h>

/* One thread's neighbours for the local solve: offset x, y from the
 * mover, 1 / G_L, F_L (4 doubles each). */
typedef struct {
    double *e;
    int64_t n, cap;
} nbuf;

/* The neighbours of point i within r of its place (x0, y0) into J->nb:
 * each as its offset from (x0, y0) on the torus, 1 / G_L and F_L. 0, or
 * -1 when out of memory. */
static int gather(const joint *J, nbuf *w, int64_t i, double x0, double y0, double r)
{
    const prog_buckets *B = J->classes ? &J->B : &J->P.G[J->K - 1];
    const int l = J->lev[i];
    int64_t wx, wy;
    const int64_t span = prog_buckets_window(B, prog_buckets_of(B, x0, y0), (int64_t)ceil(r / B->cs), &wx, &wy);
    w->n = 0;
    for (int64_t oy = 0; oy < span; oy++) {
        for (int64_t ox = 0; ox < span; ox++) {
            for (int64_t k = prog_buckets_first(B, wx + ox, wy + oy); k >= 0; k = B->next[k]) {
                if (k == i) continue;
                double dx = B->xy[2 * k] - x0, dy = B->xy[2 * k + 1] - y0;
                dx -= round(dx);
                dy -= round(dy);
                if (dx * dx + dy * dy > r * r) continue;
                if (w->n == w->cap) {
                    const int64_t c = w->cap ? 2 * w->cap : 256;
                    double *t = realloc(w->e, (size_t)c * 4 * sizeof *t);
                    if (!t) return -1;
                    w->e = t;
                    w->cap = c;
                }
                const int L = J->classes ? (J->lev[k] == l ? l : J->K) : J->lev[k] > l ? J->lev[k] : l;
                double *e = w->e + 4 * w->n++;
                e[0] = dx;
                e[1] = dy;
                e[2] = 1.0 / J->G[L];
                e[3] = J->F[L];
            }
        }
    }
    return 0;
}

/* The pair measure over the gathered neighbours at offset (px, py) (-1
 * below a floor), and its ascent direction (gx, gy): the sum of the unit
 * vectors away from every neighbour whose measure is within slack of the
 * smallest (the near-binding set; an epsilon-subgradient of the minimum). */
static double local_at(const nbuf *w, double cap, double px, double py, double slack, double *gx, double *gy)
{
    double best = cap;
    for (int64_t j = 0; j < w->n; j++) {
        const double *e = w->e + 4 * j;
        const double dx = px - e[0], dy = py - e[1], d = sqrt(dx * dx + dy * dy);
        if (d < e[3]) return -1;
        const double q = d * e[2];
        if (q < best) best = q;
    }
    if (!gx) return best;
    double sx = 0, sy = 0;
    for (int64_t j = 0; j < w->n; j++) {
        const double *e = w->e + 4 * j;
        const double dx = px - e[0], dy = py - e[1], d = sqrt(dx * dx + dy * dy);
        if (d * e[2] <= best + slack * e[2] && d > 0) sx += dx / d, sy += dy / d;
    }
    *gx = sx;
    *gy = sy;
    return best;
}

/* The local solve of point i from offset (px, py) (measure q): up to
 * iters steps along the ascent direction of local_at, the step growing
 * after a gain and halving after a loss, starting at step0; the best
 * offset into (px, py). Returns its measure (over the gathered
 * neighbours only: the caller checks it against the grid). */
static double local_solve(const joint *J, const nbuf *w, double *px, double *py, double step0, int iters)
{
    double t = step0, gx, gy;
    double q = local_at(w, J->cap, *px, *py, t, &gx, &gy);
    for (int it = 0; it < iters && t > 1e-4 * step0; it++) {
        const double g = sqrt(gx * gx + gy * gy);
        if (g < 1e-9) break; /* balanced: a local maximum of the smallest measure */
        const double cx = *px + t * gx / g, cy = *py + t * gy / g;
        const double qc = local_at(w, J->cap, cx, cy, t, NULL, NULL);
        if (qc > q) {
            *px = cx, *py = cy;
            t *= 1.5;
            if (t > step0) t = step0;
            q = local_at(w, J->cap, cx, cy, t, &gx, &gy);
        } else {
            t *= 0.5;
            q = local_at(w, J->cap, *px, *py, t, &gx, &gy);
        }
    }
    return q;
}

/* The floors from the groups' smallest distances raw[k] (dmin_k
 * Delta(m_k), exactly as measured): F_L = max over k >= L of raw[k]; with
 * classes, F_c = max(raw[c], raw[K]) (a pair within class c) and F_K =
 * raw[K] (a pair across classes: the union only). */
static void set_floors(joint *J, int K, const double *raw)
{
    if (J->classes) { /* (a union floor: the union's pairs may fall to it) */
        J->F[K] = J->floor > 0 ? fmin(raw[K], J->floor * J->Dm[K]) : raw[K];
        for (int c = 0; c < K; c++) J->F[c] = J->Fmax[c] = fmax(raw[c], J->F[K]);
        return;
    }
    double f = 0;
    for (int L = K - 1; L >= 0; L--) { /* (the polish: a prefix below the full set may fall to its floor) */
        const double v = J->floor > 0 && L < K - 1 ? fmin(raw[L], J->floor * J->Dm[L]) : raw[L];
        if (v > f) f = v;
        J->F[L] = f;
    }
    for (int l = 0; l < K; l++) {
        J->Fmax[l] = 0;
        for (int L = l; L < K; L++) J->Fmax[l] = fmax(J->Fmax[l], J->F[L]);
    }
    for (int L = 0; L < K; L++) J->R[L] = fmax(fmax(J->F[L], J->cap * J->G[L]), J->H[L]);
}

/* The reach of the pairs of a point of level l: the largest R_L over the
 * pair levels L >= l (without classes), or the grid search's radius. */
static double reach_of(const joint *J, int l)
{
    if (J->classes) return fmax(J->Fmax[l], J->cap * J->Gmax[l]);
    double r = 0;
    for (int L = l; L < J->K; L++) r = fmax(r, J->R[L]);
    return r;
}

/* The best circumcentre (offset from the mover, within reach of it) of
 * three of the nn nearest gathered neighbours by local_at, into (*px,
 * *py); its measure, or -1 when none keeps the floors. The circumcentres
 * are the vertices of the neighbours' Voronoi diagram near the mover: the
 * farthest-point move's candidates (unweighted; the weights and floors are
 * then applied by local_at). */
static double best_circumcentre(const joint *J, nbuf *w, int nn, double reach, double *px, double *py)
{
    /* the nn nearest to the front (selection; nn is small) */
    if (nn > w->n) nn = (int)w->n;
    for (int a = 0; a < nn; a++) {
        int64_t m = a;
        double dm = w->e[4 * a] * w->e[4 * a] + w->e[4 * a + 1] * w->e[4 * a + 1];
        for (int64_t j = a + 1; j < w->n; j++) {
            const double d = w->e[4 * j] * w->e[4 * j] + w->e[4 * j + 1] * w->e[4 * j + 1];
            if (d < dm) dm = d, m = j;
        }
        for (int c = 0; c < 4 && m != a; c++) {
            const double t = w->e[4 * a + c];
            w->e[4 * a + c] = w->e[4 * m + c];
            w->e[4 * m + c] = t;
        }
    }
    double best = -1;
    for (int a = 0; a < nn; a++)
        for (int b = a + 1; b < nn; b++)
            for (int c = b + 1; c < nn; c++) {
                const double ax = w->e[4 * a], ay = w->e[4 * a + 1], bx = w->e[4 * b] - ax, by = w->e[4 * b + 1] - ay;
                const double cx = w->e[4 * c] - ax, cy = w->e[4 * c + 1] - ay, D = 2.0 * (bx * cy - by * cx);
                if (fabs(D) < 1e-300) continue;
                const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
                const double ux = ax + (cy * b2 - by * c2) / D, uy = ay + (bx * c2 - cx * b2) / D;
                if (ux * ux + uy * uy > reach * reach) continue;
                const double q = local_at(w, J->cap, ux, uy, 0, NULL, NULL);
                if (q > best) best = q, *px = ux, *py = uy;
            }
    return best;
}

/* One move of point i in sweep s (prog_joint.h): the trials, then the
 * local solve; 1 when it moved, 0 when not, -1 when out of memory. Reads
 * the points within the level's reach of i's trial positions, writes i
 * alone (and its bucket). */
static int move_point(joint *J, nbuf *w, double *xy, int64_t i, int s, const cfpo_prog_joint_options *jo, int cand)
{
    static const double steps[4] = {0.4, 0.2, 0.08, 0.02}; /* of the nearest neighbour's distance */
    const double x0 = xy[2 * i], y0 = xy[2 * i + 1];
    int64_t bind;
    const double q0 = prog_joint_measure_at(J, i, x0, y0, &bind, -INFINITY);
    if (q0 < 0 || q0 >= J->cap * (1.0 + J->lam) || bind < 0) return 0; /* (a point at a floor's edge by rounding stays) */
    const double rho = 1.5 * J->G[J->K] / (jo->target_full > 0 ? jo->target_full : 0.90); /* (the swaps' reach, Delta(n)) */
    if (jo->swaps > 0 && J->classes && q0 < 1.0 && J->lev[bind] == J->lev[i] && /* bound by its own class below */
        prog_joint_swap_move(J, xy, i, q0, rho, jo->swaps))                       /* the target: a swap first */
        return 1;
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
        cx = prog_joint_wrap1(cx);
        cy = prog_joint_wrap1(cy);
        int64_t bk;
        const double q = prog_joint_measure_at(J, i, cx, cy, &bk, bq);
        if (q > bq) bq = q, bx = cx, by = cy;
    }
    if (jo->solve > 0 || jo->circum > 0) { /* the local solve from the best trial, checked against the grid */
        const int l = J->lev[i];
        const double r = fmax(J->Fmax[l], J->cap * J->Gmax[l]) + scale;
        if (gather(J, w, i, x0, y0, r) != 0) return -1;
        double px = bx - x0, py = by - y0;
        px -= round(px);
        py -= round(py);
        if (jo->circum > 0) {
            double cx = 0, cy = 0;
            const double qc = best_circumcentre(J, w, jo->circum, scale, &cx, &cy);
            if (qc > local_at(w, J->cap, px, py, 0, NULL, NULL)) px = cx, py = cy;
        }
        const double ql = jo->solve > 0 ? local_solve(J, w, &px, &py, 0.2 * scale, jo->solve)
                                        : local_at(w, J->cap, px, py, 0, NULL, NULL);
        if (ql >= 0 && px * px + py * py <= scale * scale) {
            const double cx = prog_joint_wrap1(x0 + px), cy = prog_joint_wrap1(y0 + py);
            int64_t bk;
            const double q = prog_joint_measure_at(J, i, cx, cy, &bk, bq);
            if (q > bq) bq = q, bx = cx, by = cy;
        }
    }
    if (bq <= q0 && jo->swaps > 0 && J->classes && /* a class swap, else the pair move */
        prog_joint_swap_move(J, xy, i, q0, rho, jo->swaps))
        return 1;
    if (bq <= q0) {
        if (jo->pairs <= 0 || J->lev[bind] < J->lev[i] || jo->hold > 0) return 0;
        int64_t bk;
        const double qj = prog_joint_measure_at(J, bind, xy[2 * bind], xy[2 * bind + 1], &bk, -INFINITY);
        return qj < 0 ? 0 : prog_joint_pair_move(J, xy, i, bind, fmin(q0, qj), s, jo);
    }
    prog_joint_place(J, xy, i, bx, by);
    return 1;
}

/* The moves on the points of xy in the working order (a copy; perm as
 * prog_pgrid_order's), written back into out in the caller's order before
 * each call of jo->sweep_done (which may read them) and at the end. */
static int joint_run(double *xy, double *out, const int64_t *perm, const int64_t *sizes, int K,
                     const cfpo_prog_joint_options *jo, double *dmin, double *davg, char *err, size_t errlen);

static void write_back(const double *w, double *out, const int64_t *perm, int64_t n)
{
    for (int64_t j = 0; j < n; j++) out[2 * perm[j]] = w[2 * j], out[2 * perm[j] + 1] = w[2 * j + 1];
}

int cfpo_prog_joint(double *xy, const int64_t *sizes, int K, const cfpo_prog_joint_options *jo, double *dmin,
                    double *davg, char *err, size_t errlen)
{
    if (K > 64) {
        snprintf(err, errlen, "the joint move takes at most 64 levels");
        return -1;
    }
    const int64_t n = sizes[K - 1];
    int64_t *perm = calloc((size_t)n, sizeof *perm);
    double *w = malloc(2 * (size_t)n * sizeof *w);
    if (!perm || !w || prog_pgrid_order(xy, sizes, K, perm) != 0) {
        free(perm);
        free(w);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int64_t j = 0; j < n; j++) w[2 * j] = xy[2 * perm[j]], w[2 * j + 1] = xy[2 * perm[j] + 1];
    const int rc = joint_run(w, xy, perm, sizes, K, jo, dmin, davg, err, errlen);
    write_back(w, xy, perm, n);
    free(perm);
    free(w);
    return rc;
}

static int joint_run(double *xy, double *out, const int64_t *perm, const int64_t *sizes, int K,
                     const cfpo_prog_joint_options *jo, double *dmin, double *davg, char *err, size_t errlen)
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
    if (lev)
        for (int64_t i = 0, l = 0; i < n; i++) {
            while (i >= sizes[l]) l++;
            lev[i] = (int)l;
        }
    J.classes = jo->classes;
    /* with classes one grid of every point; without, the prefixes' grids */
    /* grid g's buckets at least the pairs' reach within it (cap G_L, H_L;
     * the floors lie below), so a search reads 3 x 3 of them */
    const double side = fmax(1.25 * fmax(tp, tf), fmax(jo->hold, 1.0));
    if (!lev || (J.classes ? prog_buckets_build(&J.B, xy, n) : prog_pgrid_init(&J.P, xy, sizes, K, lev, side)) != 0) {
        free(lev);
        prog_buckets_free(&J.B);
        prog_pgrid_free(&J.P);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    J.lev = lev;
    J.K = K;
    if (J.classes) { /* class c's size in its own units, the union in Delta(n) */
        for (int c = 0; c < K; c++) {
            const double Dc = cfpo_delta_bound((double)(sizes[c] - (c ? sizes[c - 1] : 0)));
            J.G[c] = tp * Dc;
            J.H[c] = jo->hold * Dc;
        }
        J.G[K] = tf * cfpo_delta_bound((double)n);
        J.H[K] = jo->hold * cfpo_delta_bound((double)n);
        for (int c = 0; c < K; c++) J.Gmax[c] = fmax(J.G[c], J.G[K]);
        J.floor = jo->floor;
        J.Dm[K] = cfpo_delta_bound((double)n);
    } else {
        J.floor = jo->floor;
        for (int L = 0; L < K; L++) J.Dm[L] = cfpo_delta_bound((double)sizes[L]);
        for (int L = 0; L < K; L++) /* (the polish: the full set's weight for every pair) */
            J.G[L] = jo->floor > 0 ? tf * J.Dm[K - 1] : (L == K - 1 ? tf : tp) * J.Dm[L];
        for (int l = 0; l < K; l++) {
            J.Gmax[l] = 0;
            for (int L = l; L < K; L++) J.Gmax[l] = fmax(J.Gmax[l], J.G[L]);
        }
        for (int L = 0; L < K; L++) J.H[L] = jo->hold * cfpo_delta_bound((double)sizes[L]);
    }
    for (int L = 0; L <= K; L++) J.Hmax = fmax(J.Hmax, J.H[L]);
    J.cap = 1.25;
    J.lam = jo->avg;
    J.tau = jo->soft;
    const int NG = K + (J.classes ? 1 : 0);
    double raw[65];
    const int nth = jo->threads > 0 ? jo->threads : omp_get_max_threads();
    J.now = 1; /* (stamps of 0: no change yet) */
    int rc = J.classes ? cfpo_prog_measure_groups(xy, sizes, K, 1, nth, dmin, davg, raw, err, errlen)
                       : prog_pgrid_measure(&J.P, nth, J.now, dmin, davg, raw);
    if (rc == 0 && jo->sweep_done) jo->sweep_done(0, 0, dmin, davg, NG, jo->user);
    nbuf *nb = calloc((size_t)nth, sizeof *nb);
    int64_t *order = malloc((size_t)n * sizeof *order), *cell = malloc((size_t)n * sizeof *cell);
    if (rc == 0 && (!nb || !order || !cell)) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
    }
    for (int s = 1; rc == 0 && s <= jo->sweeps; s++) {
        set_floors(&J, K, raw);
        int64_t moved = 0;
        for (int l = 0; l < K && rc == 0; l++) {
            /* Level l's movers by the cells of a 9-coloured grid whose
             * cells of one colour are too far apart for their movers to
             * see each other or each other's buckets (prog_joint.h). */
            const int64_t lo = l ? sizes[l - 1] : 0, hi = sizes[l];
            const double r = reach_of(&J, l), cs = J.classes ? J.B.cs : J.P.G[l].cs; /* (grid l's buckets are the largest read) */
            const double c = (jo->pairs > 0 || jo->swaps > 0 ? 2.5 : 1.5) * r + 2.0 * cs; /* pair moves reach further */
            int64_t g = 3 * (int64_t)floor(1.0 / (3.0 * c));
            if (g < 3) g = 1;
            int64_t *start = calloc((size_t)(g * g + 1), sizeof *start);
            if (!start) {
                rc = -1;
                break;
            }
            for (int64_t i = lo; i < hi; i++) {
                int64_t cx = (int64_t)(xy[2 * i] * (double)g), cy = (int64_t)(xy[2 * i + 1] * (double)g);
                cx = cx >= g ? g - 1 : cx;
                cy = cy >= g ? g - 1 : cy;
                cell[i] = cy * g + cx;
                start[cell[i] + 1]++;
            }
            for (int64_t b = 0; b < g * g; b++) start[b + 1] += start[b];
            for (int64_t i = lo; i < hi; i++) order[lo + start[cell[i]]++] = i; /* id order within a cell */
            for (int64_t b = g * g; b > 0; b--) start[b] = start[b - 1];
            start[0] = 0;
            const int ncol = g == 1 ? 1 : 9;
            for (int col = 0; col < ncol && rc == 0; col++) {
                const int64_t per = g / 3 > 0 && g > 1 ? g / 3 : 1, ncell = g == 1 ? 1 : per * per;
                int bad = 0;
                J.now++;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : moved) reduction(| : bad) num_threads(nth)
                for (int64_t t = 0; t < ncell; t++) {
                    const int64_t b = g == 1 ? 0 : (3 * (t / per) + col / 3) * g + 3 * (t % per) + col % 3;
                    nbuf *w = &nb[omp_get_thread_num()];
                    for (int64_t u = start[b]; u < start[b + 1]; u++) {
                        const int m = move_point(&J, w, xy, order[lo + u], s, jo, cand);
                        if (m < 0) bad = 1;
                        else moved += m;
                    }
                }
                if (bad) rc = -1;
            }
            free(start);
        }
        if (rc != 0) {
            snprintf(err, errlen, "out of memory");
            break;
        }
        rc = J.classes ? cfpo_prog_measure_groups(xy, sizes, K, 1, nth, dmin, davg, raw, err, errlen)
                       : prog_pgrid_measure(&J.P, nth, J.now, dmin, davg, raw);
        if (rc == 0 && jo->sweep_done) {
            write_back(xy, out, perm, n);
            jo->sweep_done(s, moved, dmin, davg, NG, jo->user);
        }
        if (moved == 0) break;
    }
    for (int t = 0; nb && t < nth; t++) free(nb[t].e);
    free(nb);
    free(order);
    free(cell);
    prog_buckets_free(&J.B);
    prog_pgrid_free(&J.P);
    free(lev);
    return rc;
}
