/* prog_herd.c - see prog_herd.h. */
#include "prog_herd.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "prog_order.h"

double cfpo_prog_herd_radius(int64_t m1, double freq) { return freq * sqrt((double)m1); }

void cfpo_prog_herd_table(double R, cfpo_prog_herd_tab *T)
{
    T->kc = R < CFPO_PROG_HERD_KMAX ? (int)floor(R) : CFPO_PROG_HERD_KMAX;
    for (int i = 0; i <= T->kc; i++) {
        T->bmax[i] = -1;
        for (int j = 0; j <= T->kc; j++) {
            const double k2 = (double)(i * i + j * j);
            double w = 0;
            if (k2 > 0 && k2 <= R * R) {
                w = (i > 0 ? 2 : 1) * (j > 0 ? 2 : 1) / (k2 * sqrt(k2));
                T->bmax[i] = j;
            }
            T->w[i * (CFPO_PROG_HERD_KMAX + 1) + j] = w;
        }
    }
}

/* K(d) = sum over 0 < a^2 + b^2 <= R^2 of (a^2 + b^2)^-1.5 cos(2 pi (a dx + b dy)), summed
 * over a, b >= 0 as 2 cos(2 pi a dx) cos(2 pi b dy) per pair (a, -b), (a, b) */
double cfpo_prog_herd_kernel(const double *a, const double *b, const cfpo_prog_herd_tab *T)
{
    const int kc = T->kc;
    double cx[CFPO_PROG_HERD_KMAX + 1], cy[CFPO_PROG_HERD_KMAX + 1];
    const double ux = cos(2 * M_PI * (a[0] - b[0])), uy = cos(2 * M_PI * (a[1] - b[1]));
    cx[0] = cy[0] = 1;
    if (kc >= 1) cx[1] = ux, cy[1] = uy;
    for (int k = 2; k <= kc; k++) { /* Chebyshev: cos(k t) = 2 cos t cos((k - 1) t) - cos((k - 2) t) */
        cx[k] = 2 * ux * cx[k - 1] - cx[k - 2];
        cy[k] = 2 * uy * cy[k - 1] - cy[k - 2];
    }
    double s = 0;
    for (int i = 0; i <= kc; i++) {
        const double *w = T->w + i * (CFPO_PROG_HERD_KMAX + 1);
        double r = 0;
        for (int j = 0; j <= T->bmax[i]; j++) r += w[j] * cy[j];
        s += cx[i] * r;
    }
    return s;
}

static double torus_d2(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    if (dx > 0.5) dx = 1 - dx;
    if (dy > 0.5) dy = 1 - dy;
    return dx * dx + dy * dy;
}

static int64_t axis_cell(double v, int64_t G)
{
    const int64_t c = (int64_t)(v * (double)G);
    return c < 0 ? 0 : c >= G ? G - 1 : c;
}

int cfpo_prog_order_herded(double *xy, int64_t m0, int64_t m1, double per_cell, int tol, double dfloor, double freq,
                           char *err, size_t errlen)
{
    if (!(per_cell > 0) || tol < 1 || !(dfloor >= 0) || !(freq > 0)) {
        snprintf(err, errlen, "the herded order needs per_cell > 0, tol >= 1, dfloor >= 0 and freq > 0");
        return -1;
    }
    const int64_t q = m1 - m0;
    if (q <= 1) return 0;
    const int depth = cfpo_prog_order_depth(m1, per_cell);
    const int64_t G = (int64_t)1 << depth, nodes = ((((int64_t)1 << (2 * (depth + 1))) - 1) / 3);
    cfpo_prog_herd_tab *K = malloc(sizeof *K);
    double *d = malloc((size_t)q * sizeof *d), *phi = malloc((size_t)q * sizeof *phi);
    double *out = malloc(2 * (size_t)q * sizeof *out);
    int64_t *cell = malloc((size_t)q * (size_t)(depth + 1) * sizeof *cell);
    int64_t *count = calloc((size_t)nodes, sizeof *count), *took = calloc((size_t)nodes, sizeof *took);
    unsigned char *taken = calloc((size_t)q, 1);
    int rc = -1;
    if (!K || !d || !phi || !out || !cell || !count || !took || !taken) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    cfpo_prog_herd_table(cfpo_prog_herd_radius(m1, freq), K);
    for (int64_t j = 0; j < q; j++) {
        const double *p = xy + 2 * (m0 + j);
        const int64_t cx = axis_cell(p[0], G), cy = axis_cell(p[1], G);
        for (int l = 1; l <= depth; l++) { /* the node of level l holding p: (4^l - 1) / 3 + its (y, x) row-major */
            const int s = depth - l;
            const int64_t c = ((((int64_t)1 << (2 * l)) - 1) / 3) + (cy >> s) * ((int64_t)1 << l) + (cx >> s);
            cell[j * (depth + 1) + l] = c;
            count[c]++;
        }
        d[j] = INFINITY;
        phi[j] = 0;
        for (int64_t i = 0; i < m0; i++) { /* the earlier levels, in their order */
            const double e = torus_d2(p, xy + 2 * i);
            if (e < d[j]) d[j] = e;
            phi[j] += cfpo_prog_herd_kernel(p, xy + 2 * i, K);
        }
    }
    for (int64_t t = 0; t < q; t++) {
        double far = -1;
        for (int64_t j = 0; j < q; j++) { /* the free points' largest distance; taken[j] 2: free this step */
            if (taken[j] == 1) continue;
            int ok = 1;
            for (int l = 1; l <= depth && ok; l++) {
                const int64_t c = cell[j * (depth + 1) + l];
                ok = took[c] < (t + 1) * count[c] / q + tol;
            }
            taken[j] = ok ? 2 : 0;
            if (ok && d[j] > far) far = d[j];
        }
        int64_t p = -1;
        /* (dfloor Delta(m))^2 for the prefix m this pick makes, or the farthest free point's */
        double cut = dfloor * dfloor * 2 / (sqrt(3.0) * (double)(m0 + t + 1));
        if (cut > far) cut = far;
        for (int64_t j = 0; j < q; j++) {
            if (taken[j] != 2) continue;
            taken[j] = 0;
            if (!(d[j] >= cut)) continue;
            if (p < 0 || phi[j] < phi[p] || (phi[j] == phi[p] && d[j] > d[p])) p = j;
        }
        if (p < 0) { /* never: the allowances always leave a free point (prog_order.h) */
            snprintf(err, errlen, "the herded order found no free point at step %lld of %lld", (long long)t, (long long)q);
            goto done;
        }
        taken[p] = 1;
        for (int l = 1; l <= depth; l++) took[cell[p * (depth + 1) + l]]++;
        const double *pp = xy + 2 * (m0 + p);
        out[2 * t] = pp[0];
        out[2 * t + 1] = pp[1];
        for (int64_t j = 0; j < q; j++) {
            if (taken[j]) continue;
            const double *pj = xy + 2 * (m0 + j);
            const double e = torus_d2(pj, pp);
            if (e < d[j]) d[j] = e;
            phi[j] += cfpo_prog_herd_kernel(pj, pp, K);
        }
    }
    for (int64_t t = 0; t < 2 * q; t++) xy[2 * m0 + t] = out[t];
    rc = 0;
done:
    free(K);
    free(d);
    free(phi);
    free(out);
    free(cell);
    free(count);
    free(took);
    free(taken);
    return rc;
}
