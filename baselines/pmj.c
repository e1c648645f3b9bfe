/* pmj.c - see pmj.h. */
#include "pmj.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rng.h"

#define BITS 53 /* a coordinate is a 53-digit binary fraction */

static const uint64_t STREAM = 0x504d4a303242ULL; /* "PMJ02B" */

typedef struct {
    int cand;
    uint64_t seed, stream;
    uint64_t *px, *py; /* the points as 53-digit integers */
    int k;             /* the current step's target: 2^k points */
    uint8_t *occ;      /* shape a's cells at occ + (a << k): (k + 1) 2^k flags */
    uint32_t *lx, *ly; /* the valid k-digit strata of the subquadrant */
    int nx, ny;
    int g;             /* the nearest-neighbour grid: g x g cells */
    int32_t *head, *next;
    double best2;      /* the pruning bound of a nearest-neighbour query */
    int global;        /* candidates from every valid subquadrant (below) */
    int f;             /* the step's subquadrants: top f digits */
    uint32_t *box;     /* global: the subquadrants whose fixed shapes are free */
    int32_t *bpos;     /* a subquadrant's place in box, or -1 */
    int64_t nbox;
} pmj;

static uint64_t rnd(const pmj *P, int64_t i, uint64_t c, int j)
{
    return cfpo_rand64(P->seed, P->stream + ((c << 2) | (uint64_t)j) * 0x9e3779b97f4a7c15ULL, (uint64_t)i);
}

static size_t cell_index(int k, int a, uint64_t X, uint64_t Y)
{
    return ((size_t)a << k) | (size_t)((X >> (k - a)) << (k - a)) | (size_t)(Y >> a);
}

static void box_remove(pmj *P, uint64_t id)
{
    const int32_t at = P->bpos[id];
    if (at < 0) return;
    const uint32_t last = P->box[--P->nbox];
    P->box[at] = last;
    P->bpos[last] = at;
    P->bpos[id] = -1;
}

static void mark(pmj *P, int64_t j)
{
    const int k = P->k;
    const uint64_t X = P->px[j] >> (BITS - k), Y = P->py[j] >> (BITS - k);
    for (int a = 0; a <= k; a++) P->occ[cell_index(k, a, X, Y)] = 1;
}

/* Global: point j takes the subquadrants inside the cells it occupies of
 * the shapes a subquadrant fixes. */
static void take_boxes(pmj *P, int64_t j)
{
    const int k = P->k, f = P->f;
    const uint64_t X = P->px[j] >> (BITS - k), Y = P->py[j] >> (BITS - k);
    for (int a = k - f > 0 ? k - f : 0; a <= f; a++) {
        const uint64_t xa = X >> (k - a), ya = Y >> a;
        for (uint64_t u = 0; u < (uint64_t)1 << (f - a); u++)
            for (uint64_t v = 0; v < (uint64_t)1 << (f - (k - a)); v++)
                box_remove(P, ((((xa << (f - a)) | u)) << f) | (ya << (f - (k - a))) | v);
    }
}

static int grid_cell(const pmj *P, uint64_t v)
{
    int c = (int)((double)v * 0x1.0p-53 * P->g);
    return c < P->g ? c : P->g - 1;
}

static void grid_insert(pmj *P, int64_t j)
{
    const int c = grid_cell(P, P->py[j]) * P->g + grid_cell(P, P->px[j]);
    P->next[j] = P->head[c];
    P->head[c] = (int32_t)j;
}

static double torus2(uint64_t ax, uint64_t ay, uint64_t bx, uint64_t by)
{
    double dx = fabs((double)ax - (double)bx) * 0x1.0p-53, dy = fabs((double)ay - (double)by) * 0x1.0p-53;
    dx = dx > 0.5 ? 1 - dx : dx;
    dy = dy > 0.5 ? 1 - dy : dy;
    return dx * dx + dy * dy;
}

static double scan_cell(const pmj *P, int cx, int cy, uint64_t x, uint64_t y, double d2)
{
    cx = (cx % P->g + P->g) % P->g;
    cy = (cy % P->g + P->g) % P->g;
    for (int32_t q = P->head[cy * P->g + cx]; q >= 0; q = P->next[q]) {
        const double e = torus2(x, y, P->px[q], P->py[q]);
        d2 = e < d2 ? e : d2;
    }
    return d2;
}

/* The squared periodic distance from (x, y) to the nearest placed point, or
 * any value <= P->best2 once it is known to be at most that (a candidate
 * that cannot win); INFINITY with no point placed. */
static double nearest2(const pmj *P, uint64_t x, uint64_t y)
{
    const int g = P->g, cx = grid_cell(P, x), cy = grid_cell(P, y);
    const double w = 1.0 / g;
    double d2 = INFINITY;
    for (int r = 0;; r++) {
        if (2 * r + 1 > g) { /* the rings wrap: every cell once */
            for (int yy = 0; yy < g; yy++)
                for (int xx = 0; xx < g; xx++) d2 = scan_cell(P, xx, yy, x, y, d2);
            return d2;
        }
        if (r == 0) d2 = scan_cell(P, cx, cy, x, y, d2);
        for (int t = -r; t <= r && r > 0; t++) {
            d2 = scan_cell(P, cx + t, cy - r, x, y, d2);
            d2 = scan_cell(P, cx + t, cy + r, x, y, d2);
            if (t > -r && t < r) {
                d2 = scan_cell(P, cx - r, cy + t, x, y, d2);
                d2 = scan_cell(P, cx + r, cy + t, x, y, d2);
            }
        }
        /* the cells of ring r + 1 and beyond are at least r w away */
        if (d2 <= P->best2 || d2 <= (r * w) * (r * w)) return d2;
    }
}

/* The valid k-digit x strata below the f-digit prefix X0 (Y0 fixes the y
 * digits the shapes a > f ask for). */
static void valid_x(pmj *P, uint64_t prefix, int d, int f, uint64_t Y0)
{
    const int k = P->k;
    if (d > f && P->occ[((size_t)d << k) | (size_t)(prefix << (k - d)) | (size_t)(Y0 >> (f - (k - d)))]) return;
    if (d == k) {
        P->lx[P->nx++] = (uint32_t)prefix;
        return;
    }
    valid_x(P, prefix << 1, d + 1, f, Y0);
    valid_x(P, (prefix << 1) | 1, d + 1, f, Y0);
}

/* The same for y: at digit e > f the shape a = k - e, its x digits from X0. */
static void valid_y(pmj *P, uint64_t prefix, int e, int f, uint64_t X0)
{
    const int k = P->k, a = k - e;
    if (e > f && P->occ[((size_t)a << k) | (size_t)((X0 >> (f - a)) << (k - a)) | (size_t)prefix]) return;
    if (e == k) {
        P->ly[P->ny++] = (uint32_t)prefix;
        return;
    }
    valid_y(P, prefix << 1, e + 1, f, X0);
    valid_y(P, (prefix << 1) | 1, e + 1, f, X0);
}

/* The valid strata of the subquadrant whose top f digits are (X0, Y0) into
 * lx, ly (from index 0): 0 when it holds no valid position. */
static int valid(pmj *P, uint64_t X0, uint64_t Y0, int f)
{
    const int k = P->k;
    for (int a = k - f > 0 ? k - f : 0; a <= f; a++) /* the shapes the subquadrant fixes */
        if (P->occ[((size_t)a << k) | (size_t)((X0 >> (f - a)) << (k - a)) | (size_t)(Y0 >> (f - (k - a)))])
            return 0;
    P->nx = P->ny = 0;
    valid_x(P, X0, f, f, Y0);
    valid_y(P, Y0, f, f, X0);
    return P->nx > 0 && P->ny > 0;
}

/* Point j in one of the nsub (1 or 2) subquadrants (X0[s], Y0[s]), the
 * first valid one when there is one candidate, else the best candidate over
 * both: -1 when none holds a valid position. */
static int place(pmj *P, int64_t j, const uint64_t *X0, const uint64_t *Y0, int nsub, int f)
{
    const int k = P->k;
    int ok[2] = {0, 0}, any = 0;
    for (int s = 0; s < nsub; s++) {
        ok[s] = valid(P, X0[s], Y0[s], f);
        any += ok[s];
        if (ok[s] && P->cand == 1) {
            nsub = s + 1; /* pmj02: the first valid subquadrant */
            ok[0] = s == 0;
            break;
        }
    }
    if (!any) return -1;
    uint64_t bx = 0, by = 0;
    P->best2 = -1;
    for (int c = 0; c < P->cand; c++) {
        /* a valid subquadrant at random (both valid: the candidate's bit) */
        int s = ok[0] && (nsub == 1 || !ok[1] || !(rnd(P, j, (uint64_t)c, 0) & 1)) ? 0 : 1;
        valid(P, X0[s], Y0[s], f);
        const uint64_t rx = rnd(P, j, (uint64_t)c, 0) >> 1, ry = rnd(P, j, (uint64_t)c, 1);
        const uint64_t X = P->lx[rx % (uint64_t)P->nx], Y = P->ly[ry % (uint64_t)P->ny];
        /* the digits below the stratum: the high bits of fresh random words */
        const uint64_t x = (X << (BITS - k)) | (rnd(P, j, (uint64_t)c, 2) >> (64 - (BITS - k)));
        const uint64_t y = (Y << (BITS - k)) | (rnd(P, j, (uint64_t)c, 3) >> (64 - (BITS - k)));
        if (P->cand == 1) {
            bx = x, by = y;
            break;
        }
        const double d2 = nearest2(P, x, y);
        if (d2 > P->best2) {
            P->best2 = d2;
            bx = x, by = y;
        }
    }
    P->px[j] = bx;
    P->py[j] = by;
    mark(P, j);
    if (P->cand > 1) grid_insert(P, j);
    return 0;
}

/* Global: point j the best of the candidates drawn from random subquadrants
 * among all those whose fixed shapes are free (a subquadrant found without
 * a valid position leaves the list for good: strata only fill): -1 when
 * none is left. */
static int place_global(pmj *P, int64_t j)
{
    const int k = P->k, f = P->f;
    uint64_t bx = 0, by = 0;
    int got = 0;
    P->best2 = -1;
    for (uint64_t c = 0; got < P->cand && P->nbox > 0; c++) {
        const uint64_t id = P->box[rnd(P, j, c, 0) % (uint64_t)P->nbox];
        const uint64_t X0 = id >> f, Y0 = id & (((uint64_t)1 << f) - 1);
        if (!valid(P, X0, Y0, f)) {
            box_remove(P, id);
            continue;
        }
        const uint64_t X = P->lx[rnd(P, j, c, 1) % (uint64_t)P->nx], Y = P->ly[rnd(P, j, c, 1) % (uint64_t)P->ny];
        const uint64_t x = (X << (BITS - k)) | (rnd(P, j, c, 2) >> (64 - (BITS - k)));
        const uint64_t y = (Y << (BITS - k)) | (rnd(P, j, c, 3) >> (64 - (BITS - k)));
        const double d2 = got == 0 && P->cand == 1 ? 0 : nearest2(P, x, y);
        if (got++ == 0 || d2 > P->best2) {
            P->best2 = d2;
            bx = x, by = y;
        }
    }
    if (!got) return -1;
    P->px[j] = bx;
    P->py[j] = by;
    mark(P, j);
    take_boxes(P, j);
    if (P->cand > 1) grid_insert(P, j);
    return 0;
}

/* Strata and grid for the step towards 2^k points, from points 0..count-1. */
static void start_step(pmj *P, int k, int64_t count)
{
    P->k = k;
    P->f = (k + 1) / 2;
    memset(P->occ, 0, (size_t)(k + 1) << k);
    for (int64_t j = 0; j < count; j++) mark(P, j);
    if (P->global) { /* every subquadrant whose fixed shapes are free */
        const int f = P->f;
        P->nbox = 0;
        for (uint64_t id = 0; id < (uint64_t)1 << (2 * f); id++) {
            const uint64_t X0 = id >> f, Y0 = id & (((uint64_t)1 << f) - 1);
            int ok = 1;
            for (int a = k - f > 0 ? k - f : 0; a <= f && ok; a++)
                ok = !P->occ[((size_t)a << k) | (size_t)((X0 >> (f - a)) << (k - a)) | (size_t)(Y0 >> (f - (k - a)))];
            P->bpos[id] = ok ? (int32_t)P->nbox : -1;
            if (ok) P->box[P->nbox++] = (uint32_t)id;
        }
    }
    if (P->cand > 1) {
        P->g = (int)sqrt((double)((int64_t)1 << k));
        P->g = P->g < 1 ? 1 : P->g;
        for (int c = 0; c < P->g * P->g; c++) P->head[c] = -1;
        for (int64_t j = 0; j < count; j++) grid_insert(P, j);
    }
}

static uint64_t top(uint64_t v, int f) { return v >> (BITS - f); }

/* Global: the points from 2^(k-1) to 2^k (or end) on all valid subquadrants. */
static int global_step(pmj *P, int k, int64_t end)
{
    const int64_t from = (int64_t)1 << (k - 1), to = (int64_t)1 << k;
    start_step(P, k, from);
    for (int64_t j = from; j < to && j < end; j++)
        if (place_global(P, j) != 0) return -1;
    return 0;
}

/* The even step from N = 4^m points: point N + i diagonally opposite point
 * i in its cell of the 2^m grid. */
static int even_step(pmj *P, int m, int64_t N, int64_t end)
{
    start_step(P, 2 * m + 1, N);
    for (int64_t i = 0; i < N && N + i < end; i++) {
        const uint64_t X = top(P->px[i], m + 1) ^ 1, Y = top(P->py[i], m + 1) ^ 1;
        if (place(P, N + i, &X, &Y, 1, m + 1) != 0) return -1;
    }
    return 0;
}

/* The odd step from 2N points: 2N + i and 3N + i in the two subquadrants of
 * point i's cell that points i and N + i leave empty. */
static int odd_step(pmj *P, int m, int64_t N, int64_t end)
{
    const int f = m + 1;
    start_step(P, 2 * m + 2, 2 * N);
    for (int64_t i = 0; i < N && 2 * N + i < end; i++) {
        const uint64_t X = top(P->px[i], f), Y = top(P->py[i], f);
        const int first = (int)(rnd(P, 2 * N + i, PMJ_MAX_CANDIDATES + 1, 0) >> 63);
        /* (X, Y ^ 1) or (X ^ 1, Y): pmj02 the random one first, the other
         * if it is stuck; pmj02bn the best candidate of both */
        const uint64_t XS[2] = {X ^ (uint64_t)first, X ^ (uint64_t)!first};
        const uint64_t YS[2] = {Y ^ (uint64_t)!first, Y ^ (uint64_t)first};
        if (place(P, 2 * N + i, XS, YS, 2, f) != 0) return -1;
    }
    for (int64_t i = 0; i < N && 3 * N + i < end; i++) { /* diagonally opposite 2N + i */
        const uint64_t X = top(P->px[2 * N + i], f) ^ 1, Y = top(P->py[2 * N + i], f) ^ 1;
        if (place(P, 3 * N + i, &X, &Y, 1, f) != 0) return -1;
    }
    return 0;
}

int pmj_points(int64_t n, uint64_t seed, const pmj_params *prm, double *xy, int *redone, char *err, size_t errlen)
{
    if (redone) *redone = 0;
    const int candidates = prm->candidates;
    if (n < 1 || n > PMJ_MAX_N || candidates < 1 || candidates > PMJ_MAX_CANDIDATES) {
        snprintf(err, errlen, "pmj: n = %lld or %d candidates out of range", (long long)n, candidates);
        return -1;
    }
    int K = 0;
    while (((int64_t)1 << K) < n) K++;
    pmj P = {.cand = candidates, .seed = seed, .global = prm->global};
    const size_t side = (size_t)1 << ((K + 1) / 2 + 1);
    P.px = malloc((size_t)n * sizeof *P.px);
    P.py = malloc((size_t)n * sizeof *P.py);
    P.occ = malloc((size_t)(K + 1) << K);
    P.lx = malloc(side * sizeof *P.lx);
    P.ly = malloc(side * sizeof *P.ly);
    if (candidates > 1) {
        P.head = malloc(((size_t)1 << K) * sizeof *P.head);
        P.next = malloc((size_t)n * sizeof *P.next);
    }
    if (P.global) { /* 2^(2f) subquadrants, 2f <= K + 1 */
        P.box = malloc(((size_t)2 << K) * sizeof *P.box);
        P.bpos = malloc(((size_t)2 << K) * sizeof *P.bpos);
    }
    int rc = 0;
    if (!P.px || !P.py || !P.occ || !P.lx || !P.ly || (candidates > 1 && (!P.head || !P.next)) ||
        (P.global && (!P.box || !P.bpos))) {
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        rc = -1;
        goto out;
    }
    P.stream = STREAM;
    P.px[0] = rnd(&P, 0, 0, 0) >> (64 - BITS);
    P.py[0] = rnd(&P, 0, 0, 1) >> (64 - BITS);
    /* step k: the points from 2^(k-1) to 2^k; k = 2m + 1 the even step from
     * 4^m points, k = 2m + 2 the odd one */
    for (int k = 1; k <= K && rc == 0; k++) {
        const int m = (k - 1) / 2;
        const int64_t N = (int64_t)1 << (2 * m);
        int tries = 0;
        /* a step stuck in a dead end starts again on other random numbers */
        for (P.stream = STREAM; (P.global ? global_step(&P, k, n)
                                 : k % 2 ? even_step(&P, m, N, n) : odd_step(&P, m, N, n)) != 0;) {
            if (++tries >= PMJ_RETRIES) {
                snprintf(err, errlen, "pmj: the step to %lld points was stuck %d times", (long long)1 << k, tries);
                rc = -1;
                break;
            }
            P.stream = STREAM + (uint64_t)tries * 0xd1b54a32d192ed03ULL;
            if (redone) (*redone)++;
        }
    }
    for (int64_t j = 0; j < n && rc == 0; j++) {
        xy[2 * j] = (double)P.px[j] * 0x1.0p-53;
        xy[2 * j + 1] = (double)P.py[j] * 0x1.0p-53;
    }
out:
    free(P.px), free(P.py), free(P.occ), free(P.lx), free(P.ly), free(P.head), free(P.next), free(P.box),
        free(P.bpos);
    return rc;
}
