/* nngrow.h - nearest neighbour among a growing subset of a point set on the
 * unit torus: points are inserted one at a time, and a query returns the
 * squared torus distance from any position to the nearest inserted point.
 *
 * Owns: a uniform grid of about 2 inserted points a cell, rebuilt when the
 * count quadruples (the side doubles; O(n) rebuilding in all), and the ring
 * search over it: rings of cells around the query's cell until the best
 * distance found is at most r cell sides (no unseen point can be nearer),
 * falling back to all inserted points when the rings would cover more
 * cells than there are points, or wrap onto themselves. Exact: the same
 * minimum as a loop over every inserted point. Used by the prefix measures
 * (analysis/measures/prefixes.c) and the greedy farthest-point order
 * (fporder.c). */
#ifndef CFPO_BASELINES_NNGROW_H
#define CFPO_BASELINES_NNGROW_H
#include <stddef.h>

typedef struct {
    const double *xy; /* the whole set, n points; not owned */
    size_t n, count;  /* points in the set, points inserted */
    size_t *ids;      /* the inserted points' indices, in order */
    long G;           /* cells a side */
    long *head, *next;
} bl_nngrow;

/* 0, or -1 when out of memory. */
int bl_nngrow_init(bl_nngrow *g, const double *xy, size_t n);
/* Inserts point i (0 <= i < n, each at most once). 0, or -1 when out of memory. */
int bl_nngrow_insert(bl_nngrow *g, size_t i);
/* Squared torus distance from p to the nearest inserted point (INFINITY
 * when none is); *id, when not NULL: that point (the first found on ties). */
double bl_nngrow_nearest2(const bl_nngrow *g, const double *p, size_t *id);
void bl_nngrow_free(bl_nngrow *g);
/* Squared minimum-image distance on the unit torus. */
double bl_torus_d2(const double *a, const double *b);
#endif
