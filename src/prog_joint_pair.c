/* prog_joint_pair.c - see prog_joint_int.h: the pair measure of a mover of
 * the joint move, its placing, and the two-point moves (the pair move and
 * the class swap). */
#include "prog_joint_int.h"

#include <math.h>

#include "rng.h"

/* The running state of a score: the smallest pair measure, its partner,
 * the soft minimum's sum, each group's nearest distance. */
typedef struct {
    double best, S, mL[66];
    int64_t bind;
} score;

/* The pairs of point i (level l) at (x, y) with the points of one
 * bucket (first point k) within r (squared: r2) of it, all of pair level
 * `only` when only >= 0 (else found from their levels), into st: -1 when some pair falls below its
 * floor (or shrinks below its hold distance), else 0. A point farther than
 * r changes nothing (its measure is past the cap, its distance past the
 * floor and the hold distance). */
static int visit(const joint *J, const prog_buckets *B, int64_t k, int64_t i, int l, double x, double y, double r2,
                 int only, score *st)
{
    for (; k >= 0; k = B->next[k]) {
        if (k == i) continue;
        const double d2 = prog_torus_d2(x, y, B->xy[2 * k], B->xy[2 * k + 1]);
        if (d2 > r2) continue;
        const double d = sqrt(d2);
        const int L = only >= 0 ? only : J->classes ? (J->lev[k] == l ? l : J->K) : J->lev[k] > l ? J->lev[k] : l;
        if (d < J->F[L]) return -1;
        if (d < J->H[L] && d < sqrt(prog_torus_d2(B->xy[2 * i], B->xy[2 * i + 1], B->xy[2 * k], B->xy[2 * k + 1])))
            return -1; /* a pair below its hold distance may not shrink */
        const double q = d / J->G[L];
        if (J->tau > 0 && q < J->cap) /* S = sum of exp(-(q_j - best) / tau) */
            st->S = q < st->best ? st->S * exp((q - st->best) / J->tau) + 1.0 : st->S + exp((st->best - q) / J->tau);
        if (q < st->best) st->best = q, st->bind = k;
        if (J->lam > 0) {
            if (d < st->mL[L]) st->mL[L] = d;
            if (J->classes && d < st->mL[J->K]) st->mL[J->K] = d; /* the union holds every pair */
        }
    }
    return 0;
}

/* The pairs of point i (level l) placed at (x, y) with the points of B
 * within r of it (all of pair level `only` when only >= 0) into st,
 * the buckets by rings outwards from (x, y)'s: -1 when some pair falls
 * below its floor, 1 when the smallest measure fell to stop or below (the
 * rest unread: the score can only fall further), else 0. */
static int scan(const joint *J, const prog_buckets *B, int64_t i, int l, double x, double y, double r, int only,
                double stop, score *st)
{
    const int64_t gs = B->gs, b = prog_buckets_of(B, x, y), bx = b % gs, by = b / gs;
    const int64_t reach = (int64_t)ceil(r / B->cs);
    const double r2 = r * r;
    if (2 * reach + 1 >= gs) { /* the window wraps onto itself: every bucket once */
        for (int64_t c = 0; c < gs * gs; c++) {
            if (visit(J, B, B->head[c], i, l, x, y, r2, only, st) != 0) return -1;
            if (st->best <= stop) return 1;
        }
        return 0;
    }
    for (int64_t rr = 0; rr <= reach; rr++)
        for (int64_t oy = -rr; oy <= rr; oy++) {
            const int64_t step = oy == -rr || oy == rr ? 1 : 2 * rr; /* the ring's edge only */
            for (int64_t ox = -rr; ox <= rr; ox += step > 0 ? step : 1) {
                if (visit(J, B, prog_buckets_first(B, bx + ox, by + oy), i, l, x, y, r2, only, st) != 0) return -1;
                if (st->best <= stop) return 1;
            }
        }
    return 0;
}

/* The score of point i placed at (x, y): its pair measure, the smallest
 * d_ij / G_L over the other points (capped at J->cap), plus J->lam times
 * the mean over the groups that hold i of its nearest distance in the
 * group over the group's G (each capped at J->cap); or -1 when some pair
 * falls below its floor. *bind: the binding partner (-1 if none within
 * reach). Without classes the pairs of level L matter within J->R[L]:
 * those with the points of levels up to i's in the grid of i's prefix,
 * those with each finer level L in the grid of prefix L (a few buckets
 * each). */
double prog_joint_measure_at(const joint *J, int64_t i, double x, double y, int64_t *bind, double stop)
{
    score st;
    st.best = J->cap, st.S = 0, st.bind = -1;
    if (J->lam > 0)
        for (int L = 0; L <= J->K; L++) st.mL[L] = INFINITY;
    if (J->lam > 0) stop = -INFINITY; /* (the delta_avg term may lift a score whose minimum fell) */
    const int l = J->lev[i];
    *bind = -1;
    int rc;
    if (J->classes) {
        rc = scan(J, &J->B, i, l, x, y, fmax(fmax(J->Fmax[l], J->cap * J->Gmax[l]), J->Hmax), -1, stop, &st);
    } else {
        rc = scan(J, &J->P.G[l], i, l, x, y, J->R[l], l, stop, &st);
        for (int L = l + 1; L < J->K && rc == 0; L++) rc = scan(J, &J->P.V[L], i, l, x, y, J->R[L], L, stop, &st);
    }
    if (rc < 0) return -1;
    if (rc > 0) return st.best; /* at or below stop: the caller's better place stands */
    *bind = st.bind;
    double best = st.best;
    const double *mL = st.mL;
    if (J->tau > 0 && st.S > 1.0) best -= J->tau * log(st.S); /* the soft minimum, at most the minimum */
    if (J->lam <= 0) return best;
    double sum = 0;
    int cnt = 0;
    if (J->classes) {
        sum = fmin(mL[l] / J->G[l], J->cap) + fmin(mL[J->K] / J->G[J->K], J->cap);
        cnt = 2;
    } else {
        double nn = INFINITY; /* i's nearest distance in prefix L: pairs of level <= L */
        for (int L = l; L < J->K; L++) {
            if (mL[L] < nn) nn = mL[L];
            sum += fmin(nn / J->G[L], J->cap);
            cnt++;
        }
    }
    return best + J->lam * sum / cnt;
}

/* Point k to (x, y) in xy and the move grid. */
void prog_joint_place(joint *J, double *xy, int64_t k, double x, double y)
{
    if (!J->classes) {
        prog_pgrid_move(&J->P, xy, k, x, y, J->now);
        return;
    }
    prog_buckets_unlink(&J->B, k);
    xy[2 * k] = x;
    xy[2 * k + 1] = y;
    prog_buckets_link(&J->B, k);
}

/* The two-point move of i to (ax, ay) and j to (bx, by), scored: i is
 * measured with j at its new place and, when that is above base, j with i
 * at its new place; both are then put back. The smaller of the two
 * measures when both are above base, else -1. */
static double two_point_score(joint *J, double *xy, int64_t i, double ax, double ay, int64_t j, double bx, double by,
                              double base)
{
    const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
    int64_t bk;
    double q = -1;
    prog_joint_place(J, xy, j, bx, by);
    const double qi = prog_joint_measure_at(J, i, ax, ay, &bk, base);
    if (qi > base) {
        prog_joint_place(J, xy, i, ax, ay);
        const double qj = prog_joint_measure_at(J, j, bx, by, &bk, base);
        prog_joint_place(J, xy, i, xi, yi);
        if (qj > base) q = fmin(qi, qj);
    }
    prog_joint_place(J, xy, j, xj, yj);
    return q;
}

/* The pair move of point i and its binding partner j (level at least i's,
 * so within i's reach): pairs trials, i straight away from j and j from i
 * by the same step (steps 0.2, 0.1, 0.04, 0.01 of their distance, a little
 * jitter), each checked with the other at its trial place; the best that
 * raises the smaller of the two measures above base is made. 1 when made. */
int prog_joint_pair_move(joint *J, double *xy, int64_t i, int64_t j, double base, int s, const cfpo_prog_joint_options *jo)
{
    static const double steps[4] = {0.2, 0.1, 0.04, 0.01};
    const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
    double ux = xi - xj, uy = yi - yj;
    ux -= round(ux);
    uy -= round(uy);
    const double d = sqrt(ux * ux + uy * uy);
    if (d <= 0) return 0;
    ux /= d;
    uy /= d;
    double best = base, b[4] = {0};
    const uint64_t stream = ((uint64_t)s << 40) ^ (uint64_t)i ^ ((uint64_t)1 << 39);
    for (int c = 0; c < jo->pairs; c++) {
        const double st = steps[c % 4] * d;
        const double ja = 0.3 * (2.0 * cfpo_rand01(jo->seed, stream, (uint64_t)c) - 1.0);
        const double jb = 0.3 * (2.0 * cfpo_rand01(jo->seed, stream, (uint64_t)c + 32) - 1.0);
        const double ax = prog_joint_wrap1(xi + st * (ux - ja * uy)), ay = prog_joint_wrap1(yi + st * (uy + ja * ux));
        const double bx = prog_joint_wrap1(xj - st * (ux - jb * uy)), by = prog_joint_wrap1(yj - st * (uy + jb * ux));
        const double q = two_point_score(J, xy, i, ax, ay, j, bx, by, best);
        if (q > best) best = q, b[0] = ax, b[1] = ay, b[2] = bx, b[3] = by;
    }
    if (best <= base) return 0;
    prog_joint_place(J, xy, i, b[0], b[1]);
    prog_joint_place(J, xy, j, b[2], b[3]);
    return 1;
}

/* The class swap of point i (prog_joint.h swaps): i and a point k of
 * another class within rho of it exchange places (so, as sets, their
 * classes), each checked with the other at its new place; of the first
 * `tries` such k, the one that raises the smaller of the two measures the
 * most above min(q0, k's measure) is made. 1 when made. */
int prog_joint_swap_move(joint *J, double *xy, int64_t i, double q0, double rho, int tries)
{
    const prog_buckets *B = &J->B;
    const double xi = xy[2 * i], yi = xy[2 * i + 1];
    int64_t wx, wy, cand[64];
    int nc = 0;
    const int64_t span = prog_buckets_window(B, prog_buckets_of(B, xi, yi), (int64_t)ceil(rho / B->cs), &wx, &wy);
    for (int64_t oy = 0; oy < span; oy++)
        for (int64_t ox = 0; ox < span; ox++)
            for (int64_t k = prog_buckets_first(B, wx + ox, wy + oy); k >= 0 && nc < tries && nc < 64; k = B->next[k])
                if (J->lev[k] != J->lev[i] && prog_torus_d2(xi, yi, xy[2 * k], xy[2 * k + 1]) < rho * rho)
                    cand[nc++] = k;
    double gain = 0;
    int64_t best = -1;
    for (int c = 0; c < nc; c++) {
        const int64_t k = cand[c];
        const double xk = xy[2 * k], yk = xy[2 * k + 1];
        int64_t bk;
        const double qk = prog_joint_measure_at(J, k, xk, yk, &bk, -INFINITY);
        if (qk < 0) continue;
        const double base = fmin(q0, qk);
        const double q = two_point_score(J, xy, i, xk, yk, k, xi, yi, base);
        if (q > base && q - base > gain) gain = q - base, best = k;
    }
    if (best < 0) return 0;
    const double xk = xy[2 * best], yk = xy[2 * best + 1];
    prog_joint_place(J, xy, best, xi, yi);
    prog_joint_place(J, xy, i, xk, yk);
    return 1;
}
