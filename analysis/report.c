/* report.c - see report.h. */
#include "report.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "geom.h"
#include "nnhist.h"

static FILE *open_out(const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
    else setvbuf(f, NULL, _IOFBF, 1 << 20);
    return f;
}

static int close_out(FILE *f, const char *path, char *err, size_t errlen)
{
    int bad = ferror(f);
    if (fclose(f) != 0) bad = 1;
    if (bad) snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return bad ? -1 : 0;
}

static void num(FILE *f, const char *fmt, double v)
{
    if (isfinite(v)) fprintf(f, fmt, v);
    else fputs("NaN", f);
}

/* v >= 0 as "d.dddddddde+XX" (9 significant digits, relative error below
 * 1e-9), "0" or "NaN": printf's %g is most of the run time otherwise. */
static char *fmt9(char *s, double v)
{
    if (!isfinite(v) || v < 0) return s + sprintf(s, isfinite(v) ? "%.8e" : "NaN", v);
    if (v == 0 || v < 1e-99) { *s++ = '0'; return s; }
    int e = (int)floor(log10(v));
    double m = v / pow(10, e - 8);
    long long q = llround(m);
    if (q >= 1000000000LL) { e++; q = llround(v / pow(10, e - 8)); }
    if (q < 100000000LL) { e--; q = llround(v / pow(10, e - 8)); }
    char dig[9];
    for (int i = 8; i >= 0; i--) { dig[i] = (char)('0' + q % 10); q /= 10; }
    *s++ = dig[0];
    *s++ = '.';
    for (int i = 1; i < 9; i++) *s++ = dig[i];
    *s++ = 'e';
    *s++ = e < 0 ? '-' : '+';
    int a = e < 0 ? -e : e;
    if (a >= 100) *s++ = (char)('0' + a / 100);
    *s++ = (char)('0' + a / 10 % 10);
    *s++ = (char)('0' + a % 10);
    return s;
}

int an_write_spectrum(const char *path, const double *P, int K, char *err, size_t errlen)
{
    const size_t side = an_side(K);
    char *line = malloc(24 * (side + 1));
    FILE *f = line ? open_out(path, err, errlen) : NULL;
    if (!f) {
        if (!line) snprintf(err, errlen, "%s: out of memory", path);
        free(line);
        return -1;
    }
    fprintf(f, "%d", 2 * K + 1);
    for (int kx = -K; kx <= K; kx++) fprintf(f, " %d", kx);
    fputc('\n', f);
    for (int ky = -K; ky <= K; ky++) {
        char *s = line + sprintf(line, "%d", ky);
        const double *row = P + an_pidx(K, -K, ky);
        for (size_t t = 0; t < side; t++) {
            *s++ = ' ';
            s = fmt9(s, row[t]);
        }
        *s++ = '\n';
        fwrite(line, 1, (size_t)(s - line), f);
    }
    free(line);
    return close_out(f, path, err, errlen);
}

int an_write_raps(const char *path, const an_report *r, char *err, size_t errlen)
{
    FILE *f = open_out(path, err, errlen);
    if (!f) return -1;
    const an_rings *g = r->rings;
    fprintf(f, "# radially averaged power spectrum and anisotropy; n=%zu, sets=%d, K=%d\n"
               "# ring i holds the integer frequencies k with i-1/2 <= |k| < i+1/2\n"
               "# r\tr/sqrt(n)\traps\tanisotropy_db\tcount\n", r->n, r->sets, r->K);
    for (int i = 1; i <= r->K; i++) {
        fprintf(f, "%d\t%.9g\t", i, i / sqrt((double)r->n));
        num(f, "%.12g", g->mean[i]);
        fputc('\t', f);
        num(f, "%.9g", g->aniso_db[i]);
        fprintf(f, "\t%lld\n", (long long)g->count[i]);
    }
    return close_out(f, path, err, errlen);
}

int an_write_nnhist(const char *path, const an_report *r, char *err, size_t errlen)
{
    FILE *f = open_out(path, err, errlen);
    if (!f) return -1;
    fprintf(f, "# nearest-neighbour distances d / Delta(n), Delta(n) = %.12g; n=%zu, sets=%d\n"
               "# the last bin also holds everything beyond it\n"
               "# from\tto\tcount\tfraction\n", cfpo_delta_bound((double)r->n), r->n, r->sets);
    const double total = (double)r->n * r->sets;
    for (int b = 0; b < AN_NN_BINS && r->nn_hist; b++)
        fprintf(f, "%.4f\t%.4f\t%llu\t%.9g\n", b * AN_NN_BIN, (b + 1) * AN_NN_BIN,
                (unsigned long long)r->nn_hist[b], (double)r->nn_hist[b] / total);
    return close_out(f, path, err, errlen);
}

/* ------------------------------------------------------------- JSON */

static void jnum(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.12g", v);
    else fputs("null", f);
}

static void jstr(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(f, "\\%c", *p);
        else if (*p < 0x20) fprintf(f, "\\u%04x", *p);
        else fputc(*p, f);
    }
    fputc('"', f);
}

static void jkey(FILE *f, const char *k, int first)
{
    fprintf(f, "%s\n  ", first ? "" : ",");
    jstr(f, k);
    fputs(": ", f);
}

static void jarray(FILE *f, const double *v, int m)
{
    fputc('[', f);
    for (int i = 0; i < m; i++) {
        if (i) fputs(", ", f);
        jnum(f, v[i]);
    }
    fputc(']', f);
}

static void json_spectrum(FILE *f, const an_report *r)
{
    const an_rings *g = r->rings;
    const an_hsd *h = r->hsd;
    jkey(f, "spectrum", 0);
    fprintf(f, "{\"method\": \"%s\"", r->exact ? "exact" : "nufft");
    if (!r->exact)
        fprintf(f, ", \"kernel\": \"exponential of semicircle\", \"kernel_width\": %d, "
                   "\"kernel_beta\": %.6g, \"grid\": %d, \"oversampling\": 2",
                r->nufft.width, r->nufft.beta, r->nufft.grid);
    fputs(", \"check_maxdiff\": ", f);
    jnum(f, r->check_maxdiff);
    fputs(", \"seconds\": ", f);
    jnum(f, r->spectrum_seconds);
    fputc('}', f);
    jkey(f, "raps_peak", 0);
    fprintf(f, "{\"ring\": %d, \"r_over_sqrt_n\": ", g->peak_ring);
    jnum(f, g->peak_ring / sqrt((double)r->n));
    fputs(", \"raps\": ", f);
    jnum(f, g->peak_mean);
    fputc('}', f);
    jkey(f, "spike", 0);
    fprintf(f, "{\"ratio\": ");
    jnum(f, g->spike_ratio);
    if (g->spike_ring > 0)
        fprintf(f, ", \"kx\": %d, \"ky\": %d, \"ring\": %d", g->spike_kx, g->spike_ky, g->spike_ring);
    else
        fputs(", \"kx\": null, \"ky\": null, \"ring\": null", f);
    fputs(", \"P\": ", f);
    jnum(f, g->spike_P);
    fputs(", \"ring_mean\": ", f);
    jnum(f, g->spike_mean);
    fprintf(f, ", \"min_ring_count\": %d}", AN_SPIKE_MIN_COUNT);
    jkey(f, "spike_per_set", 0);
    fputc('[', f);
    for (int i = 0; i < r->sets; i++) {
        fputs(i ? ", {\"ratio\": " : "{\"ratio\": ", f);
        jnum(f, r->spike[i]);
        if (isfinite(r->spike[i]))
            fprintf(f, ", \"kx\": %d, \"ky\": %d}", r->spike_k[2 * i], r->spike_k[2 * i + 1]);
        else
            fputs(", \"kx\": null, \"ky\": null}", f);
    }
    fputc(']', f);
    jkey(f, "spike_ratio_set_mean", 0);
    jnum(f, r->spike_mean);
    jkey(f, "lattice", 0);
    fprintf(f, "{\"g\": %d, \"period\": %d, \"frequencies\": %d, \"ratio\": ", r->lattice->g, r->lattice->period,
            r->lattice->count);
    jnum(f, r->lattice->ratio);
    if (r->lattice->count) fprintf(f, ", \"kx\": %d, \"ky\": %d", r->lattice->kx, r->lattice->ky);
    fputs(", \"P\": ", f);
    jnum(f, r->lattice->P);
    fputs(", \"ring_mean\": ", f);
    jnum(f, r->lattice->mean);
    fputc('}', f);
    jkey(f, "effective_nyquist", 0);
    jnum(f, h->eff_nyquist);
    jkey(f, "effective_nyquist_detail", 0);
    fputs("{\"r_01\": ", f);
    jnum(f, h->r_01);
    fputs(", \"r_half\": ", f);
    jnum(f, h->r_half);
    fputc('}', f);
    jkey(f, "oscillation", 0);
    jnum(f, h->oscillation);
    jkey(f, "oscillation_rings", 0);
    fprintf(f, "[%d, %d]", h->osc_from, h->osc_to);
    jkey(f, "oscillation_clipped", 0);
    fputs(h->osc_clipped ? "true" : "false", f);
}

static void json_certificate(FILE *f, const an_certificate *c)
{
    jkey(f, "certificate", 0);
    if (!c) { fputs("null", f); return; }
    double n = (double)c->n;
    fprintf(f, "{\"fpd\": %s, \"points\": %zu, \"tolerance\": ", c->fpd ? "true" : "false", c->n);
    jnum(f, c->tol_rel);
    fputs(", \"delta\": ", f);
    jnum(f, c->delta);
    fputs(", \"covering_radius\": ", f);
    jnum(f, c->covering);
    fputs(",\n    \"farthest_point\": {\"pass_fraction\": ", f);
    jnum(f, (double)c->fp_pass / n);
    fputs(", \"max_violation\": ", f);
    jnum(f, c->fp_max_violation);
    fprintf(f, ", \"worst_point\": %zu}", c->fp_worst);
    fputs(",\n    \"local_characterization\": {\"pass_fraction\": ", f);
    jnum(f, (double)c->lct_pass / n);
    fputs(", \"property1_pass_fraction\": ", f);
    jnum(f, (double)c->p1_pass / n);
    fputs(", \"property2_pass_fraction\": ", f);
    jnum(f, (double)c->p2_pass / n);
    fputs(", \"property1_max_violation\": ", f);
    jnum(f, c->p1_max_violation);
    fputs(", \"property2_max_violation\": ", f);
    jnum(f, c->p2_max_violation);
    fputs("}}", f);
}

int an_write_json(const char *path, const an_report *r, char *err, size_t errlen)
{
    FILE *f = open_out(path, err, errlen);
    if (!f) return -1;
    fputc('{', f);
    jkey(f, "tool", 1);
    fprintf(f, "\"cfpo-analyze\", \"version\": \"%s\"", CFPO_VERSION);
    jkey(f, "files", 0);
    fputc('[', f);
    for (int i = 0; i < r->sets; i++) {
        if (i) fputs(", ", f);
        jstr(f, r->files[i]);
    }
    fputc(']', f);
    jkey(f, "sets", 0);
    fprintf(f, "%d", r->sets);
    jkey(f, "n", 0);
    fprintf(f, "%zu", r->n);
    jkey(f, "K", 0);
    fprintf(f, "%d", r->K);
    jkey(f, "Delta", 0);
    jnum(f, cfpo_delta_bound((double)r->n));
    jkey(f, "delta_min", 0);
    jnum(f, r->delta_min ? r->delta_min_mean : NAN);
    jkey(f, "delta_avg", 0);
    jnum(f, r->delta_avg ? r->delta_avg_mean : NAN);
    jkey(f, "delta_min_per_set", 0);
    if (r->delta_min) jarray(f, r->delta_min, r->sets);
    else fputs("null", f);
    jkey(f, "delta_avg_per_set", 0);
    if (r->delta_avg) jarray(f, r->delta_avg, r->sets);
    else fputs("null", f);
    json_spectrum(f, r);
    json_certificate(f, r->cert);
    if (r->json_extra) fputs(r->json_extra, f);
    jkey(f, "threads", 0);
    fprintf(f, "%d", r->threads);
    jkey(f, "seconds", 0);
    jnum(f, r->seconds);
    fputs("\n}\n", f);
    return close_out(f, path, err, errlen);
}

int an_write_plot(const char *path, const an_report *r, char *err, size_t errlen)
{
    FILE *f = open_out(path, err, errlen);
    if (!f) return -1;
    fprintf(f,
            "# Run inside this folder: gnuplot plot.gp -> spectrum.png, raps.png, nn_hist.png\n"
            "# n=%zu sets=%d K=%d\n"
            "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) { set terminal pngcairo size 900,900 } "
            "else { set terminal png size 900,900 }\n"
            "set output 'spectrum.png'\n"
            "set size square\nset xrange [%d:%d]\nset yrange [%d:%d]\n"
            "set cbrange [0:4]\nset palette grey\nset title 'power spectrum P(k)'\n"
            "plot 'spectrum.txt' nonuniform matrix with image notitle\n"
            "reset\n"
            "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) { set terminal pngcairo size 900,700 } "
            "else { set terminal png size 900,700 }\n"
            "set output 'raps.png'\nset multiplot layout 2,1\n"
            "set xlabel 'r / sqrt(n)'\nset yrange [0:4]\n"
            "plot 'raps.txt' using 2:3 with lines title 'RAPS', 1 with lines dt 2 notitle\n"
            "set yrange [*:*]\n"
            "plot 'raps.txt' using 2:4 with lines title 'anisotropy (dB)'\n"
            "unset multiplot\n"
            "set output 'nn_hist.png'\nset xlabel 'nearest-neighbour distance / Delta(n)'\n"
            "set style fill solid 0.5\n"
            "plot 'nn_hist.txt' using (($1+$2)/2):4 with boxes title 'fraction of points'\n",
            r->n, r->sets, r->K, -r->K, r->K, -r->K, r->K);
    return close_out(f, path, err, errlen);
}

/* ---------------------------------------------------------- summary */

static void kv(FILE *f, const char *k, const char *fmt, double v)
{
    fprintf(f, " %s=", k);
    if (isfinite(v)) fprintf(f, fmt, v);
    else fputc('-', f);
}

int an_print_imprint(FILE *f, const an_report *r)
{
    const an_rings *g = r->rings;
    const double level = an_spike_noise_level(r->K);
    if (!(g->pattern_ratio > level) || g->pattern_ring <= 0) return 0;
    const an_lattice *L = r->lattice;
    const int on_grid = L && L->count && L->kx == g->pattern_kx && L->ky == g->pattern_ky;
    fprintf(f, "imprint: P(k) at k (%d, %d) is %.1f times its ring's mean and %.1f times its neighbours', above the noise "
               "levels %.1f and %.1f of these %lld frequencies: the set carries a periodic pattern there%s\n",
            g->pattern_kx, g->pattern_ky, g->pattern_ratio, g->pattern_local, level, an_pattern_level(level),
            (long long)(2 * (int64_t)r->K + 1) * (2 * r->K + 1), on_grid ? ", a frequency of the grid (lattice_ratio)" : "");
    fflush(f);
    return 1;
}

void an_print_summary(FILE *f, const an_report *r)
{
    const an_rings *g = r->rings;
    fprintf(f, "SUMMARY method=analyze sets=%d n=%zu K=%d spectrum=%s threads=%d", r->sets, r->n,
            r->K, r->exact ? "exact" : "nufft", r->threads);
    kv(f, "seconds", "%.6f", r->seconds);
    kv(f, "spectrum_seconds", "%.6f", r->spectrum_seconds);
    kv(f, "delta_min", "%.6f", r->delta_min ? r->delta_min_mean : NAN);
    kv(f, "delta_avg", "%.6f", r->delta_avg ? r->delta_avg_mean : NAN);
    kv(f, "raps_peak", "%.6f", g->peak_mean);
    kv(f, "raps_peak_r", "%.6f", g->peak_ring / sqrt((double)r->n));
    kv(f, "eff_nyquist", "%.6f", r->hsd->eff_nyquist);
    kv(f, "oscillation", "%.6f", r->hsd->oscillation);
    kv(f, "spike_ratio", "%.6g", g->spike_ratio);
    if (g->spike_ring > 0) fprintf(f, " spike_k=%d,%d", g->spike_kx, g->spike_ky);
    else fputs(" spike_k=-", f);
    kv(f, "spike_ratio_set_mean", "%.6g", r->spike_mean);
    kv(f, "lattice_ratio", "%.6g", r->lattice->ratio);
    if (r->lattice->count) fprintf(f, " lattice_k=%d,%d", r->lattice->kx, r->lattice->ky);
    else fputs(" lattice_k=-", f);
    if (r->cert) {
        const an_certificate *c = r->cert;
        fprintf(f, " certify=%s", c->fpd ? "pass" : "fail");
        kv(f, "cert_pass", "%.6f", (double)c->fp_pass / (double)c->n);
        kv(f, "cert_max_violation", "%.6g", c->fp_max_violation);
        kv(f, "lct_pass", "%.6f", (double)c->lct_pass / (double)c->n);
    } else {
        fputs(" certify=- cert_pass=- cert_max_violation=- lct_pass=-", f);
    }
    kv(f, "check_maxdiff", "%.3g", r->check_maxdiff);
    if (r->summary_extra) fputs(r->summary_extra, f);
    fprintf(f, " peak_bytes=%llu out=%s\n", (unsigned long long)r->peak_bytes, r->out);
    fflush(f);
}
