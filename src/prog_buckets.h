/* prog_buckets.h - layer 2: the bucket grid of the progressive sampler's
 * point searches, shared by the level insertion and ordering
 * (prog_insert.c) and the bounded joint move (prog_joint.c): buckets of
 * side about Delta(m) on the unit torus, each a linked list of point ids
 * of xy, and the nearest stored point by rings of buckets. */
#ifndef CFPO_PROG_BUCKETS_H
#define CFPO_PROG_BUCKETS_H

#include <stdint.h>

typedef struct {
    int64_t gs;    /* buckets per side */
    double cs;     /* bucket side, 1 / gs */
    int64_t *head; /* first point of each bucket, -1 if none */
    int64_t *next; /* the next point of its bucket */
    const double *xy;
} prog_buckets;

/* Buckets of side about Delta(m) for up to cap points of xy (ids below
 * cap), none stored yet. 0, or -1 when out of memory (then
 * prog_buckets_free). */
int prog_buckets_init(prog_buckets *B, const double *xy, int64_t m, int64_t cap);

/* Buckets of side about Delta(m) holding points 0 .. m - 1 of xy, all
 * stored. 0, or -1 when out of memory (then prog_buckets_free). */
int prog_buckets_build(prog_buckets *B, const double *xy, int64_t m);

/* The same with buckets of side at least side (> 0). */
int prog_buckets_init_side(prog_buckets *B, const double *xy, double side, int64_t cap);
void prog_buckets_free(prog_buckets *B);

/* The bucket of (x, y) in [0, 1)^2 (clamped to the grid). */
int64_t prog_buckets_of(const prog_buckets *B, double x, double y);

/* Stores point k (at the head of its bucket's list), or takes it out. */
void prog_buckets_link(prog_buckets *B, int64_t k);
void prog_buckets_unlink(prog_buckets *B, int64_t k);

/* The square window of buckets within reach buckets of bucket b on each
 * axis, or the whole grid when that would wrap onto itself: returns its
 * side, its first bucket's column and row (unwrapped) into *x0, *y0. */
static inline int64_t prog_buckets_window(const prog_buckets *B, int64_t b, int64_t reach, int64_t *x0, int64_t *y0)
{
    const int64_t gs = B->gs, span = 2 * reach + 1 >= gs ? gs : 2 * reach + 1, lo = span == gs ? 0 : reach;
    *x0 = b % gs - lo;
    *y0 = b / gs - lo;
    return span;
}

/* Column or row v in (-gs, 2 gs) wrapped onto [0, gs) (no division). */
static inline int64_t prog_buckets_wrap(int64_t v, int64_t gs) { return v < 0 ? v + gs : v >= gs ? v - gs : v; }

/* The first point of the bucket at column x, row y (wrapped onto the
 * grid; each in (-gs, 2 gs), as a window's are). */
static inline int64_t prog_buckets_first(const prog_buckets *B, int64_t x, int64_t y)
{
    const int64_t gs = B->gs;
    return B->head[prog_buckets_wrap(y, gs) * gs + prog_buckets_wrap(x, gs)];
}

/* Squared distance on the unit torus. */
static inline double prog_torus_d2(double ax, double ay, double bx, double by)
{
    double dx = ax - bx, dy = ay - by;
    dx = dx < 0 ? -dx : dx;
    dy = dy < 0 ? -dy : dy;
    if (dx > 0.5) dx = 1.0 - dx;
    if (dy > 0.5) dy = 1.0 - dy;
    return dx * dx + dy * dy;
}

/* Squared distance from (x, y) to the nearest stored point other than
 * skip (-1: none), by rings of buckets outwards until no nearer point can
 * remain; stops early, returning a value <= stop2, once the distance
 * falls to stop2 (stop2 < 0: never). INFINITY when no point is stored. */
double prog_buckets_nearest2(const prog_buckets *B, double x, double y, int64_t skip, double stop2);

#endif
