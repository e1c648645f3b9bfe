/* engine3_step.c - one iteration of CFPO on the unit 3-torus: the grid
 * shift, the 27 colour phases, each cell's points solved in id order
 * against their 3x3x3 block, the moves, the statistics (docs/method.md,
 * "Three dimensions").
 *
 * The margin: e = L - max(delta(X), 0.7 Delta3), delta(X) rounded up by
 * 1e-9; per point min(e, L - t), t = r0 + tol L, r0 the distance from x to
 * Y(x); a point with t >= 1.5 L stays. A move is taken only when the new
 * spot is farther than t from every point of the block (checked by brute
 * force on the block, whatever the solver says), so delta(X) never falls
 * and the sorted nearest-neighbour distances rise with every move.
 *
 * On several ranks (engine3_dist.h) a rank solves its brick's cells of
 * each colour, sends the phase's moves to its neighbours before the next
 * colour, and migrates points at a new grid shift; the counts and maxima
 * are reduced over ranks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "engine3_dist.h"
#include "state3.h"
#include "omp_compat.h"
#include "solve3.h"
#include "stoprule.h"

/* The Voronoi cells the solve searches: in the near phase the first of
 * Y(x) by distance to x (the cell x lies in; two cells in iterations 1-6,
 * as in 2-D, cost 1.4x the time to delta_min 0.90 for the same number of
 * iterations at 65,536 points); after it (0) all of them. */
static int near_cells(int near)
{
    return near ? 1 : 0;
}

/* Over-relaxation weights: iterations 4-19 first / second, then from 20. */
static void relax_weights(int k, double w[2])
{
    if (k < 4) w[0] = w[1] = 0.0;
    else if (k < 20) w[0] = 3.0, w[1] = 1.8;
    else w[0] = 1.8, w[1] = 1.4;
}

typedef struct {
    double *y;      /* 3 cap: gathered block, u-frame unwrapped */
    int64_t *id;
    double *rel;    /* 3 cap: Y relative to x, hint order */
    int *ord;
    double *key;
    int cap;
    cfpo3_poly poly[2];
    cfpo3_solve_count cnt;
    cfpo3_move_list mv; /* several ranks: this thread's moves */
} scratch3;

static int scratch_grow(scratch3 *w, int need)
{
    if (need <= w->cap) return 0;
    int cap = need * 2 + 64;
    double *y = realloc(w->y, sizeof(double) * 3 * (size_t)cap);
    if (!y) return -1;
    w->y = y;
    int64_t *id = realloc(w->id, sizeof(int64_t) * (size_t)cap);
    if (!id) return -1;
    w->id = id;
    double *rel = realloc(w->rel, sizeof(double) * 3 * (size_t)cap);
    if (!rel) return -1;
    w->rel = rel;
    int *ord = realloc(w->ord, sizeof(int) * (size_t)cap);
    if (!ord) return -1;
    w->ord = ord;
    double *key = realloc(w->key, sizeof(double) * (size_t)cap);
    if (!key) return -1;
    w->key = key;
    w->cap = cap;
    return 0;
}

static double min_d2(const double *rel, int m, const double c[3])
{
    double best = INFINITY;
    for (int j = 0; j < m; j++) {
        const double dx = c[0] - rel[3 * j], dy = c[1] - rel[3 * j + 1], dz = c[2] - rel[3 * j + 2];
        const double d = dx * dx + dy * dy + dz * dz;
        if (d < best) best = d;
    }
    return best;
}

static int inside(const double c[3], const double lo[3], const double hi[3])
{
    return c[0] >= lo[0] && c[0] <= hi[0] && c[1] >= lo[1] && c[1] <= hi[1] && c[2] >= lo[2] && c[2] <= hi[2];
}

typedef struct {
    int64_t moved, solved;
    double max_move;
    int crossed, fail;
} cell_result;

/* Solves cell (ci, cj, ck) in phase `ph`. */
static void solve_cell(cfpo3_engine *e, int ci, int cj, int ck, double emargin, int force, uint64_t ph,
                       const double w[2], int cells, scratch3 *s, cell_result *r)
{
    const int g = e->G.g;
    const double L = e->G.L, tolL = e->o.tol * L;
    const int64_t c = ((int64_t)ck * g + cj) * g + ci;
    if (!force && e->o.skip && e->solvedat[c] != 0 && emargin >= e->needm[c]) {
        int changed = 0;
        for (int dz = -1; dz <= 1 && !changed; dz++)
            for (int dy = -1; dy <= 1 && !changed; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    const int64_t cc = ((int64_t)((ck + dz + g) % g) * g + (cj + dy + g) % g) * g + (ci + dx + g) % g;
                    if (e->changed[cc] >= e->solvedat[c]) {
                        changed = 1;
                        break;
                    }
                }
        if (!changed) return;
    }
    if (e->cstart[c + 1] == e->cstart[c]) { /* empty cell: nothing to move */
        e->solvedat[c] = ph;
        e->needm[c] = -INFINITY;
        return;
    }
    /* gather the block: cells z, y, x from -1 to 1, points by id */
    int cnt = 0, own0 = -1, own1 = -1;
    for (int dz = -1; dz <= 1; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int a = ci + dx, b = cj + dy, d = ck + dz;
                const int aw = (a + g) % g, bw = (b + g) % g, dw = (d + g) % g;
                const double ox = a < 0 ? -1.0 : (a >= g ? 1.0 : 0.0);
                const double oy = b < 0 ? -1.0 : (b >= g ? 1.0 : 0.0);
                const double oz = d < 0 ? -1.0 : (d >= g ? 1.0 : 0.0);
                const int64_t cc = ((int64_t)dw * g + bw) * g + aw;
                const int64_t k0 = e->cstart[cc], k1 = e->cstart[cc + 1];
                if (scratch_grow(s, cnt + (int)(k1 - k0)) != 0) {
                    r->fail = 1;
                    return;
                }
                if (cc == c) own0 = cnt, own1 = cnt + (int)(k1 - k0);
                for (int64_t k = k0; k < k1; k++) {
                    const int64_t id = e->cids[k];
                    const double *x = e->pos + 3 * id;
                    s->y[3 * cnt] = cfpo3_u(x[0], e->shift[0]) + ox;
                    s->y[3 * cnt + 1] = cfpo3_u(x[1], e->shift[1]) + oy;
                    s->y[3 * cnt + 2] = cfpo3_u(x[2], e->shift[2]) + oz;
                    s->id[cnt] = id;
                    cnt++;
                }
            }
    const double clo[3] = {ci * L, cj * L, ck * L}, chi[3] = {(ci + 1) * L, (cj + 1) * L, (ck + 1) * L};
    double need = -INFINITY;
    for (int p = own0; p < own1; p++) {
        const double *x = s->y + 3 * p;
        /* Y relative to x, in the hint order: all of it sorted by distance
         * to x (stable) for the exact solve; for the near solve only the
         * cells it searches first (nearest, then lowest place), the others
         * after them in block order */
        int m = 0;
        if (cells > 0) {
            for (int q = 0; q < cnt; q++) {
                if (q == p) continue;
                const double dx = s->y[3 * q] - x[0], dy = s->y[3 * q + 1] - x[1], dz = s->y[3 * q + 2] - x[2];
                s->key[m] = dx * dx + dy * dy + dz * dz;
                s->ord[m++] = q;
            }
            for (int k = 0; k < cells && k < m; k++) { /* selection: the k-th nearest to place k */
                int b = k;
                for (int q = k + 1; q < m; q++)
                    if (s->key[q] < s->key[b] || (s->key[q] == s->key[b] && s->ord[q] < s->ord[b])) b = q;
                if (b != k) { /* the ones between shift up one: block order kept */
                    const double kb = s->key[b];
                    const int ob = s->ord[b];
                    for (int q = b; q > k; q--) s->key[q] = s->key[q - 1], s->ord[q] = s->ord[q - 1];
                    s->key[k] = kb, s->ord[k] = ob;
                }
            }
        } else {
            for (int q = 0; q < cnt; q++) {
                if (q == p) continue;
                const double dx = s->y[3 * q] - x[0], dy = s->y[3 * q + 1] - x[1], dz = s->y[3 * q + 2] - x[2];
                const double d = dx * dx + dy * dy + dz * dz;
                int at = m;
                while (at > 0 && s->key[at - 1] > d) {
                    s->key[at] = s->key[at - 1];
                    s->ord[at] = s->ord[at - 1];
                    at--;
                }
                s->key[at] = d;
                s->ord[at] = q;
                m++;
            }
        }
        for (int k = 0; k < m; k++) {
            const int q = s->ord[k];
            s->rel[3 * k] = s->y[3 * q] - x[0];
            s->rel[3 * k + 1] = s->y[3 * q + 1] - x[1];
            s->rel[3 * k + 2] = s->y[3 * q + 2] - x[2];
        }
        if (m == 0) continue;
        const double t = sqrt(s->key[0]) + tolL;
        if (t >= 1.5 * L) continue;
        if (L - t > need) need = L - t;
        const double ex = emargin < L - t ? emargin : L - t;
        double lo[3], hi[3];
        for (int a = 0; a < 3; a++) {
            lo[a] = clo[a] - ex - x[a];
            hi[a] = chi[a] + ex - x[a];
        }
        double best[3];
        r->solved++;
        /* a block beyond the solver's capacity (possible only from a given
         * start, whose cells hold at most CFPO3_INIT_MAX_CELL points): the
         * solve sees x's nearest CFPO3_MAXM; the check below reads the
         * whole block, so a move is still safe, only perhaps not the best */
        const int ms = m < CFPO3_MAXM ? m : CFPO3_MAXM;
        if (cfpo3_near_solve(s->rel, ms, cells > 0 ? cells : ms, lo, hi, t * t, best, s->poly, &s->cnt) < 0.0)
            continue;
        if (!(inside(best, lo, hi) && min_d2(s->rel, m, best) > t * t)) continue;
        double go[3] = {best[0], best[1], best[2]};
        for (int k = 0; k < 2 && w[k] > 0.0; k++) {
            const double cand[3] = {w[k] * best[0], w[k] * best[1], w[k] * best[2]};
            if (inside(cand, lo, hi) && min_d2(s->rel, m, cand) > t * t) {
                go[0] = cand[0], go[1] = cand[1], go[2] = cand[2];
                break;
            }
        }
        /* move: u-frame, then back onto the torus */
        const int64_t id = s->id[p];
        double *xp = e->pos + 3 * id;
        int cell[3];
        double nu[3];
        for (int a = 0; a < 3; a++) {
            nu[a] = x[a] + go[a];
            double uw = nu[a];
            if (uw < 0.0) uw += 1.0;
            else if (uw >= 1.0) uw -= 1.0;
            if (uw >= 1.0) uw = 0.0;
            double xv = uw + e->shift[a];
            if (xv >= 1.0) xv -= 1.0;
            if (xv >= 1.0 || xv < 0.0) xv = 0.0;
            xp[a] = xv;
            cell[a] = cfpo3_cell1(cfpo3_u(xv, e->shift[a]), g);
        }
        const double mv = sqrt(go[0] * go[0] + go[1] * go[1] + go[2] * go[2]) / L;
        if (mv > r->max_move) r->max_move = mv;
        s->y[3 * p] = nu[0], s->y[3 * p + 1] = nu[1], s->y[3 * p + 2] = nu[2];
        const int32_t nc = (int32_t)(((int64_t)cell[2] * g + cell[1]) * g + cell[0]);
        if (e->dist && cfpo3_dist_note(&s->mv, id, (int32_t)c, nc, xp, e->prev + 3 * id) != 0) r->fail = 1;
        e->changed[c] = ph;
        if (nc != e->cellof[id]) {
            e->changed[nc] = ph;
            e->cellof[id] = nc;
            r->crossed = 1;
        }
        r->moved++;
    }
    e->solvedat[c] = ph;
    e->needm[c] = need;
}

int cfpo3_step(cfpo3_engine *e, cfpo_iter_stats *st)
{
    const double t0 = omp_get_wtime();
    const int k = e->iter + 1, g = e->G.g;
    const double L = e->G.L;
    int force = 0;
    double s[3];
    cfpo3_shift_for(e, k, s);
    if (s[0] != e->shift[0] || s[1] != e->shift[1] || s[2] != e->shift[2]) {
        memcpy(e->shift, s, sizeof s);
        if (e->dist) { /* points go to the bricks of their new cells */
            if (cfpo3_dist_migrate(e) != 0) return -1;
            cfpo3_rebucket(e);
        } else {
            cfpo3_assign(e);
        }
        force = 1;
    }
    memcpy(e->prev, e->pos, sizeof(double) * 3 * (size_t)e->n);
    double dX = e->dmin * e->G.delta3 * (1.0 + 1e-9);
    if (dX < 0.7 * e->G.delta3) dX = 0.7 * e->G.delta3;
    const double emargin = L - dX;
    double w[2] = {0.0, 0.0};
    if (e->o.relax) relax_weights(k, w);
    const int near = e->near, cells = near_cells(near);
    int64_t moved = 0, solved = 0;
    double max_move = 0.0;
    int fail = 0;
    /* this rank's brick: cells [lo, hi) along each axis */
    const cfpo3_bricks *B = &e->B;
    int lo[3], hi[3];
    for (int ax = 0; ax < 3; ax++) lo[ax] = B->lo[ax][B->me[ax]], hi[ax] = B->lo[ax][B->me[ax] + 1];
    const int nth = e->o.threads > 0 ? e->o.threads : omp_get_max_threads();
    int order[27], off[3];
    cfpo3_colours_for(e, k, order, off);
    for (int ci = 0; ci < 27; ci++) {
        const int colour = order[ci];
        const int col[3] = {colour % 3, (colour / 3) % 3, colour / 9};
        /* the brick's cells of this colour ((c + off) % 3 == col): first[ax] + 3 t, t < cnt[ax] */
        int first[3], cnt[3];
        for (int ax = 0; ax < 3; ax++) {
            first[ax] = lo[ax] + ((col[ax] - off[ax] - lo[ax]) % 3 + 6) % 3;
            cnt[ax] = first[ax] < hi[ax] ? (hi[ax] - first[ax] + 2) / 3 : 0;
        }
        const int nx = cnt[0], ny = cnt[1], per = cnt[0] * cnt[1] * cnt[2];
        const uint64_t ph = ++e->phase;
        int crossed = 0;
        const double tc = omp_get_wtime();
#pragma omp parallel num_threads(nth) reduction(+ : moved, solved) reduction(max : max_move) \
    reduction(| : crossed, fail)
        {
            scratch3 sc;
            memset(&sc, 0, sizeof sc);
#pragma omp for schedule(dynamic, 8)
            for (int q = 0; q < per; q++) {
                const int ci = first[0] + 3 * (q % nx), cj = first[1] + 3 * ((q / nx) % ny),
                          ck = first[2] + 3 * (q / (nx * ny));
                cell_result r = {0, 0, 0.0, 0, 0};
                solve_cell(e, ci, cj, ck, emargin, force, ph, w, cells, &sc, &r);
                moved += r.moved;
                solved += r.solved;
                if (r.max_move > max_move) max_move = r.max_move;
                crossed |= r.crossed;
                fail |= r.fail;
            }
            if (sc.mv.len > 0) {
#pragma omp critical(cfpo3_moves)
                for (int64_t q = 0; q < sc.mv.len && !fail; q++) {
                    const cfpo3_move *m = &sc.mv.v[q];
                    if (cfpo3_dist_note(&e->mv, m->id, m->from, m->to, m->x, m->p0) != 0) fail = 1;
                }
            }
            free(sc.y), free(sc.id), free(sc.rel), free(sc.ord), free(sc.key), free(sc.mv.v);
#pragma omp atomic
            e->count.cells += sc.cnt.cells;
#pragma omp atomic
            e->count.tests += sc.cnt.tests;
#pragma omp atomic
            e->count.cuts += sc.cnt.cuts;
        }
        e->t_compute += omp_get_wtime() - tc;
        e->phases++;
        if (e->dist) {
            if (comm_all(!fail) == 0 || cfpo3_dist_halo(e, ph, &crossed) != 0) return -1;
        } else if (fail) {
            return -1;
        }
        if (crossed) cfpo3_rebucket(e);
    }
    double max_disp = 0.0;
#pragma omp parallel for num_threads(nth) reduction(max : max_disp) schedule(static)
    for (int64_t i = 0; i < e->n; i++) {
        if (e->cellof[i] < 0) continue;
        const int64_t c = e->cellof[i];
        if (!cfpo3_bricks_mine(B, (int)(c % g), (int)((c / g) % g), (int)(c / ((int64_t)g * g)))) continue;
        double d2 = 0.0;
        for (int a = 0; a < 3; a++) {
            double d = e->pos[3 * i + a] - e->prev[3 * i + a];
            if (d > 0.5) d -= 1.0;
            else if (d < -0.5) d += 1.0;
            d2 += d * d;
        }
        if (d2 > max_disp) max_disp = d2;
    }
    max_disp = sqrt(max_disp) / L;
    int64_t counts[2] = {moved, solved};
    double maxes[2] = {max_disp, max_move};
    comm_sum_i64(counts, 2);
    comm_max_d(maxes, 2);
    moved = counts[0], solved = counts[1], max_disp = maxes[0], max_move = maxes[1];
    if (cfpo3_remeasure(e) != 0) return -1;
    e->iter = k;
    memset(st, 0, sizeof *st);
    st->iteration = k;
    st->delta_min = e->dmin;
    st->delta_avg = e->davg;
    st->moved = moved;
    st->solved = solved;
    st->max_disp = max_disp;
    st->max_move = max_move;
    /* the near phase ends with its first sweep that moves no point by tol
     * L: the next iteration solves every cell exactly (the stamps are
     * cleared, since a stamp says "the near solve keeps it") */
    const int still = cfpo_net_converged(moved, max_disp, e->o.tol);
    if (near && still) {
        e->near = 0;
        memset(e->solvedat, 0, sizeof(uint64_t) * (size_t)g * g * g);
    }
    st->near = near;
    st->converged = near ? 0 : still;
    st->seconds = omp_get_wtime() - t0;
    comm_max_d(&st->seconds, 1);
    return 0;
}
