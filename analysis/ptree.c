/* ptree.c - see ptree.h. */
#include "ptree.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"

#define LEAF 8

static void swap_pt(an_ptree *T, size_t a, size_t b)
{
    const double x = T->x[a], y = T->y[a];
    const size_t id = T->id[a];
    T->x[a] = T->x[b]; T->y[a] = T->y[b]; T->id[a] = T->id[b];
    T->x[b] = x; T->y[b] = y; T->id[b] = id;
}

/* Reorders [lo, hi) so that the k-th smallest of v is at k, smaller or
 * equal ones before it, larger or equal ones after: selection by a
 * three-way partition around a median of three. */
static void select_kth(an_ptree *T, const double *v, size_t lo, size_t hi, size_t k)
{
    while (hi - lo > 1) {
        const double a = v[lo], b = v[lo + (hi - lo) / 2], c = v[hi - 1];
        const double pivot = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
        size_t lt = lo, i = lo, gt = hi; /* [lo, lt) < pivot, [lt, i) == pivot, [gt, hi) > pivot */
        while (i < gt) {
            if (v[i] < pivot) swap_pt(T, lt++, i++);
            else if (v[i] > pivot) swap_pt(T, i, --gt);
            else i++;
        }
        if (k < lt) hi = lt;
        else if (k >= gt) lo = gt;
        else return;
    }
}

static long build(an_ptree *T, size_t lo, size_t hi)
{
    const long me = (long)T->nodes++;
    an_pnode nd = {T->x[lo], T->y[lo], T->x[lo], T->y[lo], lo, hi, -1, -1};
    for (size_t t = lo + 1; t < hi; t++) {
        if (T->x[t] < nd.x0) nd.x0 = T->x[t];
        if (T->x[t] > nd.x1) nd.x1 = T->x[t];
        if (T->y[t] < nd.y0) nd.y0 = T->y[t];
        if (T->y[t] > nd.y1) nd.y1 = T->y[t];
    }
    T->node[me] = nd;
    if (hi - lo <= LEAF || (nd.x0 == nd.x1 && nd.y0 == nd.y1)) return me;
    const size_t mid = lo + (hi - lo) / 2;
    select_kth(T, nd.x1 - nd.x0 >= nd.y1 - nd.y0 ? T->x : T->y, lo, hi, mid);
    const long left = build(T, lo, mid);
    const long right = build(T, mid, hi);
    T->node[me].left = left;
    T->node[me].right = right;
    return me;
}

int an_ptree_build(an_ptree *T, const double *xy, size_t n)
{
    memset(T, 0, sizeof *T);
    if (n == 0) return 0;
    T->x = malloc(n * sizeof *T->x);
    T->y = malloc(n * sizeof *T->y);
    T->id = malloc(n * sizeof *T->id);
    T->node = malloc((2 * n / LEAF + 2 * 64 + 1) * 2 * sizeof *T->node);
    if (!T->x || !T->y || !T->id || !T->node) return -1;
    for (size_t i = 0; i < n; i++) {
        T->x[i] = xy[2 * i];
        T->y[i] = xy[2 * i + 1];
        T->id[i] = i;
    }
    T->n = n;
    build(T, 0, n);
    return 0;
}

void an_ptree_free(an_ptree *T)
{
    free(T->x); free(T->y); free(T->id); free(T->node);
    memset(T, 0, sizeof *T);
}

/* Squared distance from (qx, qy) to a box moved by (ox, oy). Computed as
 * a point's distance is (the point moved, then the difference taken), so
 * by the monotony of rounding it is never above a point's inside. */
static double box_d2(const an_pnode *b, double ox, double oy, double qx, double qy)
{
    const double x0 = b->x0 + ox, x1 = b->x1 + ox, y0 = b->y0 + oy, y1 = b->y1 + oy;
    const double dx = qx < x0 ? x0 - qx : qx > x1 ? qx - x1 : 0;
    const double dy = qy < y0 ? y0 - qy : qy > y1 ? qy - y1 : 0;
    return dx * dx + dy * dy;
}

#define STACK 160 /* the depth is about log2(n / LEAF) */

/* The nearest point to (qx, qy) but skip: its squared distance as the
 * image distance (torus = 0) or as cfpo_torus_dist2 computes it (1). */
static double nearest(const an_ptree *T, double qx, double qy, size_t skip, int torus)
{
    double best = INFINITY;
    if (T->n == 0) return best;
    const double wx = qx - floor(qx), wy = qy - floor(qy);
    /* With the query and the points in [0, 1), each point's nearest image
     * is among its shifts by -1, 0, 1 in each coordinate. */
    for (int oy = -1; oy <= 1; oy++)
        for (int ox = -1; ox <= 1; ox++) {
            long stack[STACK];
            int sp = 0;
            stack[sp++] = 0;
            while (sp > 0) {
                const an_pnode *b = &T->node[stack[--sp]];
                /* The image distance and cfpo_torus_dist2 round apart by
                 * less than 1e-15 (every value below 2): for the latter a
                 * box is passed over only when farther than that beyond. */
                const double r = sqrt(best) + 1e-15, box = box_d2(b, ox, oy, wx, wy);
                if (torus ? box > r * r : box >= best) continue;
                if (b->left < 0) {
                    /* One position: its points are all as far; one stands
                     * for the rest (another than skip, if any). */
                    const int one = b->x0 == b->x1 && b->y0 == b->y1;
                    for (size_t t = b->lo; t < b->hi; t++) {
                        if (T->id[t] == skip) continue;
                        const double dx = (T->x[t] + ox) - wx, dy = (T->y[t] + oy) - wy;
                        const double d2 = torus ? cfpo_torus_dist2(qx, qy, T->x[t], T->y[t]) : dx * dx + dy * dy;
                        if (d2 < best) best = d2;
                        if (one) break;
                    }
                    if (best == 0) return 0; /* nothing is nearer */
                    continue;
                }
                const long l = b->left, rr = b->right;
                const int lnear = box_d2(&T->node[l], ox, oy, wx, wy) <= box_d2(&T->node[rr], ox, oy, wx, wy);
                stack[sp++] = lnear ? rr : l;
                stack[sp++] = lnear ? l : rr;
            }
        }
    return best;
}

double an_ptree_nearest(const an_ptree *T, double qx, double qy, size_t skip)
{
    return nearest(T, qx, qy, skip, 0);
}

double an_ptree_nearest_torus(const an_ptree *T, double qx, double qy, size_t skip)
{
    return nearest(T, qx, qy, skip, 1);
}

size_t an_ptree_count_box(const an_ptree *T, double cx, double cy, double h)
{
    size_t count = 0;
    if (T->n == 0) return 0;
    /* Image (ox, oy) lies in [ox, ox + 1) x [oy, oy + 1). */
    const double ox0 = floor(cx - h) - 1, ox1 = floor(cx + h) + 1, oy0 = floor(cy - h) - 1, oy1 = floor(cy + h) + 1;
    for (double oy = oy0; oy <= oy1; oy++)
        for (double ox = ox0; ox <= ox1; ox++) {
            long stack[STACK];
            int sp = 0;
            stack[sp++] = 0;
            while (sp > 0) {
                const an_pnode *b = &T->node[stack[--sp]];
                /* By the monotony of rounding, a box whose sides pass
                 * holds only points that pass, and one beyond holds none. */
                const double x0 = b->x0 + ox, x1 = b->x1 + ox, y0 = b->y0 + oy, y1 = b->y1 + oy;
                if (x0 - cx > h || cx - x1 > h || y0 - cy > h || cy - y1 > h) continue;
                if (fabs(x0 - cx) <= h && fabs(x1 - cx) <= h && fabs(y0 - cy) <= h && fabs(y1 - cy) <= h) {
                    count += b->hi - b->lo;
                    continue;
                }
                if (b->left < 0) {
                    for (size_t t = b->lo; t < b->hi; t++)
                        count += fabs((T->x[t] + ox) - cx) <= h && fabs((T->y[t] + oy) - cy) <= h;
                    continue;
                }
                stack[sp++] = b->left;
                stack[sp++] = b->right;
            }
        }
    return count;
}

/* Heap entries: (key, item, ox, oy); item >= 0 a node, item < 0 the point
 * at tree position -item - 1. Ordered by key, then item, then offset. */
static int less4(const double *a, const double *b)
{
    for (int k = 0; k < 4; k++)
        if (a[k] != b[k]) return a[k] < b[k];
    return 0;
}

static void swap4(double *a, double *b)
{
    for (int k = 0; k < 4; k++) { const double t = a[k]; a[k] = b[k]; b[k] = t; }
}

static int push(an_pwalk *W, double key, double item, double ox, double oy)
{
    if (W->len == W->cap) {
        const size_t cap = W->cap ? 2 * W->cap : 256;
        double *k = realloc(W->key, 4 * cap * sizeof *k);
        if (!k) return -1;
        W->key = k;
        W->cap = cap;
    }
    size_t c = W->len++;
    double *h = W->key;
    h[4 * c] = key; h[4 * c + 1] = item; h[4 * c + 2] = ox; h[4 * c + 3] = oy;
    while (c > 0) {
        const size_t p = (c - 1) / 2;
        if (!less4(h + 4 * c, h + 4 * p)) break;
        swap4(h + 4 * c, h + 4 * p);
        c = p;
    }
    return 0;
}

/* Moves entry r of the heap h (n entries) down to its place. */
static void sift_down(double *h, size_t n, size_t r)
{
    for (;;) {
        size_t c = 2 * r + 1;
        if (c >= n) return;
        if (c + 1 < n && less4(h + 4 * (c + 1), h + 4 * c)) c++;
        if (!less4(h + 4 * c, h + 4 * r)) return;
        swap4(h + 4 * c, h + 4 * r);
        r = c;
    }
}

static void pop(an_pwalk *W)
{
    double *h = W->key;
    const size_t n = --W->len;
    memcpy(h, h + 4 * n, 4 * sizeof *h);
    sift_down(h, n, 0);
}

int an_pwalk_start(an_pwalk *W, const an_ptree *T, double qx, double qy, double r, size_t skip)
{
    W->len = 0;
    W->skip = skip;
    W->fn = 0;
    W->T = T;
    W->qx = qx;
    W->qy = qy;
    W->r2 = r * r;
    if (T->n == 0) return 0;
    /* Image (ox, oy) of the set lies in [ox, ox + 1) x [oy, oy + 1). */
    const double ox0 = floor(qx - r), ox1 = floor(qx + r), oy0 = floor(qy - r), oy1 = floor(qy + r);
    for (double oy = oy0; oy <= oy1; oy++)
        for (double ox = ox0; ox <= ox1; ox++) {
            const double d2 = box_d2(&T->node[0], ox, oy, qx, qy);
            if (d2 <= W->r2 && push(W, d2, 0, ox, oy) != 0) return -1;
        }
    return 0;
}

void an_pwalk_filter(an_pwalk *W, const double *fv, const double *fr2, int fn)
{
    W->fv = fv;
    W->fr2 = fr2;
    W->fn = fn;
}

/* Whether the box [x0, x1] x [y0, y1] meets one of the filter's disks. */
static int kept(const an_pwalk *W, double x0, double y0, double x1, double y1)
{
    if (W->fn == 0) return 1;
    for (int v = 0; v < W->fn; v++) {
        const double cx = W->fv[2 * v], cy = W->fv[2 * v + 1];
        const double dx = cx < x0 ? x0 - cx : cx > x1 ? cx - x1 : 0;
        const double dy = cy < y0 ? y0 - cy : cy > y1 ? cy - y1 : 0;
        if (dx * dx + dy * dy <= W->fr2[v]) return 1;
    }
    return 0;
}

static int kept_node(const an_pwalk *W, const an_pnode *b, double ox, double oy)
{
    return kept(W, b->x0 + ox, b->y0 + oy, b->x1 + ox, b->y1 + oy);
}

void an_pwalk_prune(an_pwalk *W)
{
    if (W->fn == 0) return;
    const an_ptree *T = W->T;
    double *h = W->key;
    size_t k = 0;
    for (size_t e = 0; e < W->len; e++) {
        const long item = (long)h[4 * e + 1];
        const double ox = h[4 * e + 2], oy = h[4 * e + 3];
        int keep;
        if (item < 0) {
            const size_t t = (size_t)(-item - 1);
            const double X = T->x[t] + ox, Y = T->y[t] + oy;
            keep = kept(W, X, Y, X, Y);
        } else {
            keep = kept_node(W, &T->node[item], ox, oy);
        }
        if (keep) memmove(h + 4 * k++, h + 4 * e, 4 * sizeof *h);
    }
    W->len = k;
    for (size_t r = k / 2; r-- > 0;) sift_down(h, k, r); /* a heap again */
}

int an_pwalk_next(an_pwalk *W, double *px, double *py, size_t *id, double *d2)
{
    const an_ptree *T = W->T;
    while (W->len > 0) {
        const double key = W->key[0], ox = W->key[2], oy = W->key[3];
        const long item = (long)W->key[1];
        pop(W);
        if (item < 0) {
            const size_t t = (size_t)(-item - 1);
            *px = T->x[t] + ox;
            *py = T->y[t] + oy;
            if (!kept(W, *px, *py, *px, *py)) continue; /* the filter has shrunk since it was pushed */
            *id = T->id[t];
            *d2 = key;
            return 1;
        }
        const an_pnode *b = &T->node[item];
        if (b->left >= 0) {
            const double dl = box_d2(&T->node[b->left], ox, oy, W->qx, W->qy);
            const double dr = box_d2(&T->node[b->right], ox, oy, W->qx, W->qy);
            if (dl <= W->r2 && kept_node(W, &T->node[b->left], ox, oy) && push(W, dl, (double)b->left, ox, oy) != 0)
                return -1;
            if (dr <= W->r2 && kept_node(W, &T->node[b->right], ox, oy) && push(W, dr, (double)b->right, ox, oy) != 0)
                return -1;
            continue;
        }
        const int one = b->x0 == b->x1 && b->y0 == b->y1; /* one position: one of its points */
        for (size_t t = b->lo; t < b->hi; t++) {
            if (one && T->id[t] == W->skip && t + 1 < b->hi) continue; /* another copy stands for it */
            const double X = T->x[t] + ox, Y = T->y[t] + oy;
            const double dx = X - W->qx, dy = Y - W->qy, e2 = dx * dx + dy * dy;
            if (e2 <= W->r2 && kept(W, X, Y, X, Y) && push(W, e2, -(double)t - 1, ox, oy) != 0) return -1;
            if (one) break;
        }
    }
    return 0;
}

void an_pwalk_free(an_pwalk *W)
{
    free(W->key);
    memset(W, 0, sizeof *W);
}
