/* dens_measure.h - layer 2: the symmetric pair measure of a point set
 * under a density (docs/method.md, "Density").
 *
 * With local spacing r(x) = Delta(n) / sqrt(rho(x)), the measure of a pair
 * is m(i, j) = |x_i - x_j| / sqrt(r_i r_j) = |x_i - x_j| (rho_i rho_j)^(1/4)
 * / Delta(n), |.| the torus distance, rho_i the density of x_i's pixel.
 * For rho = 1 it is today's |x_i - x_j| / Delta(n). delta_min is the
 * smallest m over all pairs; delta_avg the mean over points of each
 * point's smallest m (its nearest neighbour in the measure). A point in a
 * zero-density pixel has m = 0 to every other point.
 * Owns: the measure's exact nearest-neighbour search (a uniform grid,
 * rings outward until no unvisited cell can hold a smaller m). */
#ifndef CFPO_DENS_MEASURE_H
#define CFPO_DENS_MEASURE_H

#include <stddef.h>

#include "dens_qbound.h"
#include "density.h"

/* Each point's smallest measure into m (n doubles; may be NULL), and
 * delta_min, delta_avg. n >= 2. 0, or -1 when out of memory. The result
 * does not depend on the number of threads. */
int cfpo_dens_nn(const cfpo_density *d, const double *xy, size_t n, double *m, double *delta_min, double *delta_avg);
/* A caller's store of the search grid's near bounds, kept between
 * measures of one density (the grid has no offset and its side depends on
 * n alone): per cell, the least q (qlow's) over the cells within
 * CFPO_DENS_NN_NEAR of it, which bounds q over a point's reach when the
 * reach stays inside them, in place of a query of the pyramid each point
 * (the same result: the search's minimum is exact whatever bound holds).
 * Zero-initialised; cfpo_dens_nn_near_free releases it. */
#define CFPO_DENS_NN_NEAR 4
/* The pyramid levels below the query's own that the search reads its
 * bounds from (cfpo_dens_qbound_box_finer): a box's 2 x 2 coarse texels
 * reach up to twice its side past it, into sparser ground than the reach
 * meets. At 4,096 points on the ramp 1:256 that sent a third of the points
 * on to ring 3; reading two levels finer (at most 9 x 9 texels) halves the
 * search's instructions there, the same minimum (results
 * 2026-12-01-dens23). */
#define CFPO_DENS_NN_FINER 2
typedef struct {
    long long g; /* the grid it is for (0: none) */
    const cfpo_dens_qbound *qlow;
    float *q;
} cfpo_dens_nn_near;
void cfpo_dens_nn_near_free(cfpo_dens_nn_near *c);

/* The same as cfpo_dens_nn with qlow, d's pyramid of minima
 * (cfpo_dens_qbound_build_min), built once by a caller that measures many
 * times (NULL: built here), near (NULL: none), q as for cfpo_dens_nn_first
 * below (NULL: read here), on nthreads threads (0: OpenMP's default; an
 * engine passes its own count, so that -t 1 measures on one thread). */
int cfpo_dens_nn_q(const cfpo_density *d, const cfpo_dens_qbound *qlow, cfpo_dens_nn_near *near, const double *xy,
                   const double *q, size_t n, double *m, double *delta_min, double *delta_avg, int nthreads);

/* Pieces of it, for a rank that holds part of the set (dens_engine.c):
 * the smallest measure of each of the first k of the n points xy against
 * all n (Delta = D, that of the whole set) into m, q[i] the sqrt of the
 * density at point i as cfpo_density_at gives it (NULL: read here), qlow the pyramid
 * of minima of d (cfpo_dens_qbound_build_min; NULL: built here), near as
 * above, on nthreads threads (0: OpenMP's default); 0, or -1 when out of
 * memory. Then delta_min and delta_avg of the n measures m, summed in
 * their order. */
int cfpo_dens_nn_first(const cfpo_density *d, const cfpo_dens_qbound *qlow, cfpo_dens_nn_near *near, const double *xy,
                       const double *q, size_t n, size_t k, double D, double *m, int nthreads);
void cfpo_dens_nn_sum(const double *m, size_t n, double *delta_min, double *delta_avg);

#endif
