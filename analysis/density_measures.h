/* density_measures.h - `cfpo-analyze --density SPEC`: how a point set
 * follows a density (docs/method.md, "Density").
 *
 *   delta_min, delta_avg  under the symmetric measure of
 *                         src/dens_measure.h (today's delta_min and
 *                         delta_avg when rho = 1);
 *   histogram             of each point's smallest measure (its nearest
 *                         neighbour's distance over the local spacing
 *                         sqrt(r_i r_j)), bins of 0.02 on [0, 2), the last
 *                         bin also holding everything above;
 *   count fidelity        the torus cut into B x B blocks, B = floor(sqrt(n /
 *                         64)) (about 64 points a block), each block with
 *                         mass > 0 compared with n times its mass (the
 *                         density's exact integral over it): the relative
 *                         error (count - n mass) / (n mass), its root mean
 *                         square and largest magnitude over the blocks,
 *                         and the same over the blocks expecting 16 or
 *                         more points (a block expecting 0.5 points holds 0
 *                         or 1: its relative error says little);
 *   off_support           points on zero-density pixels.
 * Several sets: the means of the sets' values, the histogram summed. */
#ifndef AN_DENSITY_MEASURES_H
#define AN_DENSITY_MEASURES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "density.h"

#define AN_DENS_BINS 100
#define AN_DENS_BIN 0.02

typedef struct {
    cfpo_density d;
    int sets;
    double dmin, davg, fid_rms, fid_max, fid_rms16, fid_max16, off; /* sums over the sets */
    int64_t blocks;
    uint64_t hist[AN_DENS_BINS];
} an_density;

int an_density_begin(an_density *a, const char *spec, char *err, size_t errlen);

/* The measures of one set, added. */
int an_density_add(an_density *a, const double *xy, size_t n, char *err, size_t errlen);

/* The count fidelity of one set (exposed for the tests). */
int an_density_fidelity(const cfpo_density *d, const double *xy, size_t n, int64_t B, double *rms, double *maxabs,
                        size_t *off);

/* The same over the blocks expecting at least emin points. */
int an_density_fidelity_min(const cfpo_density *d, const double *xy, size_t n, int64_t B, double emin, double *rms,
                            double *maxabs, size_t *off);

/* density.txt: the means as '#' lines, then the histogram (bin centre,
 * fraction). 0, or -1 with one line in err. */
int an_density_write(const an_density *a, const char *path, char *err, size_t errlen);

/* The DENSITY line on stdout. */
void an_density_print(const an_density *a, FILE *f);

void an_density_free(an_density *a);

#endif
