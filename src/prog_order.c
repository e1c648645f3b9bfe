/* prog_order.c - see prog_order.h. */
#include "prog_order.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "prog_buckets.h"

typedef struct {
    double d;
    int64_t i;
} hitem;

static int above(const hitem *a, const hitem *b) { return a->d > b->d || (a->d == b->d && a->i < b->i); }

static void hpush(hitem *h, int64_t *n, hitem v)
{
    int64_t k = (*n)++;
    while (k > 0 && above(&v, &h[(k - 1) / 2])) {
        h[k] = h[(k - 1) / 2];
        k = (k - 1) / 2;
    }
    h[k] = v;
}

static hitem hpop(hitem *h, int64_t *n)
{
    const hitem top = h[0], v = h[--(*n)];
    int64_t k = 0;
    for (;;) {
        int64_t c = 2 * k + 1;
        if (c >= *n) break;
        if (c + 1 < *n && above(&h[c + 1], &h[c])) c++;
        if (!above(&h[c], &v)) break;
        h[k] = h[c];
        k = c;
    }
    if (*n > 0) h[k] = v;
    return top;
}

/* Every untaken new point j (xy[m0 + j]) nearer to (px, py) than d[j],
 * among those within r of it (r infinite: all): d[j] lowered, then
 * lowered(j, ctx). */
typedef void (*lowered_fn)(int64_t j, void *ctx);
static void lower_near(const prog_buckets *Q, const double *xy, int64_t m0, double px, double py, double r, double *d,
                       const unsigned char *taken, lowered_fn lowered, void *ctx)
{
    const int64_t reach = isinf(r) ? Q->gs : (int64_t)ceil(r / Q->cs) + 1;
    int64_t x0, y0;
    const int64_t span = prog_buckets_window(Q, prog_buckets_of(Q, px, py), reach, &x0, &y0);
    for (int64_t oy = 0; oy < span; oy++)
        for (int64_t ox = 0; ox < span; ox++)
            for (int64_t k = prog_buckets_first(Q, x0 + ox, y0 + oy); k >= 0; k = Q->next[k]) {
                const int64_t j = k - m0;
                if (taken[j]) continue;
                const double d2 = prog_torus_d2(px, py, xy[2 * k], xy[2 * k + 1]);
                if (d2 >= d[j]) continue;
                d[j] = d2;
                lowered(j, ctx);
            }
}

/* The greedy order's heap: a lowered point's new entry, the heap first
 * compacted to one live entry per untaken point when it is full. */
typedef struct {
    hitem *h;
    int64_t *hn, hcap, q;
    const double *d;
    const unsigned char *taken;
} heap_room;

static void heap_lowered(int64_t j, void *ctx)
{
    heap_room *R = ctx;
    if (*R->hn == R->hcap) {
        *R->hn = 0;
        for (int64_t i = 0; i < R->q; i++)
            if (!R->taken[i]) hpush(R->h, R->hn, (hitem){R->d[i], i});
    }
    hpush(R->h, R->hn, (hitem){R->d[j], j});
}

int cfpo_prog_order(double *xy, int64_t m0, int64_t m1, char *err, size_t errlen)
{
    const int64_t q = m1 - m0;
    if (q <= 1) return 0;
    prog_buckets P = {0}, Q = {0};
    double *d = malloc((size_t)q * sizeof *d), *out = malloc(2 * (size_t)q * sizeof *out);
    unsigned char *taken = calloc((size_t)q, 1);
    const int64_t hcap = 8 * q + 16;
    hitem *h = malloc((size_t)hcap * sizeof *h);
    int rc = -1;
    if (!d || !out || !taken || !h || prog_buckets_init(&P, xy, m1, m1) != 0 || prog_buckets_init(&Q, xy, m1, m1) != 0) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    for (int64_t k = 0; k < m0; k++) prog_buckets_link(&P, k);
    int64_t hn = 0;
    for (int64_t j = 0; j < q; j++) { /* each new point's distance to the prefix */
        d[j] = m0 > 0 ? prog_buckets_nearest2(&P, xy[2 * (m0 + j)], xy[2 * (m0 + j) + 1], -1, -1.0) : INFINITY;
        prog_buckets_link(&Q, m0 + j);
        hpush(h, &hn, (hitem){d[j], j});
    }
    for (int64_t t = 0; t < q; t++) {
        hitem top;
        do top = hpop(h, &hn); /* stale entries (a distance lowered since) are skipped */
        while (taken[top.i] || top.d != d[top.i]);
        const int64_t p = top.i;
        taken[p] = 1;
        const double px = xy[2 * (m0 + p)], py = xy[2 * (m0 + p) + 1];
        out[2 * t] = px;
        out[2 * t + 1] = py;
        /* the untaken points nearer to p than to the set so far: within the
         * largest such distance, sqrt(top.d), of p */
        heap_room room = {h, &hn, hcap, q, d, taken};
        lower_near(&Q, xy, m0, px, py, sqrt(top.d), d, taken, heap_lowered, &room);
    }
    for (int64_t t = 0; t < 2 * q; t++) xy[2 * m0 + t] = out[t];
    rc = 0;
done:
    prog_buckets_free(&P);
    prog_buckets_free(&Q);
    free(d);
    free(out);
    free(taken);
    free(h);
    return rc;
}

/* ---- the paced order: a tournament over the quadtree. Node k of level
 * l = 0 (the root) .. depth, k the Morton code of its (y, x), is numbered
 * (4^l - 1) / 3 + k: its children are 4 k .. 4 k + 3 of level l + 1. Each
 * leaf keeps a lazy max-heap of its untaken points by distance (a point's
 * distance only falls; an entry that no longer matches is skipped); each
 * node keeps the best (d, j) below it, or none when the node (below the
 * root) has given its allowance: the root's best is the next pick. A pick,
 * a distance that falls at a leaf's best, or an allowance that grows
 * changes only the nodes from there to the root. A used-up node waits in
 * a heap keyed by the step at which its allowance passes what it gave. */

typedef struct {
    int depth;
    int64_t *leaf;        /* each new point's leaf, the Morton code of its (y, x) */
    int64_t q, t;         /* the level's new points; the step under way */
    int tol;
    int64_t *count, *took; /* per node: its new points; those given so far */
    double *bd;           /* per node: the best distance below it (-1: none) */
    int64_t *bj;          /* ... and its point */
    double *fd;           /* per node: the largest distance below it, allowances or not (-1: none):
                             at the root, how far a pick can lower a distance */
    hitem *pool;          /* the leaves' heaps: leaf f's at pool + ls[f] + 2 f, hn[f] entries of its
                             points' count + 2 */
    int64_t *hn, *ls, *lp; /* the leaves' points: lp[ls[f] .. ls[f + 1]) */
    hitem *wake;          /* the used-up nodes by the step their allowance passes what they gave
                             (d = -that step, i = the node): a heap of nw */
    int64_t nw;
    unsigned char *asleep; /* per node: in wake */
} tour;

static int64_t node_of(int l, int64_t k) { return ((((int64_t)1 << (2 * l)) - 1) / 3) + k; }

/* The Morton code of (y, x), depth bits each: y's bits odd, x's even. */
static int64_t morton(int64_t y, int64_t x, int depth)
{
    int64_t k = 0;
    for (int b = 0; b < depth; b++) k |= ((x >> b) & 1) << (2 * b) | ((y >> b) & 1) << (2 * b + 1);
    return k;
}

static void tour_free(tour *T)
{
    free(T->leaf); free(T->count); free(T->took); free(T->bd); free(T->bj); free(T->fd); free(T->pool);
    free(T->hn); free(T->ls); free(T->lp); free(T->wake); free(T->asleep);
}

static int64_t axis_cell(double v, int64_t G)
{
    const int64_t c = (int64_t)(v * (double)G);
    return c < 0 ? 0 : c >= G ? G - 1 : c;
}

/* Leaf f's best untaken point (its heap's stale entries dropped), into
 * (*d, *j); *d = -1 when none. */
static void leaf_best(tour *T, int64_t f, const double *d, const unsigned char *taken, double *bd, int64_t *bj)
{
    hitem *h = T->pool + T->ls[f] + 2 * f;
    while (T->hn[f] > 0 && (taken[h[0].i] || h[0].d != d[h[0].i])) (void)hpop(h, &T->hn[f]);
    *bd = T->hn[f] > 0 ? h[0].d : -1;
    *bj = T->hn[f] > 0 ? h[0].i : -1;
}

/* Node k of level l's best again, from its heap or its four children. */
static void recompute(tour *T, int l, int64_t k, const double *d, const unsigned char *taken)
{
    const int64_t c = node_of(l, k);
    double bd = -1, fd = -1;
    int64_t bj = -1;
    if (l == T->depth) {
        leaf_best(T, k, d, taken, &bd, &bj);
        fd = bd;
    } else
        for (int64_t ch = node_of(l + 1, 4 * k); ch < node_of(l + 1, 4 * k + 4); ch++) {
            if (T->bd[ch] > bd || (T->bd[ch] == bd && T->bd[ch] >= 0 && T->bj[ch] < bj)) bd = T->bd[ch], bj = T->bj[ch];
            if (T->fd[ch] > fd) fd = T->fd[ch];
        }
    if (l > 0 && T->took[c] >= (T->t + 1) * T->count[c] / T->q + T->tol) { /* used up: no pick below it */
        bd = -1, bj = -1;
        if (!T->asleep[c]) { /* it wakes at the first step whose allowance passes what it gave */
            T->asleep[c] = 1;
            const int64_t a = T->took[c] - T->tol + 1;
            hpush(T->wake, &T->nw, (hitem){-(double)((a * T->q + T->count[c] - 1) / T->count[c] - 1), c});
        }
    }
    T->bd[c] = bd;
    T->bj[c] = bj;
    T->fd[c] = fd;
}

/* Node k of level l and every node above it again; with `still`, only up
 * to the first node above it whose best stays (nothing above it changed
 * otherwise: no allowance, no count). */
static void climb(tour *T, int l, int64_t k, const double *d, const unsigned char *taken, int still)
{
    for (const int l0 = l; l >= 0; l--, k >>= 2) {
        const int64_t c = node_of(l, k);
        const double bd = T->bd[c], fd = T->fd[c];
        const int64_t bj = T->bj[c];
        recompute(T, l, k, d, taken);
        if (still && l < l0 && T->bd[c] == bd && T->bj[c] == bj && T->fd[c] == fd) break;
    }
}

/* Point j's entry (d[j]) into its leaf's heap; a full heap is made again
 * from its untaken points first. */
static void leaf_push(tour *T, int64_t j, const double *d, const unsigned char *taken)
{
    const int64_t f = T->leaf[j];
    hitem *h = T->pool + T->ls[f] + 2 * f;
    if (T->hn[f] == T->ls[f + 1] - T->ls[f] + 2) {
        T->hn[f] = 0;
        for (int64_t s = T->ls[f]; s < T->ls[f + 1]; s++)
            if (!taken[T->lp[s]] && T->lp[s] != j) hpush(h, &T->hn[f], (hitem){d[T->lp[s]], T->lp[s]});
    }
    hpush(h, &T->hn[f], (hitem){d[j], j});
}

static int tour_init(tour *T, const double *xy, int64_t m0, int64_t q, int depth, int tol, const double *d)
{
    const int64_t G = (int64_t)1 << depth, leaves = G * G, nodes = node_of(depth + 1, 0);
    *T = (tour){.depth = depth, .q = q, .tol = tol};
    T->leaf = malloc((size_t)q * sizeof *T->leaf);
    T->count = calloc((size_t)nodes, sizeof *T->count);
    T->took = calloc((size_t)nodes, sizeof *T->took);
    T->bd = malloc((size_t)nodes * sizeof *T->bd);
    T->bj = malloc((size_t)nodes * sizeof *T->bj);
    T->fd = malloc((size_t)nodes * sizeof *T->fd);
    T->hn = calloc((size_t)leaves, sizeof *T->hn);
    T->ls = calloc((size_t)leaves + 1, sizeof *T->ls);
    T->lp = malloc((size_t)q * sizeof *T->lp);
    T->wake = malloc((size_t)nodes * sizeof *T->wake);
    T->asleep = calloc((size_t)nodes, 1);
    T->pool = malloc(((size_t)(q + 2 * leaves)) * sizeof *T->pool);
    if (!T->leaf || !T->count || !T->took || !T->bd || !T->bj || !T->fd || !T->hn || !T->ls || !T->lp ||
        !T->wake || !T->asleep || !T->pool)
        return -1;
    for (int64_t j = 0; j < q; j++) {
        T->leaf[j] = morton(axis_cell(xy[2 * (m0 + j) + 1], G), axis_cell(xy[2 * (m0 + j)], G), depth);
        T->ls[T->leaf[j] + 1]++;
    }
    for (int64_t f = 0; f < leaves; f++) T->ls[f + 1] += T->ls[f];
    int64_t *count = T->count;
    for (int64_t j = 0; j < q; j++) {
        T->lp[T->ls[T->leaf[j]] + T->hn[T->leaf[j]]++] = j; /* hn: a fill count for now */
        for (int l = 1; l <= depth; l++) count[node_of(l, T->leaf[j] >> (2 * (depth - l)))]++;
    }
    for (int64_t f = 0; f < leaves; f++) T->hn[f] = 0;
    for (int64_t j = 0; j < q; j++) {
        const int64_t f = T->leaf[j];
        hpush(T->pool + T->ls[f] + 2 * f, &T->hn[f], (hitem){d[j], j});
    }
    return 0;
}

/* The tournament's side of a lowered distance: the point's new entry in
 * its leaf's heap, and the nodes above it again when it was its leaf's best. */
typedef struct {
    tour *T;
    const double *d;
    const unsigned char *taken;
} tour_ctx;

static void tour_lowered(int64_t j, void *ctx)
{
    tour_ctx *c = ctx;
    tour *T = c->T;
    leaf_push(T, j, c->d, c->taken);
    if (T->bj[node_of(T->depth, T->leaf[j])] == j) climb(T, T->depth, T->leaf[j], c->d, c->taken, 1);
}

/* The paced order (prog_order.h) of points m0 .. m1 - 1, depth >= 1. */
static int order_paced(double *xy, int64_t m0, int64_t m1, int depth, int tol, char *err, size_t errlen)
{
    const int64_t q = m1 - m0;
    if (q <= 1) return 0;
    prog_buckets P = {0}, Q = {0};
    tour T = {0};
    double *d = malloc((size_t)q * sizeof *d), *out = malloc(2 * (size_t)q * sizeof *out);
    unsigned char *taken = calloc((size_t)q, 1);
    int rc = -1;
    if (!d || !out || !taken || prog_buckets_init(&P, xy, m1, m1) != 0 || prog_buckets_init(&Q, xy, m1, m1) != 0)
        goto oom;
    for (int64_t k = 0; k < m0; k++) prog_buckets_link(&P, k);
    for (int64_t j = 0; j < q; j++) { /* each new point's distance to the prefix */
        d[j] = m0 > 0 ? prog_buckets_nearest2(&P, xy[2 * (m0 + j)], xy[2 * (m0 + j) + 1], -1, -1.0) : INFINITY;
        prog_buckets_link(&Q, m0 + j);
    }
    if (tour_init(&T, xy, m0, q, depth, tol, d) != 0) goto oom;
    for (int l = depth; l >= 0; l--)
        for (int64_t k = 0; k < ((int64_t)1 << (2 * l)); k++) recompute(&T, l, k, d, taken);
    for (int64_t t = 0; t < q; t++) {
        T.t = t; /* a node's allowance at step t: floor((t + 1) c / q) + tol of its c points */
        while (T.nw > 0 && -T.wake[0].d <= (double)t) { /* the used-up nodes whose allowance has grown */
            const int64_t c = hpop(T.wake, &T.nw).i;
            T.asleep[c] = 0;
            int l = 1;
            while (node_of(l + 1, 0) <= c) l++;
            climb(&T, l, c - node_of(l, 0), d, taken, 1);
        }
        const int64_t p = T.bj[0];
        taken[p] = 1;
        for (int l = 1; l <= depth; l++) T.took[node_of(l, T.leaf[p] >> (2 * (depth - l)))]++;
        climb(&T, depth, T.leaf[p], d, taken, 0); /* the counts changed all the way up */
        const double px = xy[2 * (m0 + p)], py = xy[2 * (m0 + p) + 1];
        out[2 * t] = px;
        out[2 * t + 1] = py;
        /* the untaken points nearer to p than to the set so far: within the
         * largest distance of the points left (held back or not) of p */
        if (T.fd[0] < 0) continue; /* none left */
        tour_ctx tc = {&T, d, taken};
        lower_near(&Q, xy, m0, px, py, sqrt(T.fd[0]), d, taken, tour_lowered, &tc);
    }
    for (int64_t t = 0; t < 2 * q; t++) xy[2 * m0 + t] = out[t];
    rc = 0;
    goto done;
oom:
    snprintf(err, errlen, "out of memory");
done:
    prog_buckets_free(&P);
    prog_buckets_free(&Q);
    tour_free(&T);
    free(d);
    free(out);
    free(taken);
    return rc;
}

int cfpo_prog_order_depth(int64_t m1, double per_cell)
{
    int L = 0;
    while (L < 15 && (double)m1 / pow(4.0, L + 1) >= per_cell) L++;
    return L;
}

int cfpo_prog_order_paced(double *xy, int64_t m0, int64_t m1, double per_cell, int tol, char *err, size_t errlen)
{
    if (!(per_cell > 0) || tol < 1) {
        snprintf(err, errlen, "the paced order needs per_cell > 0 and tol >= 1");
        return -1;
    }
    const int depth = cfpo_prog_order_depth(m1, per_cell);
    return depth > 0 ? order_paced(xy, m0, m1, depth, tol, err, errlen) : cfpo_prog_order(xy, m0, m1, err, errlen);
}
