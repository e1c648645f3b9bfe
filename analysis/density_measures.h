/* density_measures.h - `cfpo-analyze --density SPEC`: how a point set
 * follows a density (docs/method.md, "Density").
 *
 *   delta_min, delta_avg  under the symmetric measure of
 *                         src/density/dens_measure.h (today's delta_min and
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
 *   off_support           points on zero-density pixels;
 *   capacity deviation    std / mean of the points' capacities, the
 *                         integral of rho over each Voronoi cell
 *                         (capacity.h), exact for the piecewise-constant
 *                         density; the cells come from the caller (the
 *                         periodic Delaunay triangulation); NAN for a set
 *                         without them;
 *   differential-domain   spectrum of Wei and Wang with the symmetric
 *                         normalisation (dda.h), window radius
 *                         AN_DDA_RADIUS local spacings: its rings' means
 *                         and anisotropy (dda_raps.txt), the whole
 *                         spectrum (dda_spectrum.txt), and its peak,
 *                         low-frequency mean and anisotropy on the DENSITY
 *                         line.
 * Several sets: the means of the sets' values, the histogram summed, the
 * spectra averaged. */
#ifndef AN_DENSITY_MEASURES_H
#define AN_DENSITY_MEASURES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "capacity.h"
#include "dda.h"
#include "density.h"

#define AN_DENS_BINS 100
#define AN_DENS_BIN 0.02

typedef struct {
    cfpo_density d;
    int sets;
    double dmin, davg, fid_rms, fid_max, fid_rms16, fid_max16, off; /* sums over the sets */
    int64_t blocks;
    uint64_t hist[AN_DENS_BINS];
    double cap_dev, cap_sum_err; /* the deviations summed over cap_sets sets; the largest |sum c - 1| */
    int cap_sets;
    int K;                       /* the spectrum's, fixed by the first set */
    double radius, pairs;        /* the window; pairs summed over the sets */
    double *dda;                 /* the sets' spectra summed, then (an_density_finish) their mean */
    size_t n;                    /* for the summary: the (mean) number of points */
    an_dda_summary sum;
    double cap_seconds, dda_seconds; /* the capacities' integrals (not the triangulation), the spectra */
} an_density;

int an_density_begin(an_density *a, const char *spec, char *err, size_t errlen);

/* The measures of one set, added; cells: its Voronoi cells or NULL (no
 * capacity); K: the differential-domain spectrum's frequencies (the
 * first set's K holds for all). */
int an_density_add(an_density *a, const double *xy, size_t n, const an_vcells *cells, int K, char *err,
                   size_t errlen);

/* After the last set: the mean spectrum and its summary for n points. 0,
 * or -1 when out of memory. */
int an_density_finish(an_density *a, size_t n);

/* dda_raps.txt and dda_spectrum.txt. 0, or -1 with one line in err. */
int an_density_write_dda(const an_density *a, const char *raps_path, const char *spectrum_path, char *err,
                         size_t errlen);

/* The count fidelity of one set (exposed for the tests). */
int an_density_fidelity(const cfpo_density *d, const double *xy, size_t n, int64_t B, double *rms, double *maxabs,
                        size_t *off);

/* density.txt: the means as '#' lines, then the histogram (bin centre,
 * fraction). 0, or -1 with one line in err. */
int an_density_write(const an_density *a, const char *path, char *err, size_t errlen);

/* The DENSITY line on stdout. */
void an_density_print(const an_density *a, FILE *f);

void an_density_free(an_density *a);

#endif
