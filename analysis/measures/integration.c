/* integration.c - see integration.h.
 *
 * The estimates: points in blocks of AN_BLOCK; each thread owns a fixed
 * range of integrands and adds, block after block, the block's double sum
 * into a long double per integrand: every integrand's sum runs in the same
 * order whatever the number of threads, so the result is the same bytes. */
#include "integration.h"

#include <math.h>
#include <stdlib.h>

#include "omp_compat.h"
#include "quadrature.h"
#include "rng.h"

#define AN_BLOCK 2048
#define GL_N 16
#define GL_PANELS 64

void an_integ_draw(int gauss, uint64_t seed, int m, an_integ_fn *f)
{
    const uint64_t stream = gauss ? 0x6761757373ull : 0x6865617679ull, base = 8 * (uint64_t)m;
    double u[5];
    for (int k = 0; k < 5; k++) u[k] = cfpo_rand01(seed, stream, base + (uint64_t)k);
    f->gauss = gauss;
    f->mx = f->my = f->a = f->b = f->c = f->nx = f->ny = f->r = 0;
    if (gauss) {
        f->mx = u[0];
        f->my = u[1];
        const double th = 2 * M_PI * u[2], s1 = 0.01 + 0.99 * u[3], s2 = 0.01 + 0.99 * u[4];
        const double co = cos(th), si = sin(th);
        f->a = co * co / s1 + si * si / s2;
        f->b = co * si * (1 / s1 - 1 / s2);
        f->c = si * si / s1 + co * co / s2;
    } else {
        const double th = 2 * M_PI * u[0];
        f->nx = cos(th);
        f->ny = sin(th);
        f->r = -(f->nx * u[1] + f->ny * u[2]);
    }
}

double an_integ_value(const an_integ_fn *f, double x, double y)
{
    if (!f->gauss) return f->nx * x + f->ny * y + f->r > 0 ? 1 : 0;
    const double dx = x - f->mx, dy = y - f->my;
    return exp(-0.5 * (f->a * dx * dx + 2 * f->b * dx * dy + f->c * dy * dy));
}

/* Phi(u) - Phi(l), l <= u, without cancellation in the tails. */
static double phi_diff(double l, double u)
{
    const double s = M_SQRT1_2;
    if (l > 0) return 0.5 * (erfc(l * s) - erfc(u * s));
    if (u < 0) return 0.5 * (erfc(-u * s) - erfc(-l * s));
    return 0.5 * (erf(u * s) - erf(l * s));
}

static double gauss_integral(double mx, double my, double a, double b, double c)
{
    double gx[GL_N], gw[GL_N];
    cfpo_gauss_legendre(GL_N, gx, gw);
    const double sc = sqrt(c), kx = a - b * b / c, norm = sqrt(2 * M_PI / c);
    double sum = 0;
    for (int p = 0; p < GL_PANELS; p++) {
        const double lo = (double)p / GL_PANELS, half = 0.5 / GL_PANELS;
        double ps = 0;
        for (int i = 0; i < GL_N; i++) {
            const double x = lo + half * (1 + gx[i]), dx = x - mx, sh = b * dx / c;
            ps += gw[i] * exp(-0.5 * kx * dx * dx) * phi_diff(sc * (-my + sh), sc * (1 - my + sh));
        }
        sum += ps * half;
    }
    return norm * sum;
}

/* The area of {x in [0, 1]^2 : nx x + ny y + r > 0}: the square clipped by
 * the half-plane (one Sutherland-Hodgman step), then the shoelace. */
static double half_plane_area(double nx, double ny, double r)
{
    static const double sq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double poly[8][2];
    int m = 0;
    for (int i = 0; i < 4; i++) {
        const double *p = sq[i], *q = sq[(i + 1) % 4];
        const double sp = nx * p[0] + ny * p[1] + r, sq_ = nx * q[0] + ny * q[1] + r;
        if (sp > 0) { poly[m][0] = p[0]; poly[m][1] = p[1]; m++; }
        if ((sp > 0) != (sq_ > 0)) {
            const double t = sp / (sp - sq_);
            poly[m][0] = p[0] + t * (q[0] - p[0]);
            poly[m][1] = p[1] + t * (q[1] - p[1]);
            m++;
        }
    }
    double A = 0;
    for (int i = 0; i < m; i++) A += poly[i][0] * poly[(i + 1) % m][1] - poly[(i + 1) % m][0] * poly[i][1];
    return 0.5 * fabs(A);
}

double an_integ_truth(const an_integ_fn *f)
{
    return f->gauss ? gauss_integral(f->mx, f->my, f->a, f->b, f->c) : half_plane_area(f->nx, f->ny, f->r);
}

double an_integ_truth_sq(const an_integ_fn *f)
{
    /* f^2 is the Gaussian with Sigma / 2; an indicator is its own square */
    return f->gauss ? gauss_integral(f->mx, f->my, 2 * f->a, 2 * f->b, 2 * f->c) : an_integ_truth(f);
}

int an_integration_compute(const double *xy, size_t n, int M, uint64_t seed, an_integration *out)
{
    const int F = 2 * M; /* 0..M-1 Gaussian, M..2M-1 Heaviside */
    an_integ_fn *fn = malloc((size_t)F * sizeof *fn);
    long double *acc = calloc((size_t)F, sizeof *acc);
    double *truth = malloc((size_t)F * sizeof *truth);
    if (!fn || !acc || !truth) {
        free(fn); free(acc); free(truth);
        return -1;
    }
    #pragma omp parallel for schedule(static)
    for (int m = 0; m < F; m++) {
        an_integ_draw(m < M, seed, m % M, &fn[m]);
        truth[m] = an_integ_truth(&fn[m]);
    }
    #pragma omp parallel
    {
        const int T = omp_get_num_threads(), t = omp_get_thread_num();
        const int lo = (int)((long long)F * t / T), hi = (int)((long long)F * (t + 1) / T);
        for (size_t b0 = 0; b0 < n; b0 += AN_BLOCK) {
            const size_t b1 = b0 + AN_BLOCK < n ? b0 + AN_BLOCK : n;
            for (int m = lo; m < hi; m++) {
                const an_integ_fn *f = &fn[m];
                double s = 0;
                if (f->gauss) {
                    for (size_t j = b0; j < b1; j++) {
                        const double dx = xy[2 * j] - f->mx, dy = xy[2 * j + 1] - f->my;
                        s += exp(-0.5 * (f->a * dx * dx + 2 * f->b * dx * dy + f->c * dy * dy));
                    }
                } else {
                    size_t cnt = 0;
                    for (size_t j = b0; j < b1; j++) cnt += f->nx * xy[2 * j] + f->ny * xy[2 * j + 1] + f->r > 0;
                    s = (double)cnt;
                }
                acc[m] += s;
            }
        }
    }
    double mse[2] = {0, 0}, m2[2] = {0, 0};
    for (int m = 0; m < F; m++) {
        const double e = (double)(acc[m] / (long double)n) - truth[m], e2 = e * e;
        mse[m >= M] += e2;
        m2[m >= M] += e2 * e2;
    }
    out->M = M;
    for (int k = 0; k < 2; k++) {
        const double mean = mse[k] / M, var = m2[k] / M - mean * mean;
        const double se = M > 1 ? sqrt((var > 0 ? var : 0) / (M - 1)) : NAN;
        if (k == 0) { out->gauss_mse = mean; out->gauss_se = se; }
        else { out->heaviside_mse = mean; out->heaviside_se = se; }
    }
    free(fn); free(acc); free(truth);
    return 0;
}
