/* pdset.h - the growing sample set and its front, shared by boundary
 * sampling and Bridson: points in placement order (growing arrays), the
 * background grid, and the active list (samples that may still have free
 * space around them) with O(1) random choice and removal.
 * Does not own: how a new point is chosen (bsample.c, bridson.c). */
#ifndef CFPO_BASELINES_PDSET_H
#define CFPO_BASELINES_PDSET_H

#include <stdint.h>

#include "arcs.h"
#include "pdgrid.h"

typedef struct {
    pdgrid G;
    double rho;          /* placement / coverage radius, r (1 + PD_RHO_EPS) */
    double *xy;
    int64_t n, cap;
    uint32_t *active;    /* ids on the front */
    int64_t nactive;
    int64_t *pos;        /* per id: index in `active`, or -1 when retired */
    int64_t *slot;       /* per id: index of its arcs in `arcs`, or -1 (BS only) */
    arcs *pool;          /* arcs of the active ids (BS only) */
    int64_t *free_slots;
    int64_t npool, nfree, poolcap;
    int track_arcs;      /* BS: keep arcs for every active sample */
} pdset;

/* 0, or -1 when out of memory. hint: the expected number of points. */
int pdset_init(pdset *S, double r, int64_t hint, int track_arcs);
void pdset_free(pdset *S);

/* Adds (x, y) (no conflict: the caller checked) and makes it active. With
 * arc tracking, its arcs are computed from its neighbours within 2 rho,
 * the neighbours' arcs lose what it covers, and samples left with no arc
 * leave the front. Returns the id, or -1 when out of memory. */
int64_t pdset_add(pdset *S, double x, double y);

/* Removes the active sample at index k of the active list. */
void pdset_retire(pdset *S, int64_t k);

/* The arcs of C(s, rho) not covered by the other samples, from scratch. */
void pdset_free_arcs(const pdset *S, uint32_t s, arcs *A);

/* Hands the point array to the caller (the set no longer owns it). */
double *pdset_take_points(pdset *S);

#endif
