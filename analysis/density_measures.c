/* density_measures.c - see density_measures.h. */
#include "density_measures.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "dens_measure.h"
#include "power.h"
#include "report.h"

int an_density_begin(an_density *a, const char *spec, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    a->radius = AN_DDA_RADIUS;
    a->sum = (an_dda_summary){.peak = NAN, .peak_freq = NAN, .low = NAN, .aniso_db = NAN};
    return cfpo_density_load(spec, &a->d, err, errlen);
}

/* The count fidelity over the blocks expecting at least emin points. */
static int an_density_fidelity_min(const cfpo_density *d, const double *xy, size_t n, int64_t B, double emin,
                                   double *rms, double *maxabs, size_t *off)
{
    double *mass = calloc((size_t)(B * B), sizeof *mass);
    int64_t *cnt = calloc((size_t)(B * B), sizeof *cnt);
    if (!mass || !cnt) { free(mass); free(cnt); return -1; }
    const double pw = 1.0 / (double)d->w, ph = 1.0 / (double)d->h, bs = 1.0 / (double)B;
    for (int64_t j = 0; j < d->h; j++)
        for (int64_t i = 0; i < d->w; i++) {
            const double r = d->rho[j * d->w + i];
            if (r == 0) continue;
            const double x0 = (double)i * pw, x1 = x0 + pw, y0 = (double)j * ph, y1 = y0 + ph;
            for (int64_t by = (int64_t)(y0 * (double)B); by < B && (double)by * bs < y1; by++) {
                const double oy = fmin(y1, (double)(by + 1) * bs) - fmax(y0, (double)by * bs);
                if (oy <= 0) continue;
                for (int64_t bx = (int64_t)(x0 * (double)B); bx < B && (double)bx * bs < x1; bx++) {
                    const double ox = fmin(x1, (double)(bx + 1) * bs) - fmax(x0, (double)bx * bs);
                    if (ox > 0) mass[by * B + bx] += r * ox * oy;
                }
            }
        }
    size_t o = 0;
    for (size_t k = 0; k < n; k++) {
        const double x = xy[2 * k], y = xy[2 * k + 1];
        int64_t bx = (int64_t)(x * (double)B), by = (int64_t)(y * (double)B);
        bx = bx < 0 ? 0 : bx >= B ? B - 1 : bx;
        by = by < 0 ? 0 : by >= B ? B - 1 : by;
        cnt[by * B + bx]++;
        if (!(cfpo_density_at(d, x, y) > 0)) o++;
    }
    double s2 = 0, mx = 0;
    int64_t used = 0;
    for (int64_t b = 0; b < B * B; b++) {
        if (!(mass[b] > 0) || (double)n * mass[b] < emin) continue;
        const double e = (double)n * mass[b], rel = ((double)cnt[b] - e) / e;
        s2 += rel * rel;
        if (fabs(rel) > mx) mx = fabs(rel);
        used++;
    }
    *rms = used ? sqrt(s2 / (double)used) : 0;
    *maxabs = mx;
    *off = o;
    free(mass);
    free(cnt);
    return 0;
}

int an_density_fidelity(const cfpo_density *d, const double *xy, size_t n, int64_t B, double *rms, double *maxabs,
                        size_t *off)
{
    return an_density_fidelity_min(d, xy, n, B, 0, rms, maxabs, off);
}

/* The capacity deviation and the spectrum of one set. */
static int add_structure(an_density *a, const double *xy, size_t n, const an_vcells *cells, int K, char *err,
                         size_t errlen)
{
    double t0 = cli_now();
    if (cells && cells->n == n) {
        double *cap = malloc(n * sizeof *cap), s = 0;
        if (!cap || an_capacity_compute(&a->d, cells, cap) != 0) {
            free(cap);
            snprintf(err, errlen, "out of memory for the capacities");
            return -1;
        }
        for (size_t i = 0; i < n; i++) s += cap[i];
        a->cap_dev += an_capacity_deviation(cap, n);
        a->cap_sets++;
        if (fabs(s - 1) > a->cap_sum_err) a->cap_sum_err = fabs(s - 1);
        free(cap);
    }
    double t1 = cli_now();
    a->cap_seconds += t1 - t0;
    if (!a->dda) {
        a->K = K;
        if (!(a->dda = calloc(an_side(K) * an_side(K), sizeof *a->dda))) {
            snprintf(err, errlen, "out of memory for the differential-domain spectrum");
            return -1;
        }
    }
    const size_t N = an_side(a->K) * an_side(a->K);
    double *S = malloc(N * sizeof *S);
    an_dda_info info;
    if (!S) {
        snprintf(err, errlen, "out of memory for the differential-domain spectrum");
        return -1;
    }
    if (an_dda_compute(&a->d, xy, n, a->K, a->radius, S, &info, err, errlen) != 0) {
        free(S);
        return -1;
    }
    for (size_t t = 0; t < N; t++) a->dda[t] += S[t];
    a->pairs += info.pairs;
    free(S);
    a->dda_seconds += cli_now() - t1;
    return 0;
}

int an_density_add(an_density *a, const double *xy, size_t n, const an_vcells *cells, int K, char *err,
                   size_t errlen)
{
    double *m = malloc(n * sizeof *m), dmin, davg, rms, mx, rms16, mx16;
    size_t off;
    int64_t B = (int64_t)floor(sqrt((double)n / 64));
    if (B < 1) B = 1;
    if (!m || cfpo_dens_nn(&a->d, xy, n, m, &dmin, &davg) != 0 ||
        an_density_fidelity(&a->d, xy, n, B, &rms, &mx, &off) != 0 ||
        an_density_fidelity_min(&a->d, xy, n, B, 16, &rms16, &mx16, &off) != 0) {
        free(m);
        snprintf(err, errlen, "out of memory for the density measures");
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        int b = (int)(m[i] / AN_DENS_BIN);
        a->hist[b < 0 ? 0 : b >= AN_DENS_BINS ? AN_DENS_BINS - 1 : b]++;
    }
    free(m);
    a->sets++;
    a->dmin += dmin;
    a->davg += davg;
    a->fid_rms += rms;
    a->fid_max += mx;
    a->fid_rms16 += rms16;
    a->fid_max16 += mx16;
    a->off += (double)off;
    a->blocks = B;
    return add_structure(a, xy, n, cells, K, err, errlen);
}

int an_density_finish(an_density *a, size_t n)
{
    a->n = n;
    if (!a->dda || a->sets < 1) return 0;
    const size_t N = an_side(a->K) * an_side(a->K);
    for (size_t t = 0; t < N; t++) a->dda[t] /= a->sets;
    return an_dda_summarise(a->dda, a->K, n, &a->sum);
}

int an_density_write_dda(const an_density *a, const char *raps_path, const char *spectrum_path, char *err,
                         size_t errlen)
{
    if (!a->dda) return 0;
    if (an_dda_write_raps(raps_path, a->dda, a->K, a->n, a->sets, a->radius, err, errlen) != 0) return -1;
    return an_write_spectrum(spectrum_path, a->dda, a->K, err, errlen);
}

int an_density_write(const an_density *a, const char *path, char *err, size_t errlen)
{
    cli_atomic f;
    if (cli_atomic_open(&f, path, err, errlen) != 0) return -1;
    const double s = a->sets > 0 ? a->sets : 1;
    uint64_t tot = 0;
    for (int b = 0; b < AN_DENS_BINS; b++) tot += a->hist[b];
    fprintf(f.f, "# density hash %016llx, %lld x %lld pixels, contrast %.6g\n", (unsigned long long)a->d.hash,
            (long long)a->d.w, (long long)a->d.h, a->d.rho_max / a->d.rho_min);
    fprintf(f.f, "# delta_min %.6f delta_avg %.6f (symmetric measure, mean of %d sets)\n", a->dmin / s, a->davg / s,
            a->sets);
    fprintf(f.f, "# count fidelity over %lld x %lld blocks: rms %.6f max %.6f (blocks expecting 16 or more points: "
            "rms %.6f max %.6f); off support %.1f points\n", (long long)a->blocks, (long long)a->blocks,
            a->fid_rms / s, a->fid_max / s, a->fid_rms16 / s, a->fid_max16 / s, a->off / s);
    fprintf(f.f, "# capacity deviation (std / mean of the density's integral over each Voronoi cell) %.6f over %d "
            "sets; largest |sum of capacities - 1| %.3g\n", a->cap_sets ? a->cap_dev / a->cap_sets : NAN,
            a->cap_sets, a->cap_sum_err);
    fprintf(f.f, "# differential-domain spectrum (window R = %g local spacings, %.0f pairs a set): peak %.6f at "
            "|k| / sqrt(n) = %.4f, low-frequency mean %.6f, anisotropy %.3f dB (dda_raps.txt, dda_spectrum.txt)\n",
            a->radius, a->pairs / s, a->sum.peak, a->sum.peak_freq, a->sum.low, a->sum.aniso_db);
    fprintf(f.f, "# nearest-neighbour measure histogram: bin centre, fraction of points\n");
    for (int b = 0; b < AN_DENS_BINS; b++)
        fprintf(f.f, "%.3f %.6g\n", (b + 0.5) * AN_DENS_BIN, tot ? (double)a->hist[b] / (double)tot : 0.0);
    return cli_atomic_commit(&f, err, errlen);
}

void an_density_print(const an_density *a, FILE *f)
{
    const double s = a->sets > 0 ? a->sets : 1;
    fprintf(f, "DENSITY hash=%016llx contrast=%.4g density_delta_min=%.6f density_delta_avg=%.6f "
               "count_fidelity_rms=%.6f count_fidelity_max=%.6f count_fidelity16_rms=%.6f count_fidelity16_max=%.6f "
               "blocks=%lld off_support=%.1f capacity_deviation=%.6f dda_peak=%.6f dda_peak_freq=%.6f dda_low=%.6f "
               "dda_aniso_db=%.6f capacity_seconds=%.3f dda_seconds=%.3f\n",
            (unsigned long long)a->d.hash, a->d.rho_max / a->d.rho_min, a->dmin / s, a->davg / s, a->fid_rms / s,
            a->fid_max / s, a->fid_rms16 / s, a->fid_max16 / s, (long long)a->blocks, a->off / s,
            a->cap_sets ? a->cap_dev / a->cap_sets : NAN, a->sum.peak, a->sum.peak_freq, a->sum.low, a->sum.aniso_db,
            a->cap_seconds, a->dda_seconds);
}

void an_density_free(an_density *a)
{
    cfpo_density_free(&a->d);
    free(a->dda);
    a->dda = NULL;
}
