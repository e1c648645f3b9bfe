/* prefixes.c - per-prefix measures of a set in file order and the exact
 * worst prefix (prefixes.h). The per-prefix numbers reuse the whole-set
 * modules: nnhist.c (delta), the baselines' nngrow.c (the running
 * nearest-neighbour distances), nufft.c (the periodogram), rings.c and
 * lowfreq.c (P0), shiftvar.c (integration variance). */
#include "prefixes.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lowfreq.h"
#include "nngrow.h"
#include "nnhist.h"
#include "power.h"
#include "rings.h"

double an_prefix_delta(size_t m) { return sqrt(2.0 / (sqrt(3.0) * (double)m)); }

static int cmp_size(const void *a, const void *b)
{
    const size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

static int push(an_prefix_row **rows, int *count, int *cap, size_t m, int kind)
{
    for (int i = 0; i < *count; i++)
        if ((*rows)[i].m == m) return 0; /* a size once, its first kind */
    if (*count == *cap) {
        const int c = *cap ? 2 * *cap : 64;
        an_prefix_row *r = realloc(*rows, (size_t)c * sizeof *r);
        if (!r) return -1;
        *rows = r;
        *cap = c;
    }
    an_prefix_row *r = &(*rows)[(*count)++];
    memset(r, 0, sizeof *r);
    r->m = m;
    r->kind = kind;
    return 0;
}

static int cmp_row(const void *a, const void *b)
{
    return cmp_size(&((const an_prefix_row *)a)->m, &((const an_prefix_row *)b)->m);
}

int an_prefix_plan(size_t n, size_t base, const size_t *given, int ngiven, an_prefix_row **rows, int *count,
                   char *err, size_t errlen)
{
    *rows = NULL;
    *count = 0;
    int cap = 0;
    if (n < 2 || base < 2 || base > n) {
        snprintf(err, errlen, "the prefix base %zu must be in [2, n = %zu]", base, n);
        return -1;
    }
    if (ngiven > 0) {
        for (int i = 0; i < ngiven; i++) {
            if (given[i] < 2 || given[i] > n) {
                snprintf(err, errlen, "prefix size %zu is not in [2, n = %zu]", given[i], n);
                free(*rows), *rows = NULL, *count = 0;
                return -1;
            }
            if (push(rows, count, &cap, given[i], AN_PREFIX_GIVEN) != 0) goto oom;
        }
    } else {
        size_t p = 1;
        while (p < base) p *= 2;
        for (; p <= n; p *= 2) {
            if (push(rows, count, &cap, p, AN_PREFIX_DYADIC) != 0) goto oom;
            if (2 * p <= n) {
                if (push(rows, count, &cap, p + 1, AN_PREFIX_SAMPLE) != 0) goto oom;
                if (push(rows, count, &cap, (size_t)llround((double)p * sqrt(2.0)), AN_PREFIX_SAMPLE) != 0)
                    goto oom;
            }
            if (p > n / 2) break;
        }
        if (push(rows, count, &cap, n, AN_PREFIX_FULL) != 0) goto oom;
    }
    qsort(*rows, (size_t)*count, sizeof **rows, cmp_row);
    return 0;
oom:
    free(*rows), *rows = NULL, *count = 0;
    snprintf(err, errlen, "out of memory");
    return -1;
}

int an_prefix_running(const double *xy, size_t n, double *d)
{
    bl_nngrow g;
    if (bl_nngrow_init(&g, xy, n) != 0) return -1;
    for (size_t j = 0; j < n; j++) {
        d[j] = sqrt(bl_nngrow_nearest2(&g, xy + 2 * j, NULL));
        if (bl_nngrow_insert(&g, j) != 0) {
            bl_nngrow_free(&g);
            return -1;
        }
    }
    bl_nngrow_free(&g);
    return 0;
}

double an_prefix_worst(const double *d, size_t n, size_t m0, size_t *at)
{
    double dm = INFINITY;
    for (size_t j = 1; j < m0; j++) dm = fmin(dm, d[j]);
    double worst = dm / an_prefix_delta(m0);
    *at = m0;
    for (size_t j = m0; j < n; j++) { /* d[j] opens prefix j + 1 */
        const double v = d[j] / an_prefix_delta(j + 1);
        if (v < worst) worst = v, *at = j + 1;
    }
    return worst;
}

int an_prefix_measure(const double *xy, int width, an_prefix_row *row, char *err, size_t errlen)
{
    const size_t m = row->m;
    double *nn = malloc(m * sizeof *nn);
    if (!nn || an_nn_stats(xy, m, NULL, nn, &row->dmin, &row->davg) != 0) {
        free(nn);
        snprintf(err, errlen, "out of memory for the prefix of %zu points", m);
        return -1;
    }
    free(nn);
    const int K = an_default_K(m);
    double *P = malloc(an_side(K) * an_side(K) * sizeof *P);
    if (!P) {
        snprintf(err, errlen, "out of memory for the prefix of %zu points", m);
        return -1;
    }
    if (an_power_nufft(xy, m, K, width, P, NULL, err, errlen) != 0) {
        free(P);
        return -1;
    }
    an_rings rings;
    an_lowfreq lf;
    if (an_rings_compute(P, K, &rings) != 0 || an_lowfreq_compute(P, K, m, &rings, &lf) != 0) {
        free(P);
        snprintf(err, errlen, "out of memory for the prefix of %zu points", m);
        return -1;
    }
    an_rings_free(&rings);
    row->p0 = lf.p0;
    an_shiftvar sv;
    an_shiftvar_compute(P, K, m, &sv);
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) row->var[t] = sv.var[t];
    free(P);
    return 0;
}

int an_prefixes_compute(const double *xy, size_t n, size_t base, const size_t *given, int ngiven, int width,
                        an_prefixes *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    if (an_prefix_plan(n, base, given, ngiven, &out->rows, &out->count, err, errlen) != 0) return -1;
    out->base = base;
    for (int i = 0; i < out->count; i++)
        if (an_prefix_measure(xy, width, &out->rows[i], err, errlen) != 0) {
            an_prefixes_free(out);
            return -1;
        }
    double *d = malloc(n * sizeof *d);
    if (!d || an_prefix_running(xy, n, d) != 0) {
        free(d);
        an_prefixes_free(out);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    out->worst_any = an_prefix_worst(d, n, base, &out->worst_any_m);
    free(d);
    return 0;
}

void an_prefixes_free(an_prefixes *p)
{
    free(p->rows);
    p->rows = NULL;
    p->count = 0;
}

static const char *kind_name[] = {"dyadic", "sample", "given", "full"};

int an_prefixes_write(const char *path, const an_prefixes *p, char *err, size_t errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# prefixes of the set in file order; delta_* / Delta(m), Delta(m) = sqrt(2/(sqrt(3) m))\n"
               "# worst prefix over every m >= %zu: delta_min %.6f at m = %zu\n"
               "# m kind delta_min delta_avg p0",
            p->base, p->worst_any, p->worst_any_m);
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) fprintf(f, " shiftvar_%s", an_integrands[t].name);
    fputc('\n', f);
    for (int i = 0; i < p->count; i++) {
        const an_prefix_row *r = &p->rows[i];
        fprintf(f, "%zu %s %.6f %.6f %.6g", r->m, kind_name[r->kind], r->dmin, r->davg, r->p0);
        for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) fprintf(f, " %.6g", r->var[t]);
        fputc('\n', f);
    }
    if (fclose(f) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

char *an_prefixes_summary(const an_prefixes *p)
{
    char *s = malloc(512);
    if (!s) return NULL;
    if (!p) {
        snprintf(s, 512, " prefix_base=- prefix_worst_dyadic_dmin=- prefix_worst_dyadic_m=-"
                         " prefix_worst_dyadic_davg=- prefix_worst_sample_dmin=- prefix_worst_sample_m=-"
                         " prefix_worst_any_dmin=- prefix_worst_any_m=-");
        return s;
    }
    int wd = -1, ws = -1;
    double davg = INFINITY;
    for (int i = 0; i < p->count; i++) {
        const an_prefix_row *r = &p->rows[i];
        if (r->kind == AN_PREFIX_DYADIC) {
            if (wd < 0 || r->dmin < p->rows[wd].dmin) wd = i;
            davg = fmin(davg, r->davg);
        } else if (ws < 0 || r->dmin < p->rows[ws].dmin) {
            ws = i;
        }
    }
    int k = snprintf(s, 512, " prefix_base=%zu", p->base);
    if (wd >= 0)
        k += snprintf(s + k, 512 - (size_t)k, " prefix_worst_dyadic_dmin=%.6f prefix_worst_dyadic_m=%zu"
                      " prefix_worst_dyadic_davg=%.6f", p->rows[wd].dmin, p->rows[wd].m, davg);
    else
        k += snprintf(s + k, 512 - (size_t)k, " prefix_worst_dyadic_dmin=- prefix_worst_dyadic_m=-"
                      " prefix_worst_dyadic_davg=-");
    if (ws >= 0)
        k += snprintf(s + k, 512 - (size_t)k, " prefix_worst_sample_dmin=%.6f prefix_worst_sample_m=%zu",
                      p->rows[ws].dmin, p->rows[ws].m);
    else
        k += snprintf(s + k, 512 - (size_t)k, " prefix_worst_sample_dmin=- prefix_worst_sample_m=-");
    snprintf(s + k, 512 - (size_t)k, " prefix_worst_any_dmin=%.6f prefix_worst_any_m=%zu", p->worst_any,
             p->worst_any_m);
    return s;
}
