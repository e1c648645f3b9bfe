/* quadrature.h - layer 0 (includes nothing of the project): Gauss-Legendre
 * quadrature.
 *
 * Owns: the nodes and weights of q-point Gauss-Legendre quadrature on
 * [-1, 1] (Newton's method on the Legendre polynomial P_q from the
 * Tricomi-like first guess cos(pi (i + 3/4) / (q + 1/2))). Used by the
 * NUFFT's kernel transform (nufft.c) and the exact Gaussian integrals of
 * cfpo-analyze (analysis/measures/integration.c). */
#ifndef CFPO_QUADRATURE_H
#define CFPO_QUADRATURE_H

/* z[i], w[i] for i = 0..q-1 (q >= 1), nodes from largest to smallest. */
void cfpo_gauss_legendre(int q, double *z, double *w);

#endif
