/* prog_insert.h - layer 4: the start of a progressive level's new points
 * (progressive.h): best-candidate insertion (Mitchell, "Spectrally optimal
 * sampling for distribution ray tracing", SIGGRAPH 1991) next to points
 * already placed, on the unit torus.
 * Owns: the candidates, the bucket grid that finds a candidate's nearest
 * point, the order of insertion (id order, serial: the same bytes always).
 * The order of a level's points once optimised: prog_order.h.
 * May include: geom.h, rng.h (layers 0-1). */
#ifndef CFPO_PROG_INSERT_H
#define CFPO_PROG_INSERT_H

#include <stddef.h>
#include <stdint.h>

/* Points m0 .. m1 - 1 of xy (x0 y0 x1 y1 ...) in id order, after the m0
 * points already there: each the one of `cand` uniform draws (seed,
 * stream `stream`) farthest from every point before it. 0, or -1 with one
 * line in err (out of memory). */
int cfpo_prog_insert(double *xy, int64_t m0, int64_t m1, int cand, uint64_t seed, uint64_t stream, char *err,
                     size_t errlen);

#endif
