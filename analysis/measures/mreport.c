/* mreport.c - see mreport.h. */
#include "mreport.h"
#include "pcf.h"
#include "quad.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"

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

static const char *dt_keys[4] = {"psi6", "voronoi_area_var", "mesh_ratio", "covering_radius"};

/* covering radius over Delta(n), like delta_min */
static double dt_value(const an_measures *m, int i, int k)
{
    const an_delaunay *d = &m->dt[i];
    const double v[4] = {d->psi6, d->area_var, d->mesh_ratio, d->covering / cfpo_delta_bound((double)m->n)};
    return v[k];
}

static double dt_mean(const an_measures *m, int k)
{
    if (!m->dt) return NAN;
    double s = 0;
    for (int i = 0; i < m->sets; i++) s += dt_value(m, i, k);
    return s / m->sets;
}

static double integ_mean(const an_measures *m, int heaviside, int se)
{
    if (!m->integ) return NAN;
    double s = 0;
    for (int i = 0; i < m->sets; i++) {
        const an_integration *g = &m->integ[i];
        const double v = heaviside ? (se ? g->heaviside_se : g->heaviside_mse) : (se ? g->gauss_se : g->gauss_mse);
        s += se ? v * v : v;
    }
    return se ? sqrt(s) / m->sets : s / m->sets;
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
    for (int k = 0; k < 4; k++) kv(f, dt_keys[k], dt_mean(m, k));
    kv(f, "utk_gauss_mse", integ_mean(m, 0, 0));
    kv(f, "utk_heaviside_mse", integ_mean(m, 1, 0));
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

    fputs(",\n  \"pcf\": ", f);
    if (!m->pcf) {
        fputs("null", f);
    } else {
        int pk = 0;
        for (int b = 1; b < m->pcf_bins; b++)
            if (m->pcf[b] > m->pcf[pk]) pk = b;
        fprintf(f, "{\"file\": \"pcf.txt\", \"sigma\": %g, \"rmax\": %g, \"step\": %g, \"bins\": %d, "
                   "\"kernel_cut_sigma\": %g, \"peak\": ", m->pcf_sigma, m->pcf_rmax, m->pcf_sigma / 5, m->pcf_bins,
                AN_PCF_CUT);
        jnum(f, m->pcf[pk]);
        fprintf(f, ", \"peak_r\": %.6g, \"seconds\": ", (pk + 1) * m->pcf_sigma / 5);
        jnum(f, m->pcf_seconds);
        fputc('}', f);
    }

    fputs(",\n  \"delaunay\": ", f);
    if (!m->dt) {
        fputs("null", f);
    } else {
        fputs("{", f);
        for (int k = 0; k < 4; k++) {
            fprintf(f, "%s\"%s\": ", k ? ", " : "", dt_keys[k]);
            jnum(f, dt_mean(m, k));
        }
        fputs(", \"seconds\": ", f);
        jnum(f, m->dt_seconds);
        fputs(",\n    \"per_set\": {", f);
        for (int k = 0; k < 4; k++) {
            fprintf(f, "%s\"%s\": [", k ? ", " : "", dt_keys[k]);
            for (int i = 0; i < m->sets; i++) {
                if (i) fputs(", ", f);
                jnum(f, dt_value(m, i, k));
            }
            fputc(']', f);
        }
        fputs("}}", f);
    }

    fputs(",\n  \"integration\": ", f);
    if (!m->integ) {
        fputs("null", f);
    } else {
        fprintf(f, "{\"integrands\": %d, \"seed\": %llu, \"gauss\": {\"mse\": ", m->integ[0].M,
                (unsigned long long)m->integ_seed);
        jnum(f, integ_mean(m, 0, 0));
        fputs(", \"se\": ", f);
        jnum(f, integ_mean(m, 0, 1));
        fputs("}, \"heaviside\": {\"mse\": ", f);
        jnum(f, integ_mean(m, 1, 0));
        fputs(", \"se\": ", f);
        jnum(f, integ_mean(m, 1, 1));
        fputs("}, \"seconds\": ", f);
        jnum(f, m->integ_seconds);
        fputs(",\n    \"per_set\": {\"gauss\": [", f);
        for (int i = 0; i < m->sets; i++) {
            if (i) fputs(", ", f);
            jnum(f, m->integ[i].gauss_mse);
        }
        fputs("], \"heaviside\": [", f);
        for (int i = 0; i < m->sets; i++) {
            if (i) fputs(", ", f);
            jnum(f, m->integ[i].heaviside_mse);
        }
        fputs("]}}", f);
    }
    return finish(f, &buf);
}

static int close_file(FILE *f, const char *path, char *err, size_t errlen)
{
    int bad = ferror(f);
    if (fclose(f) != 0) bad = 1;
    if (bad) snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return bad ? -1 : 0;
}

int an_measures_write_pcf(const char *path, const an_measures *m, char *err, size_t errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# pair correlation g(r) on the torus, no window correction; n=%zu, sets=%d (their mean)\n"
               "# Gaussian kernel sigma = %g Delta(n), cut at %g sigma; Delta(n) = %.12g\n"
               "# r/Delta\tg\n", m->n, m->sets, m->pcf_sigma, AN_PCF_CUT, cfpo_delta_bound((double)m->n));
    for (int b = 0; m->pcf && b < m->pcf_bins; b++) fprintf(f, "%.6g\t%.12g\n", (b + 1) * m->pcf_sigma / 5, m->pcf[b]);
    return close_file(f, path, err, errlen);
}

int an_measures_write_pcf_plot(const char *path, const an_measures *m, char *err, size_t errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# gnuplot pcf.gp: pcf.png, the pair correlation of pcf.txt\n"
               "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) { set terminal pngcairo size 800,500 } "
               "else { set terminal png size 800,500 }\nset output 'pcf.png'\n"
               "set xlabel 'r / Delta(n)'\nset ylabel 'g(r)'\nset grid\n"
               "set title 'pair correlation, n = %zu, %d set(s), sigma = %g Delta'\n"
               "plot 'pcf.txt' using 1:2 with lines title 'g(r)', 1 with lines dt 2 lc rgb 'gray' notitle\n",
               m->n, m->sets, m->pcf_sigma);
    return close_file(f, path, err, errlen);
}
