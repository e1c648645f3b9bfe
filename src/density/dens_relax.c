/* dens_relax.c - layer 2: the density start's gridless relaxation
 * (dens_relax.h). */
#include "dens_relax.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bigmem.h"
#include "geom.h"
#include "omp_compat.h"

/* r0 = RADIUS Delta(n); a pair nearer than r0 / sqrt(q_i q_j) is pushed
 * apart by ALPHA (r - d) / 2 on each side; a point's whole move is capped
 * at CAP r0 / q_i (the uniform start's constants, start_relax.c). */
#define RADIUS 1.0
#define ALPHA 0.5
#define CAP 0.5
#define STEPS 32

int cfpo_dens_relax_steps(int64_t n) { return n > 0 ? STEPS : 0; }

typedef struct {
    int64_t nb;          /* bins a side */
    uint32_t *off;       /* CSR offsets over nb^2 bins */
    uint32_t *id;        /* the points, bin by bin, each bin's by id */
    double *sx, *sy;     /* their places */
    double *sw;          /* q^(-1/2) there */
    const double *tq;    /* the smallest q over the 3 x 3 tiles around each of T x T */
    int64_t T;
    double r0;
} bins;

static inline int64_t axis_bin(double v, int64_t nb)
{
    int64_t b = (int64_t)(v * (double)nb);
    return b >= nb ? nb - 1 : (b < 0 ? 0 : b);
}

/* The pushes on (px, py) (q^(-1/2) = wi) from the points of bins
 * [c0, c1] of row ry (c0 <= c1 < nb), added in order to (*fx, *fy). */
static void push_run(const bins *B, int64_t ry, int64_t c0, int64_t c1, double px, double py, double wi, double *fx,
                     double *fy)
{
    const uint32_t a = B->off[ry * B->nb + c0], e = B->off[ry * B->nb + c1 + 1];
    const double *restrict sx = B->sx, *restrict sy = B->sy, *restrict sw = B->sw;
    const double rw = B->r0 * wi;
    double gx = *fx, gy = *fy;
    for (uint32_t t = a; t < e; t++) {
        double ex = px - sx[t], ey = py - sy[t];
        ex -= rint(ex);
        ey -= rint(ey);
        const double d2 = ex * ex + ey * ey, r = rw * sw[t];
        if (d2 < r * r && d2 > 0) {
            const double dd = sqrt(d2), w = 0.5 * (r - dd) / dd;
            gx += w * ex;
            gy += w * ey;
        }
    }
    *fx = gx;
    *fy = gy;
}

/* The new place of the point (px, py), q^(-1/2) = wi, from the bins its
 * reach's box touches: rows from the lowest, each row's bins from the
 * lowest column (the box's columns cut at the seam into two runs), each
 * bin's points by id. */
static void move_at(const bins *B, const cfpo_density *d, double px, double py, double wi, double *nx, double *ny)
{
    const int64_t nb = B->nb, T = B->T;
    const double lo = B->tq[axis_bin(py, T) * T + axis_bin(px, T)];
    const double R = B->r0 * wi / sqrt(lo);
    const int64_t x0 = (int64_t)floor((px - R) * (double)nb), x1 = (int64_t)floor((px + R) * (double)nb);
    const int64_t y0 = (int64_t)floor((py - R) * (double)nb), y1 = (int64_t)floor((py + R) * (double)nb);
    double fx = 0, fy = 0;
    for (int64_t yy = y0; yy <= y1; yy++) {
        const int64_t ry = yy < 0 ? yy + nb : (yy >= nb ? yy - nb : yy);
        if (x0 < 0) {
            push_run(B, ry, x0 + nb, nb - 1, px, py, wi, &fx, &fy);
            push_run(B, ry, 0, x1, px, py, wi, &fx, &fy);
        } else if (x1 >= nb) {
            push_run(B, ry, x0, nb - 1, px, py, wi, &fx, &fy);
            push_run(B, ry, 0, x1 - nb, px, py, wi, &fx, &fy);
        } else {
            push_run(B, ry, x0, x1, px, py, wi, &fx, &fy);
        }
    }
    const double len = ALPHA * sqrt(fx * fx + fy * fy), lim = CAP * B->r0 * wi * wi;
    const double s = len > lim ? ALPHA * lim / len : ALPHA;
    double u = px + s * fx, v = py + s * fy;
    u -= floor(u);
    v -= floor(v);
    if (!(u < 1.0)) u = 0.0;
    if (!(v < 1.0)) v = 0.0;
    if (cfpo_density_at(d, u, v) > 0) {
        *nx = u;
        *ny = v;
    } else { /* no point on zero density: this one stays */
        *nx = px;
        *ny = py;
    }
}

/* For each of the T x T tiles of the torus, the smallest positive q over
 * it and the eight tiles around it: every pixel that meets a tile counts
 * for it. */
static double *tile_qmin(const cfpo_density *d, int64_t T)
{
    double *m = malloc((size_t)(T * T) * sizeof *m);
    if (!m) return NULL;
    for (int64_t t = 0; t < T * T; t++) m[t] = INFINITY;
    for (int64_t j = 0; j < d->h; j++) {
        const int64_t ta = j * T / d->h, tb = ((j + 1) * T - 1) / d->h;
        for (int64_t i = 0; i < d->w; i++) {
            const double r = d->rho[j * d->w + i];
            if (!(r > 0)) continue;
            const double q = sqrt(r);
            const int64_t sa = i * T / d->w, sb = ((i + 1) * T - 1) / d->w;
            for (int64_t ty = ta; ty <= tb && ty < T; ty++)
                for (int64_t tx = sa; tx <= sb && tx < T; tx++)
                    if (q < m[ty * T + tx]) m[ty * T + tx] = q;
        }
    }
    double *m9 = malloc((size_t)(T * T) * sizeof *m9);
    if (!m9) { free(m); return NULL; }
    for (int64_t ty = 0; ty < T; ty++)
        for (int64_t tx = 0; tx < T; tx++) {
            double lo = INFINITY;
            for (int64_t a = -1; a <= 1; a++)
                for (int64_t b = -1; b <= 1; b++) {
                    const double v = m[((ty + a + T) % T) * T + (tx + b + T) % T];
                    if (v < lo) lo = v;
                }
            m9[ty * T + tx] = lo;
        }
    free(m);
    return m9;
}

int cfpo_dens_relax(const cfpo_density *d, int64_t n, double *xy, int steps, int threads, int part, int parts,
                    cfpo_dens_relax_share share, void *ctx)
{
    if (parts < 1 || part < 0 || part >= parts || (parts > 1 && !share)) return -1;
    if (steps <= 0 || n <= 0 || (uint64_t)n >= UINT32_MAX) return 0;
    bins B;
    B.r0 = RADIUS * cfpo_delta_bound((double)n);
    const double qmin = sqrt(d->rho_min);
    /* bins of the densest reach's side, at most 4 n of them */
    int64_t nb = (int64_t)floor(sqrt(d->rho_max) / B.r0);
    const int64_t cap = (int64_t)floor(sqrt(4.0 * (double)n));
    if (nb > cap) nb = cap;
    /* a pair reaches at most r0 / qmin: it must stay under half the
     * torus, and the 3 x 3 tiles of side at least that around a point
     * hold every point it can meet */
    const double rfar = B.r0 / qmin;
    if (nb < 3 || nb * nb >= INT32_MAX || !(2 * rfar + 2.0 / (double)nb < 1.0)) return 0;
    B.nb = nb;
    B.T = (int64_t)floor(1.0 / rfar);
    if (B.T < 3) B.T = 1; /* one tile: its smallest q is the density's */
    double *tq = tile_qmin(d, B.T);
    B.tq = tq;
    const size_t offb = (size_t)(nb * nb + 1) * sizeof *B.off, db = (size_t)n * sizeof(double),
                 ib = (size_t)n * sizeof(uint32_t);
    B.off = cfpo_map_bytes(offb);
    B.id = cfpo_map_bytes(ib);
    B.sx = cfpo_map_bytes(db);
    B.sy = cfpo_map_bytes(db);
    B.sw = cfpo_map_bytes(db);
    uint32_t *bin = cfpo_map_bytes(ib);
    double *mine = parts > 1 ? cfpo_map_bytes(2 * db) : NULL, *all = parts > 1 ? cfpo_map_bytes(2 * db) : NULL;
    int rc = tq && B.off && B.id && B.sx && B.sy && B.sw && bin && (parts == 1 || (mine && all)) ? 0 : -1;
    if (parts > 1 && share(ctx, rc == 0, NULL, 0, NULL) != 0) rc = -1; /* every part ready, or none goes on */
    const int nt = threads > 0 ? threads : 1;
    for (int k = 0; k < steps && rc == 0; k++) {
        memset(B.off, 0, offb);
        for (int64_t i = 0; i < n; i++) {
            bin[i] = (uint32_t)(axis_bin(xy[2 * i + 1], nb) * nb + axis_bin(xy[2 * i], nb));
            B.off[bin[i] + 1]++;
        }
        for (int64_t b = 0; b < nb * nb; b++) B.off[b + 1] += B.off[b];
        for (int64_t i = 0; i < n; i++) { /* by id within a bin; off[b] runs ahead */
            const uint32_t t = B.off[bin[i]]++;
            B.id[t] = (uint32_t)i;
        }
        for (int64_t b = nb * nb; b > 0; b--) B.off[b] = B.off[b - 1];
        B.off[0] = 0;
        /* this part's rows of bins and their points t in [t0, t1) */
        const int64_t row0 = nb * part / parts, row1 = nb * (part + 1) / parts;
        const uint32_t t0 = B.off[row0 * nb], t1 = B.off[row1 * nb];
#pragma omp parallel num_threads(nt)
        {
#pragma omp for schedule(static, 4096)
            for (int64_t t = 0; t < n; t++) {
                const uint32_t i = B.id[t];
                B.sx[t] = xy[2 * i];
                B.sy[t] = xy[2 * i + 1];
                B.sw[t] = 1.0 / sqrt(sqrt(cfpo_density_at(d, B.sx[t], B.sy[t])));
            }
            /* every point from the step's old places (the bins' copy),
             * row by row of bins; one part: straight into xy, else into
             * the part's slice of `mine`, in bin order */
#pragma omp for schedule(static, 2)
            for (int64_t row = row0; row < row1; row++)
                for (uint32_t t = B.off[row * nb]; t < B.off[(row + 1) * nb]; t++) {
                    const uint32_t i = B.id[t];
                    double *o = parts > 1 ? mine + 2 * (size_t)(t - t0) : xy + 2 * (size_t)i;
                    move_at(&B, d, B.sx[t], B.sy[t], B.sw[t], &o[0], &o[1]);
                }
        }
        if (parts > 1) { /* every part's places, in bin order: back by id */
            if (share(ctx, 1, mine, (size_t)(t1 - t0) * 2 * sizeof *mine, all) != 0) {
                rc = -1;
                break;
            }
            for (int64_t t = 0; t < n; t++) {
                xy[2 * (size_t)B.id[t]] = all[2 * t];
                xy[2 * (size_t)B.id[t] + 1] = all[2 * t + 1];
            }
        }
    }
    cfpo_unmap_bytes(B.off, offb); cfpo_unmap_bytes(B.id, ib); cfpo_unmap_bytes(B.sx, db);
    cfpo_unmap_bytes(B.sy, db); cfpo_unmap_bytes(B.sw, db); cfpo_unmap_bytes(bin, ib);
    cfpo_unmap_bytes(mine, 2 * db); cfpo_unmap_bytes(all, 2 * db);
    free(tq);
    return rc;
}
