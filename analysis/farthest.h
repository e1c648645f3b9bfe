/* farthest.h - the farthest point of a square from a finite set, for any
 * size of set: the certificate's one solver call (certify.c).
 *
 * Up to AN_FAR_SMALL points it is the core's exact LocalCFPO solver
 * (cfpo_local_solve), unchanged, so sets like cfpo's (a few dozen points
 * in a neighbourhood) give the same bits as before. Above that the same
 * exact method (the largest vertex distance over each point's Voronoi
 * region clipped to the square) runs in another order, so that degenerate
 * sets (clusters, lines, repeated points) cost about n log n instead of
 * n^3:
 *  - repeated positions are merged (the distance to a set does not depend
 *    on how often a position occurs);
 *  - each point's region is clipped by the other points ring by ring on a
 *    grid over their bounding box, nearest rings first, and the rings stop
 *    as soon as every point left is at least twice the region's reach away
 *    (such a bisector cannot cut it);
 *  - the pruning of the core solver is kept (a region no farther than the
 *    best value found is abandoned; points are visited near the hint first,
 *    by rings of cells around it).
 * Both give the exact maximum up to the rounding of the clipping; the
 * value returned is recomputed from the distances themselves. */
#ifndef AN_FARTHEST_H
#define AN_FARTHEST_H

#include <stddef.h>

#include "geom.h"

#define AN_FAR_SMALL 128

/* Grows on demand; zero-initialise, an_far_free at the end. */
typedef struct {
    double *ux, *uy, *key, *pa, *pb, *sd, *scratch;
    size_t *cell_start;
    size_t cap, cells_cap;
} an_far_ws;

/* The point (*cx, *cy) of S farthest from the m points (yx, yy): returns
 * its squared distance to them (infinity for m = 0, with S's centre), or
 * -1 (out of memory, or no vertex found: a solver failure). */
double an_farthest(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy, double *cx,
                   double *cy, an_far_ws *ws);
void an_far_free(an_far_ws *ws);

#endif
