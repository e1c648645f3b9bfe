/* mreport.c - see mreport.h. */
#include "mreport.h"
#include "quad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void kv(FILE *f, const char *k, double v)
{
    fprintf(f, " %s=", k);
    if (isfinite(v)) fprintf(f, "%.6g", v);
    else fputc('-', f);
}

static void jnum(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.12g", v);
    else fputs("null", f);
}

static const char *disc_keys[5] = {"wrap_around_l2", "diaphony", "l2_star", "generalized_l2", "centred_l2"};
static const char *disc_short[5] = {"disc_wrap_l2", "disc_diaphony", "disc_l2_star", "disc_gen_l2", "disc_centred_l2"};

static double disc_value(const an_discrepancy *d, int k)
{
    const double v[5] = {d->wrap_l2, d->diaphony, d->l2_star, d->generalized_l2, d->centred_l2};
    return v[k];
}

static double disc_mean(const an_measures *m, int k)
{
    if (!m->disc) return NAN;
    double s = 0;
    for (int i = 0; i < m->sets; i++) s += disc_value(&m->disc[i], k);
    return s / m->sets;
}

/* open_memstream sets the buffer's address at fclose: read it after. */
static char *finish(FILE *f, char **buf)
{
    if (fclose(f) != 0) { free(*buf); return NULL; }
    return *buf;
}

char *an_measures_summary(const an_measures *m)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return NULL;
    kv(f, "p0", m->lowfreq->p0);
    kv(f, "h_index", m->lowfreq->h);
    kv(f, "lowk_alpha", m->lowfreq->alpha);
    for (int k = 0; k < 5; k++) kv(f, disc_short[k], disc_mean(m, k));
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
        char key[64];
        snprintf(key, sizeof key, "shiftvar_%s", an_integrands[t].name);
        kv(f, key, m->shiftvar->var[t]);
    }
    return finish(f, &buf);
}

char *an_measures_json(const an_measures *m)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return NULL;
    const an_lowfreq *l = m->lowfreq;
    fputs(",\n  \"low_frequency\": {\"range\": ", f);
    jnum(f, l->range);
    fputs(", \"P0\": ", f);
    jnum(f, l->p0);
    fprintf(f, ", \"P0_count\": %lld, \"H\": ", l->p0_count);
    jnum(f, l->h);
    fputs(", \"intercept\": ", f);
    jnum(f, l->s0);
    fputs(", \"peak\": ", f);
    jnum(f, l->peak);
    fprintf(f, ", \"peak_ring\": %d, \"alpha\": ", l->peak_ring);
    jnum(f, l->alpha);
    fprintf(f, ", \"rings\": [1, %d]}", l->rings);

    fputs(",\n  \"discrepancy\": ", f);
    if (!m->disc) {
        fputs("null", f);
    } else {
        fprintf(f, "{\"rooted\": true, \"accumulation\": \"%s\"", AN_QUAD_NAME);
        for (int k = 0; k < 5; k++) {
            fprintf(f, ", \"%s\": ", disc_keys[k]);
            jnum(f, disc_mean(m, k));
        }
        fputs(", \"seconds\": ", f);
        jnum(f, m->disc_seconds);
        fputs(",\n    \"per_set\": {", f);
        for (int k = 0; k < 5; k++) {
            fprintf(f, "%s\"%s\": [", k ? ", " : "", disc_keys[k]);
            for (int i = 0; i < m->sets; i++) {
                if (i) fputs(", ", f);
                jnum(f, disc_value(&m->disc[i], k));
            }
            fputc(']', f);
        }
        fputs("}}", f);
    }

    fputs(",\n  \"shift_variance\": {\"tail\": \"P = 1 beyond the box\"", f);
    for (int t = 0; t < AN_SHIFTVAR_COUNT; t++) {
        const an_integrand *g = &an_integrands[t];
        fprintf(f, ",\n    \"%s\": {\"%s\": %g, \"var\": ", g->name, g->disk ? "radius" : "sigma", g->size);
        jnum(f, m->shiftvar->var[t]);
        fputs(", \"n2_var\": ", f);
        jnum(f, m->shiftvar->var[t] * (double)m->n * (double)m->n);
        fputs(", \"tail\": ", f);
        jnum(f, m->shiftvar->tail[t]);
        fputc('}', f);
    }
    fputc('}', f);
    return finish(f, &buf);
}
