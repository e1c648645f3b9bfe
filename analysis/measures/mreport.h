/* mreport.h - how cfpo-analyze reports the measures of this folder: the
 * keys they add to the SUMMARY line and to stats.json, as text that
 * report.c inserts (before peak_bytes, and before "threads").
 *
 * Owns: the names and formats. SUMMARY keys (6 significant digits, "-"
 * when undefined): p0 h_index lowk_alpha, disc_wrap_l2 disc_diaphony
 * disc_l2_star disc_gen_l2 disc_centred_l2 (square roots; the mean over the
 * sets), shiftvar_<integrand> for each integrand of shiftvar.h. stats.json
 * keys: low_frequency, discrepancy (with per_set arrays), shift_variance.
 * Does not own: any computation. */
#ifndef AN_MREPORT_H
#define AN_MREPORT_H

#include "discrepancy.h"
#include "lowfreq.h"
#include "shiftvar.h"

typedef struct {
    int sets;
    size_t n;
    const an_discrepancy *disc; /* [sets]; NULL: not computed */
    const an_lowfreq *lowfreq;
    const an_shiftvar *shiftvar;
    double disc_seconds;        /* all sets */
} an_measures;

/* malloc'd text, NULL when out of memory. */
char *an_measures_summary(const an_measures *m);
char *an_measures_json(const an_measures *m);

#endif
