/* bench_solver.h - layer 5: the solver's capture and replay modes of cfpo-bench
 * (bench_solver.c). */
#ifndef CFPO_BENCH_SOLVER_H
#define CFPO_BENCH_SOLVER_H

#include <stdint.h>

/* Runs n points (default variant, one thread, seed) to the largest of
 * its[]; records every local solve of the iterations in its[] to path. */
int bench_capture(const char *prog, int64_t n, uint64_t seed, const int *its, int nits, const char *path);
/* Replays the calls of path through the plain and the AVX2 solver (only:
 * NULL for both, "plain" or "avx2"), rounds times each, best time kept;
 * exits non-zero when any call's bits differ. */
int bench_replay(const char *prog, const char *path, const char *only, int rounds);

#endif
