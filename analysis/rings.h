/* rings.h - statistics of a periodogram over rings of frequencies.
 *
 * Owns: the ring of a frequency (ring i holds the integer k with
 * i - 1/2 <= |k| < i + 1/2, i.e. i(i-1) < |k|^2 <= i(i+1)), the radially
 * averaged power spectrum (RAPS, the mean of P on each ring), the
 * anisotropy (10 log10 of the unbiased variance of P on the ring over the
 * squared mean, in dB, as psa computes it) and the spike ratio: the largest
 * single P(k) over its ring's mean, on the rings of at least
 * AN_SPIKE_MIN_COUNT frequencies. Rings 1..K are complete inside [-K, K]^2;
 * k = 0 (ring 0) and the corners beyond ring K are left out. */
#ifndef AN_RINGS_H
#define AN_RINGS_H

#include <stddef.h>
#include <stdint.h>

/* Rings with fewer frequencies than this are left out of the spike ratio:
 * P(-k) = P(k), so a ring of c frequencies holds c/2 independent values and
 * its largest ratio is at most c/2, an average of too few values to say
 * anything. Rings 1 and 2 (8 and 12 frequencies) are left out; ring 3 has
 * 20 and every later ring more. */
#define AN_SPIKE_MIN_COUNT 16

typedef struct {
    int K;
    int64_t *count;    /* [K+1] frequencies on ring i */
    double *sum;       /* [K+1] sum of P on ring i */
    double *mean;      /* [K+1] RAPS; mean[0] unused (0) */
    double *aniso_db;  /* [K+1] anisotropy in dB; NAN where undefined
                          (fewer than 2 values, or a zero mean) */
    /* The spike ratio: the largest P(k) / mean of its ring over the rings
     * of at least AN_SPIKE_MIN_COUNT frequencies, k taken in the half plane
     * ky > 0 or (ky = 0, kx > 0); ties go to the first in (ky, kx) order.
     * NAN (and spike_ring 0) when no ring qualifies or every such ring
     * has mean 0. */
    double spike_ratio, spike_P, spike_mean;
    int spike_kx, spike_ky, spike_ring;
    /* The pattern: the largest P(k) / ring mean above the noise level
     * an_spike_noise_level(K) among the k whose P also stands that far
     * above the mean of its neighbourhood, the (2 AN_PATTERN_BOX + 1)^2 - 1
     * frequencies around it (an_pattern_level): a periodic pattern is a
     * peak above every side; a ring whose P steps within it (the edge of
     * a band, where P changes by 100x between neighbouring radii) has
     * frequencies far above the ring's mean but not above their outer
     * neighbours. pattern_ratio NAN (pattern_ring 0) when no k passes
     * both; pattern_local is P(k) over that neighbourhood's mean. */
    double pattern_ratio, pattern_local;
    int pattern_kx, pattern_ky, pattern_ring;
    /* The highest ring mean. */
    double peak_mean;
    int peak_ring;
} an_rings;

/* The lattice ratio: the largest P(k) / mean of its ring over the axis
 * frequencies of a grid of g cells a side coloured with period p, k =
 * (j g / p, 0) and (0, j g / p) for j = 1..2p where j g / p is a whole
 * number, |k| <= K and the ring qualifies as for the spike ratio: where
 * the cells (j = p) and their colours (j < p) would print a grid on a set.
 * Returns the number of frequencies looked at; 0 (ratio NAN) when none
 * qualifies or g < 1. */
typedef struct {
    int g, period, count;
    double ratio, P, mean;
    int kx, ky;
} an_lattice;
int an_lattice_compute(const double *P, const an_rings *r, int g, int period, an_lattice *out);
/* The grid of the lattice ratio: `asked` when it is 0 or more (--grid),
 * else the grid cfpo uses for n points (the paper's and the adaptive
 * variant's; 0 when n is too small for one); and the colour period assumed
 * for a grid of g cells: 3 when 3 divides g, else 2 when g is even, else 1. */
int an_lattice_grid(int64_t asked, size_t n);
/* The spike ratio's noise level for the spectrum on [-K, K]^2: ln(M / 2)
 * + 4 with M = (2K + 1)^2 frequencies. P(k) / its ring's mean is about
 * Exp(1) for a set without a periodic pattern, and the largest of M / 2
 * independent such values (P(-k) = P(k)) is ln(M / 2) + 0.58 give or take
 * 1.3 (Gumbel); it passes the level with probability about 1 - exp(-e^-4)
 * = 1.8%. A spike above it is a pattern, not noise. */
double an_spike_noise_level(int K);
/* The neighbourhood of the pattern test: the box of half side
 * AN_PATTERN_BOX around k (48 frequencies), and the level P(k) must reach
 * over their mean: the t at which such a ratio of noise (Exp(1) over the
 * mean of 48 Exp(1)) passes with the same probability as the ring ratio
 * passes `level`: (1 + t / 48)^-48 = e^-level, t = 48 (e^(level / 48) - 1)
 * (24.7 for the level 19.9 of K = 2048). */
#define AN_PATTERN_BOX 3
double an_pattern_level(double level);
int an_lattice_period(int g);

/* Ring index of a frequency with |k|^2 = r2. */
int an_ring_of(int64_t r2);

/* 0, or -1 when out of memory. Free with an_rings_free. */
int an_rings_compute(const double *P, int K, an_rings *r);
void an_rings_free(an_rings *r);

#endif
