/* q6.c - see q6.h. Y_6m from the associated Legendre functions by their
 * three-term recurrence and e^{i m phi} as ((x + i y)/rho)^m, for m = 0..6;
 * the negative orders enter through q_{6,-m} = (-1)^m conj(q_6m), so sums
 * over m = -6..6 are the m = 0 term plus twice the m > 0 terms. */
#include "q6.h"

#include <math.h>
#include <stdlib.h>

#include "nn3.h"

#define L6 6

/* Re and Im of Y_6m(r) for m = 0..6 (r need not be a unit vector). */
static void ylm6(const double r[3], double re[L6 + 1], double im[L6 + 1])
{
    const double len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double x = r[2] / len; /* cos theta */
    const double rho = sqrt(r[0] * r[0] + r[1] * r[1]);
    const double cphi = rho > 0.0 ? r[0] / rho : 1.0, sphi = rho > 0.0 ? r[1] / rho : 0.0;
    const double sth = sqrt(fmax(0.0, 1.0 - x * x));
    double cr = 1.0, ci = 0.0; /* e^{i m phi} */
    for (int m = 0; m <= L6; m++) {
        /* P_m^m, P_{m+1}^m, ..., P_6^m */
        double pmm = 1.0;
        for (int k = 1; k <= m; k++) pmm *= -(2.0 * k - 1.0) * sth;
        double plm = pmm;
        if (m < L6) {
            double p1 = x * (2.0 * m + 1.0) * pmm, p0 = pmm;
            for (int l = m + 2; l <= L6; l++) {
                const double p2 = (x * (2.0 * l - 1.0) * p1 - (l + m - 1.0) * p0) / (double)(l - m);
                p0 = p1;
                p1 = p2;
            }
            plm = p1;
        }
        double fr = 1.0; /* (l-m)!/(l+m)! */
        for (int k = L6 - m + 1; k <= L6 + m; k++) fr /= (double)k;
        const double norm = sqrt((2.0 * L6 + 1.0) / (4.0 * M_PI) * fr);
        re[m] = norm * plm * cr;
        im[m] = norm * plm * ci;
        const double nr = cr * cphi - ci * sphi, ni = cr * sphi + ci * cphi;
        cr = nr;
        ci = ni;
    }
}

static double sumsq(const double *re, const double *im)
{
    double s = re[0] * re[0] + im[0] * im[0];
    for (int m = 1; m <= L6; m++) s += 2.0 * (re[m] * re[m] + im[m] * im[m]);
    return s;
}

int cfpo3_q6(const double *p, size_t n, int k, double bond, int bonds, cfpo3_q6_result *r)
{
    int64_t *idx = malloc(sizeof(int64_t) * (size_t)k * n);
    double *q = malloc(sizeof(double) * 2 * (L6 + 1) * n);
    if (!idx || !q || cfpo3_knn(p, n, k, idx, NULL) != 0) {
        free(idx);
        free(q);
        return -1;
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        double *qr = q + 2 * (L6 + 1) * i, *qi = qr + L6 + 1;
        for (int m = 0; m <= L6; m++) qr[m] = qi[m] = 0.0;
        for (int a = 0; a < k; a++) {
            const int64_t j = idx[(size_t)k * i + (size_t)a];
            const double d[3] = {cfpo3_pdiff(p[3 * j], p[3 * i]), cfpo3_pdiff(p[3 * j + 1], p[3 * i + 1]),
                                 cfpo3_pdiff(p[3 * j + 2], p[3 * i + 2])};
            double yr[L6 + 1], yi[L6 + 1];
            ylm6(d, yr, yi);
            for (int m = 0; m <= L6; m++) {
                qr[m] += yr[m] / k;
                qi[m] += yi[m] / k;
            }
        }
    }
    double gr[L6 + 1] = {0}, gi[L6 + 1] = {0}, loc = 0.0;
    int64_t crystal = 0;
    for (size_t i = 0; i < n; i++) { /* in id order: the same sums for any thread count */
        const double *qr = q + 2 * (L6 + 1) * i, *qi = qr + L6 + 1;
        for (int m = 0; m <= L6; m++) {
            gr[m] += qr[m] / (double)n;
            gi[m] += qi[m] / (double)n;
        }
        const double si = sumsq(qr, qi);
        loc += sqrt(4.0 * M_PI / 13.0 * si);
        int nb = 0;
        for (int a = 0; a < k; a++) {
            const int64_t j = idx[(size_t)k * i + (size_t)a];
            const double *pr = q + 2 * (L6 + 1) * (size_t)j, *pi = pr + L6 + 1;
            double dot = qr[0] * pr[0] + qi[0] * pi[0];
            for (int m = 1; m <= L6; m++) dot += 2.0 * (qr[m] * pr[m] + qi[m] * pi[m]);
            const double den = sqrt(si * sumsq(pr, pi));
            if (den > 0.0 && dot / den > bond) nb++;
        }
        crystal += nb >= bonds;
    }
    r->q6_global = sqrt(4.0 * M_PI / 13.0 * sumsq(gr, gi));
    r->q6_local = loc / (double)n;
    r->crystal = crystal;
    r->crystal_frac = (double)crystal / (double)n;
    free(idx);
    free(q);
    return 0;
}
