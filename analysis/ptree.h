/* ptree.h - a static 2-d tree over the points of a set on the unit torus,
 * for the queries that would otherwise scan every point: the nearest
 * point to a place (all periodic images), and the images of the points in
 * a disk, nearest first. Used by the certificate (certify/) and by the
 * distance statistics of crowded sets (nnhist.c), so it lives beside both.
 *
 * Split at the median of each box's wider side, so the depth stays about
 * log2(n / leaf) however the points crowd (clusters, lines, repeats). */
#ifndef AN_PTREE_H
#define AN_PTREE_H

#include <stddef.h>

typedef struct {
    double x0, y0, x1, y1; /* the bounding box of the node's points */
    size_t lo, hi;         /* its points: x/y/id[lo, hi) */
    long left, right;      /* children; left < 0: a leaf */
} an_pnode;

typedef struct {
    double *x, *y; /* the points in tree order, in [0, 1) */
    size_t *id;    /* their indices in the input */
    an_pnode *node;
    size_t n, nodes;
} an_ptree;

/* Builds the tree over the n points xy (interleaved, in [0, 1)): 0, or -1
 * out of memory. an_ptree_free in either case. */
int an_ptree_build(an_ptree *T, const double *xy, size_t n);
void an_ptree_free(an_ptree *T);

/* The squared torus distance from (qx, qy) to its nearest point whose
 * index is not `skip` (pass n to skip none); INFINITY when there is none. */
double an_ptree_nearest(const an_ptree *T, double qx, double qy, size_t skip);

/* The same nearest point, its distance computed as cfpo_torus_dist2 does
 * (the same bits as a scan of every point would give), for (qx, qy) in
 * [0, 1). */
double an_ptree_nearest_torus(const an_ptree *T, double qx, double qy, size_t skip);

/* How many images (x_j + ox, y_j + oy) have |X - cx| <= h and
 * |Y - cy| <= h, each difference computed as written. */
size_t an_ptree_count_box(const an_ptree *T, double cx, double cy, double h);

/* The images of the points within distance r of (qx, qy) in the plane
 * (the set repeated with period 1), nearest first: a best-first walk with
 * its own heap. Where the points of a leaf all share one position, one of
 * them stands for all: not `skip`, unless it is the last of them.
 * Zero-initialise; an_pwalk_start, then an_pwalk_next until
 * it returns 0; an_pwalk_free at the end (the heap is reused across
 * starts). */
typedef struct {
    double *key;  /* heap: (squared distance, item, ox, oy) */
    size_t len, cap;
    const an_ptree *T;
    double qx, qy, r2;
    size_t skip;
    const double *fv, *fr2; /* the filter (an_pwalk_filter): disks, fn of them */
    int fn;
} an_pwalk;

int an_pwalk_start(an_pwalk *W, const an_ptree *T, double qx, double qy, double r, size_t skip);
/* 1 with the next image (*px, *py) of point *id at squared distance *d2,
 * 0 when no image is left within r, -1 out of memory. Equal distances come
 * out in an unspecified but fixed order. */
int an_pwalk_next(an_pwalk *W, double *px, double *py, size_t *id, double *d2);
void an_pwalk_free(an_pwalk *W);

/* From now on, images (and boxes of them) meeting none of the fn closed
 * disks of centres fv[2v], fv[2v + 1] and squared radii fr2[v] are left
 * out (fn = 0: none is): not queued, and an image queued before is dropped
 * when it comes out. The arrays are read at each step, not copied: a caller
 * may shrink the disks as it goes (what they leave out stays out), never
 * grow them. start clears it. */
void an_pwalk_filter(an_pwalk *W, const double *fv, const double *fr2, int fn);

/* Drops at once what the filter leaves out from the queue (after the disks
 * shrank: images and boxes queued under wider ones), instead of one at a
 * time as they come out. The order of what is left is unchanged. */
void an_pwalk_prune(an_pwalk *W);

#endif
