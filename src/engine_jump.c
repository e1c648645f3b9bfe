/* engine_jump.c - the adaptive variant's hole jumps (docs/method.md).
 *
 * In the first iterations the set has holes beside crowded spots, and local
 * moves carry the excess across only slowly; FPO's early advantage is that
 * every move goes to the largest hole anywhere. So at the start of the
 * iterations JUMP_FIRST..JUMP_LAST (after the grid shift), the most crowded
 * points jump into the largest holes of their block of JUMP_BLOCK x
 * JUMP_BLOCK cells:
 *
 *  - every own cell offers its hole: the spot of the cell farthest from
 *    the points of its 3x3 block (LocalCFPO with S = the cell and nobody
 *    left out), of radius R, capped at L (a point beyond the block is at
 *    least L from the cell); and its worst point: the one nearest to the
 *    others of its block, at distance r;
 *  - every rank sends its first K candidates of each kind (K a function of
 *    n alone) and every rank sorts the union the same way: holes by R
 *    descending, then global cell; points by r ascending, then id. The
 *    first K of each list are then the same for any number of ranks;
 *  - block by block (blocks in row-major order, candidates in list order),
 *    the holes and points of a block are paired greedily: the next hole
 *    whose cell touches no cell of a hole already taken (so two landing
 *    spots are at least L apart) with the next point, until the block's
 *    first pair whose gain R - r is not above tol L;
 *  - from iteration JUMP_WIDE on, what the blocks left unpaired is paired
 *    again the same way within blocks twice as wide (8 x 8 cells), then
 *    16 x 16, and so on up to the whole torus, the leftovers back in list
 *    order each time; but a pair of these wider rounds is passed over if
 *    it would take the net count of points that the wider pairs of this
 *    iteration brought into (or took out of) any smaller block past
 *    JUMP_NET: the long jumps fill holes that have no crowded point near
 *    them without emptying or crowding a whole region, which the local
 *    moves would take hundreds of iterations to even out;
 *  - a paired point leaves its cell and lands at the hole, with its id,
 *    in the cell that holds the spot (a hole on the cell's upper or right
 *    edge belongs to the next cell).
 *
 * delta(X) cannot decrease: the jumper lands R from every point of the
 * hole's block (or farther: the departures only widen gaps), at least L
 * from every point beyond it and from every other landing spot, with
 * R > r >= its old distance to its nearest point; every other point only
 * loses neighbours or gains one at least R away. */
#include "cells.h"

#include <stdlib.h>
#include <string.h>

#include "geom.h"

#define JUMP_FIRST 2 /* the first iteration that starts with jumps */
#define JUMP_LAST 5  /* the last one */
#define JUMP_BLOCK 4   /* cells a side of the blocks that pair holes and points first */
#define JUMP_WIDE 3    /* from this iteration on, wider and wider blocks pair what is left */
#define JUMP_NET 2     /* the most points a wider pairing may bring into or take out of a block */
#define JUMP_SHARE 4   /* K = n / JUMP_SHARE candidates of each kind (at least 64) */
#define JUMP_SCALES 40 /* room for the block sizes JUMP_BLOCK * 2^k up to g */

typedef struct {
    double key;    /* -R for a hole, r for a point */
    uint64_t tie;  /* global cell of a hole, id of a point */
    double x, y;   /* landing spot, or the point's position */
    int64_t cell;  /* global cell */
} jcand;

typedef struct {
    int64_t cell; /* own cell of the arrival */
    uint64_t id;
    double x, y;
    float dq[2];
} jarrival;

static int cmp_cand(const void *a, const void *b)
{
    const jcand *p = a, *q = b;
    if (p->key != q->key) return p->key < q->key ? -1 : 1;
    return p->tie < q->tie ? -1 : (p->tie > q->tie);
}

static int cmp_arr(const void *a, const void *b)
{
    const jarrival *p = a, *q = b;
    if (p->cell != q->cell) return p->cell < q->cell ? -1 : 1;
    return p->id < q->id ? -1 : (p->id > q->id);
}

/* Worst point of own cell (lx, ly) (key INFINITY when it has none), or,
 * with floor2 >= 0, its hole (key 0 when none beats sqrt(floor2)). */
static jcand cell_candidate(const cfpo_engine *E, int64_t lx, int64_t ly, double *buf, double floor2)
{
    const double L = E->G.L;
    const int64_t c = ly * E->w + lx, cx = E->x0 + lx, cy = E->y0 + ly;
    const int64_t gc = cy * E->G.g + cx;
    const size_t mcap = E->scratch_m;
    double *xs = buf, *ys = buf + mcap, *sol = buf + 2 * mcap;
    int off = 0;
    const int m = eng_gather_block(E, lx, ly, xs, ys, &off);
    if (floor2 >= 0) {
        const double ox = (double)cx * L + E->G.shift, oy = (double)cy * L + E->G.shift;
        const cfpo_square S = {0, 0, L, L};
        double hx = 0.5 * L, hy = 0.5 * L;
        const double R2 = m ? cfpo_local_solve(xs, ys, m, -1, S, hx, hy, floor2, &hx, &hy, sol) : INFINITY;
        const double R = R2 > floor2 ? fmin(sqrt(R2), L) : 0;
        return (jcand){-R, (uint64_t)gc, cfpo_wrap01(hx + ox), cfpo_wrap01(hy + oy), gc};
    }
    jcand w = {INFINITY, 0, 0, 0, gc};
    const uint32_t s = E->start[c], e = E->start[c + 1];
    for (uint32_t k = 0; k < e - s; k++) {
        const int gi = off + (int)k;
        const double r = sqrt(cfpo_min_dist2(xs[gi], ys[gi], xs, ys, m, gi));
        if (r < w.key) w = (jcand){r, E->pid[s + k], E->px[s + k], E->py[s + k], gc};
    }
    return w;
}

/* The candidates of every own cell; nonzero ones (a worst point nearer
 * than L to its neighbours, a hole) packed at the front. */
static size_t candidates(const cfpo_engine *E, jcand *out, double floor2)
{
#pragma omp parallel for schedule(dynamic, 16) num_threads(E->nthreads)
    for (int64_t c = 0; c < E->cells; c++)
        out[c] = cell_candidate(E, c % E->w, c / E->w, E->scratch[omp_get_thread_num()], floor2);
    size_t n = 0;
    for (int64_t c = 0; c < E->cells; c++)
        if (floor2 >= 0 ? out[c].key < 0 : out[c].key < E->G.L) out[n++] = out[c];
    return n;
}

/* The first K of every rank's sorted candidates, merged and sorted the
 * same way on every rank: the first K of the union. */
static int merge_first(jcand *mine, size_t nmine, size_t K, jcand **all, size_t *nall)
{
    qsort(mine, nmine, sizeof *mine, cmp_cand);
    if (nmine > K) nmine = K;
    void *buf = NULL;
    size_t bytes = 0;
    if (comm_allgatherv(mine, nmine * sizeof *mine, &buf, &bytes) != 0) return -1;
    *all = buf;
    *nall = bytes / sizeof **all;
    if (*nall) qsort(*all, *nall, sizeof **all, cmp_cand);
    if (*nall > K) *nall = K;
    return 0;
}

static int touches_taken(const uint8_t *taken, int64_t g, int64_t cell)
{
    const int64_t cx = cell % g, cy = cell / g;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (taken[((cy + dy + g) % g) * g + (cx + dx + g) % g]) return 1;
    return 0;
}

/* Rebuilds the own cells without the departing slots and with the
 * arrivals (sorted by cell, then id), every cell in id order. */
static int rebuild(cfpo_engine *E, const uint8_t *gone, size_t ngone, jarrival *arr, size_t narr)
{
    const size_t nnew = (size_t)E->nloc - ngone + narr;
    if (eng_ensure_cap(E, nnew) != 0) return -1;
    float *dq = malloc((nnew ? nnew : 1) * 2 * sizeof *dq);
    if (!dq) return -1;
    size_t k = 0, a = 0;
    int maxcell = 0;
    for (int64_t c = 0; c < E->cells; c++) {
        const uint32_t s = E->start[c], e = E->start[c + 1];
        E->start[c] = (uint32_t)k;
        const size_t k0 = k;
        uint32_t i = s;
        while (i < e || (a < narr && arr[a].cell == c)) {
            const int take_old = i < e && !(a < narr && arr[a].cell == c && arr[a].id < E->pid[i]);
            if (take_old) {
                if (!gone[i]) {
                    E->tx[k] = E->px[i];
                    E->ty[k] = E->py[i];
                    E->tid[k] = E->pid[i];
                    dq[2 * k] = E->dq[2 * i];
                    dq[2 * k + 1] = E->dq[2 * i + 1];
                    k++;
                }
                i++;
            } else {
                E->tx[k] = arr[a].x;
                E->ty[k] = arr[a].y;
                E->tid[k] = arr[a].id;
                dq[2 * k] = arr[a].dq[0];
                dq[2 * k + 1] = arr[a].dq[1];
                k++;
                a++;
            }
        }
        if ((int)(k - k0) > maxcell) maxcell = (int)(k - k0);
    }
    E->start[E->cells] = (uint32_t)k;
    double *t = E->px; E->px = E->tx; E->tx = t;
    t = E->py; E->py = E->ty; E->ty = t;
    uint64_t *u = E->pid; E->pid = E->tid; E->tid = u;
    memcpy(E->dq, dq, k * 2 * sizeof *dq);
    free(dq);
    E->nloc = (int64_t)k;
    E->maxcell = maxcell;
    return eng_ensure_scratch(E);
}

int eng_jump_due(const cfpo_engine *E)
{
    return E->G.variant == CFPO_VARIANT_ADAPTIVE && E->cur >= JUMP_FIRST && E->cur <= JUMP_LAST;
}

/* Block of global cell c among blocks of s x s cells in row-major order
 * (nb a side; the last row and column may be narrower). */
static int64_t block_of(int64_t c, int64_t g, int64_t s, int64_t nb)
{
    return (c / g / s) * nb + (c % g) / s;
}

/* Sorts list a (n entries, in list order) stably by block into tmp, then
 * back; first[b] .. first[b + 1] is block b's range. */
static void by_block(jcand *a, jcand *tmp, size_t n, int64_t *first, int64_t g, int64_t s, int64_t nb)
{
    memset(first, 0, (size_t)(nb * nb + 1) * sizeof *first);
    if (n == 0) return; /* a may be NULL */
    for (size_t i = 0; i < n; i++) first[block_of(a[i].cell, g, s, nb) + 1]++;
    for (int64_t b = 0; b < nb * nb; b++) first[b + 1] += first[b];
    for (size_t i = 0; i < n; i++) tmp[first[block_of(a[i].cell, g, s, nb)]++] = a[i];
    memcpy(a, tmp, n * sizeof *a);
    for (int64_t b = nb * nb; b > 0; b--) first[b] = first[b - 1];
    first[0] = 0;
}

/* The block sizes: JUMP_BLOCK, twice that, ..., the last one g (the whole
 * torus), and for each the net count of points the round's wider pairs
 * brought into each block. */
typedef struct {
    int ns;
    int64_t s[JUMP_SCALES], nb[JUMP_SCALES];
    int *net[JUMP_SCALES];
} jscales;

/* Whether moving a point from cell pc to a hole in cell hc, in a pairing
 * of blocks of scale k, keeps every smaller block's net count within
 * JUMP_NET (the pair lies in one block of scale k and above). */
static int net_ok(const jscales *S, int k, int64_t g, int64_t hc, int64_t pc)
{
    for (int l = 0; l < k; l++) {
        const int64_t a = block_of(hc, g, S->s[l], S->nb[l]), b = block_of(pc, g, S->s[l], S->nb[l]);
        if (a != b && (S->net[l][a] >= JUMP_NET || S->net[l][b] <= -JUMP_NET)) return 0;
    }
    return 1;
}

static void net_add(jscales *S, int k, int64_t g, int64_t hc, int64_t pc)
{
    for (int l = 0; l < k; l++) {
        S->net[l][block_of(hc, g, S->s[l], S->nb[l])]++;
        S->net[l][block_of(pc, g, S->s[l], S->nb[l])]--;
    }
}

typedef struct {
    uint8_t *taken; /* global cells of the holes taken */
    uint8_t *gone;  /* own slots of the points that leave */
    size_t ngone;
    jarrival *arr; /* the points that land in own cells */
    size_t narr;
} jmoves;

/* Point p jumps to hole h: the owner of p's cell drops it, the owner of
 * h's cell receives it. */
static void jump_one(cfpo_engine *E, jmoves *M, const jcand *h, const jcand *p)
{
    const int64_t g = E->G.g;
    M->taken[h->cell] = 1;
    const double dx = h->x - p->x - nearbyint(h->x - p->x), dy = h->y - p->y - nearbyint(h->y - p->y);
    if (dx * dx + dy * dy > E->max_move) E->max_move = dx * dx + dy * dy;
    const int64_t plx = p->cell % g - E->x0, ply = p->cell / g - E->y0;
    if (plx >= 0 && plx < E->w && ply >= 0 && ply < E->h) {
        const int64_t c = ply * E->w + plx;
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++)
            if (E->pid[k] == p->tie) {
                M->gone[k] = 1;
                M->ngone++;
            }
    }
    /* Jumps come before the iteration's first move, so the jump is the
     * point's whole net displacement so far. */
    const int64_t hlx = cfpo_grid_coord(&E->G, h->x) - E->x0, hly = cfpo_grid_coord(&E->G, h->y) - E->y0;
    if (hlx >= 0 && hlx < E->w && hly >= 0 && hly < E->h)
        M->arr[M->narr++] = (jarrival){hly * E->w + hlx, p->tie, h->x, h->y, {(float)dx, (float)dy}};
}

/* Pairs holes H with points P block by block, blocks of scale k (both
 * lists by block, list order within a block; first[] of by_block): a
 * hole whose cell touches a hole already taken is passed over; at k > 0
 * so is a point whose jump would take a smaller block's net count past
 * JUMP_NET (and a hole with no such point left); a block stops at its
 * first pair that gains no more than tol L. Used holes get key 0 (a
 * hole's key is -R < 0), used points key INFINITY. */
static void pair_blocks(cfpo_engine *E, jmoves *M, jscales *S, int k, jcand *H, const int64_t *hb, jcand *P,
                        const int64_t *pb)
{
    const int64_t g = E->G.g;
    const double tolL = E->o.tol * E->G.L;
    for (int64_t b = 0; b < S->nb[k] * S->nb[k]; b++) {
        const size_t pe = (size_t)pb[b + 1];
        size_t j0 = (size_t)pb[b];
        for (size_t i = (size_t)hb[b]; i < (size_t)hb[b + 1] && j0 < pe; i++) {
            if (touches_taken(M->taken, g, H[i].cell)) continue;
            size_t j = j0;
            while (j < pe && (P[j].key == INFINITY || (k > 0 && !net_ok(S, k, g, H[i].cell, P[j].cell)))) j++;
            if (j >= pe) continue;
            if (!(-H[i].key > P[j].key + tolL)) break;
            jump_one(E, M, &H[i], &P[j]);
            net_add(S, k, g, H[i].cell, P[j].cell);
            H[i].key = 0;
            P[j].key = INFINITY;
            while (j0 < pe && P[j0].key == INFINITY) j0++;
        }
    }
}

/* Drops the used entries (key 0 or INFINITY) and puts the rest back in
 * list order. */
static size_t left_over(jcand *a, size_t n, double used)
{
    size_t q = 0;
    for (size_t i = 0; i < n; i++)
        if (a[i].key != used) a[q++] = a[i];
    if (q) qsort(a, q, sizeof *a, cmp_cand);
    return q;
}

int eng_jump(cfpo_engine *E)
{
    const int64_t g = E->G.g, cells = E->cells;
    const double L = E->G.L, tolL = E->o.tol * L;
    const size_t K = E->n / JUMP_SHARE > 64 ? (size_t)(E->n / JUMP_SHARE) : 64;
    int rc = -1;
    jcand *hole = malloc((size_t)(cells ? cells : 1) * sizeof *hole);
    jcand *worst = malloc((size_t)(cells ? cells : 1) * sizeof *worst);
    jcand *H = NULL, *P = NULL;
    jmoves M = {calloc((size_t)(g * g), 1), calloc((size_t)(E->nloc ? E->nloc : 1), 1), 0, NULL, 0};
    jcand *tmp = NULL;
    int64_t *hb = NULL, *pb = NULL;
    size_t nh = 0, np = 0;
    jscales S = {0};
    if (!hole || !worst || !M.taken || !M.gone) goto out;
    /* Worst points first: a hole pairs only if it beats the smallest r by
     * more than tol L, so the holes' solves can prune below that. */
    const size_t nw = candidates(E, worst, -1);
    double rmin = nw ? worst[0].key : INFINITY;
    for (size_t i = 1; i < nw; i++) rmin = fmin(rmin, worst[i].key);
    comm_min_d(&rmin, 1);
    if (!(rmin < L)) {
        rc = 0;
        goto out;
    }
    const size_t nho = candidates(E, hole, (rmin + tolL) * (rmin + tolL));
    if (merge_first(hole, nho, K, &H, &nh) != 0 || merge_first(worst, nw, K, &P, &np) != 0) goto out;
    /* The scales: JUMP_BLOCK alone before iteration JUMP_WIDE, from then
     * on every doubling of it up to the whole torus. */
    for (int64_t s = JUMP_BLOCK; S.ns < JUMP_SCALES; s *= 2) {
        S.s[S.ns] = s < g ? s : g;
        S.nb[S.ns] = (g + S.s[S.ns] - 1) / S.s[S.ns];
        S.net[S.ns] = calloc((size_t)(S.nb[S.ns] * S.nb[S.ns]), sizeof **S.net);
        if (!S.net[S.ns++]) goto out;
        if (s >= g || E->cur < JUMP_WIDE) break;
    }
    M.arr = malloc((np ? np : 1) * sizeof *M.arr);
    tmp = malloc((nh > np ? nh : np ? np : 1) * sizeof *tmp);
    hb = malloc((size_t)(S.nb[0] * S.nb[0] + 1) * sizeof *hb);
    pb = malloc((size_t)(S.nb[0] * S.nb[0] + 1) * sizeof *pb);
    if (!M.arr || !tmp || !hb || !pb) goto out;
    for (int k = 0; k < S.ns; k++) {
        if (k > 0) { /* what the smaller blocks left */
            nh = left_over(H, nh, 0);
            np = left_over(P, np, INFINITY);
        }
        by_block(H, tmp, nh, hb, g, S.s[k], S.nb[k]);
        by_block(P, tmp, np, pb, g, S.s[k], S.nb[k]);
        pair_blocks(E, &M, &S, k, H, hb, P, pb);
    }
    qsort(M.arr, M.narr, sizeof *M.arr, cmp_arr);
    if (rebuild(E, M.gone, M.ngone, M.arr, M.narr) != 0) goto out;
    for (int64_t c = 0; c < cells; c++) E->mask[c] |= NEED_BIT;
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    rc = eng_refresh_halo(E);
out:
    free(hole);
    free(worst);
    free(H);
    free(P);
    free(M.taken);
    free(M.gone);
    free(M.arr);
    free(tmp);
    free(hb);
    free(pb);
    for (int k = 0; k < S.ns; k++) free(S.net[k]);
    return rc;
}
