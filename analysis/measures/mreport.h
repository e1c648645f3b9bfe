/* mreport.h - how cfpo-analyze reports the measures of this folder: the
 * keys they add to the SUMMARY line and to stats.json, as text that
 * report.c inserts (before peak_bytes, and before "threads").
 *
 * Owns: the names and formats. SUMMARY keys (6 significant digits, "-"
 * when undefined): p0 h_index lowk_alpha, disc_wrap_l2 disc_diaphony
 * disc_l2_star disc_gen_l2 disc_centred_l2 (square roots; the mean over the
 * sets), shiftvar_<integrand> for each integrand of shiftvar.h. stats.json
 * keys: low_frequency, discrepancy (with per_set arrays), shift_variance.
 * Structure and integration: SUMMARY psi6 voronoi_area_var mesh_ratio
 * covering_radius (over Delta(n)), utk_gauss_mse utk_heaviside_mse (the
 * means over the sets; "-" when a set has none); stats.json pcf,
 * delaunay, integration; the file pcf.txt (r / Delta, g: the mean of the
 * sets' g) and pcf.gp (gnuplot pcf.gp draws pcf.png).
 * Does not own: any computation. */
#ifndef AN_MREPORT_H
#define AN_MREPORT_H

#include <stddef.h>
#include <stdint.h>

#include "delaunay.h"
#include "discrepancy.h"
#include "integration.h"
#include "lowfreq.h"
#include "shiftvar.h"

typedef struct {
    int sets;
    size_t n;
    const an_discrepancy *disc; /* [sets]; NULL: not computed */
    const an_lowfreq *lowfreq;
    const an_shiftvar *shiftvar;
    double disc_seconds;        /* all sets */
    const an_delaunay *dt;      /* [sets]; NULL: not computed; NaN: none for that set */
    double dt_seconds;
    const an_integration *integ; /* [sets]; NULL: not computed */
    uint64_t integ_seed;
    double integ_seconds;
    const double *pcf;          /* [pcf_bins], the mean over the sets; NULL: none */
    int pcf_bins;
    double pcf_sigma, pcf_rmax, pcf_seconds; /* sigma, rmax: / Delta(n) */
} an_measures;

/* malloc'd text, NULL when out of memory. */
char *an_measures_summary(const an_measures *m);
char *an_measures_json(const an_measures *m);
/* pcf.txt and pcf.gp. 0, or -1 with a message. */
int an_measures_write_pcf(const char *path, const an_measures *m, char *err, size_t errlen);
int an_measures_write_pcf_plot(const char *path, const an_measures *m, char *err, size_t errlen);

#endif
