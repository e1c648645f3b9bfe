/* prog_joint_int.h - layer 4, internal to the joint move (prog_joint.h):
 * its state, shared by prog_joint.c (the sweeps, the trials, the local
 * solve) and prog_joint_pair.c (the pair measure of a mover at a place,
 * the placing of a point, the pair move and the class swap).
 * May include: prog_joint.h, geom.h, prog_buckets.h, prog_pgrid.h (layers 0-4). */
#ifndef CFPO_PROG_JOINT_INT_H
#define CFPO_PROG_JOINT_INT_H

#include <math.h>
#include <stdint.h>

#include "geom.h"
#include "prog_buckets.h"
#include "prog_joint.h"
#include "prog_pgrid.h"

/* v onto [0, 1). */
static inline double prog_joint_wrap1(double v)
{
    const double w = v - floor(v);
    return w < 1.0 ? w : 0.0;
}

/* The state of one joint move. */
typedef struct {
    prog_buckets B;     /* with classes: every point (one grid) */
    prog_pgrid P;       /* without: the prefixes' grids (P.G[K - 1] holds every point) */
    const int *lev;     /* each point's level */
    double R[65];       /* without classes: the reach of a pair of level L, max(F_L, cap G_L, H_L) */
    uint32_t now;       /* the time of the colour phase under way (stamps, prog_pgrid.h) */
    int K, classes;
    double F[65], G[65]; /* the pair floors (distances) and weights by pair level */
    double Gmax[65];     /* max of G over the pair levels a point of level l can be in */
    double H[65];        /* hold distances: a pair shorter than H_L may not shrink */
    double Hmax;         /* the largest of them */
    double Fmax[65];     /* the same for F */
    double Dm[65];       /* Delta(m_L) of each prefix */
    double floor;        /* > 0: the polish's floor, with classes the union's (prog_joint.h floor) */
    double cap;          /* the measure counted up to this (a mover at or past it has nothing to gain) */
    double tau;          /* > 0: the pair measure is the soft minimum with this temperature (prog_joint.h soft) */
    double lam;          /* weight of the mover's mean nearest distance over its groups (prog_joint.h avg) */
} joint;

/* The score of point i placed at (x, y): its pair measure, the smallest
 * d_ij / G_L over the other points (capped at J->cap), plus J->lam times
 * the mean over the groups that hold i of its nearest distance in the
 * group over the group's G (each capped at J->cap); or -1 when some pair
 * falls below its floor; at or below stop: that value (the rest unread).
 * *bind: the binding partner (-1 if none within reach). */
double prog_joint_measure_at(const joint *J, int64_t i, double x, double y, int64_t *bind, double stop);

/* Point k to (x, y) in xy and the move grid. */
void prog_joint_place(joint *J, double *xy, int64_t k, double x, double y);

/* The pair move of point i and its binding partner j (pairs trials); 1 when made. */
int prog_joint_pair_move(joint *J, double *xy, int64_t i, int64_t j, double base, int s, const cfpo_prog_joint_options *jo);

/* The class swap of point i (measure q0) with a point of another class
 * within rho (the first `tries`); 1 when made. */
int prog_joint_swap_move(joint *J, double *xy, int64_t i, double q0, double rho, int tries);

#endif
