/* ccvt.h - capacity-constrained Voronoi tessellation by discrete point
 * swapping (Balzer, Schloemer, Deussen 2009) on the unit torus.
 *
 * Owns: the n sites and the n * m discrete points (m per site; by default
 * the nodes of a regular lattice, as Balzer's code lays them, else uniform
 * random), the assignment of points to sites (site i owns slots
 * i*m .. i*m+m-1, so every site owns exactly m points by construction and a
 * swap exchanges two slots), one iteration (the swap step over pairs of
 * sites in increasing (i, j) order; by default, as in Balzer's code, both
 * sites of a pair that swapped move to the centroids of their points at
 * once, before the next pair; or, CCVT_UPDATE_PASS, every site that
 * swapped moves once after the whole pass),
 * the energy (the sum over the points of the squared periodic distance to
 * their site) and the iteration statistics.
 * Does not own: the stopping loop, files or the command line (main_ccvt.c).
 *
 * The swap step of a pair (i, j): the points of i by decreasing gain
 * d(x, s_i)^2 - d(x, s_j)^2 and the points of j by theirs, paired in that
 * order while the two gains add up to more than 0 (the paper's two
 * max-heaps; sorting the candidates gives the same pairs). Only pairs that
 * can swap are looked at, and the result is the paper's all-pairs step:
 * a swap needs a point of i nearer to s_j than to s_i (or the converse),
 * hence |s_i - s_j| < 2 max(r_i, r_j), r the largest distance of a site to
 * its points (pairs from a hash grid of the sites); and a pair whose two
 * sites are unchanged since it last made no swap cannot swap now (skipped).
 *
 * The lattice: cols x rows nodes (k mod cols, k div cols) / (cols, rows)
 * from the origin, cols x rows = n m, rows the largest divisor of n m up to
 * sqrt(n m) (a square sqrt(nm) x sqrt(nm) lattice when n m is a square, as
 * for every power-of-two n and m); refused when cols > 2 rows.
 *
 * Converged (CCVT_UPDATE_PAIR): a whole pass swapped nothing (Balzer's
 * rule; --tol plays no part). CCVT_UPDATE_PASS: no swap, or no site moved
 * tol * L (cfpo_net_converged).
 *
 * Start: n uniform random sites (the paper's). The assignment, by default
 * Balzer's code's (CCVT_ASSIGN_NEAREST): the points, last first, each to
 * the nearest site not yet full; the sites stay where they are until
 * they swap. CCVT_ASSIGN_CURVE, the other: a
 * choice of this implementation (the paper assigns at random, which makes
 * every pair a candidate, O(n^2 m) per iteration): sites and points sorted
 * along one Hilbert curve laid at a random offset on the torus, the points
 * cut into n runs of m consecutive ones, run r to the r-th site along the
 * curve, so each site starts with points near it. (Sites at the runs'
 * centroids instead would start on the curve's nearly square blocks, a
 * lattice the swaps do not undo.)
 *
 * Memory: 16 n m bytes for the points, 8 n m more while the start is
 * sorted, O(n + m) besides. Default m (ccvt_default_m): 1024 up to
 * n = 16,384, then 2^24 / n (at least 16), i.e. at most 256 MiB of points.
 *
 * Scale L: cfpo's cell side for this n (cfpo_grid_init), so --tol means
 * what it means for cfpo and FPO. */
#ifndef CFPO_BASELINES_CCVT_H
#define CFPO_BASELINES_CCVT_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo.h"
#include "density.h"

enum { CCVT_POINTS_LATTICE = 0, CCVT_POINTS_RANDOM = 1 };
enum { CCVT_UPDATE_PAIR = 0, CCVT_UPDATE_PASS = 1 };
enum { CCVT_ASSIGN_NEAREST = 0, CCVT_ASSIGN_CURVE = 1 };

typedef struct {
    uint64_t seed;
    int64_t m;    /* points per site; 0: ccvt_default_m(n) */
    double tol;   /* relative to L, as cfpo's tol (CCVT_UPDATE_PASS only) */
    int points;   /* CCVT_POINTS_LATTICE (default) or CCVT_POINTS_RANDOM */
    int update;   /* CCVT_UPDATE_PAIR (default) or CCVT_UPDATE_PASS */
    int assign;   /* CCVT_ASSIGN_NEAREST (default) or CCVT_ASSIGN_CURVE */
    const cfpo_density *density; /* NULL: uniform. Else the capacity is
                     the density's: the n m points and the n start sites
                     are drawn proportional to rho (dens_draw.h, from the
                     numbers of the random point set and sites), so every
                     site's m points carry mass 1/n of rho, as Balzer et
                     al. give CCVT a density; `points` plays no part (a
                     lattice has no density), and for rho = 1 the run is
                     CCVT_POINTS_RANDOM's, byte for byte. delta_min,
                     delta_avg: in the symmetric measure (dens_measure.h). */
} ccvt_options;

void ccvt_options_init(ccvt_options *o);
int64_t ccvt_default_m(int64_t n);
/* The lattice of N points: cols x rows; -1 when cols > 2 rows. */
int ccvt_lattice_shape(int64_t N, int64_t *cols, int64_t *rows);

typedef struct ccvt_engine ccvt_engine;

/* The start (random sites, lattice or random points). NULL with a message
 * when out of memory, n * m is too large or has no lattice (the caller
 * checks n against cfpo's minimum). */
ccvt_engine *ccvt_create(int64_t n, const ccvt_options *o, char *err, size_t errlen);
/* A given start: n * m points (xy interleaved, in [0,1)), site i owning
 * points i*m .. i*m+m-1; sites at their centroids; scale L; the update
 * CCVT_UPDATE_PAIR. For tests. */
ccvt_engine *ccvt_create_from(int64_t n, int64_t m, const double *pts, double L, double tol,
                              char *err, size_t errlen);
void ccvt_free(ccvt_engine *E);

/* One iteration. s->moved: sites that moved (swapped points); s->solved:
 * pairs of sites compared; s->max_disp: the largest site move / L;
 * s->converged: see above. */
void ccvt_iterate(ccvt_engine *E, cfpo_iter_stats *s);

/* CCVT_UPDATE_PAIR or CCVT_UPDATE_PASS from the next iteration on. */
void ccvt_set_update(ccvt_engine *E, int update);
/* Swaps of the last iteration. */
int64_t ccvt_swaps(const ccvt_engine *E);
/* The energy, recomputed from scratch (O(n m)). With checking on (for
 * tests), every iteration also records it after its swap step, before the
 * sites move: ccvt_energy_after_swaps (NAN when checking is off). */
double ccvt_energy(const ccvt_engine *E);
void ccvt_set_check(ccvt_engine *E, int on);
double ccvt_energy_after_swaps(const ccvt_engine *E);

/* delta_min, delta_avg of the sites, normalised by Delta(n) (under a
 * density: in the symmetric measure). */
void ccvt_deltas(ccvt_engine *E, double *dmin, double *davg);

const double *ccvt_sites(const ccvt_engine *E);   /* 2n doubles */
const double *ccvt_points(const ccvt_engine *E);  /* 2nm doubles, by slot */
int64_t ccvt_m(const ccvt_engine *E);

#endif
