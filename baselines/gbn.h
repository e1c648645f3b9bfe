/* gbn.h - Gaussian blue noise (Ahmed, Ren, Wonka 2022) on the unit torus:
 * gradient descent on the energy sum_{i != j} exp(-|x_i - x_j|^2 / (2 s^2)),
 * s = sigma / sqrt(n), as the authors' toroidal code runs it.
 *
 * Owns: the engine (uniform random start; every iteration moves every point
 * at once, Jacobi-style, by step * sum_j d_ij exp(-|d_ij|^2 / (2 s^2)),
 * d_ij the nearest periodic image of x_i - x_j, the step divided by sigma^2
 * when sigma > 1, as the authors' code; then wraps into [0, 1)); the
 * authors' defaults (sigma 1, step 0.25, 1000 iterations); the kernel
 * truncated at `cutoff` s through a cell list of side >= cutoff s (the
 * authors sum over all pairs in O(n^2) on a GPU); the iteration statistics.
 * A point's move is a fixed-order sum over its 3 x 3 cells, so the points
 * are the same bytes for any number of OpenMP threads.
 * Does not own: the run loop and its stop rules (bl_loop.c), files. */
#ifndef CFPO_BASELINES_GBN_H
#define CFPO_BASELINES_GBN_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GBN_SIGMA 1.0     /* the authors' default, in units of n^(-1/2) */
#define GBN_STEP 0.25     /* the authors' default time step */
#define GBN_ITERATIONS 1000 /* the authors' example run */
#define GBN_CUTOFF 6.0    /* the kernel's truncation, in s */

typedef struct {
    uint64_t seed;
    double sigma, step, cutoff, tol;
    int iterations; /* converged after this many (the authors' fixed count) */
    int threads;    /* OpenMP threads; 0: all cores */
} gbn_options;

void gbn_options_init(gbn_options *o);

/* Bytes for n points. */
double gbn_bytes(int64_t n);

typedef struct gbn_engine gbn_engine;

/* The uniform start; NULL with a message when out of memory. */
gbn_engine *gbn_create(int64_t n, const gbn_options *o, char *err, size_t errlen);
void gbn_free(gbn_engine *E);

/* One gradient step of every point; fills everything but s->iteration.
 * Converged after o.iterations steps, or earlier when no point moved
 * tol * L (L cfpo's cell side for n). */
void gbn_iterate(gbn_engine *E, cfpo_iter_stats *s);

/* delta_min, delta_avg of the current points. */
void gbn_deltas(gbn_engine *E, double *dmin, double *davg);

/* The points (x0 y0 x1 y1 ...), owned by E. */
const double *gbn_points(const gbn_engine *E);

/* The gradient sum of point i over every other point (nearest image, no
 * truncation): the authors' O(n) sum, for tests. */
void gbn_full_gradient(const gbn_engine *E, int64_t i, double *gx, double *gy);

/* The truncated sum the iteration uses, for tests. */
void gbn_cell_gradient(gbn_engine *E, int64_t i, double *gx, double *gy);

#ifdef __cplusplus
}
#endif
#endif
