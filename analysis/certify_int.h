/* certify_int.h - what the certificate's files share (certify.c, vmax.c,
 * lct.c): the set and its indexes, and the per-thread buffers. */
#ifndef AN_CERTIFY_INT_H
#define AN_CERTIFY_INT_H

#include <stddef.h>
#include <stdint.h>

#include "farthest.h"
#include "grid.h"
#include "ptree.h"

typedef struct {
    const double *xy;
    size_t n;
    an_grid G;
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

/* A grid cell and a radius (or a bound of it); qsort's order: largest
 * radius first, then the lower cell index (certify.c). */
typedef struct {
    double r;
    size_t c;
} an_cell_key;
int an_cell_key_desc(const void *a, const void *b);

/* Room for m collected images, and polygons of m + 8 vertices: 0, or -1
 * (the buffers kept so far stay valid). */
int an_cert_reserve(an_cert_work *w, size_t m);

/* All images of points within Chebyshev distance H of (cx, cy) into
 * w->x/y/id/m, in a fixed order (cells by rows, points by index inside a
 * cell): 0, or -1 out of memory. */
int an_cert_collect(const an_cert_ctx *C, double cx, double cy, double H, an_cert_work *w);

/* An upper bound of cell c's largest empty circle radius with X \ {skip}
 * (skip = n: none): its centre's distance to the set plus its
 * half-diagonal, raised against rounding. */
double an_cell_bound(const an_cert_ctx *C, size_t c, size_t skip);

/* Cell c's largest empty circle radius with X \ {skip} into *out and
 * where it is reached (wrapped) into arg[0..1], given ub = an upper bound
 * of it. 0, -1 out of memory, -2 the solver found nothing. */
int an_cell_radius(const an_cert_ctx *C, size_t c, double ub, size_t skip, an_cert_work *w, double *out, double *arg);

/* Both properties of the Local Characterization Theorem for point i, with
 * D(x) of half-side h (lct.c): their violations, absolute. 0, -1 out of
 * memory, -2 the solver found no vertex. */
int an_lct(const an_cert_ctx *C, size_t i, an_cert_work *w, double h, double *p1, double *p2);

/* The touching test of a bisector with a convex polygon P (vmax.c): eps =
 * 1e-9 of P's extent from (x, y), and whether the bisector of (x, y) and
 * (px, py) meets P within eps, (v - m).n >= -eps |n| at a vertex v. */
double an_touch_eps(const double *P, int nv, double x, double y);
int an_touches(const double *P, int nv, double x, double y, double px, double py, double eps);

/* T of the farthest point test for point i at (x, y) (certify.c says what
 * it is): the square of half-side s, the images of the touching points
 * gathered within Chebyshev Hg. *T = -1 when V(x) is empty or T < rho
 * for certain. 0, -1 out of memory, or -2 the solver found no vertex. */
int an_vmax(const an_cert_ctx *C, size_t i, an_cert_work *w, double x, double y, double s, double Hg, double *T,
            double *tx, double *ty);

#endif
