/* wse3.c - weighted sample elimination on the unit 3-torus (wse3.h) and
 * its command cfpo3d-wse (bl3.h). */
#include "wse3.h"
#include "wse_heap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bl3.h"
#include "nn3.h"
#include "rng.h"
#include "solve3.h"
#include "wse.h"

#define WSE3_STREAM 0x5753453343ULL /* "WSE3C" */

double wse3_dmax(size_t N) { return cfpo3_delta_bound((double)N); }

double wse3_dmin(size_t N, size_t M, int limit)
{
    return limit ? wse3_dmax(N) * (1 - pow((double)N / (double)M, WSE_GAMMA)) * WSE_BETA : 0;
}

typedef struct {
    const double *p;
    size_t c;
    double dmax, dmin, alpha;
    long G;                /* cells a side; 0: every pair, every image */
    size_t *cstart, *cell;
    wse_heap H; /* the weights' max-heap, ties by index */
    char *dead;
} stage;

static int64_t weight_ab(const stage *S, size_t a, size_t b)
{
    const double *p = S->p + 3 * a, *q = S->p + 3 * b;
    if (S->G) {
        const double dx = cfpo3_pdiff(p[0], q[0]), dy = cfpo3_pdiff(p[1], q[1]), dz = cfpo3_pdiff(p[2], q[2]);
        return wse_pair_weight(dx * dx + dy * dy + dz * dz, S->dmax, S->dmin, S->alpha);
    }
    int64_t w = 0;
    for (int oz = -2; oz <= 2; oz++)
        for (int oy = -2; oy <= 2; oy++)
            for (int ox = -2; ox <= 2; ox++) {
                const double dx = p[0] - q[0] + ox, dy = p[1] - q[1] + oy, dz = p[2] - q[2] + oz;
                w += wse_pair_weight(dx * dx + dy * dy + dz * dz, S->dmax, S->dmin, S->alpha);
            }
    return w;
}

static long cell1(double x, long G)
{
    long c = (long)floor(x * (double)G);
    return c < 0 ? 0 : (c >= G ? G - 1 : c);
}

static size_t cell_of(const double *p, long G) { return (size_t)((cell1(p[2], G) * G + cell1(p[1], G)) * G + cell1(p[0], G)); }

static void neighbours(stage *S, size_t a, void (*f)(stage *, size_t, size_t))
{
    if (!S->G) {
        for (size_t b = 0; b < S->c; b++)
            if (b != a && !S->dead[b]) f(S, a, b);
        return;
    }
    const double *p = S->p + 3 * a;
    const long G = S->G, cx = cell1(p[0], G), cy = cell1(p[1], G), cz = cell1(p[2], G);
    for (long oz = -1; oz <= 1; oz++)
        for (long oy = -1; oy <= 1; oy++)
            for (long ox = -1; ox <= 1; ox++) {
                const size_t c = (size_t)((((cz + oz + G) % G) * G + (cy + oy + G) % G) * G + (cx + ox + G) % G);
                for (size_t k = S->cstart[c]; k < S->cstart[c + 1]; k++) {
                    const size_t b = S->cell[k];
                    if (b != a && !S->dead[b]) f(S, a, b);
                }
            }
}

static void add_weight(stage *S, size_t a, size_t b) { S->H.w[a] += weight_ab(S, a, b); }

static void lower_weight(stage *S, size_t a, size_t b)
{
    wse_heap_lower(&S->H, b, weight_ab(S, a, b));
}

int wse3_order(const double *xyz, size_t M, size_t n, double alpha, int limit, size_t *keep)
{
    stage S = {.p = xyz, .c = M, .alpha = alpha};
    S.dmax = wse3_dmax(n);
    S.dmin = wse3_dmin(n, M, limit);
    S.G = S.dmax <= 1.0 / 3 ? (long)floor(1.0 / S.dmax) : 0;
    if (S.G > 1024) S.G = 1024;
    const size_t cells = S.G ? (size_t)S.G * (size_t)S.G * (size_t)S.G : 0;
    S.cstart = calloc(cells + 2, sizeof *S.cstart);
    S.cell = malloc(M * sizeof *S.cell);
    const int heap_ok = wse_heap_alloc(&S.H, M, NULL) == 0;
    S.dead = calloc(M, 1);
    int rc = -1;
    if (!S.cstart || !S.cell || !heap_ok || !S.dead) goto done;
    if (S.G) { /* counting sort into cells */
        for (size_t a = 0; a < M; a++) S.cstart[cell_of(xyz + 3 * a, S.G) + 2]++;
        for (size_t k = 2; k < cells + 2; k++) S.cstart[k] += S.cstart[k - 1];
        for (size_t a = 0; a < M; a++) S.cell[S.cstart[cell_of(xyz + 3 * a, S.G) + 1]++] = a;
    }
    for (size_t a = 0; a < M; a++) neighbours(&S, a, add_weight);
    wse_heap_build(&S.H, M);
    for (size_t e = 0; e + n < M; e++) {
        const size_t a = wse_heap_pop(&S.H);
        S.dead[a] = 1;
        neighbours(&S, a, lower_weight);
    }
    size_t k = 0;
    for (size_t a = 0; a < M; a++)
        if (!S.dead[a]) keep[k++] = a;
    rc = 0;
done:
    free(S.cstart), free(S.cell), free(S.dead);
    wse_heap_free(&S.H);
    return rc;
}

int wse3_points(int64_t n, uint64_t seed, double ratio, double alpha, int limit, double *out, char *err,
                size_t errlen)
{
    const size_t M = (size_t)ceil(ratio * (double)n);
    double *cand = malloc(3 * M * sizeof *cand);
    size_t *keep = malloc((size_t)n * sizeof *keep);
    if (cand)
        for (size_t i = 0; i < 3 * M; i++) cand[i] = cfpo_rand01(seed, WSE3_STREAM, (uint64_t)i);
    if (!cand || !keep || wse3_order(cand, M, (size_t)n, alpha, limit, keep) != 0) {
        free(cand), free(keep);
        snprintf(err, errlen, "out of memory for %zu candidates", M);
        return -1;
    }
    for (size_t i = 0; i < (size_t)n; i++)
        for (int a = 0; a < 3; a++) out[3 * i + a] = cand[3 * keep[i] + a];
    free(cand), free(keep);
    return 0;
}

enum { RATIO, ALPHA, LIMIT };

static int run_wse(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                   int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    (void)cb, (void)user;
    *xyz = malloc(3 * (size_t)n * sizeof **xyz);
    if (!*xyz) {
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        return -1;
    }
    if (wse3_points(n, seed, opt[RATIO], opt[ALPHA], opt[LIMIT] != 0, *xyz, err, errlen) != 0) {
        free(*xyz);
        *xyz = NULL;
        return -1;
    }
    info->trials = (int64_t)ceil(opt[RATIO] * (double)n);
    *n_out = n;
    return 0;
}

const bl3_method bl3_wse = {
    .name = "wse3d", .prog = "cfpo3d-wse", .min_n = 1, .run = run_wse, .noptions = 3,
    .options = {{"ratio", WSE_RATIO, 1, 100, "      --ratio R        candidates per output point (default %g, the paper's)\n"},
                {"alpha", WSE_ALPHA, 0.01, 64, "      --alpha A        the weight's exponent (default %g, the paper's)\n"},
                {"weight-limit", 1, 0, 1,
                 "      --weight-limit 0|1  weight limiting, beta 0.65, gamma 1.5 (default %g: on, the\n"
                 "                       paper's)\n"}},
    .about = "Weighted sample elimination (Yuksel, Eurographics 2015) on the periodic unit\n"
             "cube: ratio * n white-noise candidates, pair weights (1 - d/d_max)^alpha within\n"
             "d_max = 2 r_max = Delta3(n), r_max = (1 / (4 sqrt(2) n))^(1/3), weight limiting,\n"
             "the heaviest sample eliminated until n remain. Direct."};
