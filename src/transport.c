/* transport.c - see transport.h: the low-frequency modes, the transport field
 * and the clipped move of the hyperuniform variant. */
#include "transport.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"

/* The coefficient sum runs over at most this many fixed chunks of the
 * points, summed in chunk order: the same bits for any thread count. */
#define CHUNKS 16
/* A spot this hair short of where the displacement meets a circle or the
 * square, so that rounding leaves it outside; the exact check decides. */
#define SHORT (1 - 1e-9)

int cfpo_transport_init(cfpo_transport *F, int64_t n, int threads)
{
    const int K = (int)floor(sqrt((double)n / 25.0));
    const size_t most = (size_t)(2 * K + 1) * (size_t)(K + 1), W = (size_t)(2 * K + 1);
    F->K = K;
    F->m = 0;
    F->threads = threads > 0 ? threads : 1;
    F->k = malloc(sizeof(int) * 2 * most);
    F->c = calloc(2 * most, sizeof(double));
    F->part = calloc(CHUNKS * 2 * most, sizeof(double));
    F->tab = malloc(sizeof(double) * 4 * W * (CHUNKS + (size_t)F->threads));
    if (!F->k || !F->c || !F->part || !F->tab) {
        cfpo_transport_free(F);
        return -1;
    }
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (ky == 0 && kx <= 0) continue; /* one of each pair +-k, no k = 0 */
            if (!cfpo_in_lowk_band(kx, ky, (int64_t)n)) continue;
            F->k[2 * F->m] = kx;
            F->k[2 * F->m + 1] = ky;
            F->m++;
        }
    return 0;
}

void cfpo_transport_free(cfpo_transport *F)
{
    free(F->k);
    free(F->c);
    free(F->part);
    free(F->tab);
    F->k = NULL;
    F->c = NULL;
    F->part = NULL;
    F->tab = NULL;
    F->m = 0;
}

/* exp(-2 pi i k x) for k = -K..K at re[K + k], im[K + k], by recurrence
 * from one cosine and sine. */
static void powers(double x, int K, double *re, double *im)
{
    const double c = cos(2 * M_PI * x), s = -sin(2 * M_PI * x);
    re[K] = 1;
    im[K] = 0;
    for (int k = 1; k <= K; k++) {
        re[K + k] = re[K + k - 1] * c - im[K + k - 1] * s;
        im[K + k] = re[K + k - 1] * s + im[K + k - 1] * c;
        re[K - k] = re[K + k];
        im[K - k] = -im[K + k];
    }
}

void cfpo_transport_coeffs(cfpo_transport *F, const double *x, const double *y, int64_t np, int64_t n)
{
    const int m = F->m, W = 2 * F->K + 1;
    const int64_t nch = np < CHUNKS ? (np > 0 ? np : 1) : CHUNKS;
    double *part = F->part;
    memset(part, 0, sizeof(double) * (size_t)nch * 2 * (size_t)m);
#pragma omp parallel for schedule(static) num_threads(F->threads)
    for (int64_t ch = 0; ch < nch; ch++) {
        double *tab = F->tab + (size_t)ch * 4 * (size_t)W;
        double *er = tab, *ei = tab + W, *fr = tab + 2 * W, *fi = tab + 3 * W, *p = part + ch * 2 * m;
        for (int64_t j = np * ch / nch; j < np * (ch + 1) / nch; j++) {
            powers(x[j], F->K, er, ei);
            powers(y[j], F->K, fr, fi);
            for (int q = 0; q < m; q++) {
                const int a = F->K + F->k[2 * q], b = F->K + F->k[2 * q + 1];
                p[2 * q] += er[a] * fr[b] - ei[a] * fi[b];
                p[2 * q + 1] += er[a] * fi[b] + ei[a] * fr[b];
            }
        }
    }
    for (int q = 0; q < m; q++) {
        double re = 0, im = 0;
        for (int64_t ch = 0; ch < nch; ch++) {
            re += part[ch * 2 * m + 2 * q];
            im += part[ch * 2 * m + 2 * q + 1];
        }
        const double kx = F->k[2 * q], ky = F->k[2 * q + 1];
        const double s = 2 * M_PI * (double)n * (kx * kx + ky * ky);
        F->c[2 * q] = re / s;
        F->c[2 * q + 1] = im / s;
    }
}

void cfpo_transport_field(const cfpo_transport *F, double x, double y, int thread, double *ux, double *uy)
{
    const int W = 2 * F->K + 1;
    double *tab = F->tab + (size_t)(CHUNKS + thread) * 4 * (size_t)W;
    double *er = tab, *ei = tab + W, *fr = tab + 2 * W, *fi = tab + 3 * W;
    powers(x, F->K, er, ei);
    powers(y, F->K, fr, fi);
    double sx = 0, sy = 0;
    for (int q = 0; q < F->m; q++) {
        const int a = F->K + F->k[2 * q], b = F->K + F->k[2 * q + 1];
        /* exp(2 pi i k.x) = cos + i sin, the conjugate of the tables' product */
        const double co = er[a] * fr[b] - ei[a] * fi[b], si = -(er[a] * fi[b] + ei[a] * fr[b]);
        /* Re(-i c exp(2 pi i k.x)) = c_re sin + c_im cos; each pair +-k twice */
        const double t = F->c[2 * q] * si + F->c[2 * q + 1] * co;
        sx += F->k[2 * q] * t;
        sy += F->k[2 * q + 1] * t;
    }
    *ux = 2 * sx;
    *uy = 2 * sy;
}

/* How far (a fraction s of (vx, vy), in [0, 1]) the point can go before it
 * comes nearer than sqrt(floor2) to a block point or leaves S; *blk: the
 * block point that stops it, -2 / -3 the square's side in x / y, -1 none. */
static double reach(double x, double y, double vx, double vy, const double *bx, const double *by, int m, int self,
                    double floor2, const cfpo_square *S, int *blk)
{
    const double a = vx * vx + vy * vy;
    double s = 1;
    *blk = -1;
    if (a == 0) return 0;
    for (int i = 0; i < m; i++) {
        if (i == self) continue;
        const double dx = x - bx[i], dy = y - by[i], b = 2 * (dx * vx + dy * vy);
        if (b >= 0) continue; /* going away from it */
        const double disc = b * b - 4 * a * (dx * dx + dy * dy - floor2);
        if (disc <= 0) continue;
        double s1 = (-b - sqrt(disc)) / (2 * a);
        if (s1 < 0) s1 = 0;
        if (s1 < s) s = s1, *blk = i;
    }
    const double sx = vx > 0 ? (S->x1 - x) / vx : vx < 0 ? (S->x0 - x) / vx : 1;
    const double sy = vy > 0 ? (S->y1 - y) / vy : vy < 0 ? (S->y0 - y) / vy : 1;
    if (sx < s) s = fmax(sx, 0), *blk = -2;
    if (sy < s) s = fmax(sy, 0), *blk = -3;
    return s;
}

static int admissible(double x, double y, const double *bx, const double *by, int m, int self, double floor2,
                      const cfpo_square *S)
{
    return x >= S->x0 && x <= S->x1 && y >= S->y0 && y <= S->y1 && cfpo_min_dist2(x, y, bx, by, m, self) >= floor2;
}

int cfpo_transport_move(double x, double y, double vx, double vy, const double *bx, const double *by, int m,
                      int self, double floor2, const cfpo_square *S, double *nx, double *ny)
{
    *nx = x;
    *ny = y;
    int blk;
    const double s = reach(x, y, vx, vy, bx, by, m, self, floor2, S, &blk) * SHORT;
    const double px = x + s * vx, py = y + s * vy;
    if (s <= 0 || !admissible(px, py, bx, by, m, self, floor2, S)) return 0;
    *nx = px;
    *ny = py;
    if (blk == -1) return 1;
    /* the rest of the displacement, along the tangent of what stopped it */
    double rx = (1 - s) * vx, ry = (1 - s) * vy;
    if (blk >= 0) {
        const double ex = px - bx[blk], ey = py - by[blk], pr = (rx * ex + ry * ey) / (ex * ex + ey * ey);
        rx -= pr * ex;
        ry -= pr * ey;
    } else if (blk == -2) {
        rx = 0;
    } else {
        ry = 0;
    }
    int b2;
    const double t = reach(px, py, rx, ry, bx, by, m, self, floor2, S, &b2) * SHORT;
    const double qx = px + t * rx, qy = py + t * ry;
    if (t > 0 && admissible(qx, qy, bx, by, m, self, floor2, S)) {
        *nx = qx;
        *ny = qy;
    }
    return 1;
}
