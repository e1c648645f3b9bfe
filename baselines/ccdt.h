/* ccdt.h - capacity-constrained Delaunay triangulation (Xu, Liu, Gotsman,
 * Gortler 2011) on CGAL's periodic Delaunay triangulation of the unit torus.
 *
 * Owns: the dynamic triangulation of the n points, the energy (the sum of
 * the squared triangle areas; on the torus there are always 2n triangles
 * of total area 1, so this is the area variance up to constants), one
 * iteration (every point in id order: the position that minimises the
 * squared deviations of its incident triangles' areas from the mean 1/(2n)
 * - the area of a triangle is linear in one vertex, so this is a 2x2
 * least-squares problem - then the move, kept when the energy of the whole
 * triangulation decreased, undone otherwise), the net displacements and the
 * iteration statistics.
 * Does not own: the stopping loop, files or the command line (main_ccdt.c).
 *
 * The energy change of a move is exact and local: every triangle the move
 * creates or destroys has its three vertices among the point, its old and
 * its new neighbours, so the sums of the squared areas of the triangles
 * around those vertices before and after differ by exactly the change.
 * A point moves only if its optimum lies more than tol * L away, L =
 * cfpo's cell side (as for cfpo and FPO); converged when no point's net
 * move over an iteration reaches tol * L, or nothing moved.
 * A C interface over a C++ implementation. */
#ifndef CFPO_BASELINES_CCDT_H
#define CFPO_BASELINES_CCDT_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ccdt_engine ccdt_engine;

/* Uniform random start (the paper's). NULL with a message. */
ccdt_engine *ccdt_create(int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
/* A given start (n points, xy interleaved, in [0,1), distinct), scale L.
 * For tests. */
ccdt_engine *ccdt_create_from(int64_t n, const double *xy, double L, double tol, char *err,
                              size_t errlen);
void ccdt_free(ccdt_engine *E);

/* One iteration. s->moved: accepted moves; s->solved: points whose
 * optimum was computed (n); s->max_disp: largest net move / L. */
void ccdt_iterate(ccdt_engine *E, cfpo_iter_stats *s);

/* Moves tried and undone (energy not lower) in the last iteration. */
int64_t ccdt_rejected(const ccdt_engine *E);
/* The energy as tracked move by move, and recomputed from all triangles. */
double ccdt_energy(const ccdt_engine *E);
double ccdt_energy_recomputed(const ccdt_engine *E);
/* Coefficient of variation of the triangle areas (std / mean), from the
 * tracked energy; and the largest |area - mean| / mean, recomputed. */
double ccdt_area_cv(const ccdt_engine *E);
double ccdt_area_maxdev(const ccdt_engine *E);

void ccdt_deltas(ccdt_engine *E, double *dmin, double *davg);
const double *ccdt_points(const ccdt_engine *E);
/* CGAL's is_valid(), n vertices, stored points equal to the array, 2n
 * triangles. 1 when all hold. */
int ccdt_check(const ccdt_engine *E);

#ifdef __cplusplus
}
#endif
#endif
