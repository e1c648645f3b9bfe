/* prog_measure.h - the prefixes' measures of a progressive set: each
 * prefix's (or class's) delta_min and delta_avg in its own Delta(m), by
 * buckets, on threads with the same bits for any count. Used by the
 * progressive driver (progressive.c) and the joint move (prog_joint.c).
 * May include nothing of the project but its types. */
#ifndef CFPO_PROG_MEASURE_H
#define CFPO_PROG_MEASURE_H

#include <stddef.h>
#include <stdint.h>

/* delta_min and delta_avg of each prefix sizes[0..K) of xy (the first
 * sizes[k] points), each in its own Delta(m_k), into dmin[k], davg[k].
 * 0, or -1 with one line in err (out of memory). */
int cfpo_prog_measure(const double *xy, const int64_t *sizes, int K, double *dmin, double *davg, char *err,
                      size_t errlen);

/* The groups' measures, and (raw, may be NULL) each group's smallest
 * distance itself. Groups: the prefixes [0, sizes[k]); with classes,
 * class k [sizes[k - 1], sizes[k]) and then the union [0, sizes[K - 1])
 * (K + 1 groups). The nearest distances on nth threads, summed in id
 * order (the same bits for any nth). 0, or -1 with one line in err. */
int cfpo_prog_measure_groups(const double *xy, const int64_t *sizes, int K, int classes, int nth, double *dmin,
                             double *davg, double *raw, char *err, size_t errlen);

#endif
