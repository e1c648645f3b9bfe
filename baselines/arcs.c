/* arcs.c - see arcs.h. */
#include "arcs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom.h"

static const double TWO_PI = 6.283185307179586476925286766559;

void arcs_full(arcs *A)
{
    A->m = 1;
    A->lo[0] = 0.0;
    A->hi[0] = TWO_PI;
}

static void push(double *lo, double *hi, int *m, double l, double h)
{
    if (*m == ARCS_CAP) { /* impossible by the packing bound in arcs.h */
        fprintf(stderr, "arcs: more than %d arcs on one circle\n", ARCS_CAP);
        abort();
    }
    lo[*m] = l;
    hi[*m] = h;
    (*m)++;
}

/* Removes [a, b] with 0 <= a <= b <= 2 pi. */
static void remove_plain(arcs *A, double a, double b)
{
    double lo[ARCS_CAP], hi[ARCS_CAP];
    int m = 0;
    for (int i = 0; i < A->m; i++) {
        const double l = A->lo[i], h = A->hi[i];
        if (b <= l || a >= h) { /* no overlap */
            push(lo, hi, &m, l, h);
            continue;
        }
        if (l < a && a - l >= ARCS_EPS) push(lo, hi, &m, l, a);
        if (h > b && h - b >= ARCS_EPS) push(lo, hi, &m, b, h);
    }
    for (int i = 0; i < m; i++) A->lo[i] = lo[i], A->hi[i] = hi[i];
    A->m = m;
}

void arcs_remove(arcs *A, double a, double b)
{
    const double shift = floor(a / TWO_PI) * TWO_PI;
    a -= shift;
    b -= shift;
    if (b <= TWO_PI) {
        remove_plain(A, a, b);
    } else {
        remove_plain(A, a, TWO_PI);
        remove_plain(A, 0.0, b - TWO_PI);
    }
}

void arcs_cover(arcs *A, double sx, double sy, double qx, double qy, double rho)
{
    const double dx = cfpo_torus_diff(qx, sx), dy = cfpo_torus_diff(qy, sy);
    const double d = sqrt(dx * dx + dy * dy);
    if (!(d < 2.0 * rho)) return;
    const double alpha = acos(d / (2.0 * rho)), beta = atan2(dy, dx);
    arcs_remove(A, beta - alpha, beta + alpha);
}

double arcs_total(const arcs *A)
{
    double t = 0;
    for (int i = 0; i < A->m; i++) t += A->hi[i] - A->lo[i];
    return t;
}

double arcs_pick(const arcs *A, double u)
{
    double t = u * arcs_total(A);
    for (int i = 0; i < A->m; i++) {
        const double len = A->hi[i] - A->lo[i];
        if (t < len || i == A->m - 1) {
            double a = A->lo[i] + t;
            return a > A->hi[i] ? A->hi[i] : a;
        }
        t -= len;
    }
    return 0.0; /* empty: the caller never asks */
}
