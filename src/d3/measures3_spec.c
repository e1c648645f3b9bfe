/* measures3_spec.c - see measures3_spec.h. */
#include "measures3_spec.h"

#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "nufft.h"
#include "quadrature.h"

#define SPEC_W 10

static size_t side(int K) { return 2 * (size_t)K + 1; }

int cfpo3_spec_default_K(size_t n)
{
    const double K = ceil(2 * cbrt((double)n));
    return K < 8 ? 8 : (K > 64 ? 64 : (int)K);
}

int cfpo3_power_exact(const double *p, size_t n, int K, double *P)
{
    const size_t S = side(K), S3 = S * S * S;
    double *re = calloc(S3, sizeof *re), *im = calloc(S3, sizeof *im);
    double *e = malloc(3 * 2 * S * sizeof *e); /* cos, sin of each axis' phases */
    if (!re || !im || !e) {
        free(re), free(im), free(e);
        return -1;
    }
    for (size_t j = 0; j < n; j++) {
        for (int a = 0; a < 3; a++)
            for (int k = -K; k <= K; k++) {
                /* the phase k x reduced to [0, 1) before sin and cos */
                double t = (double)k * p[3 * j + a];
                t -= floor(t);
                e[(a * S + (size_t)(k + K)) * 2] = cos(2 * M_PI * t);
                e[(a * S + (size_t)(k + K)) * 2 + 1] = -sin(2 * M_PI * t);
            }
        for (size_t z = 0; z < S; z++)
            for (size_t y = 0; y < S; y++) {
                const double *ez = e + (2 * S + z) * 2, *ey = e + (S + y) * 2;
                const double cr = ez[0] * ey[0] - ez[1] * ey[1], ci = ez[0] * ey[1] + ez[1] * ey[0];
                double *r = re + (z * S + y) * S, *i = im + (z * S + y) * S;
                for (size_t x = 0; x < S; x++) {
                    const double *ex = e + x * 2;
                    r[x] += cr * ex[0] - ci * ex[1];
                    i[x] += cr * ex[1] + ci * ex[0];
                }
            }
    }
    for (size_t k = 0; k < S3; k++) P[k] = (re[k] * re[k] + im[k] * im[k]) / (double)n;
    free(re), free(im), free(e);
    return 0;
}

static double es_kernel(double t, double alpha, double beta)
{
    const double s = 1.0 - (t / alpha) * (t / alpha);
    return s > 0 ? exp(beta * (sqrt(s) - 1.0)) : 0.0;
}

int cfpo3_power_nufft(const double *p, size_t n, int K, double *P, char *err, size_t errlen)
{
    if (K < 1 || K > CFPO3_SPEC_KMAX) {
        snprintf(err, errlen, "spectrum: K = %d is outside 1..%d", K, CFPO3_SPEC_KMAX);
        return -1;
    }
    const int w = SPEC_W, M = cfpo_nufft_fft_size(2 * (2 * K + 1));
    const double alpha = w / 2.0, beta = 2.30 * w;
    const size_t MM = (size_t)M * (size_t)M * (size_t)M;
    fftw_complex *g = fftw_malloc(MM * sizeof *g);
    double *ph = malloc(((size_t)K + 1) * sizeof *ph);
    if (!g || !ph) {
        fftw_free(g), free(ph);
        snprintf(err, errlen, "spectrum: out of memory for a %d^3 grid", M);
        return -1;
    }
    for (size_t i = 0; i < MM; i++) g[i][0] = g[i][1] = 0;
    for (size_t j = 0; j < n; j++) {
        double v[3][SPEC_W];
        int l0[3];
        for (int a = 0; a < 3; a++) {
            const double u = p[3 * j + a] * (double)M;
            l0[a] = (int)ceil(u - alpha);
            for (int b = 0; b < w; b++) v[a][b] = es_kernel(u - (double)(l0[a] + b), alpha, beta);
        }
        for (int c = 0; c < w; c++) {
            const size_t z = (size_t)(((l0[2] + c) % M + M) % M);
            for (int b = 0; b < w; b++) {
                const size_t y = (size_t)(((l0[1] + b) % M + M) % M);
                const double vzy = v[2][c] * v[1][b];
                fftw_complex *row = g + (z * (size_t)M + y) * (size_t)M;
                for (int a = 0; a < w; a++) row[((l0[0] + a) % M + M) % M][0] += vzy * v[0][a];
            }
        }
    }
    fftw_plan plan = fftw_plan_dft_3d(M, M, M, g, g, FFTW_FORWARD, FFTW_ESTIMATE);
    if (!plan) {
        fftw_free(g), free(ph);
        snprintf(err, errlen, "spectrum: FFTW could not plan a %d^3 transform", M);
        return -1;
    }
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    /* phihat(k / M) = integral of phi(t) cos(2 pi k t / M) over |t| <= alpha */
    enum { Q = 80 };
    double z[Q], wq[Q];
    cfpo_gauss_legendre(Q, z, wq);
    for (int k = 0; k <= K; k++) {
        double s = 0;
        for (int i = 0; i < Q; i++) s += wq[i] * es_kernel(alpha * z[i], alpha, beta) * cos(2 * M_PI * k * alpha * z[i] / M);
        ph[k] = alpha * s;
    }
    const size_t S = side(K);
    for (int kz = -K; kz <= K; kz++)
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                const fftw_complex *c = g + (((size_t)((kz + M) % M) * (size_t)M + (size_t)((ky + M) % M)) * (size_t)M +
                                             (size_t)((kx + M) % M));
                const double d = ph[abs(kx)] * ph[abs(ky)] * ph[abs(kz)];
                P[((size_t)(kz + K) * S + (size_t)(ky + K)) * S + (size_t)(kx + K)] =
                    ((*c)[0] * (*c)[0] + (*c)[1] * (*c)[1]) / (d * d) / (double)n;
            }
    fftw_free(g), free(ph);
    return 0;
}

void cfpo3_power_shells(const double *P, int K, double *shell, long *count)
{
    const size_t S = side(K);
    for (int s = 0; s <= K; s++) shell[s] = 0, count[s] = 0;
    for (int kz = -K; kz <= K; kz++)
        for (int ky = -K; ky <= K; ky++)
            for (int kx = -K; kx <= K; kx++) {
                const long s = lround(sqrt((double)(kx * kx + ky * ky + kz * kz)));
                if (s > K) continue;
                shell[s] += P[((size_t)(kz + K) * S + (size_t)(ky + K)) * S + (size_t)(kx + K)];
                count[s]++;
            }
    for (int s = 0; s <= K; s++) shell[s] = count[s] ? shell[s] / (double)count[s] : NAN;
}

int cfpo3_power_peak(const double *shell, int K)
{
    int peak = 1;
    for (int s = 1; s <= K; s++)
        if (shell[s] > shell[peak]) peak = s;
    return peak;
}

double cfpo3_power_p0(const double *P, int K, size_t n, long *cnt)
{
    const double R = 0.2 * cbrt((double)n);
    const size_t S = side(K);
    *cnt = 0;
    if (floor(R) > K || R < 1) return NAN;
    const int r = (int)floor(R);
    double sum = 0;
    for (int kz = -r; kz <= r; kz++)
        for (int ky = -r; ky <= r; ky++)
            for (int kx = -r; kx <= r; kx++) {
                const double q = (double)(kx * kx + ky * ky + kz * kz);
                if (q == 0 || q > R * R) continue;
                sum += P[((size_t)(kz + K) * S + (size_t)(ky + K)) * S + (size_t)(kx + K)];
                (*cnt)++;
            }
    return *cnt ? sum / (double)*cnt : NAN;
}

double cfpo3_spike_noise_level(int K)
{
    const double S = 2.0 * K + 1;
    return log(S * S * S / 2) + 4;
}

void cfpo3_power_spike(const double *P, int K, const double *shell, const long *count, cfpo3_spike *out)
{
    const size_t S = side(K);
    out->ratio = out->P = out->mean = NAN;
    out->kx = out->ky = out->kz = out->shell = 0;
    out->noise = cfpo3_spike_noise_level(K);
    for (int kz = 0; kz <= K; kz++)
        for (int ky = kz > 0 ? -K : 0; ky <= K; ky++)
            for (int kx = (kz > 0 || ky > 0) ? -K : 1; kx <= K; kx++) {
                const long s = lround(sqrt((double)(kx * kx + ky * ky + kz * kz)));
                if (s < 1 || s > K || count[s] < CFPO3_SPIKE_MIN_COUNT || !(shell[s] > 0)) continue;
                const double p = P[((size_t)(kz + K) * S + (size_t)(ky + K)) * S + (size_t)(kx + K)];
                const double q = p / shell[s];
                if (!(q <= out->ratio)) { /* also the first (NAN) */
                    out->ratio = q, out->P = p, out->mean = shell[s];
                    out->kx = kx, out->ky = ky, out->kz = kz, out->shell = (int)s;
                }
            }
    out->pass = !(out->ratio > out->noise);
}
