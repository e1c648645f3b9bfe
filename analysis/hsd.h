/* hsd.h - the two spectral measures of Heck, Schloemer and Deussen (2013,
 * "Blue noise sampling with controlled aliasing") that the psa tool
 * reports, computed from our periodogram instead of psa's RDF-derived
 * curve. Definitions (README.md gives them in full):
 *
 * Effective Nyquist frequency. C(r) = mean of P(k) over 0 < |k| <= r.
 * r_half = the first |k| >= sqrt(n)/2 with C > 0.5; r_01 = the largest
 * |k| <= r_half with C < 0.1. nu_eff = r_01 / 2 (a signal band-limited to
 * nu_eff is sampled without aliasing up to the 10% level); reported, as
 * psa prints it, relative to sqrt(n)/2, i.e. r_01 / sqrt(n). 0 if no
 * such r_01; NAN if C never exceeds 0.5 within K.
 *
 * Oscillation. nu_osc = the first ring whose RAPS reaches 0.98; over the
 * rings nu_osc .. nu_osc + 5 sqrt(n) (cut at K), 10 sqrt(area-weighted
 * mean of (RAPS - 1)^2), the ring counts being the area weights. NAN if
 * no ring reaches 0.98. */
#ifndef AN_HSD_H
#define AN_HSD_H

#include <stddef.h>

#include "rings.h"

typedef struct {
    double eff_nyquist;    /* r_01 / sqrt(n) */
    double r_half, r_01;   /* in frequency units */
    double oscillation;
    int osc_from, osc_to;  /* rings used */
    int osc_clipped;       /* 1 when nu_osc + 5 sqrt(n) > K */
} an_hsd;

/* P as in power.h, n points per set. 0, or -1 when out of memory. */
int an_hsd_compute(const double *P, int K, size_t n, const an_rings *r, an_hsd *h);

#endif
