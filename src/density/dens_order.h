/* dens_order.h - layer 2: the density solve's neighbours in order: the
 * points of a 3 x 3 block within the reach of the moving point (a key
 * d^2 q_j and a block index j each), placed by (key, index), the kmax
 * smallest kept; the solve reads them nearest first (dens_cell.c gathers
 * them). The order is total, so the list depends on the block alone, not
 * on how it is found: by insertion (each place found by branches that
 * random keys mispredict: a tenth of a flat density's iteration and of
 * cos a=0.9's, natively), or, on a CPU with the AVX-512 route
 * (dens_solve.h's choice), with no branch on the keys: each candidate's
 * place counted in 8-lane compares against all of them (up to 64), and
 * for a block of one bucket clear of the torus's wrap the keys too
 * computed eight points at a time, by the scalar loop's operations.
 * Owns: that order. May include dens_solve.h. */
#ifndef CFPO_DENS_ORDER_H
#define CFPO_DENS_ORDER_H

/* The cnt candidates (keys ck, block indices cj as doubles, each
 * distinct) in order by (key, index) into key and nj, the first kmax of
 * them (kmax > 0). Returns how many were placed, min(cnt, kmax). */
int cfpo_dens_order(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj);

/* The same list, by counting in 8-lane compares where the CPU has the
 * AVX-512 route and cnt <= 64 (else cfpo_dens_order). */
int cfpo_dens_order_fast(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj);

/* The same list for the m points (bx, by, br: block frame, q) of a block
 * that wraps nowhere, the candidates being every j != p with key
 * ((bx_j - ax)^2 + (by_j - ay)^2) br_j < T, in the scalar loop's
 * operations: the count, or -1 where the CPU lacks the AVX-512 route or m
 * exceeds 64 (then gather and order them with cfpo_dens_order). */
int cfpo_dens_order_block(const double *bx, const double *by, const double *br, int m, int p, double ax, double ay,
                          double T, int kmax, double *key, int *nj);

#endif
