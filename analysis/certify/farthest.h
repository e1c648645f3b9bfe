/* farthest.h - the farthest point of a square from a finite set, for any
 * size of set: the certificate's one solver call (certify.c).
 *
 * Up to AN_FAR_SMALL points it is the core's exact LocalCFPO solver
 * (cfpo_local_solve), unchanged, so sets like cfpo's (a few dozen points
 * in a neighbourhood) give the same bits as before. Above that the same
 * exact method (the largest vertex distance over each point's Voronoi
 * region clipped to the square) runs in another order, so that degenerate
 * sets (clusters, lines, repeated points) cost about n log n instead of
 * n^2 or n^3:
 *  - the points go into a 2-d tree split at the middle of the wider side
 *    of each box (deep where the points are dense), and repeated positions
 *    are merged (the distance to a set does not depend on how often a
 *    position occurs);
 *  - each point's region is clipped by the other points box by box,
 *    nearest first, skipping every box at least twice the region's reach
 *    away (no bisector of its points can cut the region);
 *  - the best value starts at the farthest corner of the square, and a
 *    point with a neighbour in each of the eight 45-degree sectors around
 *    it closer than sqrt(2) times that value is passed over: its region
 *    cannot reach farther (farthest.c says why); a region no farther than
 *    the best value found is abandoned, as in the core solver;
 *  - the square is first solved against the points not passed over only:
 *    that answer bounds the true one from above, and is kept when no
 *    passed-over point is nearer to its point (then it is reached).
 * Both give the exact maximum up to the rounding of the clipping; the
 * value returned is recomputed from the distances themselves. */
#ifndef AN_FARTHEST_H
#define AN_FARTHEST_H

#include <stddef.h>

#include "geom.h"

#define AN_FAR_SMALL 128

/* Grows on demand; zero-initialise, an_far_free at the end. */
struct an_kd_node;
typedef struct {
    double *x, *y, *key, *pa, *pb, *sd, *scratch;
    double *fx, *fy; /* the points that may be nearest somewhere in the square */
    struct an_kd_node *nodes;
    size_t cap, nodes_used;
    long *hull;    /* per position: the hull vertices before and after it, or -1 */
    double *hbuf;  /* the hull's sort buffer */
    int hull_ok;   /* hull[] describes the current tree */
} an_far_ws;

/* The point (*cx, *cy) of S farthest from the m points (yx, yy): returns
 * its squared distance to them (infinity for m = 0, with S's centre), or
 * -1 (out of memory, or no vertex found: a solver failure). */
double an_farthest(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy, double *cx,
                   double *cy, an_far_ws *ws);
void an_far_free(an_far_ws *ws);

/* A set prepared once for many solves (farprep.c): the same answers as
 * an_farthest's tree, with each solve costing about the number of
 * positions whose Voronoi cell reaches far (a cluster's rim) instead of
 * the whole set. Zero-initialise; an_far_prep_free at the end. */
typedef struct {
    an_far_ws tree;  /* the set's positions in tree order, and the tree */
    double *reach2;  /* per tree position: its cell's squared reach */
    size_t *cand;    /* the positions by decreasing reach */
    double *yx, *yy; /* the set as given, to recognise it */
    size_t *copies;  /* per tree position: how often the set holds it */
    double x0, y0, x1, y1; /* the set's bounding box */
    double Rb;       /* the half-side of the box a cell's reach is taken in */
    size_t m, u, cap;
    int ready;       /* built since set */
} an_far_prep;

/* 1 when the m points (yx, yy) are, in order, the set last given. */
int an_far_prep_same(const an_far_prep *P, const double *yx, const double *yy, size_t m);
/* Keeps a copy of the set (not built yet): 0, or -1 out of memory. */
int an_far_prep_set(an_far_prep *P, const double *yx, const double *yy, size_t m);
/* Builds the tree and the reaches of the set given: 0, or -1. */
int an_far_prep_build(an_far_prep *P);
/* The point of S farthest from the set, or (exclude) from the set with
 * one copy of the position (ex, ey) left out; its squared distance. With
 * exclude, `from` (or NULL) may give this function's answer for the same
 * S with nothing left out, which spares most of the work. -1
 * out of memory or not built; -3 when this case is not for the prepared
 * form (the position is not in the set, or its cell is not bounded):
 * call an_farthest. */
double an_far_prep_solve(const an_far_prep *P, cfpo_square S, int exclude, double ex, double ey, const double *from,
                         double *cx, double *cy, an_far_ws *ws);
/* The squared distance from (x, y) to the set, or (exclude) to the set
 * with one copy of the position (ex, ey) left out (INFINITY if none is
 * left); -1 not built. */
double an_far_prep_nearest(const an_far_prep *P, double x, double y, int exclude, double ex, double ey);
void an_far_prep_free(an_far_prep *P);

/* qsort's order of (x, y) pairs of doubles: by x, then by y. */
int an_cmp_pair(const void *a, const void *b);

#endif
