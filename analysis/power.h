/* power.h - the periodogram of a point set on the unit torus.
 *
 * Owns: the definition P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n at integer
 * frequencies k = (kx, ky) in [-K, K]^2, the layout of the result and the
 * two ways to compute it: the core library's type-1 non-uniform FFT (nufft.c over src/solver/nufft.h)
 * and the exact direct sum (exact.c), the reference the first is tested
 * against. Does not own: what is done with P (rings.c, hsd.c).
 *
 * Layout: P[(ky + K) * (2K + 1) + (kx + K)], rows by ky, both from -K.
 * P(-k) = P(k) always; P(0) = n. */
#ifndef AN_POWER_H
#define AN_POWER_H

#include <math.h>
#include <stddef.h>

#define AN_KMAX 4096 /* largest K accepted (memory: about 160 K^2 bytes) */

static inline size_t an_side(int K) { return 2 * (size_t)K + 1; }
/* cfpo-analyze's default K for n points: ceil(6 sqrt(n)), clamped to [8, 2048]. */
static inline int an_default_K(size_t n)
{
    const double K = ceil(6 * sqrt((double)n));
    return K < 8 ? 8 : (K > 2048 ? 2048 : (int)K);
}
static inline size_t an_pidx(int K, int kx, int ky)
{
    return (size_t)(ky + K) * an_side(K) + (size_t)(kx + K);
}

/* What the NUFFT used, for reports. */
typedef struct {
    int width;       /* kernel support in grid points per axis */
    int grid;        /* oversampled grid side M */
    double beta;     /* exponential-of-semicircle shape */
    double seconds_spread, seconds_fft;
} an_nufft_info;

/* Default kernel width: aliasing error about 10^-(width-1) of the largest
 * term, far below the 1e-6 the tests demand. */
#define AN_NUFFT_WIDTH 12

/* P through the NUFFT. width 0 = AN_NUFFT_WIDTH (allowed 4..16). P holds
 * (2K+1)^2 doubles. 0, or -1 with a message (out of memory, bad K). info
 * may be NULL. Deterministic: the result does not depend on the number of
 * threads (the FFT itself runs on one thread). */
int an_power_nufft(const double *xy, size_t n, int K, int width, double *P, an_nufft_info *info,
                   char *err, size_t errlen);

/* Progress callback for the slow exact path: fraction done in [0, 1]. */
typedef void (*an_progress_fn)(double frac, void *user);

/* P by direct summation: every term exp(-2 pi i k.x_j) computed from sin
 * and cos of the reduced phase, O(n K^2). Deterministic. */
int an_power_exact(const double *xy, size_t n, int K, double *P, an_progress_fn progress,
                   void *user, char *err, size_t errlen);

/* Largest difference between two spectra, relative to max(P_ref(k), 1):
 * relative where P is at or above the white-noise level 1, absolute (in
 * units of that level) below it. */
double an_power_maxdiff(const double *P, const double *Pref, int K);

#endif
