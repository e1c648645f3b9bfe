/* pcf.c - see pcf.h. */
#include "pcf.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "omp_compat.h"

static double delta_of(size_t n) { return sqrt(2.0 / (sqrt(3.0) * (double)n)); }

int an_pcf_bins(size_t n, double sigma, double rmax)
{
    if (n < 2 || !(sigma > 0) || !(rmax > 0)) return 0;
    const double D = delta_of(n), h = sigma / 5;
    double B = floor(rmax / h + 1e-9);
    const double fit = floor((0.5 / D - AN_PCF_CUT * sigma) / h);
    if (fit < B) B = fit;
    return B < 1 ? 0 : (int)B;
}

static double wrap(double d) { return d - floor(d + 0.5); } /* to [-1/2, 1/2) */

typedef struct {
    double sig, h, cut, cut2, step; /* absolute: sigma, bin step, support; exp(-tau^2) */
    int bins;
} kernel;

/* Adds exp(-(r_b - d)^2 / (2 sigma^2)) for the bins within the support. */
static inline void add_pair(const kernel *k, double d, double *acc)
{
    int lo = (int)ceil((d - k->cut) / k->h), hi = (int)floor((d + k->cut) / k->h);
    if (lo < 1) lo = 1;
    if (hi > k->bins) hi = k->bins;
    if (lo > hi) return;
    const double tau = k->h / k->sig, t = (lo * k->h - d) / k->sig;
    double e = exp(-0.5 * t * t), q = exp(-t * tau - 0.5 * tau * tau);
    for (int b = lo; b <= hi; b++) {
        acc[b - 1] += e;
        e *= q;
        q *= k->step;
    }
}

static inline void pair(const kernel *k, const double *xy, size_t i, size_t j, double *acc)
{
    const double dx = wrap(xy[2 * i] - xy[2 * j]), dy = wrap(xy[2 * i + 1] - xy[2 * j + 1]);
    const double d2 = dx * dx + dy * dy;
    if (d2 < k->cut2) add_pair(k, sqrt(d2), acc);
}

/* sum over ordered pairs -> g */
static void normalise(const kernel *k, size_t n, const double *acc, double *g)
{
    const double c = 2.0 / ((double)n * (double)(n - 1) * 2 * M_PI * k->sig * sqrt(2 * M_PI));
    for (int b = 1; b <= k->bins; b++) g[b - 1] = c * acc[b - 1] / (b * k->h);
}

static void setup(kernel *k, size_t n, double sigma, int bins)
{
    const double D = delta_of(n);
    k->sig = sigma * D;
    k->h = k->sig / 5;
    k->bins = bins;
    k->cut = AN_PCF_CUT * k->sig;
    const double rc = bins * k->h + k->cut;
    k->cut2 = rc * rc;
    k->step = exp(-(k->h / k->sig) * (k->h / k->sig));
}

static size_t cell_of(double v, size_t g)
{
    size_t c = (size_t)(v * (double)g);
    return c >= g ? g - 1 : c;
}

int an_pcf_compute(const double *xy, size_t n, double sigma, double rmax, int bins, double *g)
{
    (void)rmax;
    kernel k;
    setup(&k, n, sigma, bins);
    const double rc = sqrt(k.cut2);
    size_t G = (size_t)floor(1.0 / rc);
    if (G > 4096) G = 4096;
    if (G < 3) { /* small n: every pair */
        double *acc = calloc((size_t)bins, sizeof *acc);
        if (!acc) return -1;
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n; j++) pair(&k, xy, i, j, acc);
        normalise(&k, n, acc, g);
        free(acc);
        return 0;
    }
    size_t *start = calloc(G * G + 1, sizeof *start), *idx = malloc(n * sizeof *idx);
    double *rows = calloc(G * (size_t)bins, sizeof *rows);
    if (!start || !idx || !rows) {
        free(start); free(idx); free(rows);
        return -1;
    }
    for (size_t i = 0; i < n; i++) start[cell_of(xy[2 * i + 1], G) * G + cell_of(xy[2 * i], G) + 1]++;
    for (size_t c = 0; c < G * G; c++) start[c + 1] += start[c];
    for (size_t i = 0; i < n; i++) idx[start[cell_of(xy[2 * i + 1], G) * G + cell_of(xy[2 * i], G)]++] = i;
    for (size_t c = G * G; c > 0; c--) start[c] = start[c - 1];
    start[0] = 0;
    static const int half[4][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}}; /* (dx, dy) */
    #pragma omp parallel for schedule(dynamic, 1)
    for (size_t cy = 0; cy < G; cy++) {
        double *acc = rows + cy * (size_t)bins;
        for (size_t cx = 0; cx < G; cx++) {
            const size_t c = cy * G + cx;
            for (size_t a = start[c]; a < start[c + 1]; a++)
                for (size_t b = a + 1; b < start[c + 1]; b++) pair(&k, xy, idx[a], idx[b], acc);
            for (int s = 0; s < 4; s++) {
                const size_t ox = (size_t)((long long)(cx + G) + half[s][0]) % G;
                const size_t oy = (cy + (size_t)half[s][1]) % G;
                const size_t o = oy * G + ox;
                for (size_t a = start[c]; a < start[c + 1]; a++)
                    for (size_t b = start[o]; b < start[o + 1]; b++) pair(&k, xy, idx[a], idx[b], acc);
            }
        }
    }
    for (size_t r = 1; r < G; r++)
        for (int b = 0; b < bins; b++) rows[b] += rows[r * (size_t)bins + b];
    normalise(&k, n, rows, g);
    free(start); free(idx); free(rows);
    return 0;
}

void an_pcf_brute(const double *xy, size_t n, double sigma, int bins, double *g)
{
    kernel k;
    setup(&k, n, sigma, bins);
    for (int b = 0; b < bins; b++) g[b] = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            if (i == j) continue;
            const double dx = wrap(xy[2 * i] - xy[2 * j]), dy = wrap(xy[2 * i + 1] - xy[2 * j + 1]);
            const double d = sqrt(dx * dx + dy * dy);
            if (d >= sqrt(k.cut2)) continue;
            for (int b = 1; b <= bins; b++) {
                const double t = b * k.h - d;
                if (fabs(t) <= k.cut) g[b - 1] += exp(-t * t / (2 * k.sig * k.sig));
            }
        }
    for (int b = 1; b <= bins; b++)
        g[b - 1] /= (double)n * (double)(n - 1) * 2 * M_PI * (b * k.h) * k.sig * sqrt(2 * M_PI);
}
