/* bl_set.h - layer 2 of the baselines: the engine of a direct sampler
 * (bl_method.h): a set of n points made at once by its create, with no
 * iterate. The white-noise, jittered and Sobol' samplers (bl_direct.c),
 * weighted sample elimination (bl_wse.c) and PMJ02BN (bl_pmj.c) share
 * it: their create allocates the set, fills bl_set_xy and hands it to the
 * run loop, which then reads these three members of the method's table. */
#ifndef CFPO_BL_SET_H
#define CFPO_BL_SET_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int64_t n;
    double *xy; /* 2 n doubles */
} bl_set;

/* A set of n points, its coordinates not yet written; NULL with "out of
 * memory for n = N" in err. */
bl_set *bl_set_new(int64_t n, char *err, size_t errlen);

/* The method table's deltas (the set's nearest-neighbour statistics; NaN
 * when out of memory, as the other engines), points and destroy. */
void bl_set_deltas(void *E, double *dmin, double *davg);
const double *bl_set_points(void *E);
void bl_set_destroy(void *E);

/* The three, for a method table's initialiser. */
#define BL_SET_ENGINE .deltas = bl_set_deltas, .points = bl_set_points, .destroy = bl_set_destroy

#endif
