/* q6.h - layer 2 of the 3-D engine (includes nn3.h): Steinhardt's bond
 * order in three dimensions, to see crystallisation.
 *
 * Owns: q_6m(i) over each point's k nearest neighbours (periodic), the
 * global Q6 (q_6m averaged over all bonds; Steinhardt, Nelson and Ronchetti
 * 1983), the mean local q6, and the crystal-like particles by the local
 * bond criterion of ten Wolde, Ruiz-Montero and Frenkel (1996): i and j
 * (j among i's k neighbours) are bonded when the normalised product
 * Re sum_m q_6m(i) q_6m(j)* / (|q6(i)| |q6(j)|) exceeds `bond`; i is
 * crystal-like with at least `bonds` such bonds. Reference Q6: FCC 0.5745
 * (k 12), BCC 0.5107 (k 14), SC 0.3536 (k 6). */
#ifndef CFPO_Q6_H
#define CFPO_Q6_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double q6_global;    /* Q6 of the whole set */
    double q6_local;     /* mean over points of q6(i) */
    int64_t crystal;     /* crystal-like points */
    double crystal_frac; /* crystal / n */
} cfpo3_q6_result;

/* p: n points in [0,1)^3; 1 <= k < n. 0, or -1 (memory). */
int cfpo3_q6(const double *p, size_t n, int k, double bond, int bonds, cfpo3_q6_result *r);

#endif
