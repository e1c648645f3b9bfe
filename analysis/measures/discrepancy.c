/* discrepancy.c - see discrepancy.h.
 *
 * The pair sums, over ordered pairs (i, j), i = j included:
 *  - sum min(a_i, a_j) over one axis: sorted, a_(k) counts 2(m - 1 - k) + 1
 *    times (min_sum);
 *  - sum min(a_i, a_j) min(b_i, b_j): sorted by a, each point meets the
 *    points of larger a, whose min with b is b_j below b_i and b_i above:
 *    a Fenwick tree over the ranks of b holding counts and sums of b
 *    (minmin_sum);
 *  - sum |dx|^p |dy|^q, p, q in {0, 1, 2} (the torus-invariant two):
 *    p or q 0 or 2 reduce to one sort and prefix sums of moments x^a y^b;
 *    |dx||dy| = 2 (concordant pairs' dx dy) - (all pairs' dx dy), the
 *    concordant part by a Fenwick tree of count, x, y, xy over y ranks,
 *    points taken in x order (pair_table).
 * Ties need no care: a tied pair's term is the same whichever side it is
 * counted on (min of equal values, or a zero difference). */
#include "discrepancy.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"
#include "quad.h"

/* A sort key: the value, its rounding to double (monotone, so comparing
 * the doubles first and the values only on a tie gives the same order,
 * with far fewer software comparisons) and the index (the last tie-break:
 * the same order on every run). */
typedef struct {
    an_quad key;
    double near;
    uint32_t i;
} qkey;

static int cmp_qkey(const void *pa, const void *pb)
{
    const qkey *a = pa, *b = pb;
    if (a->near != b->near) return a->near < b->near ? -1 : 1;
    if (a->key < b->key) return -1;
    if (a->key > b->key) return 1;
    return (a->i > b->i) - (a->i < b->i);
}

static void sort_keys(qkey *k, const an_quad *v, size_t m)
{
    for (size_t t = 0; t < m; t++) { k[t].key = v[t]; k[t].near = (double)v[t]; k[t].i = (uint32_t)t; }
    qsort(k, m, sizeof *k, cmp_qkey);
}

/* Fenwick trees (1-based; position r + 1 holds rank r). */
typedef struct {
    an_quad s;
    int64_t c;
} fen1;

typedef struct {
    an_quad sx, sy, sxy;
    int64_t c;
} fen3;

/* sum_ij min(a_i, a_j), sorting into k. */
static an_quad min_sum(const an_quad *a, size_t m, qkey *k)
{
    sort_keys(k, a, m);
    an_quad s = 0;
    for (size_t t = 0; t < m; t++) s += k[t].key * (an_quad)(2 * (m - 1 - t) + 1);
    return s;
}

/* sum_ij min(a_i, a_j) min(b_i, b_j); k, rank, tree: scratch of m (m + 1). */
static an_quad minmin_sum(const an_quad *a, const an_quad *b, size_t m, qkey *k, uint32_t *rank, fen1 *tree)
{
    sort_keys(k, b, m);
    for (size_t t = 0; t < m; t++) rank[k[t].i] = (uint32_t)t;
    sort_keys(k, a, m);
    memset(tree, 0, (m + 1) * sizeof *tree);
    an_quad diag = 0, off = 0;
    for (size_t p = m; p-- > 0;) {
        const uint32_t i = k[p].i;
        an_quad s = 0;
        int64_t c = 0;
        for (size_t r = rank[i]; r > 0; r &= r - 1) { s += tree[r].s; c += tree[r].c; }
        const int64_t later = (int64_t)(m - 1 - p);
        off += a[i] * (s + b[i] * (an_quad)(later - c));
        diag += a[i] * b[i];
        for (size_t r = (size_t)rank[i] + 1; r <= m; r += r & (~r + 1)) { tree[r].s += b[i]; tree[r].c++; }
    }
    return diag + 2 * off;
}

/* E[p][q] = sum_ij |dx|^p |dy|^q for p, q in {0, 1, 2}. */
static void pair_table(const double *xy, size_t n, qkey *kx, qkey *ky, an_quad *tmp, uint32_t *rank,
                       fen3 *tree, an_quad E[3][3])
{
    /* moments M[a][b] = sum x^a y^b, a, b <= 2 */
    an_quad M[3][3] = {{0}};
    for (size_t i = 0; i < n; i++) {
        const an_quad x = xy[2 * i], y = xy[2 * i + 1];
        const an_quad px[3] = {1, x, x * x}, py[3] = {1, y, y * y};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) M[a][b] += px[a] * py[b];
    }
    const an_quad N = (an_quad)n;
    for (size_t i = 0; i < n; i++) tmp[i] = xy[2 * i];
    sort_keys(kx, tmp, n);
    for (size_t i = 0; i < n; i++) tmp[i] = xy[2 * i + 1];
    sort_keys(ky, tmp, n);
    E[0][0] = N * N;
    E[2][0] = 2 * N * M[2][0] - 2 * M[1][0] * M[1][0];
    E[0][2] = 2 * N * M[0][2] - 2 * M[0][1] * M[0][1];
    E[2][2] = 2 * N * M[2][2] - 4 * M[2][1] * M[0][1] - 4 * M[1][2] * M[1][0] + 2 * M[2][0] * M[0][2] +
              4 * M[1][1] * M[1][1];
    /* one axis |d|, the other d^2 or 1: sorted by the |d| axis, prefix moments */
    for (int axis = 0; axis < 2; axis++) {
        const qkey *k = axis == 0 ? kx : ky;
        an_quad S[3][2] = {{0}}; /* sum over earlier points of o^a s^b, s the sorted axis, o the other */
        an_quad e1 = 0, e2 = 0;  /* sum |ds|, sum |ds| do^2 over earlier pairs */
        for (size_t t = 0; t < n; t++) {
            const uint32_t i = k[t].i;
            const an_quad s = k[t].key, o = xy[2 * i + 1 - axis];
            e1 += s * S[0][0] - S[0][1];
            e2 += o * o * (s * S[0][0] - S[0][1]) - 2 * o * (s * S[1][0] - S[1][1]) + (s * S[2][0] - S[2][1]);
            const an_quad po[3] = {1, o, o * o};
            for (int a = 0; a < 3; a++) { S[a][0] += po[a]; S[a][1] += po[a] * s; }
        }
        if (axis == 0) { E[1][0] = 2 * e1; E[1][2] = 2 * e2; }
        else { E[0][1] = 2 * e1; E[2][1] = 2 * e2; }
    }
    /* |dx||dy|: concordant pairs by a Fenwick tree over y ranks, x order */
    for (size_t t = 0; t < n; t++) rank[ky[t].i] = (uint32_t)t;
    memset(tree, 0, (n + 1) * sizeof *tree);
    an_quad conc = 0;
    for (size_t t = 0; t < n; t++) {
        const uint32_t i = kx[t].i;
        const an_quad x = xy[2 * i], y = xy[2 * i + 1];
        an_quad sx = 0, sy = 0, sxy = 0;
        int64_t c = 0;
        for (size_t r = rank[i]; r > 0; r &= r - 1) {
            sx += tree[r].sx; sy += tree[r].sy; sxy += tree[r].sxy; c += tree[r].c;
        }
        conc += x * y * (an_quad)c - x * sy - y * sx + sxy;
        const an_quad xyv = x * y;
        for (size_t r = (size_t)rank[i] + 1; r <= n; r += r & (~r + 1)) {
            tree[r].sx += x; tree[r].sy += y; tree[r].sxy += xyv; tree[r].c++;
        }
    }
    const an_quad all = 2 * N * M[1][1] - 2 * M[1][0] * M[0][1];
    E[1][1] = 4 * conc - all;
}

/* sum_ij prod_k (c0 + c1 |d_k| + c2 d_k^2) from the table. */
static an_quad pair_poly(an_quad E[3][3], const an_quad c[3])
{
    an_quad s = 0;
    for (int p = 0; p < 3; p++)
        for (int q = 0; q < 3; q++) s += c[p] * c[q] * E[p][q];
    return s;
}

/* The torus-invariant two: WD^2 and diaphony^2. 0, or -1 out of memory. */
static int torus_part(const double *xy, size_t n, an_quad *wd2, an_quad *dia2)
{
    qkey *kx = malloc(n * sizeof *kx), *ky = malloc(n * sizeof *ky);
    an_quad *tmp = malloc(n * sizeof *tmp);
    uint32_t *rank = malloc(n * sizeof *rank);
    fen3 *tree = malloc((n + 1) * sizeof *tree);
    const int bad = !kx || !ky || !tmp || !rank || !tree;
    if (!bad) {
        const an_quad N2 = (an_quad)n * (an_quad)n;
        an_quad E[3][3] = {{0}};
        pair_table(xy, n, kx, ky, tmp, rank, tree, E);
        const an_quad cw[3] = {1.5, -1, 1};
        *wd2 = pair_poly(E, cw) / N2 - (an_quad)16 / 9;
        const an_quad pi = (an_quad)3.14159265358979323846264338327950288L;
        const an_quad c2 = 2 * pi * pi;
        const an_quad ch[3] = {1 + c2 / 6, -c2, c2};
        const an_quad h0 = 1 + pi * pi / 3;
        *dia2 = (pair_poly(E, ch) - N2) / (N2 * (h0 * h0 - 1));
    }
    free(kx); free(ky); free(tmp); free(rank); free(tree);
    return bad ? -1 : 0;
}

/* L2-star^2, generalised L2^2 and centred L2^2. 0, or -1 out of memory. */
static int box_part(const double *xy, size_t n, an_quad *star2, an_quad *gen2, an_quad *cen2)
{
    qkey *k = malloc(n * sizeof *k);
    an_quad *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    an_quad *ga = malloc(n * sizeof *ga), *gb = malloc(n * sizeof *gb);
    uint32_t *rank = malloc(n * sizeof *rank);
    fen1 *tree = malloc((n + 1) * sizeof *tree);
    const int bad = !k || !a || !b || !ga || !gb || !rank || !tree;
    if (bad) goto done;
    const an_quad N = (an_quad)n, N2 = N * N;

    /* L2-star and generalised L2: a = 1 - x, b = 1 - y;
     * 1 - max(x) = min(a), 2 - max(x) = 1 + min(a) */
    an_quad s_star = 0, s_gen = 0;
    for (size_t i = 0; i < n; i++) {
        const an_quad x = xy[2 * i], y = xy[2 * i + 1];
        a[i] = 1 - x;
        b[i] = 1 - y;
        s_star += (1 - x * x) * (1 - y * y);
        s_gen += (3 - x * x) * (3 - y * y) / 4;
    }
    const an_quad mm = minmin_sum(a, b, n, k, rank, tree);
    const an_quad ma = min_sum(a, n, k), mb = min_sum(b, n, k);
    *star2 = (an_quad)1 / 9 - s_star / (2 * N) + mm / N2;
    *gen2 = (an_quad)16 / 9 - 2 * s_gen / N + (N2 + ma + mb + mm) / N2;

    /* centred L2: per axis 1 + (|u_i| + |u_j| - |u_i - u_j|)/2 is
     * 1 + min(|u_i|, |u_j|) when u_i, u_j have the same sign, else 1 */
    an_quad s_cen = 0;
    for (size_t i = 0; i < n; i++) {
        const an_quad u = (an_quad)xy[2 * i] - (an_quad)0.5, v = (an_quad)xy[2 * i + 1] - (an_quad)0.5;
        a[i] = u < 0 ? -u : u;
        b[i] = v < 0 ? -v : v;
        s_cen += (1 + a[i] / 2 - a[i] * a[i] / 2) * (1 + b[i] / 2 - b[i] * b[i] / 2);
    }
    an_quad pc = N2;
    for (int axis = 0; axis < 2; axis++)
        for (int side = 0; side < 2; side++) { /* u < 0, u >= 0 */
            size_t m = 0;
            for (size_t i = 0; i < n; i++)
                if ((xy[2 * i + axis] >= 0.5) == side) ga[m++] = axis ? b[i] : a[i];
            pc += min_sum(ga, m, k);
        }
    for (int q = 0; q < 4; q++) {
        size_t m = 0;
        for (size_t i = 0; i < n; i++)
            if ((xy[2 * i] >= 0.5) == (q & 1) && (xy[2 * i + 1] >= 0.5) == (q >> 1)) {
                ga[m] = a[i];
                gb[m++] = b[i];
            }
        pc += minmin_sum(ga, gb, m, k, rank, tree);
    }
    *cen2 = (an_quad)169 / 144 - 2 * s_cen / N + pc / N2;
done:
    free(k); free(a); free(b); free(ga); free(gb); free(rank); free(tree);
    return bad ? -1 : 0;
}

double an_discrepancy_bytes(size_t n)
{
    /* both parts at once (two threads) */
    const double torus = 2.0 * sizeof(qkey) + sizeof(an_quad) + sizeof(uint32_t) + sizeof(fen3);
    const double box = sizeof(qkey) + 4.0 * sizeof(an_quad) + sizeof(uint32_t) + sizeof(fen1);
    return (double)(n + 1) * (torus + box);
}

static double root(an_quad sq) { return sq > 0 ? sqrt((double)sq) : 0; }

int an_discrepancy_compute(const double *xy, size_t n, an_discrepancy *d, char *err, size_t errlen)
{
    if (n < 1 || n >= UINT32_MAX) {
        snprintf(err, errlen, "discrepancy: n = %zu (needs 1 to %u points)", n, UINT32_MAX - 1);
        return -1;
    }
    an_quad wd2 = 0, dia2 = 0, star2 = 0, gen2 = 0, cen2 = 0;
    int bad_t = 0, bad_b = 0;
    /* two independent parts, each summed in one fixed order: the same bits
     * on one thread or two */
#pragma omp parallel sections num_threads(2) if (omp_get_max_threads() > 1 && n >= 4096)
    {
#pragma omp section
        bad_t = torus_part(xy, n, &wd2, &dia2);
#pragma omp section
        bad_b = box_part(xy, n, &star2, &gen2, &cen2);
    }
    if (bad_t || bad_b) {
        snprintf(err, errlen, "discrepancy: out of memory for n = %zu (needs %.0f MB)", n,
                 an_discrepancy_bytes(n) / 1e6);
        return -1;
    }
    d->wrap_l2 = root(wd2);
    d->diaphony = root(dia2);
    d->l2_star = root(star2);
    d->generalized_l2 = root(gen2);
    d->centred_l2 = root(cen2);
    return 0;
}
