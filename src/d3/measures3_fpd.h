/* measures3_fpd.h - the farthest-point certificate of a set on the unit
 * 3-torus (built only where CGAL is: CFPO_HAVE_CGAL).
 *
 * A set X is a farthest-point distribution (FPD) when no point can be moved
 * farther from the rest: for each x_i, its distance d_i to X \ {x_i} is at
 * least R_i, the radius of the largest empty sphere of X \ {x_i} (the
 * largest circumsphere of its periodic Delaunay triangulation). Checked
 * exactly as FPO searches (CGAL's Periodic_3_Delaunay_triangulation_3):
 * the largest circumsphere of the cells not incident to x_i (a sorted list
 * of the whole triangulation's cells), and of the cells made by removing
 * x_i (those incident to its former neighbours); x_i is then put back. A
 * point passes when R_i <= d_i (1 + 1e-9). Cost: a removal and an
 * insertion a point (measured in docs/results/2026-11-28-3d-baselines.md). */
#ifndef CFPO_MEASURES3_FPD_H
#define CFPO_MEASURES3_FPD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t passed;        /* points that pass */
    double max_violation; /* max over points of (R_i - d_i) / Delta3(n), <= 0 when all pass */
} cfpo3_fpd_result;

/* 0, or -1 with a message (duplicates, too few points, memory). each: NULL,
 * or n doubles that receive every point's violation (R_i - d_i) /
 * Delta3(n) (the point passes when R_i <= d_i (1 + 1e-9)). */
int cfpo3_fpd_certify(const double *p, size_t n, cfpo3_fpd_result *r, double *each, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
