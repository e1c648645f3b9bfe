/* wse.c - weighted sample elimination and its progressive order (wse.h). */
#include "wse.h"
#include "wse_heap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "jitter.h"
#include "nngrow.h"

double wse_dmax(size_t N) { return 2.0 * sqrt(1.0 / (2.0 * sqrt(3.0) * (double)N)); }

int64_t wse_pair_weight(double q, double dmax, double dmin, double alpha)
{
    if (!(q < dmax * dmax)) return 0;
    double d = sqrt(q);
    if (d < dmin) d = dmin;
    return (int64_t)llround(pow(1.0 - d / dmax, alpha) * WSE_UNIT);
}

/* One stage: the c points ids[0..c) down to t. */
typedef struct {
    const double *xy;
    const size_t *ids;
    size_t c;
    double dmax, dmin, alpha;
    long G;              /* cells a side; 0: every pair, every image */
    size_t *cstart, *cell; /* the points of each cell (local indices) */
    wse_heap H;          /* the weights' max-heap of local indices, ties by candidate index */
    char *dead;
} stage;

/* the pair weight of local points a and b, all images within d_max */
static int64_t weight_ab(const stage *S, size_t a, size_t b)
{
    const double *p = S->xy + 2 * S->ids[a], *q = S->xy + 2 * S->ids[b];
    if (S->G) return wse_pair_weight(bl_torus_d2(p, q), S->dmax, S->dmin, S->alpha);
    int64_t w = 0;
    for (int oy = -2; oy <= 2; oy++)
        for (int ox = -2; ox <= 2; ox++) {
            const double dx = p[0] - q[0] + ox, dy = p[1] - q[1] + oy;
            w += wse_pair_weight(dx * dx + dy * dy, S->dmax, S->dmin, S->alpha);
        }
    return w;
}

static long cell_of(double x, long G)
{
    long c = (long)floor(x * (double)G);
    return c < 0 ? 0 : (c >= G ? G - 1 : c);
}

/* calls f(S, a, b, sign) for every live neighbour b != a of a */
static void neighbours(stage *S, size_t a, int64_t sign, void (*f)(stage *, size_t, size_t, int64_t))
{
    if (!S->G) {
        for (size_t b = 0; b < S->c; b++)
            if (b != a && !S->dead[b]) f(S, a, b, sign);
        return;
    }
    const double *p = S->xy + 2 * S->ids[a];
    const long G = S->G, cx = cell_of(p[0], G), cy = cell_of(p[1], G);
    for (long oy = -1; oy <= 1; oy++)
        for (long ox = -1; ox <= 1; ox++) {
            const long c = ((cy + oy + G) % G) * G + (cx + ox + G) % G;
            for (size_t k = S->cstart[c]; k < S->cstart[c + 1]; k++) {
                const size_t b = S->cell[k];
                if (b != a && !S->dead[b]) f(S, a, b, sign);
            }
        }
}

static void add_weight(stage *S, size_t a, size_t b, int64_t sign) { S->H.w[a] += sign * weight_ab(S, a, b); }

static void lower_weight(stage *S, size_t a, size_t b, int64_t sign)
{
    (void)sign;
    wse_heap_lower(&S->H, b, weight_ab(S, a, b));
}

/* ids[0..c) to ids[0..t) kept (in their order) and ids[t..c) eliminated,
 * the later-eliminated first. */
static int eliminate(const double *xy, size_t *ids, size_t c, size_t t, const wse_params *p)
{
    if (t >= c) return 0;
    stage S = {.xy = xy, .ids = ids, .c = c, .alpha = p->alpha};
    S.dmax = wse_dmax(t);
    S.dmin = p->weight_limit ? S.dmax * (1 - pow((double)t / (double)c, WSE_GAMMA)) * WSE_BETA : 0;
    S.G = S.dmax <= 1.0 / 3 ? (long)floor(1.0 / S.dmax) : 0;
    if (S.G > 4096) S.G = 4096;
    const size_t cells = S.G ? (size_t)S.G * (size_t)S.G : 0;
    S.cstart = calloc(cells + 2, sizeof *S.cstart);
    S.cell = malloc(c * sizeof *S.cell);
    const int heap_ok = wse_heap_alloc(&S.H, c, ids) == 0;
    S.dead = calloc(c, 1);
    size_t *gone = malloc(c * sizeof *gone);
    int rc = -1;
    if (!S.cstart || !S.cell || !heap_ok || !S.dead || !gone) goto done;
    if (S.G) { /* counting sort of the points into cells */
        for (size_t a = 0; a < c; a++)
            S.cstart[cell_of(xy[2 * ids[a] + 1], S.G) * S.G + cell_of(xy[2 * ids[a]], S.G) + 2]++;
        for (size_t k = 2; k < cells + 2; k++) S.cstart[k] += S.cstart[k - 1];
        for (size_t a = 0; a < c; a++)
            S.cell[S.cstart[cell_of(xy[2 * ids[a] + 1], S.G) * S.G + cell_of(xy[2 * ids[a]], S.G) + 1]++] = a;
    }
    for (size_t a = 0; a < c; a++) neighbours(&S, a, 1, add_weight);
    wse_heap_build(&S.H, c);
    for (size_t e = 0; e < c - t; e++) {
        const size_t a = wse_heap_pop(&S.H);
        S.dead[a] = 1;
        gone[e] = ids[a];
        neighbours(&S, a, -1, lower_weight);
    }
    size_t k = 0;
    for (size_t a = 0; a < c; a++)
        if (!S.dead[a]) ids[k++] = ids[a];
    for (size_t e = c - t; e-- > 0;) ids[k++] = gone[e];
    rc = 0;
done:
    free(S.cstart), free(S.cell), free(S.dead), free(gone);
    wse_heap_free(&S.H);
    return rc;
}

int wse_order(const double *xy, size_t M, size_t n, const wse_params *p, size_t *order)
{
    size_t *ids = malloc(M * sizeof *ids);
    if (!ids) return -1;
    for (size_t i = 0; i < M; i++) ids[i] = i;
    int rc = eliminate(xy, ids, M, n, p);
    for (size_t c = n; rc == 0 && p->progressive && c > 1; c /= 2) rc = eliminate(xy, ids, c, c / 2, p);
    if (rc == 0) memcpy(order, ids, n * sizeof *ids);
    free(ids);
    return rc;
}

int wse_points(int64_t n, uint64_t seed, double ratio, const wse_params *p, double *out, char *err, size_t errlen)
{
    const size_t M = (size_t)ceil(ratio * (double)n);
    double *cand = malloc(2 * M * sizeof *cand);
    size_t *order = malloc((size_t)n * sizeof *order);
    if (!cand || !order) {
        free(cand), free(order);
        snprintf(err, errlen, "out of memory for %zu candidates", M);
        return -1;
    }
    white_points((int64_t)M, seed, cand);
    if (wse_order(cand, M, (size_t)n, p, order) != 0) {
        free(cand), free(order);
        snprintf(err, errlen, "out of memory for %zu candidates", M);
        return -1;
    }
    for (size_t i = 0; i < (size_t)n; i++) out[2 * i] = cand[2 * order[i]], out[2 * i + 1] = cand[2 * order[i] + 1];
    free(cand), free(order);
    return 0;
}
