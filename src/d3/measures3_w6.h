/* measures3_w6.h - Steinhardt's third-order invariant W6 (Steinhardt,
 * Nelson and Ronchetti 1983), beside Q6 (q6.h), to tell crystal kinds
 * apart: the bond order Q_6m = mean over all bonds (each point to its k
 * nearest neighbours, periodic) of Y_6m(bond direction), and
 *   W6 = sum_{m1+m2+m3=0} (6 6 6; m1 m2 m3) Q_6m1 Q_6m2 Q_6m3 / (sum_m |Q_6m|^2)^(3/2)
 * with the Wigner 3j symbols by Racah's formula; the mean local w6 the
 * same over each point's own bonds. Reference values: FCC -0.013161,
 * HCP -0.012442, BCC +0.013161, simple cubic +0.013161, icosahedral
 * -0.169754. Also returns Q6 = sqrt(4 pi / 13 sum_m |Q_6m|^2) (q6.h's
 * q6_global, computed here independently). */
#ifndef CFPO_MEASURES3_W6_H
#define CFPO_MEASURES3_W6_H

#include <stddef.h>

typedef struct {
    double q6, w6, w6_local;
} cfpo3_w6_result;

/* The Wigner 3j symbol (6 6 6; m1 m2 m3) (0 unless m1 + m2 + m3 = 0). */
double cfpo3_wigner666(int m1, int m2, int m3);
/* 1 <= k < n. 0, or -1 (memory). */
int cfpo3_w6(const double *p, size_t n, int k, cfpo3_w6_result *r);

#endif
