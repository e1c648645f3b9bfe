/* arcs.h - exact boundary-arc bookkeeping for Poisson-disk sampling
 * (Dunbar & Humphreys 2006, "boundary sampling").
 *
 * Owns: the part of the circle C(s, rho) around a sample s that no disk
 * D(t, rho) of another sample t covers, kept as sorted disjoint angle
 * intervals in [0, 2 pi]; subtracting the arc a new neighbour covers;
 * drawing a uniformly distributed point of what is left.
 *
 * Why it gives maximal sets: if some point u of the torus were farther than
 * rho from every sample, then with s the sample nearest to u, the point of
 * segment s-u at distance rho from s and an arc around it on C(s, rho)
 * would be uncovered. So when every sample's arcs are empty, every point of
 * the torus is within rho of a sample.
 *
 * Capacity: the samples within 2 rho of s are pairwise at least r apart
 * (r <= rho, rho < 1.0001 r), so disks of radius r/2 around them are disjoint
 * inside an annulus of area 6 pi r^2 (slightly more): at most 24
 * neighbours, hence at most 24 gaps on the circle, plus one when a gap
 * straddles angle 0 and is stored as two pieces. ARCS_CAP leaves room.
 * Arcs shorter than ARCS_EPS radians are dropped: the region such an arc
 * would bound is within rho (1 + 1e-18) of the samples. */
#ifndef CFPO_BASELINES_ARCS_H
#define CFPO_BASELINES_ARCS_H

#define ARCS_CAP 32
#define ARCS_EPS 1e-9

typedef struct {
    int m;                   /* number of arcs; 0 = fully covered */
    double lo[ARCS_CAP], hi[ARCS_CAP];
} arcs;

/* The whole circle. */
void arcs_full(arcs *A);

/* Removes the angles in [a, b] (any real a <= b, b - a < 2 pi; taken
 * modulo 2 pi). */
void arcs_remove(arcs *A, double a, double b);

/* Removes the part of C(s, rho) within distance rho of q (q's nearest
 * periodic image to s; nothing when |q - s| >= 2 rho). */
void arcs_cover(arcs *A, double sx, double sy, double qx, double qy, double rho);

/* Total angle left. */
double arcs_total(const arcs *A);

/* The angle at fraction u in [0, 1) of the total length (uniform when u is). */
double arcs_pick(const arcs *A, double u);

#endif
