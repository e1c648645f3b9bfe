/* dens_cell.c - layer 3: one cell's solves under a density: each point
 * of the cell in id order, its old value, its neighbours, the candidate
 * (dens_solve.h) and the accept rule (dens_engine.h, docs/method.md
 * "Density"). */
#include <math.h>
#include <stdlib.h>

#include "dens_impl.h"
#include "dens_order.h"
#include "dens_scan.h"
#include "dens_solve.h"
#include "policy.h"
#include "geom.h"

static int grow_ring(tbuf *b, size_t need)
{
    free(b->ring);
    b->ring = malloc(need * sizeof *b->ring);
    b->ring_cap = b->ring ? need : 0;
    return b->ring ? 0 : -1;
}

/* What bounds the points a ring scan leaves out, for spot_ok. */
typedef struct {
    int wrap;          /* the block spans the torus: differences wrap */
    double qlo, h;     /* the block's smallest q; a bucket's side */
    double lo, L;      /* sqrt(rho_min); the cell side */
    int n;             /* the block's points */
    int vec;           /* one bucket clear of the wrap, the AVX-512 route: dens_scan.h */
    int nt;            /* levels (dens_levels.h): the outside bound's tiers, 0 for the one grid's bound */
    const double *tq;  /* their q */
} scan_limits;

/* Whether (px, py) (block frame) may take point p: f there (q = rc) is
 * above thr against every other point of the block (rings of buckets
 * around it until the points left cannot reach thr: the same decision as
 * against every point), no point outside the block can be nearer in f
 * than the old value (their distance is at least the spot's distance e
 * to the block's edge, their density at least rho_min), and it lies in
 * cell `cell`. Then *cc its bucket and (*x, *y) its place on the torus;
 * else *viol the block index of a point that is too near, if one is. */
static int spot_ok(const cfpo_dens_engine *E, tbuf *b, cfpo_dens_buckets *bk, int p, const scan_limits *m, double thr,
                   double oldf, double ox, double oy, double px, double py, double rc, int64_t cell, int *cc, double *x,
                   double *y, int *viol)
{
    const int c0 = cfpo_dens_bucket_of(bk, px, py);
    /* the block's arrays and the flag in locals (spot_ok writes none of them) */
    const double *restrict bx = b->bx, *restrict by = b->by, *restrict br = b->br;
    const int *restrict head = bk->head, *restrict next = bk->next;
    const int *ring = b->ring; /* written by cfpo_dens_ring each ring */
    const int wrap = m->wrap;
    *viol = -1;
    /* a block of one bucket clear of the wrap: its points eight at a
     * time where the CPU has the AVX-512 route (dens_scan.h; the same
     * first point as the bucket's list in order) */
    const int fast = m->vec ? cfpo_dens_scan_block(bx, by, br, m->n, p, px, py, rc, thr) : -2;
    if (fast >= 0) {
        *viol = fast;
        return 0;
    }
    for (int k = 0; fast == -2; k++) {
        if (k > 1 && m->qlo > 0) {
            const double e = (double)(k - 1) * m->h;
            if (e * e * m->qlo * rc > thr * BOUND_SAFE) break;
        }
        const int nb = cfpo_dens_ring(bk, c0, k, b->ring);
        if (nb < 0) break;
        for (int r = 0; r < nb; r++)
            for (int j = head[ring[r]]; j >= 0; j = next[j]) {
                if (j == p) continue;
                double ex = bx[j] - px, ey = by[j] - py;
                if (wrap) { ex -= rint(ex); ey -= rint(ey); }
                if (!((ex * ex + ey * ey) * br[j] * rc > thr)) {
                    *viol = j;
                    return 0;
                }
            }
    }
    if (!m->wrap) {
        const double e = fmin(fmin(px + m->L, 2 * m->L - px), fmin(py + m->L, 2 * m->L - py));
        if (m->nt ? !cfpo_dens_levels_clear(m->tq, m->nt, m->lo, m->L, e, rc, oldf) : !(e * e * m->lo * rc >= oldf))
            return 0;
    }
    *x = cfpo_wrap01(ox + px);
    *y = cfpo_wrap01(oy + py);
    if (cell_of(E, *x, *y) != cell) return 0; /* rounding left the cell */
    *cc = c0;
    return 1;
}

/* The block's points j != p that the buckets (fx.., fy..) hold with
 * d^2 q_j < T, by (d^2 q_j, j): the KMAX smallest, in order, into
 * b->scratch (keys) and b->nj. Returns their count. They are gathered
 * first (b->ck, b->cj: room for the whole block), with no branch on
 * whether each is in reach, and then placed in order (dens_order.h:
 * by insertion, or by counting each one's place in 8-lane compares where
 * the CPU has the AVX-512 route). The list depends on the set alone. */
static int nearest_in_reach(tbuf *b, const cfpo_dens_buckets *bk, int p, double ax, double ay, double T, int wrap,
                            int fx, int nx_, int fy, int ny_)
{
    /* the loop's arrays in locals: the stores to the list do not make the
     * compiler load them again */
    const double *restrict px_ = b->bx, *restrict py_ = b->by, *restrict pr_ = b->br;
    const int *restrict head = bk->head, *restrict next = bk->next;
    double *restrict key = b->scratch, *restrict ck = b->ck, *restrict cj = b->cj;
    int *restrict nj = b->nj;
    const int B = bk->B;
    int cnt = 0;
    for (int iy = 0; iy < ny_; iy++) {
        const int ry = fy + iy < B ? fy + iy : fy + iy - B;
        for (int ix = 0; ix < nx_; ix++) {
            const int c = ry * B + (fx + ix < B ? fx + ix : fx + ix - B);
            for (int j = head[c]; j >= 0; j = next[j]) {
                double ex = px_[j] - ax, ey = py_[j] - ay;
                if (wrap) { ex -= rint(ex); ey -= rint(ey); }
                const double d2 = (ex * ex + ey * ey) * pr_[j];
                /* written always, kept when in reach: no branch to
                 * mispredict (the block's room holds one more) */
                ck[cnt] = d2;
                cj[cnt] = (double)j;
                cnt += (d2 < T) & (j != p);
            }
        }
    }
    return cfpo_dens_order_fast(ck, cj, cnt, KMAX, key, nj);
}

/* Solves the points of cell (cx, cy) one after another; returns the moves
 * made, the largest move (in local spacings) into *maxd. */
int64_t dens_solve_cell(cfpo_dens_engine *E, tbuf *b, int64_t cx, int64_t cy, double *maxd)
{
    const int64_t g = E->g;
    const double L = E->L, ox = (double)cx * L + E->sx, oy = (double)cy * L + E->sy;
    const int wrap = g < 6; /* the block spans the torus: differences wrap */
    const int levels = E->lv.n > 1;
    int m = 0, c0 = 0, c1 = 0;
    double qlo = INFINITY, qbl = 0; /* the block's smallest and largest q, taken in its gather */
    /* the pixels every spot evaluated here lies on (each box S is clipped
     * to the cell), asked for before the block's gather and ranking */
    cfpo_density_prefetch_box(E->d, cfpo_wrap01(ox), cfpo_wrap01(oy), L);
    /* the block clear of the torus's seam: with one grid the offset is
     * under a cell, so the seam lies in cell g - 1; a finer level's seam
     * may lie further in (its cells take level 0's offset), and the block
     * keeps a cell away from it */
    const int clear = levels ? cx >= 1 && cy >= 1 && (double)(cx + 3) * L + E->sx <= 1 && (double)(cy + 3) * L + E->sy <= 1
                             : cx >= 1 && cx <= g - 3 && cy >= 1 && cy <= g - 3;
    if (!wrap && clear) {
        /* a block clear of the grid's seam (cells 1..g-2, none wrapped;
         * cell g-1 straddles x = 1 + sx): each row's three cells are one
         * run of slots, and each point's offset from its cell's centre is
         * under 0.5, so the rint below is 0 and the offset is u itself:
         * the same points in the same order, the same bits */
        for (int dy = -1; dy <= 1; dy++) {
            const int64_t row = (cy + dy) * g + cx;
            const int64_t s0 = E->cstart[row - 1], s1 = E->cstart[row + 2];
            if (dy == 0) {
                c0 = m + (int)(E->cstart[row] - s0);
                c1 = m + (int)(E->cstart[row + 1] - s0);
            }
            for (int64_t s = s0; s < s1; s++) {
                const double *r = E->cxyq + 3 * s; /* the store's x, y, q of point cidx[s] */
                b->bx[m] = r[0] - ox;
                b->by[m] = r[1] - oy;
                b->br[m] = r[2];
                b->bid[m] = E->cidx[s];
                b->bslot[m] = s;
                if (r[2] < qlo) qlo = r[2];
                if (r[2] > qbl) qbl = r[2];
                m++;
            }
        }
    } else {
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int64_t c = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                if (dx == 0 && dy == 0) c0 = m;
                const double mx = ((double)dx + 0.5) * L, my = ((double)dy + 0.5) * L;
                for (int64_t s = E->cstart[c]; s < E->cstart[c + 1]; s++) {
                    const double *r = E->cxyq + 3 * s;
                    double u = r[0] - ox, v = r[1] - oy;
                    b->bx[m] = u - rint(u - mx);
                    b->by[m] = v - rint(v - my);
                    b->br[m] = r[2];
                    b->bid[m] = E->cidx[s];
                    b->bslot[m] = s;
                    if (r[2] < qlo) qlo = r[2];
                    if (r[2] > qbl) qbl = r[2];
                    m++;
                }
                if (dx == 0 && dy == 0) c1 = m;
            }
    }
    const double lo = sqrt(E->d->rho_min), rmax = E->D / lo, hi = L * (1 - 1e-9);
    /* the block's buckets (one for a small block); its smallest q bounds
     * the measure of the points a ring scan leaves out */
    cfpo_dens_buckets *bk = &b->bk;
    if (cfpo_dens_buckets_build(bk, b->bx, b->by, m, -L, -L, 3 * L, wrap, m < BUCKET_FROM ? (double)m + 1 : BUCKET_PER) != 0
        || ((size_t)(8 * bk->B + 1) > b->ring_cap && grow_ring(b, (size_t)(8 * bk->B + 1)) != 0)) {
        b->oom = 1;
        return 0;
    }
    /* the near solve (policy.h): where q is nearly flat over the block,
     * the uniform path's; across a steeper change the nearest two
     * polygons first, then all of them when those give no move (fall: the
     * polygons a near solve that gives no move goes on to, 0: none) */
    int fall;
    const int cells0 = cfpo_policy_density_near(E->iter, qlo, qbl, DENS_CELLS, &fall);
    const double h = bk->h, gain = E->o.tol * E->D;
    /* a block of one bucket clear of the wrap on the AVX-512 route: its
     * neighbours and accept checks eight points at a time (dens_order.h,
     * dens_scan.h) */
    const int vec = bk->B == 1 && !wrap && cfpo_dens_route() == 2;
    double tq[CFPO_DENS_TIERS];
    const int nt = levels && !wrap ? cfpo_dens_levels_tiers(&E->lv, E->cur, cx, cy, tq) : 0;
    const scan_limits lim = {wrap, qlo, h, lo, L, m, vec, nt, tq};
    int64_t moves = 0;
    /* the largest q over the cell: every box S below is clipped to the
     * cell, so this bounds q at every spot a solve evaluates, as the
     * bound over S itself did (it only prunes: the same vertex, the same
     * bits; dens_qbound.h). Where the levels size the cells (1.25-2.5
     * local spacings) S, two spacings wide, covers most of its cell, so
     * the bound is about as tight, for one query a cell instead of one a
     * point (docs/method.md, "The solve's work") */
    const double qcell = cfpo_dens_qbound_box(&E->qb, ox, oy, ox + hi, oy + hi);
    for (int p = c0; p < c1; p++) {
        if (levels && E->lev[b->bid[p]] != E->cur) continue; /* another level's point: a neighbour only */
        const double ax = b->bx[p], ay = b->by[p], ra = b->br[p];
        const double ri = ra > 0 ? E->D / ra : rmax;
        /* neighbours by their weight in the measure, d^2 q_j, up to what a
         * neighbour of the point's own density at REACH spacings weighs */
        const double T = REACH * REACH * ri * ri * (ra > 0 ? ra : lo);
        /* the KMAX nearest in the measure (smallest d^2 q_j) within T,
         * nearest first (ties: block order), from the buckets that cover
         * the reach: d^2 q_j < T needs d < sqrt(T / qlo). Ordered by
         * distance alone, a sparse point beside a dense region (1:16 at a
         * million points on the image) saw only the dense side's points
         * and never moved */
        int kk = 0, fx, nx_, fy, ny_;
        double R = sqrt(T / qlo);
        if (ra > 2 * qlo) {
            /* a point of a dense part of a high-contrast block: a winner
             * within R has q_j at least the smallest q over the box of
             * half-side R around the point (dens_qbound.h), so the reach
             * shrinks to what that q allows; the same neighbours */
            const double ql = cfpo_dens_qbound_box(&E->qlow, ox + ax - R, oy + ay - R, ox + ax + R, oy + ay + R);
            if (ql > qlo) R = sqrt(T / ql) * BOUND_SAFE;
        }
        cfpo_dens_span(bk, ax - R, ax + R, bk->x0, &fx, &nx_);
        cfpo_dens_span(bk, ay - R, ay + R, bk->y0, &fy, &ny_);
        kk = vec ? cfpo_dens_order_block(b->bx, b->by, b->br, m, p, ax, ay, T, KMAX, b->scratch, b->nj) : -1;
        if (kk < 0) kk = nearest_in_reach(b, bk, p, ax, ay, T, wrap, fx, nx_, fy, ny_);
        for (int t = 0; t < kk; t++) { /* their places, as the scan computed them */
            const int j = b->nj[t];
            double ex = b->bx[j] - ax, ey = b->by[j] - ay;
            if (wrap) { ex -= rint(ex); ey -= rint(ey); }
            b->nx[t] = ax + ex; b->ny[t] = ay + ey; b->nr[t] = b->br[j];
        }
        const int cp = cfpo_dens_bucket_of(bk, ax, ay);
        /* old: the smallest d^2 q_j over the block. The scan above saw
         * every point with d^2 q_j < T, so when it found one its first key
         * is that smallest value (the same expression, bit for bit); else
         * rings of buckets around the point until the points left are too
         * far to go below it */
        const int seen = kk > 0 && b->scratch[0] < T * (1 - 1e-9); /* clear of the reach's rounding */
        double old = seen ? b->scratch[0] : INFINITY;
        for (int k = 0; !seen; k++) {
            if (k > 1 && qlo > 0) {
                const double e = (double)(k - 1) * h;
                if (e * e * qlo >= old * BOUND_SAFE) break;
            }
            const int nb = cfpo_dens_ring(bk, cp, k, b->ring);
            if (nb < 0) break;
            for (int r = 0; r < nb; r++)
                for (int j = bk->head[b->ring[r]]; j >= 0; j = bk->next[j]) {
                    if (j == p) continue;
                    double ex = b->bx[j] - ax, ey = b->by[j] - ay;
                    if (wrap) { ex -= rint(ex); ey -= rint(ey); }
                    const double v = (ex * ex + ey * ey) * b->br[j];
                    if (v < old) old = v;
                }
        }
        const double oldf = old * ra;
        cfpo_square S = {ax - ri, ay - ri, ax + ri, ay + ri};
        if (S.x0 < 0) S.x0 = 0;
        if (S.y0 < 0) S.y0 = 0;
        if (S.x1 > hi) S.x1 = hi;
        if (S.y1 > hi) S.y1 = hi;
        double cxp, cyp, fc;
        /* the near solve's polygons first; all of them when those give no
         * move (and `fall`), the search going on from the polygons it has
         * done (`from`: the same vertex as searching them all again) */
        int cells = cells0, from = 0;
    solve:
        if (!cfpo_dens_solve_from(b->nx, b->ny, b->nr, kk, from, cells, S, E->d, qcell, ox, oy, oldf, &cxp, &cyp, &fc,
                                  b->scratch + KMAX)) {
            if (cells < fall) { from = cells; cells = fall; goto solve; }
            continue;
        }
        /* a move must gain more than tol local spacings in the measure
         * (sqrt(f) / Delta), as the uniform path's must gain tol L; the
         * over-relaxed spots a + w (c - a) of the iteration's weights
         * first, in order (policy.h), where one passes the same rules,
         * else the candidate */
        const double thr = oldf * (1 + 1e-12);
        double rc = 0, x = 0, y = 0, wv[3];
        int cc = -1, viol;
        const int nw = cfpo_policy_density_relax(E->iter, wv);
        for (int q = 0; q < nw && cc < 0; q++) {
            const double rx = ax + wv[q] * (cxp - ax), ry = ay + wv[q] * (cyp - ay);
            if (!(rx >= S.x0 && rx <= S.x1 && ry >= S.y0 && ry <= S.y1)) continue;
            const double rr = cfpo_dens_local_q(E->d, ox, oy, rx, ry);
            const double fr = rr > 0 ? cfpo_dens_value(b->nx, b->ny, b->nr, kk, rr, rx, ry) : -1;
            if (rr > 0 && sqrt(fr) > sqrt(oldf) + gain && fr > thr &&
                spot_ok(E, b, bk, p, &lim, thr, oldf, ox, oy, rx, ry, rr, cy * g + cx, &cc, &x, &y, &viol)) {
                rc = rr;
                cxp = rx;
                cyp = ry;
            }
        }
        if (cc < 0) {
            if (!(sqrt(fc) > sqrt(oldf) + gain && fc > thr)) {
                if (cells < fall) { from = cells; cells = fall; goto solve; }
                continue;
            }
            rc = cfpo_dens_local_q(E->d, ox, oy, cxp, cyp);
            if (!(rc > 0)) continue;
            if (!spot_ok(E, b, bk, p, &lim, thr, oldf, ox, oy, cxp, cyp, rc, cy * g + cx, &cc, &x, &y, &viol)) {
                /* a point the solve did not look at is too near the
                 * candidate (the KMAX nearest in the measure can all lie
                 * on one side: a sparse point beside a dense edge sees
                 * only the edge's points and is refused every spot on
                 * its sparse side): add it and solve again */
                int listed = viol < 0 || kk >= KMAX + KADD;
                for (int t = 0; t < kk && !listed; t++) listed = b->nj[t] == viol; /* rounding: no new point */
                if (listed) continue;
                double ex = b->bx[viol] - ax, ey = b->by[viol] - ay;
                if (wrap) { ex -= rint(ex); ey -= rint(ey); }
                b->nx[kk] = ax + ex; b->ny[kk] = ay + ey; b->nr[kk] = b->br[viol];
                b->nj[kk++] = viol;
                from = 0; /* another neighbour: every polygon again */
                goto solve;
            }
        }
        const int64_t id = b->bid[p];
        if (levels) { /* every level's blocks around the old and the new place */
            const uint32_t f = cfpo_dens_levels_fine(&E->lv, x, y);
            cfpo_dens_levels_mark_fine(&E->lv, E->ltouch, E->phase, E->fine[id], f);
            E->fine[id] = f;
        }
        const double dd = sqrt((cxp - ax) * (cxp - ax) + (cyp - ay) * (cyp - ay)) / ri;
        if (dd > *maxd) *maxd = dd;
        cfpo_dens_buckets_move(bk, p, cp, cc);
        b->bx[p] = cxp;
        b->by[p] = cyp;
        b->br[p] = rc;
        E->s.xy[2 * id] = x;
        E->s.xy[2 * id + 1] = y;
        E->s.q[id] = rc;
        double *r = E->cxyq + 3 * b->bslot[p];
        r[0] = x;
        r[1] = y;
        r[2] = rc;
        moves++;
        if (E->on_move) E->on_move(E->s.xy, id, E->move_user);
    }
    return moves;
}
