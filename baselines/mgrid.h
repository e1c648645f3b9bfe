/* mgrid.h - a dynamic grid of points on the unit torus for the symmetric
 * pair measure under a density (src/density/dens_measure.h): with q = sqrt(rho) at
 * a point, the squared measure of a pair times Delta(n)^2 is
 * v = d^2 q_i q_j, d the torus distance (cfpo_torus_dist2). Used by the
 * adaptive dart throwing (conflict test) and by FPO under a density (the
 * exact smallest measure of a place).
 *
 * Owns: g x g cells, each a doubly linked list of point ids (any number a
 * cell), insert and remove in O(1), and the ring search: cells are visited
 * ring by ring around the query's cell; once rings 0..k are done every
 * unvisited point is at least k / g away, so its v is at least
 * (k / g)^2 q q_min and the search stops when that reaches the bound
 * (q_min = the density's smallest non-zero q; points on zero-density
 * pixels have q = 0 and v = 0 to everything). Rings that wrap visit a cell
 * more than once, which a minimum does not notice.
 * Does not own: the points' coordinates (the caller's array, read through
 * the pointer given at init) or the density. */
#ifndef CFPO_BASELINES_MGRID_H
#define CFPO_BASELINES_MGRID_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int64_t g;
    const double *xy;   /* the caller's coordinates by id */
    const double *q;    /* the caller's q by id */
    double qmin;        /* smallest non-zero q of the density */
    int64_t *head;      /* g g first id of each cell, -1 when empty */
    int64_t *next, *prev, *cell; /* by id; cell -1 when not stored */
} mgrid;

/* Room for ids 0..cap-1, g = floor(sqrt(expected / 2)) clamped to 1..4096
 * (about 2 points a cell at the mean density). 0, or -1 out of memory. */
int mgrid_init(mgrid *M, size_t cap, size_t expected, const double *xy, const double *q, double qmin);
void mgrid_free(mgrid *M);

/* Stores id at xy[2 id], xy[2 id + 1]; removes it. */
void mgrid_insert(mgrid *M, int64_t id);
void mgrid_remove(mgrid *M, int64_t id);

/* The smallest v = d^2 qx q_j over the stored points j other than the
 * `nex` ids in `ex`, from (x, y) with q = qx, or `bound` when none is
 * below it. */
double mgrid_min(const mgrid *M, double x, double y, double qx, const int64_t *ex, int nex, double bound);

/* 1 when some stored point has d^2 qx q_j < r2 (the adaptive conflict). */
int mgrid_conflict(const mgrid *M, double x, double y, double qx, double r2);

#endif
