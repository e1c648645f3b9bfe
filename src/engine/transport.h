/* transport.h - layer 1: the low-frequency transport of the hyperuniform
 * variant (docs/method.md, "--variant hyperuniform").
 *
 * The density modes rho_hat(k) = sum_j exp(-2 pi i k.x_j) of a set of n
 * points over 0 < |k| <= 0.2 sqrt(n) (exactly: 25 |k|^2 <= n, the range of
 * cfpo-analyze's p0), and the linearised transport that removes them: the
 * displacement u = grad phi with lap phi = the relative density restricted
 * to those modes, u(x) = sum_k -i k rho_hat(k) / (2 pi n |k|^2)
 * exp(2 pi i k.x). Past the band's radius kb the modes are taken with a
 * weight falling as cos^2 to 0 at (1 + CFPO_TRANSPORT_TAPER) kb, so that
 * P rises over a few rings there instead of stepping up about 100 times
 * inside one. A point follows u as far as it can while its distance to
 * every point of its 3x3 block stays at least a floor, then slides along
 * what stopped it.
 *
 * Both sums go through the non-uniform FFT (nufft.h), kernel width
 * CFPO_TRANSPORT_WIDTH: type 1 for rho_hat (spread in fixed point, so the
 * same bits for any thread count and, the parts' integer grids summed, any
 * rank count), type 2 for u (ux + i uy as one complex field), O(n + K^2
 * log K) a sweep instead of the direct sums' O(n K^2).
 *
 * Owns: the band's coefficients of u and the field at a point, the clipped
 * move. Does not own: when the transport runs (policy.c), which points it
 * moves (backend_cpu.c) or adding the ranks' grids (engine_schedule.c). */
#ifndef CFPO_TRANSPORT_H
#define CFPO_TRANSPORT_H

#include <stddef.h>
#include <stdint.h>

#include "geom.h"
#include "nufft.h"

/* The kernel width: the NUFFT's error about 10^-(w-1) of the largest term. */
#define CFPO_TRANSPORT_WIDTH 6
/* The field's taper past the band, relative to its radius: 3 rings of the
 * spectrum at 262,144 points. */
#define CFPO_TRANSPORT_TAPER 0.03

typedef struct {
    int K;        /* the largest |kx|, |ky| of the band and its taper */
    cfpo_nufft U; /* both directions */
    double *C;    /* (2K + 1)^2 complex: the ux + i uy coefficients */
} cfpo_transport;

/* The transport of a set of n points (n >= 25: the band is not empty),
 * spreading on `threads` threads. 0, or -1 out of memory. */
int cfpo_transport_init(cfpo_transport *F, int64_t n, int threads);
void cfpo_transport_free(cfpo_transport *F);
/* The memory cfpo_transport_init takes for a set of n points, and the most
 * a sweep adds while it spreads np of them (its order), in bytes: what
 * --dry-run adds for the hyperuniform variant. */
double cfpo_transport_bytes(int64_t n, int64_t np);

/* The np points (x[j], y[j]) of this part of a set of n points spread onto
 * the grid (cfpo_nufft_spread); 0, or -1 out of memory. Then the caller
 * adds the other parts' grids (cfpo_transport_grid, _grid_count) and calls
 * cfpo_transport_finish: the field from the whole set's modes. */
int cfpo_transport_spread(cfpo_transport *F, const double *x, const double *y, int64_t np, int64_t n);
int64_t *cfpo_transport_grid(cfpo_transport *F);
size_t cfpo_transport_grid_count(const cfpo_transport *F);
void cfpo_transport_finish(cfpo_transport *F, int64_t n);

/* u at (x, y) (torus coordinates in [0, 1)): a pure function of the point
 * and the last cfpo_transport_finish. */
void cfpo_transport_field(const cfpo_transport *F, double x, double y, double *ux, double *uy);

/* The point `self` of the m block points (bx, by) at (x, y), displaced by
 * (vx, vy): it goes along the displacement until the spot would come
 * nearer than sqrt(floor2) to a block point or leave S, then slides on,
 * with what is left of the displacement, along the tangent of what stopped
 * it, as far again. The spot (*nx, *ny) is in S and at least sqrt(floor2)
 * from every other block point, checked exactly; (x, y) itself if no
 * such spot was found (x must then satisfy both). r02: the point's squared
 * distance to the nearest other block point (a displacement that stays
 * clear of every circle skips the search). Returns 1 if it moved. */
int cfpo_transport_move(double x, double y, double vx, double vy, const double *bx, const double *by, int m,
                      int self, double r02, double floor2, const cfpo_square *S, double *nx, double *ny);

#endif
