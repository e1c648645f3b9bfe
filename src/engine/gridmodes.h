/* gridmodes.h - layer 1: the grid's print on a set and the transport that
 * removes it (issue 44; docs/method.md, "The grid's print").
 *
 * The first sweeps of a run move points far under a fixed grid, and each
 * writes a small density modulation with the grid's periods into the set:
 * a sharp peak of P(k) at the lattice vectors k = (mx, my) q, q = g / 3
 * (the cell and its three colours; q = g where 3 does not divide g), the
 * neighbouring frequencies untouched. Later sweeps under moving grids do
 * not erase it (its phase stays put over hundreds of sweeps). Its size is
 * a draw of the start against the first grids; at 4,194,304 points one
 * seed in five kept 14 times the ring at (0, g).
 *
 * The removal: the set's modes rho_hat(k) = sum_j exp(-2 pi i k.x_j) at
 * those vectors and the linearised transport that cancels them, as the
 * hyperuniform variant's for its band (transport.h): u = grad phi with
 * lap phi = the relative density restricted to the vectors,
 * u(x) = 2 Re sum_k -i k rho_hat(k) / (2 pi n |k|^2) exp(2 pi i k.x)
 * over the half plane ky > 0 or (ky = 0, kx > 0). The modes are summed in
 * fixed point, so the same bits for any thread count and, the parts'
 * sums added, any rank count. A modulation of relative size e moves the
 * points by about e / (2 pi |k|): at 4M, 0.14% of a cell.
 *
 * Owns: the vectors, the modes and the field at a point. Does not own:
 * when it runs (policy.c), how a point follows the field (transport.h's
 * clipped move, backend_cpu.c) or adding the ranks' sums
 * (engine_schedule.c). */
#ifndef CFPO_GRIDMODES_H
#define CFPO_GRIDMODES_H

#include <stdint.h>

/* (mx, my) with |mx|, |my| <= 4 in the half plane: 4 + 4 x 9. */
#define CFPO_GRIDMODES_MAX 40
/* The field is tabulated on T x T spots of its period (1 / q on each
 * axis) and read bilinearly: a wave of up to 4 periods is sampled 16
 * times a wavelength, an error of about 0.5% of the field (measured in
 * test_gridmodes: a planted print loses more than 99.9% of its P). */
#define CFPO_GRIDMODES_TABLE 64

typedef struct {
    int count;                      /* vectors in use */
    int q;                          /* their step: g / 3, or g */
    int reach;                      /* the largest |mx|, |my|: 4 or 1 */
    int mx[CFPO_GRIDMODES_MAX], my[CFPO_GRIDMODES_MAX];
    int scale_bits;                 /* the fixed point's 2^bits */
    int64_t acc[2 * CFPO_GRIDMODES_MAX]; /* sums of cos, sin (fixed point) */
    double c[2 * CFPO_GRIDMODES_MAX];    /* rho_hat(k) / (2 pi n |k|^2) */
    double *tab;                    /* the field on the table's spots */
} cfpo_gridmodes;

/* The vectors of a grid of g cells a side for a set of n points: (mx, my)
 * g / 3 with |mx|, |my| <= 4 where 3 divides g, else (mx, my) g with
 * |mx|, |my| <= 1 (the cells alone); count 0 where g < 3. 0, or -1 out of
 * memory (count 0). cfpo_gridmodes_free releases the table. */
int cfpo_gridmodes_init(cfpo_gridmodes *M, int g, int64_t n);
void cfpo_gridmodes_free(cfpo_gridmodes *M);

/* This part's np points (x[j], y[j] in [0, 1)) summed into M->acc (set,
 * not added); then the caller adds the other parts' M->acc (2 count
 * values) and calls cfpo_gridmodes_finish. */
void cfpo_gridmodes_sum(cfpo_gridmodes *M, const double *x, const double *y, int64_t np, int threads);
void cfpo_gridmodes_finish(cfpo_gridmodes *M, int64_t n);

/* P(k) = |rho_hat(k)|^2 / n at vector i, from the last finish. */
double cfpo_gridmodes_power(const cfpo_gridmodes *M, int i, int64_t n);

/* u at (x, y) (torus coordinates in [0, 1)), read from the table: a pure
 * function of the point and the last cfpo_gridmodes_finish. */
void cfpo_gridmodes_field(const cfpo_gridmodes *M, double x, double y, double *ux, double *uy);

#endif
