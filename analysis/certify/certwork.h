/* certwork.h - the certificate's shared half (certify.c, cellradius.c,
 * lct.c, vmax.c): the set with its indexes (an_cert_ctx), the per-thread
 * buffers (an_cert_work), and the periodic images of the points around a
 * place, collected into those buffers. */
#ifndef AN_CERTWORK_H
#define AN_CERTWORK_H

#include <stddef.h>
#include <stdint.h>

#include "farthest.h"
#include "cellgrid.h"
#include "ptree.h"

typedef struct {
    const double *xy;
    size_t n;
    an_cellgrid G;
    const an_ptree *tree;  /* the points, for nearest-first walks */
    const double *nn;
    double delta, rho, Dn;
    double *rho_cell;      /* per cell, where it was solved */
    double *arg_cell;      /* 2 per cell: where the cell's radius is reached */
    const double *cell_ub; /* per cell: an upper bound of its radius */
    const size_t *order;   /* the cells being solved */
    size_t top;            /* the cell where rho is reached */
} an_cert_ctx;

#define AN_PREP_SLOTS 8 /* a thread keeps this many large neighbourhoods */
#define AN_PREP_AFTER 3 /* and prepares one seen this many times */

/* Per-thread buffers: collected images (position, id), a subset, scratch. */
typedef struct {
    double *x, *y, *sx, *sy, *scratch;
    double *pa, *pb, *sd; /* polygons being clipped, signed distances */
    double *fr2;          /* squared radii of the walks' filter disks */
    size_t *id;
    uint8_t *mark;
    size_t *marked;       /* the ids marked, to clear them */
    size_t m, cap;
    an_far_ws far;        /* the farthest-point solver's buffers */
    an_far_prep prep[AN_PREP_SLOTS]; /* large neighbourhoods, prepared when seen again */
    unsigned long used[AN_PREP_SLOTS], clock; /* when each slot was last used */
    unsigned seen[AN_PREP_SLOTS];                /* how often each slot's set came */
    an_pwalk walk;
    double *cand;         /* vmax.c: images that may touch V(x), 2 per */
    size_t *cand_id, ccap;
} an_cert_work;

/* Room for m collected images, and polygons of m + 8 vertices: 0, or -1
 * (the buffers kept so far stay valid). */
int an_cert_reserve(an_cert_work *w, size_t m);

/* All images of points within Chebyshev distance H of (cx, cy) into
 * w->x/y/id/m, in a fixed order (cells by rows, points by index inside a
 * cell): 0, or -1 out of memory. */
int an_cert_collect(const an_cert_ctx *C, double cx, double cy, double H, an_cert_work *w);

/* Frees every buffer of w (each thread's, at the end). */
void an_cert_work_free(an_cert_work *w);

#endif
