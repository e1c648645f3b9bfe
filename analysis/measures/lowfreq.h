/* lowfreq.h - the low-frequency end of a periodogram: how much power a set
 * leaves below its blue-noise peak, the measure that decides how fast its
 * integration error falls with n.
 *
 * Owns the definitions (P as in power.h, rings and RAPS as in rings.h,
 * R = 0.2 sqrt(n)):
 *   P0     the mean of P(k) over the integer k with 0 < |k| <= R.
 *   H      the hyperuniformity index of the structure-factor package
 *          (Hawat, Gautier, Bardenet, Lachieze-Rey; hyperuniformity.py,
 *          effective_hyperuniformity; Torquato 2018, Klatt et al. 2019):
 *          S_hat(0) / S(k_peak), S_hat(0) the intercept of the unweighted
 *          least-squares line through the RAPS of rings 1..floor(R) (x: the
 *          mean |k| of each ring), S(k_peak) the RAPS at the first local
 *          maximum of the RAPS (rings 2..K-1, as scipy's find_peaks) that
 *          reaches 1, or 1 if there is none. "Effectively hyperuniform"
 *          when H <= 1e-3. The line's intercept goes negative for a k^2
 *          spectrum (jittered): P0 beside it says more.
 *   alpha  the least-squares slope of log RAPS against log mean |k| over
 *          the same rings (those with RAPS > 0): about 0 for white noise
 *          and for a flat floor, 2 for jittered, larger for BNOT.
 * All three are NAN when the box does not hold the range (K < floor(R)) or
 * it holds no frequency (n < 25); H and alpha also below 2 rings. */
#ifndef AN_LOWFREQ_H
#define AN_LOWFREQ_H

#include <stddef.h>

#include "rings.h"

typedef struct {
    double range;      /* R = 0.2 sqrt(n) */
    double p0;
    long long p0_count; /* frequencies in P0 */
    double h, s0, peak; /* H = s0 / peak */
    int peak_ring;      /* 0: no peak reaching 1 (peak = 1) */
    double alpha;
    int rings;          /* rings 1..rings in the fits */
} an_lowfreq;

/* r: the rings of the same P. 0, or -1 when out of memory. */
int an_lowfreq_compute(const double *P, int K, size_t n, const an_rings *r, an_lowfreq *out);

#endif
