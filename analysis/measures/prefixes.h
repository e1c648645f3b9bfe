/* prefixes.h - the measures of a set's prefixes in file order (progressive,
 * nested sets): P_m is the first m points, judged in its own units
 * Delta(m) = sqrt(2 / (sqrt(3) m)).
 *
 * Owns: the choice of prefix sizes, the per-prefix row (delta_min and
 * delta_avg / Delta(m), P0 of lowfreq.h and the shift variances of
 * shiftvar.h from the prefix's own periodogram, K = the default of
 * cfpo-analyze for m), the exact worst prefix over every m >= m0 in one pass
 * and prefixes.txt.
 *
 * Worst prefix (docs: shared design note, section 1): with d_j the distance
 * from x_j to x_1..x_(j-1), delta_min(P_m) = min over 2 <= j <= m of d_j, and
 * since Delta(m) falls with m, the worst prefix over all m >= m0 is
 * min(delta_min(P_m0) / Delta(m0), min over j > m0 of d_j / Delta(j)). The d_j
 * come from an incremental grid (baselines/nngrow.h: n
 * nearest-neighbour queries). */
#ifndef AN_PREFIXES_H
#define AN_PREFIXES_H
#include <stddef.h>
#include "shiftvar.h"

#define AN_PREFIX_BASE 16 /* default smallest prefix (dyadic sizes from it) */

enum { AN_PREFIX_DYADIC = 0, AN_PREFIX_SAMPLE = 1, AN_PREFIX_GIVEN = 2, AN_PREFIX_FULL = 3 };

typedef struct {
    size_t m;
    int kind;          /* AN_PREFIX_* */
    double dmin, davg; /* / Delta(m) */
    double p0;         /* NAN below 25 points (lowfreq.h) */
    double var[AN_SHIFTVAR_COUNT];
} an_prefix_row;

typedef struct {
    an_prefix_row *rows;
    int count;
    size_t base;
    double worst_any;    /* exact, over every m >= base */
    size_t worst_any_m;
} an_prefixes;

/* Delta(m) of the 2-D torus. */
double an_prefix_delta(size_t m);
/* The sizes measured: given (ngiven > 0; each in [2, n], sorted and made
 * unique here) or the default: every power of two from base to n, the
 * non-dyadic sample 2^k + 1 and round(2^k sqrt 2) between consecutive ones
 * (the first point after a dyadic prefix is where a nested set is weakest),
 * and n itself when it is not a power of two. 0, or -1 with a message. */
int an_prefix_plan(size_t n, size_t base, const size_t *given, int ngiven, an_prefix_row **rows, int *count,
                   char *err, size_t errlen);
/* d[j] = distance from point j to points 0..j-1 (0-based; d[0] = INFINITY),
 * through nngrow.h. 0, or -1 when out of memory. */
int an_prefix_running(const double *xy, size_t n, double *d);
/* The exact worst prefix over m in [m0, n] (2 <= m0 <= n) from the running
 * distances; *at: the m where it is reached (the first such). */
double an_prefix_worst(const double *d, size_t n, size_t m0, size_t *at);
/* Fills one row for the first row->m points (NUFFT kernel width `width`,
 * 0 = default). 0, or -1 with a message. */
int an_prefix_measure(const double *xy, int width, an_prefix_row *row, char *err, size_t errlen);
/* Everything: plan, rows, worst prefix. n >= 2, 2 <= base <= n. */
int an_prefixes_compute(const double *xy, size_t n, size_t base, const size_t *given, int ngiven, int width,
                        an_prefixes *out, char *err, size_t errlen);
void an_prefixes_free(an_prefixes *p);
/* prefixes.txt: a header comment, then `m kind delta_min delta_avg p0
 * shiftvar_...` one row per prefix. 0, or -1 with a message. */
int an_prefixes_write(const char *path, const an_prefixes *p, char *err, size_t errlen);
/* The SUMMARY keys (a leading space each; '-' values when p is NULL):
 * prefix_base prefix_worst_dyadic_dmin prefix_worst_dyadic_m
 * prefix_worst_dyadic_davg prefix_worst_sample_dmin prefix_worst_sample_m
 * prefix_worst_any_dmin prefix_worst_any_m. malloc'ed, NULL when out of memory. */
char *an_prefixes_summary(const an_prefixes *p);
#endif
