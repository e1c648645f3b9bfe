/* capacity.c - see capacity.h. */
#include "capacity.h"

#include "density_walk.h"

#include <math.h>
#include <stdlib.h>

typedef struct {
    const cfpo_density *d;
    double *pre; /* row j: pre[j (w + 1) + i] = sum_{i' < i} rho(i', j) / w */
} table;

static int table_build(table *t, const cfpo_density *d)
{
    const int64_t w = d->w, h = d->h;
    t->d = d;
    t->pre = malloc((size_t)((w + 1) * h) * sizeof *t->pre);
    if (!t->pre) return -1;
    for (int64_t j = 0; j < h; j++) {
        double *p = t->pre + j * (w + 1), s = 0;
        p[0] = 0;
        for (int64_t i = 0; i < w; i++) p[i + 1] = (s += d->rho[j * w + i] / (double)w);
    }
    return 0;
}

/* F(x, y) = int_0^x rho(t, y) dt, continued past [0, 1) by the row sums. */
static double F(const table *t, double x, double y)
{
    const int64_t w = t->d->w, h = t->d->h;
    const int64_t i = (int64_t)floor(x * (double)w), j = (int64_t)floor(y * (double)h);
    const int64_t jj = j - cfpo_floor_div(j, h) * h, qi = cfpo_floor_div(i, w), ii = i - qi * w;
    const double *p = t->pre + jj * (w + 1);
    return (double)qi * p[w] + p[ii] + t->d->rho[jj * w + ii] * (x - (double)i / (double)w);
}

typedef struct {
    const table *t;
    double x0, y0, dx, dy, sum;
} edge_ctx;

static void edge_piece(void *vc, double t0, double t1, int64_t i, int64_t j)
{
    (void)i;
    (void)j;
    edge_ctx *c = vc;
    const double tm = 0.5 * (t0 + t1);
    c->sum += F(c->t, c->x0 + tm * c->dx, c->y0 + tm * c->dy) * (t1 - t0);
}

/* int F dy along the segment (x0, y0) -> (x1, y1), cut at every pixel edge. */
static double edge(const table *t, double x0, double y0, double x1, double y1)
{
    const double dx = x1 - x0, dy = y1 - y0;
    if (dy == 0) return 0;
    edge_ctx c = {t, x0, y0, dx, dy, 0};
    cfpo_density_walk(t->d, x0, y0, dx, dy, edge_piece, &c);
    return c.sum * dy;
}

static double polygon(const table *t, const double *v, size_t m)
{
    double s = 0;
    for (size_t a = 0; a < m; a++) {
        const size_t b = a + 1 == m ? 0 : a + 1;
        s += edge(t, v[2 * a], v[2 * a + 1], v[2 * b], v[2 * b + 1]);
    }
    return s;
}

double an_capacity_polygon(const cfpo_density *d, const double *v, size_t m)
{
    table t;
    if (table_build(&t, d) != 0) return NAN;
    const double s = polygon(&t, v, m);
    free(t.pre);
    return s;
}

int an_capacity_compute(const cfpo_density *d, const an_vcells *c, double *cap)
{
    table t;
    if (table_build(&t, d) != 0) return -1;
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t i = 0; i < c->n; i++)
        cap[i] = polygon(&t, c->v + 2 * c->start[i], c->start[i + 1] - c->start[i]);
    free(t.pre);
    return 0;
}

double an_capacity_deviation(const double *cap, size_t n)
{
    double s = 0, s2 = 0;
    for (size_t i = 0; i < n; i++) s += cap[i], s2 += cap[i] * cap[i];
    const double v = (double)n * s2 / (s * s) - 1;
    return sqrt(v > 0 ? v : 0);
}

void an_vcells_free(an_vcells *c)
{
    free(c->start);
    free(c->v);
    c->start = NULL;
    c->v = NULL;
    c->n = 0;
}
