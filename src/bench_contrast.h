/* bench_contrast.h - layer 5: the density's cost an iteration against a
 * reference density, for cfpo-bench (bench_contrast.c). */
#ifndef CFPO_BENCH_CONTRAST_H
#define CFPO_BENCH_CONTRAST_H

#include <stdint.h>

/* Times an iteration of CFPO under `density` against one under
 * `reference` (both density SPECs of `cfpo --density`) at n points, as the
 * command runs them by default (its default tolerance, the lazy measure):
 * `rounds` rounds, each running seeds 1 .. seeds under both, alternating
 * which goes first; each run's time is the sum of the seconds its
 * iterations 3-22 report (the first two carry the start's largest moves).
 * Prints a line a round on stderr and one RESULT line (medians, the
 * ratio's quartiles over the rounds, each density's best round and the
 * ratio of the two). Exits on error. */
int bench_contrast(const char *prog, int64_t n, int threads, int rounds, int seeds, const char *density,
                   const char *reference);

#endif
