/* measures3_pcf.h - the pair correlation function g(r) of a set on the
 * unit 3-torus.
 *
 * Owns: g over bins of width dr on [0, rmax) of r / Delta3(n): the
 * periodic pairs (minimum image) at distance in bin b, counted once each,
 * divided by what a Poisson set of the same n would give on average,
 * n (n - 1) / 2 times the shell's volume (4 pi / 3)(r_hi^3 - r_lo^3) in
 * box units. rmax Delta3(n) must stay below 1/2 (one image per pair). A
 * cell list finds the pairs; the tests check it against all pairs. */
#ifndef CFPO_MEASURES3_PCF_H
#define CFPO_MEASURES3_PCF_H

#include <stddef.h>

/* g[0..bins): bins = ceil(rmax / dr). 0, or -1 (memory, or rmax too
 * large for n). */
int cfpo3_pcf(const double *p, size_t n, double rmax, double dr, double *g, int bins);
/* The bins of width dr that g(r) of n points takes up to rmax (in units
 * of Delta3(n)), rmax first lowered by dr until rmax Delta3(n) < 1/2 (half
 * the box); 0 or less when none fits. */
int cfpo3_pcf_bins(size_t n, double rmax, double dr);

#endif
