/* dens_scan.h - layer 2: the accept check's scan of a block of one
 * bucket (dens_cell.c's spot_ok): is a spot above a value against every
 * other point of the block? The first point, in block order, that is not
 * is what the scan of the bucket's list answers (a block of one bucket
 * lists its points in block order). Where the CPU has the AVX-512 route
 * (dens_solve.h's choice) eight points are tested at a time, each by the
 * scalar loop's operations in its order.
 * Owns: that scan. May include dens_solve.h. */
#ifndef CFPO_DENS_SCAN_H
#define CFPO_DENS_SCAN_H

/* For the m points (bx, by, br) of a block that wraps nowhere and the
 * spot (px, py) with q = rc: the first j != p, in order, with
 * !(((bx_j - px)^2 + (by_j - py)^2) br_j rc > thr); -1 when there is
 * none; -2 where the CPU lacks the AVX-512 route or m exceeds 64 (then
 * scan the bucket). */
int cfpo_dens_scan_block(const double *bx, const double *by, const double *br, int m, int p, double px, double py,
                         double rc, double thr);

#endif
