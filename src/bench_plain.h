/* bench_plain.h - layer 5: the plain engine of cfpo-bench (bench_plain.c). */
#ifndef CFPO_BENCH_PLAIN_H
#define CFPO_BENCH_PLAIN_H

#include <stdint.h>

/* Runs `iters` iterations of the paper's CFPO on n points (seed, the
 * paper's default tolerance) the plainest way: one thread, every point
 * solved every iteration with cfpo_local_solve, the cell list sorted again
 * after every phase, delta_min and delta_avg from the 3x3 blocks after
 * every iteration. Prints one RESULT line; writes the points in id order
 * to path (any format of pointfile.h) unless path is NULL. Exits on error. */
int bench_plain(const char *prog, int64_t n, uint64_t seed, int iters, const char *path);

#endif
