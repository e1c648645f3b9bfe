/* nnhist.h - nearest-neighbour distances of one set: delta_min and
 * delta_avg normalised by Delta(n) (from the core's cfpo_nn_stats), and a
 * histogram of the normalised distances d / Delta(n): AN_NN_BINS bins of
 * width AN_NN_BIN on [0, AN_NN_BINS * AN_NN_BIN), the last bin also holding
 * everything beyond. Counts add over sets. */
#ifndef AN_NNHIST_H
#define AN_NNHIST_H

#include <stddef.h>
#include <stdint.h>

#include "ptree.h"

#define AN_NN_BINS 200
#define AN_NN_BIN 0.01

typedef struct {
    double delta_min, delta_avg; /* of this set, / Delta(n) */
    double *nn;                  /* n distances (not normalised), owned */
} an_nn;

/* The core's cfpo_nn_stats, the same bits (each distance the same
 * minimum of cfpo_torus_dist2, summed in the same order). Where more than
 * AN_NN_CROWDED points share a cell of the core's grid (about 2 a cell),
 * through the points' tree T (NULL: one is built), about n log n however
 * they crowd, where the grid costs n^2 on a cluster; else the core's grid,
 * faster on a spread set. 0, or -1. */
#define AN_NN_CROWDED 64
int an_nn_stats(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg);
/* The same, always through the tree. */
int an_nn_stats_tree(const double *xy, size_t n, const an_ptree *T, double *nn, double *delta_min, double *delta_avg);

/* n >= 2. Adds this set's distances into hist (AN_NN_BINS counts).
 * 0, or -1 when out of memory. Free nn with free(). */
int an_nn_compute(const double *xy, size_t n, an_nn *out, uint64_t *hist);

#endif
