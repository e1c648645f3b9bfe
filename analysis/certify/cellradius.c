/* cellradius.c - see cellradius.h. */
#include "cellradius.h"

#include <math.h>

#include "farthest.h"
#include "geom.h"
#include "ptree.h"

typedef an_cert_ctx ctx;
typedef an_cert_work work;

double an_cell_bound(const ctx *C, size_t c, size_t skip)
{
    const size_t g = C->G.g;
    const double L = C->G.L, cx = ((double)(c % g) + 0.5) * L, cy = ((double)(c / g) + 0.5) * L;
    return (sqrt(an_ptree_nearest(C->tree, cx, cy, skip)) + 0.5 * L * sqrt(2.0)) * (1 + 1e-9) + 1e-15;
}

/* For p in the cell, d(p, X) <= d(centre, X) + |p - centre| <= ub, so
 * p's nearest point lies within ub + the cell's half-diagonal of the
 * centre: only those points are needed. */
int an_cell_radius(const ctx *C, size_t c, double ub, size_t skip, work *w, double *out, double *arg)
{
    const size_t g = C->G.g;
    const double L = C->G.L, x0 = (double)(c % g) * L, y0 = (double)(c / g) * L;
    const cfpo_square S = {x0, y0, x0 + L, y0 + L};
    const double cx = x0 + 0.5 * L, cy = y0 + 0.5 * L;
    const double R = (ub + 0.5 * L * sqrt(2.0)) * (1 + 1e-9) + 1e-15;
    if (an_cert_collect(C, cx, cy, R, w) != 0) return -1;
    size_t m = 0;
    for (size_t t = 0; t < w->m; t++) {
        const double dx = w->x[t] - cx, dy = w->y[t] - cy;
        if (w->id[t] == skip || dx * dx + dy * dy > R * R) continue;
        w->x[m] = w->x[t];
        w->y[m] = w->y[t];
        m++;
    }
    double px, py;
    const double r2 = an_farthest(w->x, w->y, m, S, cx, cy, &px, &py, &w->far);
    if (r2 < 0 || m == 0) return -2;
    *out = sqrt(r2);
    arg[0] = cfpo_wrap01(px);
    arg[1] = cfpo_wrap01(py);
    return 0;
}

int an_cell_key_desc(const void *a, const void *b)
{
    const an_cell_key *p = a, *q = b;
    if (p->r != q->r) return p->r > q->r ? -1 : 1;
    return p->c < q->c ? -1 : (p->c > q->c);
}
