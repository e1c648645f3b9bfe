/* farthest_int.h - the pieces of farthest.c that its prepared form
 * (farprep.c) shares: the 2-d tree over a workspace's points and the
 * clipping of one point's region by the others. */
#ifndef AN_FARTHEST_INT_H
#define AN_FARTHEST_INT_H

#include <stddef.h>
#include <stdlib.h>

#include "farthest.h"

/* Grows array p to n elements, or returns -1 from the caller. */
#define GROW(p, n)                                                                                                     \
    do {                                                                                                               \
        void *q_ = realloc((p), (n) * sizeof *(p));                                                                    \
        if (!q_) return -1;                                                                                            \
        (p) = q_;                                                                                                      \
    } while (0)

/* A node of the 2-d tree: the bounding box of its points, their range in
 * x/y, and its children (left < 0: a leaf). */
typedef struct an_kd_node {
    double x0, y0, x1, y1;
    size_t lo, hi;
    long left, right;
} kd_node;

#define KD_DEPTH 120 /* midpoint splits: enough for any double-precision spread */

/* Point i's region: a convex polygon P of nv vertices, far2 its largest
 * squared distance from point i. */
typedef struct {
    double *P, *Q, *sd;
    int nv;
    double far2;
} region;

/* Room for m points (and polygons of m + 8 vertices): 0 or -1. */
int an_far_reserve(an_far_ws *ws, size_t m);

/* The tree over ws->x/y[lo, hi): split at the middle of the wider side of
 * the bounding box; a leaf keeps each position once. The root's index. */
long an_kd_build(an_far_ws *ws, size_t lo, size_t hi, int depth);

/* Squared distance from (ax, ay) to a node's box, rounded down a little. */
double an_kd_box_d2(const kd_node *n, double ax, double ay);

/* Clips point i's region by every other point of the tree in ws (but
 * point excl) near enough to cut it, nearest boxes first; 0 once it is
 * empty or no farther than best. */
int an_clip_region(const an_far_ws *ws, size_t i, size_t excl, region *R, double best);

/* Links each hull vertex of the tree's positions in ws to its hull
 * neighbours (hull.c); other positions get -1. */
void an_hull_links(an_far_ws *ws);

/* An upper bound of the squared distance from position i to the points of
 * its region within the convex polygon dom (ndom <= 8 vertices): the wedge
 * between its bisectors with its hull neighbours, cut to dom; INFINITY
 * when i is not a hull vertex. */
double an_wedge_bound(const an_far_ws *ws, size_t i, const double *dom, int ndom);

/* The farthest point of square S from the m points by a few of them
 * (farsub.c): its squared distance to all m, when the few decide it, or
 * -3 when they do not (then solve it whole). scratch: room for the core
 * solver on 24 points. */
double an_farthest_sub(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy, double *cx,
                       double *cy, double *scratch);

/* an_farthest without the try on a few points (for a caller that made
 * it already). */
double an_farthest_whole(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy,
                         double *cx, double *cy, an_far_ws *ws);

/* The same for m points that all share y or all share x (row.c): the
 * squared answer, or -3 when they do not. tmp: room for m values. */
double an_farthest_row(const double *yx, const double *yy, size_t m, cfpo_square S, double *cx, double *cy,
                       double *tmp);

/* The shortcuts before a tree: a row (an_farthest_row), then a few points
 * (an_farthest_sub); -3 when neither decides it. */
double an_farthest_quick(const double *yx, const double *yy, size_t m, cfpo_square S, double hx, double hy,
                         double *cx, double *cy, double *scratch);

#define AN_NEAREST_EACH 9 /* probes at most */

/* For each of the k <= AN_NEAREST_EACH probes, the index of the nearest of
 * the m points (the first of equals) into arg, in one pass (farsub.c). */
void an_nearest_each(const double *yx, const double *yy, size_t m, const double (*probe)[2], int k, size_t *arg);

#endif
