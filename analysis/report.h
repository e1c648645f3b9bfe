/* report.h - everything cfpo-analyze writes: the files of the output
 * folder and the one summary line.
 *
 * Owns: the formats. spectrum.txt is a gnuplot "nonuniform matrix" (first
 * row: the count then kx = -K..K; then one row per ky: ky, then P); raps.txt
 * has the columns r, r/sqrt(n), RAPS, anisotropy (dB), count; nn_hist.txt
 * has bin start, bin end (both / Delta(n)), count, fraction; stats.json
 * holds every scalar; plot.gp draws the three with gnuplot. Non-finite
 * values are written as NaN in text and null in JSON.
 * Does not own: any computation. */
#ifndef AN_REPORT_H
#define AN_REPORT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "certify.h"
#include "hsd.h"
#include "power.h"
#include "rings.h"

typedef struct {
    const char *const *files;
    int sets;
    size_t n;
    int K;
    int exact;                 /* spectrum by direct summation */
    an_nufft_info nufft;       /* when !exact */
    double check_maxdiff;      /* NAN unless --check */
    const double *delta_min, *delta_avg; /* per set; NULL when n < 2 */
    double delta_min_mean, delta_avg_mean;
    const uint64_t *nn_hist;   /* AN_NN_BINS counts over all sets; NULL when n < 2 */
    const an_rings *rings;     /* of the averaged spectrum */
    const an_hsd *hsd;
    const double *spike;       /* per set: the set's own spike ratio (NAN: none) */
    const int *spike_k;        /* per set: its kx, ky */
    double spike_mean;         /* mean of the per-set spike ratios */
    const an_lattice *lattice; /* of the averaged spectrum; g 0: not asked */
    const an_certificate *cert; /* NULL without --certify */
    int threads;
    double seconds, spectrum_seconds;
    uint64_t peak_bytes;
    const char *out;
    /* Text of the measures of measures/ (mreport.h), or NULL: inserted into
     * the summary line before peak_bytes and into stats.json before
     * "threads". */
    const char *summary_extra, *json_extra;
} an_report;

int an_write_spectrum(const char *path, const double *P, int K, char *err, size_t errlen);
int an_write_raps(const char *path, const an_report *r, char *err, size_t errlen);
int an_write_nnhist(const char *path, const an_report *r, char *err, size_t errlen);
int an_write_json(const char *path, const an_report *r, char *err, size_t errlen);
int an_write_plot(const char *path, const an_report *r, char *err, size_t errlen);
void an_print_summary(FILE *f, const an_report *r);
/* One plain line when the spike ratio of the (averaged) spectrum is above
 * the noise level an_spike_noise_level(K) at a k that also stands above
 * its neighbourhood (the rings' pattern, rings.h): where it sits, and
 * whether that is a frequency of cfpo's grid (the lattice ratio's).
 * Nothing otherwise.
 * Returns 1 when it printed the line. */
int an_print_imprint(FILE *f, const an_report *r);

#endif
