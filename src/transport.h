/* transport.h - layer 1: the low-frequency transport of the hyperuniform
 * variant (docs/method.md, "--variant hyperuniform").
 *
 * The density modes rho_hat(k) = sum_j exp(-2 pi i k.x_j) of a set of n
 * points over 0 < |k| <= 0.2 sqrt(n) (exactly: 25 |k|^2 <= n, the range of
 * cfpo-analyze's p0), and the linearised transport that removes them: the
 * displacement u = grad phi with lap phi = the relative density restricted
 * to those modes, u(x) = sum_k -i k rho_hat(k) / (2 pi n |k|^2)
 * exp(2 pi i k.x). A point follows u as far as it can while its distance to
 * every point of its 3x3 block stays at least a floor, then slides along
 * what stopped it.
 *
 * Owns: the mode list, the coefficients (a sum over all points in fixed
 * chunks, so the same bits for any thread count), the field at a point and
 * the clipped move. Does not own: when the transport runs (policy.c) or
 * which points it moves (backend_cpu.c). */
#ifndef CFPO_TRANSPORT_H
#define CFPO_TRANSPORT_H

#include <stddef.h>
#include <stdint.h>

#include "geom.h"

typedef struct {
    int m;     /* modes, one of each pair +-k */
    int K;     /* the largest |kx|, |ky| */
    int *k;    /* 2 per mode: kx, ky */
    double *c; /* 2 per mode: rho_hat(k) / (2 pi n |k|^2), real and imaginary */
    double *part; /* the chunks' partial sums */
    double *tab;  /* per chunk, then per thread: the exponentials of one point */
    int threads;
} cfpo_transport;

/* The modes of a set of n points, c zeroed, scratch for `threads` threads.
 * 0, or -1 out of memory. */
int cfpo_transport_init(cfpo_transport *F, int64_t n, int threads);
void cfpo_transport_free(cfpo_transport *F);

/* c from the np points (x[j], y[j]) of a set of n points, on F's threads;
 * the same bits for any thread count. */
void cfpo_transport_coeffs(cfpo_transport *F, const double *x, const double *y, int64_t np, int64_t n);

/* u at (x, y) (torus coordinates), by thread `thread` of F's. */
void cfpo_transport_field(const cfpo_transport *F, double x, double y, int thread, double *ux, double *uy);

/* The point `self` of the m block points (bx, by) at (x, y), displaced by
 * (vx, vy): it goes along the displacement until the spot would come
 * nearer than sqrt(floor2) to a block point or leave S, then slides on,
 * with what is left of the displacement, along the tangent of what stopped
 * it, as far again. The spot (*nx, *ny) is in S and at least sqrt(floor2)
 * from every other block point, checked exactly; (x, y) itself if no
 * such spot was found (x must then satisfy both). Returns 1 if it moved. */
int cfpo_transport_move(double x, double y, double vx, double vy, const double *bx, const double *by, int m,
                      int self, double floor2, const cfpo_square *S, double *nx, double *ny);

#endif
