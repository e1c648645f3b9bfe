/* prog_colour.c - see prog_colour.h. */
#include "prog_colour.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom.h"
#include "prog_buckets.h"

typedef struct {
    int64_t n;
    int K;
    int64_t *off;  /* pairs of point i: nb[off[i] .. off[i + 1]) */
    int64_t *nb;
    double *pen;   /* each pair's cost when both are of one class */
    double *cost;  /* cost[i K + c]: i's cost were it of class c */
    int *cls;
    int64_t *count, *target;
} colouring;

/* Every pair within r, both ways, with its cost. 0, or -1 when out of memory. */
static int pairs(colouring *C, const double *xy, double r)
{
    prog_buckets B;
    const int64_t n = C->n;
    if (prog_buckets_init_side(&B, xy, r, n) != 0) {
        prog_buckets_free(&B);
        return -1;
    }
    for (int64_t i = n - 1; i >= 0; i--) prog_buckets_link(&B, i);
    int64_t cap = 24 * n, m = 0;
    C->off = malloc((size_t)(n + 1) * sizeof *C->off);
    C->nb = malloc((size_t)cap * sizeof *C->nb);
    C->pen = malloc((size_t)cap * sizeof *C->pen);
    int rc = C->off && C->nb && C->pen ? 0 : -1;
    for (int64_t i = 0; i < n && rc == 0; i++) {
        C->off[i] = m;
        int64_t wx, wy;
        const int64_t span = prog_buckets_window(&B, prog_buckets_of(&B, xy[2 * i], xy[2 * i + 1]), 1, &wx, &wy);
        for (int64_t oy = 0; oy < span && rc == 0; oy++)
            for (int64_t ox = 0; ox < span && rc == 0; ox++)
                for (int64_t k = prog_buckets_first(&B, wx + ox, wy + oy); k >= 0; k = B.next[k]) {
                    if (k == i) continue;
                    const double d2 = prog_torus_d2(xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1]);
                    if (d2 >= r * r) continue;
                    if (m == cap) {
                        cap *= 2;
                        int64_t *a = realloc(C->nb, (size_t)cap * sizeof *a);
                        if (a) C->nb = a;
                        double *b = realloc(C->pen, (size_t)cap * sizeof *b);
                        if (b) C->pen = b;
                        if (!a || !b) {
                            rc = -1;
                            break;
                        }
                    }
                    const double q = r * r / fmax(d2, 1e-300);
                    C->nb[m] = k;
                    C->pen[m++] = q * q * q * q - 1.0; /* (r / d)^8 - 1 */
                }
    }
    if (rc == 0) C->off[n] = m;
    prog_buckets_free(&B);
    return rc;
}

/* Point i from its class to class b: the costs of its neighbours follow. */
static void relabel(colouring *C, int64_t i, int b)
{
    const int a = C->cls[i];
    for (int64_t e = C->off[i]; e < C->off[i + 1]; e++) {
        double *cj = C->cost + C->nb[e] * C->K;
        if (a >= 0) cj[a] -= C->pen[e];
        cj[b] += C->pen[e];
    }
    if (a >= 0) C->count[a]--;
    C->count[b]++;
    C->cls[i] = b;
}

/* One pass of local moves in id order; the moves made. */
static int64_t pass(colouring *C, int64_t slack)
{
    const int K = C->K;
    int64_t made = 0;
    for (int64_t i = 0; i < C->n; i++) {
        const int a = C->cls[i];
        const double *ci = C->cost + i * K;
        if (ci[a] <= 0) continue;
        int best = -1;
        double gain = 1e-12 * ci[a];
        for (int b = 0; b < K; b++) /* a relabel within the slack */
            if (b != a && C->count[b] < C->target[b] + slack && C->count[a] > C->target[a] - slack &&
                ci[a] - ci[b] > gain)
                gain = ci[a] - ci[b], best = b;
        if (best >= 0) {
            relabel(C, i, best);
            made++;
            continue;
        }
        int64_t bj = -1; /* else the best swap with a neighbour of another class */
        for (int64_t e = C->off[i]; e < C->off[i + 1]; e++) {
            const int64_t j = C->nb[e];
            const int b = C->cls[j];
            if (b == a) continue;
            const double *cj = C->cost + j * K;
            const double g = ci[a] + cj[b] - (ci[b] - C->pen[e]) - (cj[a] - C->pen[e]);
            if (g > gain) gain = g, bj = j;
        }
        if (bj >= 0) {
            const int b = C->cls[bj];
            relabel(C, i, b);
            relabel(C, bj, a);
            made++;
        }
    }
    return made;
}

/* The class the sizes are restored from: the last class over its size (-1: none). */
static int over_class(const colouring *C)
{
    int over = -1;
    for (int c = 0; c < C->K; c++)
        if (C->count[c] > C->target[c]) over = c;
    return over;
}

/* Point i's cheapest relabel from class a to a class under its size:
 * its cost change, and the class in *to (the first of equal costs). */
static double cheapest(const colouring *C, int64_t i, int a, int *to)
{
    double bc = INFINITY;
    *to = -1;
    for (int b = 0; b < C->K; b++) {
        const double d = C->cost[i * C->K + b] - C->cost[i * C->K + a];
        if (C->count[b] < C->target[b] && d < bc) bc = d, *to = b;
    }
    return bc;
}

/* The sizes restored by a scan of every point for each relabel (O(n) a
 * relabel): the reference of restore(). The relabels made. */
static int64_t restore_scan(colouring *C)
{
    int64_t made = 0;
    for (int over; (over = over_class(C)) >= 0; made++) {
        int64_t bi = -1;
        int bb = -1;
        double bc = INFINITY;
        for (int64_t i = 0; i < C->n; i++) {
            if (C->cls[i] != over) continue;
            int b;
            const double d = cheapest(C, i, over, &b);
            if (d < bc) bc = d, bi = i, bb = b;
        }
        relabel(C, bi, bb);
    }
    return made;
}

/* A tournament tree over the points of one class in id order: each leaf
 * holds its point's cheapest relabel (INFINITY once relabelled), each
 * node the leaf of least cost below it, the lower leaf of equal costs. */
typedef struct {
    int64_t P;     /* leaves (a power of two) */
    int64_t *id;   /* id[l]: leaf l's point (-1: none) */
    double *d;     /* d[l]: its cheapest relabel's cost */
    int *to;       /* to[l]: that relabel's class */
    int64_t *win;  /* win[v], v in [1, 2P): the winning leaf below node v */
} tourney;

static void tourney_up(tourney *T, int64_t l)
{
    for (int64_t v = (l + T->P) / 2; v >= 1; v /= 2) {
        const int64_t a = T->win[2 * v], b = T->win[2 * v + 1];
        T->win[v] = T->d[b] < T->d[a] ? b : a;
    }
}

/* The same relabels as restore_scan() (the least cost, the lowest id and
 * then the lowest class of equal costs), in O((n K + relabels x
 * neighbours x log n) K): a relabel changes the costs of its point's
 * neighbours only, so only their leaves are updated; the tree is built
 * again only when the class over its size or the set of classes under
 * theirs changes (each at most K times: a class over its size only loses
 * points, one under only gains). The relabels made, or -1 when out of
 * memory. */
static int64_t restore(colouring *C)
{
    const int64_t n = C->n;
    const int K = C->K;
    if (over_class(C) < 0) return 0;
    int64_t P = 1, most = 0; /* the leaves: the largest class (a class over its size only loses points) */
    for (int c = 0; c < K; c++) most = C->count[c] > most ? C->count[c] : most;
    while (P < most) P *= 2;
    tourney T = {.P = P};
    T.id = malloc((size_t)P * sizeof *T.id);
    T.d = malloc((size_t)P * sizeof *T.d);
    T.to = malloc((size_t)P * sizeof *T.to);
    T.win = malloc(2 * (size_t)P * sizeof *T.win);
    int64_t *leaf = malloc((size_t)n * sizeof *leaf);
    unsigned char *under = malloc((size_t)K);
    int64_t made = T.id && T.d && T.to && T.win && leaf && under ? 0 : -1;
    int cur = -1; /* the class the tree holds (-1: none) */
    for (int over; made >= 0 && (over = over_class(C)) >= 0; made++) {
        int same = over == cur;
        for (int b = 0; b < K && same; b++) same = under[b] == (C->count[b] < C->target[b]);
        if (!same) { /* build it */
            cur = over;
            for (int b = 0; b < K; b++) under[b] = C->count[b] < C->target[b];
            int64_t m = 0;
            for (int64_t i = 0; i < n; i++) {
                leaf[i] = -1;
                if (C->cls[i] != over) continue;
                leaf[i] = m;
                T.id[m] = i;
                T.d[m] = cheapest(C, i, over, &T.to[m]);
                m++;
            }
            for (int64_t l = m; l < P; l++) T.id[l] = -1, T.d[l] = INFINITY, T.to[l] = -1;
            for (int64_t l = 0; l < P; l++) T.win[P + l] = l;
            for (int64_t v = P - 1; v >= 1; v--) {
                const int64_t a = T.win[2 * v], b = T.win[2 * v + 1];
                T.win[v] = T.d[b] < T.d[a] ? b : a;
            }
        }
        const int64_t l = T.win[1], i = T.id[l];
        relabel(C, i, T.to[l]);
        leaf[i] = -1;
        T.d[l] = INFINITY;
        tourney_up(&T, l);
        for (int64_t e = C->off[i]; e < C->off[i + 1]; e++) {
            const int64_t j = C->nb[e];
            if (leaf[j] < 0) continue;
            T.d[leaf[j]] = cheapest(C, j, over, &T.to[leaf[j]]);
            tourney_up(&T, leaf[j]);
        }
    }
    free(T.id);
    free(T.d);
    free(T.to);
    free(T.win);
    free(leaf);
    free(under);
    return made;
}

/* The same-class pairs closer than t (cost above (r / t)^8 - 1), each once. */
static int64_t close_pairs(const colouring *C, double pmin)
{
    int64_t c = 0;
    for (int64_t i = 0; i < C->n; i++)
        for (int64_t e = C->off[i]; e < C->off[i + 1]; e++)
            if (C->nb[e] > i && C->cls[C->nb[e]] == C->cls[i] && C->pen[e] > pmin) c++;
    return c;
}

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cfpo_prog_colour(double *xy, const int64_t *sizes, int K, cfpo_prog_colour_options *co, char *err,
                     size_t errlen)
{
    const double c0 = thread_cpu();
    const int64_t n = sizes[K - 1];
    const double reach = co->reach > 0 ? co->reach : 1.0;
    const double r = reach * cfpo_delta_bound((double)n / K);
    colouring C = {.n = n, .K = K};
    C.cost = calloc((size_t)n * K, sizeof *C.cost);
    C.cls = malloc((size_t)n * sizeof *C.cls);
    C.count = calloc((size_t)K, sizeof *C.count);
    C.target = malloc((size_t)K * sizeof *C.target);
    double *w = malloc(2 * (size_t)n * sizeof *w);
    int rc = C.cost && C.cls && C.count && C.target && w ? pairs(&C, xy, r) : -1;
    if (rc == 0) {
        for (int c = 0; c < K; c++) C.target[c] = sizes[c] - (c ? sizes[c - 1] : 0);
        for (int64_t i = 0; i < n; i++) C.cls[i] = -1;
        for (int64_t i = 0; i < n; i++) { /* greedy: the least cost among the classes not full */
            int best = -1;
            for (int c = 0; c < K; c++)
                if (C.count[c] < C.target[c] && (best < 0 || C.cost[i * K + c] < C.cost[i * K + best])) best = c;
            relabel(&C, i, best);
        }
        const double q = 1.0 / (0.8 * 0.8);
        const double pmin = pow(reach * reach * q, 4) - 1.0; /* a pair closer than 0.8 Delta(N/K) */
        co->close_start = close_pairs(&C, pmin);
        const int passes = co->passes > 0 ? co->passes : 50;
        const int64_t slack = n / K / 200 + 1;
        int p = 0;
        while (p < passes && pass(&C, slack) > 0) p++;
        const int64_t moved = co->restore_scan ? restore_scan(&C) : restore(&C);
        if (moved < 0) rc = -1;
        co->restores = moved;
        while (rc == 0 && p < passes && pass(&C, 0) > 0) p++; /* swaps only: the sizes stay */
        co->passes_run = p;
        co->close_end = close_pairs(&C, pmin);
        int64_t *at = rc == 0 ? calloc((size_t)K, sizeof *at) : NULL;
        if (!at) rc = -1;
        for (int c = 0; at && c < K; c++) at[c] = c ? sizes[c - 1] : 0;
        for (int64_t i = 0; at && i < n; i++) {
            const int64_t j = at[C.cls[i]]++;
            w[2 * j] = xy[2 * i];
            w[2 * j + 1] = xy[2 * i + 1];
        }
        if (at) memcpy(xy, w, 2 * (size_t)n * sizeof *w);
        free(at);
    }
    if (rc != 0) snprintf(err, errlen, "out of memory");
    free(C.off);
    free(C.nb);
    free(C.pen);
    free(C.cost);
    free(C.cls);
    free(C.count);
    free(C.target);
    free(w);
    co->cpu_seconds = thread_cpu() - c0;
    return rc;
}
