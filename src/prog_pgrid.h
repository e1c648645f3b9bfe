/* prog_pgrid.h - layer 3: the nested bucket grids of the progressive
 * joint move (prog_joint.h): grid g holds the points of prefix g (ids
 * below sizes[g]) in buckets of side about Delta(m_g), so a search of
 * radius about Delta(m_g) in it reads a few buckets whatever g is (one
 * grid of the full set's buckets would read n / m_g of them). Each bucket
 * carries a stamp: the time (a counter the caller advances) of the last
 * move into or out of it, so a caller can tell whether anything moved
 * near a place since a given time. Also each prefix's nearest distances,
 * measured again only where a stamp changed since the last measure (the
 * same values as a full measure, exactly), and the working order of the
 * points (Morton order within each level).
 * Owns: the grids, their stamps, the kept nearest distances, the order.
 * May include: prog_buckets.h (layer 2). */
#ifndef CFPO_PROG_PGRID_H
#define CFPO_PROG_PGRID_H

#include <stdint.h>

#include "prog_buckets.h"

typedef struct {
    int K;
    const int64_t *sizes;
    const int *lev;          /* each point's level */
    prog_buckets G[64];      /* grid g: prefix g */
    prog_buckets V[64];      /* g >= 1: level g's points alone, G[g]'s buckets (a search of a finer
                                level reads no coarser point) */
    uint32_t *stamp[64];     /* per bucket of grid g: the time of its last change (0: none) */
    double *nd[64];          /* prefix g's nearest distances (sizes[g] each) */
    uint32_t measured;       /* the time of the last measure (0: none yet) */
} prog_pgrid;

/* The grids of prefixes sizes[0..K) of xy (K <= 64), every point stored,
 * grid g's buckets of side at least f Delta(m_g) (f >= 1; a search of
 * radius up to the side reads 3 x 3 buckets). 0, or -1 when out of memory
 * (then prog_pgrid_free). */
int prog_pgrid_init(prog_pgrid *P, const double *xy, const int64_t *sizes, int K, const int *lev, double f);
void prog_pgrid_free(prog_pgrid *P);

/* Point k to (x, y) in xy and in the grids of its prefixes (levels
 * lev[k] .. K - 1) and of its level; its old and new buckets stamped with now (>= 1). */
void prog_pgrid_move(prog_pgrid *P, double *xy, int64_t k, double x, double y, uint32_t now);

/* 1 when some bucket of grid g within r of (x, y) has a stamp >= t. */
int prog_pgrid_changed(const prog_pgrid *P, int g, double x, double y, double r, uint32_t t);

/* Each prefix's delta_min and delta_avg in its own Delta(m) (dmin, davg)
 * and smallest distance (raw, may be NULL), the nearest distances of
 * nth threads summed in id order; a point's nearest distance is found
 * again only when a stamp near it changed since the last measure (at the
 * first measure every one). now: the time of this measure (the stamps
 * after it are newer). 0, or -1 when out of memory. */
int prog_pgrid_measure(prog_pgrid *P, int nth, uint32_t now, double *dmin, double *davg, double *raw);

/* A working order of xy's points: perm[j] is the id of working id j; each
 * level's ids (sizes[l - 1] .. sizes[l] - 1) in Morton order of their
 * places, ties by id (neighbours near each other in memory; the same set
 * of ids per level). 0, or -1 when out of memory. */
int prog_pgrid_order(const double *xy, const int64_t *sizes, int K, int64_t *perm);

#endif
