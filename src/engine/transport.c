/* transport.c - see transport.h: the band's transport field through the
 * NUFFT and the clipped move of the hyperuniform variant. */
#include "transport.h"

#include <math.h>
#include <stdlib.h>

/* A spot this hair short of where the displacement meets a circle or the
 * square, so that rounding leaves it outside; the exact check decides. */
#define SHORT (1 - 1e-9)

/* The largest |kx|, |ky| the field takes: the band and its taper. */
static int field_K(int64_t n) { return (int)floor(sqrt((double)n / 25.0) * (1 + CFPO_TRANSPORT_TAPER)); }

/* The weight of mode k in the field: 1 on the band (25 |k|^2 <= n), falling
 * as cos^2 to 0 at (1 + CFPO_TRANSPORT_TAPER) times its radius, 0 beyond. */
static double band_weight(int kx, int ky, int64_t n)
{
    if (cfpo_in_lowk_band(kx, ky, n)) return 1;
    const int64_t q = (int64_t)kx * kx + (int64_t)ky * ky;
    if (q == 0) return 0;
    const double r = (sqrt(25.0 * (double)q / (double)n) - 1) / CFPO_TRANSPORT_TAPER;
    if (r >= 1) return 0;
    const double c = cos(0.5 * M_PI * r);
    return c * c;
}

int cfpo_transport_init(cfpo_transport *F, int64_t n, int threads)
{
    char err[128];
    F->K = field_K(n);
    F->C = NULL;
    if (F->K < 1) F->K = 1; /* below 25 points the band is empty: C stays 0 */
    if (cfpo_nufft_init(&F->U, F->K, CFPO_TRANSPORT_WIDTH, CFPO_NUFFT_TYPE1 | CFPO_NUFFT_TYPE2, threads, err,
                        sizeof err) != 0)
        return -1;
    const size_t W = 2 * (size_t)F->K + 1;
    F->C = calloc(2 * W * W, sizeof *F->C);
    if (!F->C) {
        cfpo_transport_free(F);
        return -1;
    }
    return 0;
}

void cfpo_transport_free(cfpo_transport *F)
{
    if (F->U.phihat) cfpo_nufft_free(&F->U);
    free(F->C);
    F->C = NULL;
}

double cfpo_transport_bytes(int64_t n, int64_t np)
{
    int K = field_K(n);
    if (K < 1) K = 1;
    int M = 2 * (2 * K + 1);
    if (M < 2 * CFPO_TRANSPORT_WIDTH) M = 2 * CFPO_TRANSPORT_WIDTH;
    M = cfpo_nufft_fft_size(M);
    const double m = (double)M, w = 2.0 * K + 1;
    /* type 1's real grid (M x (M/2 + 1) complex), type 2's complex grid,
     * the band's coefficients, and the spread's order of the points */
    return 8.0 * m * 2.0 * (double)(M / 2 + 1) + 16.0 * m * m + 16.0 * w * w + 8.0 * (double)np;
}

int cfpo_transport_spread(cfpo_transport *F, const double *x, const double *y, int64_t np, int64_t n)
{
    return cfpo_nufft_spread(&F->U, x, y, 1, (size_t)np, n);
}

int64_t *cfpo_transport_grid(cfpo_transport *F) { return cfpo_nufft_grid(&F->U); }
size_t cfpo_transport_grid_count(const cfpo_transport *F) { return cfpo_nufft_grid_count(&F->U); }

void cfpo_transport_finish(cfpo_transport *F, int64_t n)
{
    const int K = F->K, W = 2 * K + 1;
    cfpo_nufft_type1_finish(&F->U, n);
    /* ux + i uy = sum_k c(k) (ky - i kx) exp(2 pi i k.x), c(k) = rho_hat(k) / (2 pi n |k|^2) */
    for (int ky = -K; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            double *C = F->C + 2 * ((size_t)(ky + K) * (size_t)W + (size_t)(kx + K));
            const double w = band_weight(kx, ky, n);
            if (w == 0) {
                C[0] = C[1] = 0;
                continue;
            }
            double re, im;
            cfpo_nufft_coef(&F->U, kx, ky, &re, &im);
            const double s = 2 * M_PI * (double)n * (double)(kx * kx + ky * ky) / w;
            re /= s;
            im /= s;
            C[0] = re * ky + im * kx;
            C[1] = im * ky - re * kx;
        }
    cfpo_nufft_type2_prepare(&F->U, F->C);
}

void cfpo_transport_field(const cfpo_transport *F, double x, double y, double *ux, double *uy)
{
    cfpo_nufft_type2_at(&F->U, x, y, ux, uy);
}

/* The fractions of (vx, vy) that take (x, y) to S's side in x and in y
 * (1 where it does not move on that axis). */
static void to_sides(double x, double y, double vx, double vy, const cfpo_square *S, double *sx, double *sy)
{
    *sx = vx > 0 ? (S->x1 - x) / vx : vx < 0 ? (S->x0 - x) / vx : 1;
    *sy = vy > 0 ? (S->y1 - y) / vy : vy < 0 ? (S->y0 - y) / vy : 1;
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
    double sx, sy;
    to_sides(x, y, vx, vy, S, &sx, &sy);
    if (sx < s) s = fmax(sx, 0), *blk = -2;
    if (sy < s) s = fmax(sy, 0), *blk = -3;
    return s;
}

static int admissible(double x, double y, const double *bx, const double *by, int m, int self, double floor2,
                      const cfpo_square *S)
{
    return x >= S->x0 && x <= S->x1 && y >= S->y0 && y <= S->y1 && cfpo_min_dist2(x, y, bx, by, m, self) >= floor2;
}

/* A displacement that ends this much farther than the floor from the
 * nearest point, less its length, is clear of every circle. */
#define CLEAR (1 + 1e-9)

int cfpo_transport_move(double x, double y, double vx, double vy, const double *bx, const double *by, int m,
                      int self, double r02, double floor2, const cfpo_square *S, double *nx, double *ny)
{
    *nx = x;
    *ny = y;
    /* the whole displacement inside S and clear of every circle: the spot
     * the search below finds (s = SHORT, nothing stops it), without it */
    const double a = vx * vx + vy * vy;
    if (a > 0) {
        double sx, sy;
        to_sides(x, y, vx, vy, S, &sx, &sy);
        if (sx >= 1 && sy >= 1 && sqrt(r02) - sqrt(a) > sqrt(floor2) * CLEAR) {
            *nx = x + SHORT * vx;
            *ny = y + SHORT * vy;
            return 1;
        }
    }
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
