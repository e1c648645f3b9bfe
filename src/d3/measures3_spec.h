/* measures3_spec.h - the power spectrum of a set on the unit 3-torus.
 *
 * Owns: P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n at the integer frequencies
 * k in [-K, K]^3 (P(0) = n, P(-k) = P(k)), two ways: the exact direct sum
 * (O(n K^3), the tests' reference) and a type-1 non-uniform FFT (Barnett,
 * Magland and af Klinteberg 2019, as the 2-D analysis': an oversampled
 * M^3 grid, M >= 2 (2K + 1), the exponential-of-semicircle kernel of width
 * w = 10, FFTW, deconvolution by the kernel's transform from Gauss-Legendre
 * quadrature; error about 1e-8 of P's largest term); its average over
 * shells |k| in [s - 1/2, s + 1/2) (RAPS in 3-D, shells s = 1..K, complete
 * inside the box); and P0, the mean of P over 0 < |k| <= 0.2 n^(1/3) (the
 * 2-D P0's band, 0.2 sqrt(n), scaled to the 3-D spacing). Layout:
 * P[((kz + K) S + ky + K) S + kx + K], S = 2K + 1. */
#ifndef CFPO_MEASURES3_SPEC_H
#define CFPO_MEASURES3_SPEC_H

#include <stddef.h>

#define CFPO3_SPEC_KMAX 128

/* cfpo3d-analyze's default K: ceil(2 n^(1/3)), clamped to [8, 64]. */
int cfpo3_spec_default_K(size_t n);
/* P by direct summation. P holds (2K+1)^3 doubles. 0, or -1 (memory). */
int cfpo3_power_exact(const double *p, size_t n, int K, double *P);
/* P by the NUFFT (1 <= K <= CFPO3_SPEC_KMAX). 0, or -1 with a message. */
int cfpo3_power_nufft(const double *p, size_t n, int K, double *P, char *err, size_t errlen);
/* Shell means: shell[s], count[s] for s = 0..K (shell 0 is k = 0). */
void cfpo3_power_shells(const double *P, int K, double *shell, long *count);
/* P0 over 0 < |k| <= 0.2 n^(1/3) (NAN when the box does not hold it or it
 * holds no frequency); *cnt the frequencies averaged. */
double cfpo3_power_p0(const double *P, int K, size_t n, long *cnt);
/* The highest of shells 1..K (the first on ties; K >= 1). */
int cfpo3_power_peak(const double *shell, int K);

/* The per-mode spike check (the 3-D form of the 2-D analysis' spike
 * ratio, analysis/rings.h): the largest P(k) over its shell's mean, over
 * k in the half space (kz > 0, or kz = 0 and ky > 0, or kz = ky = 0 and
 * kx > 0; P(-k) = P(k)) on shells 1..K of at least CFPO3_SPIKE_MIN_COUNT
 * frequencies whose mean is positive (ties: the first in (kz, ky, kx)
 * order). For a set without structure P(k) / mean is about Exp(1) and
 * independent across the half space's (2K+1)^3 / 2 modes, so its maximum
 * is about ln((2K+1)^3 / 2); the noise level is that plus 4 (the 2-D
 * check's ln(M/2) + 4 with M = (2K+1)^3 modes), and a set passes when its
 * ratio is at most the level. shell: cfpo3_power_shells' means and counts. */
#define CFPO3_SPIKE_MIN_COUNT 16
typedef struct {
    double ratio, P, mean; /* NAN when no shell qualifies */
    int kx, ky, kz, shell;
    double noise;          /* ln((2K+1)^3 / 2) + 4 */
    int pass;              /* ratio <= noise (1 when no shell qualifies) */
} cfpo3_spike;
double cfpo3_spike_noise_level(int K);
void cfpo3_power_spike(const double *P, int K, const double *shell, const long *count, cfpo3_spike *out);

#endif
