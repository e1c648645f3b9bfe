/* solve3.c - see solve3.h. The solve clips each cell lazily (the
 * farthest vertex's cutting bisectors only, nearest site first). The
 * clipping: Sutherland-Hodgman on every face
 * loop, a cut edge's new vertex made once (an edge map keyed by its two
 * old vertices, computed from the inside end), and the cap face on the
 * plane ordered by pseudo-angle in the projection that drops the normal's
 * largest axis (a linear map of the plane, so it keeps the cyclic order).
 * Vertices with n.c - off <= 0 are inside: a vertex exactly on the plane
 * stays and joins the cap (the degenerate vertices of crystalline
 * neighbourhoods). */
#include "solve3.h"

void cfpo3_poly_box(cfpo3_poly *p, const double lo[3], const double hi[3])
{
    for (int i = 0; i < 8; i++) {
        p->v[0][i] = (i & 1) ? hi[0] : lo[0];
        p->v[1][i] = (i & 2) ? hi[1] : lo[1];
        p->v[2][i] = (i & 4) ? hi[2] : lo[2];
        p->w[i] = -1.0;
    }
    p->nv = 8;
    /* faces x = lo, x = hi, y = lo, y = hi, z = lo, z = hi, as loops */
    static const int loops[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    p->nf = 6;
    for (int f = 0; f < 6; f++) {
        p->fs[f] = 4 * f;
        for (int k = 0; k < 4; k++) p->fi[4 * f + k] = loops[f][k];
    }
    p->fs[6] = 24;
}

double cfpo3_poly_far(const cfpo3_poly *p, const double y[3], int *at)
{
    double far = -1.0;
    int w = -1;
    for (int i = 0; i < p->nv; i++) {
        const double dx = p->v[0][i] - y[0], dy = p->v[1][i] - y[1], dz = p->v[2][i] - y[2];
        const double d = dx * dx + dy * dy + dz * dz;
        if (d > far) {
            far = d;
            w = i;
        }
    }
    if (at) *at = w;
    return far;
}

static double pseudo_angle(double dx, double dy)
{
    const double s = fabs(dx) + fabs(dy);
    if (s == 0.0) return 0.0;
    const double p = dy / s;
    if (dx < 0.0) return 2.0 - p;
    return dy < 0.0 ? 4.0 + p : p;
}

int cfpo3_poly_clip(const cfpo3_poly *p, cfpo3_poly *q, const double n[3], double off)
{
    double d[P3_MAXV];
    int out = 0;
    for (int i = 0; i < p->nv; i++) /* apart from the count, so that it vectorises */
        d[i] = n[0] * p->v[0][i] + n[1] * p->v[1][i] + n[2] * p->v[2][i] - off;
    for (int i = 0; i < p->nv; i++) out += d[i] > 0.0;
    if (out == 0) return 0;
    if (out == p->nv) return -1;
    /* inside vertices keep their coordinates under new indices */
    int map[P3_MAXV];
    int nv = 0;
    for (int i = 0; i < p->nv; i++) {
        if (d[i] <= 0.0) {
            map[i] = nv;
            q->v[0][nv] = p->v[0][i];
            q->v[1][nv] = p->v[1][i];
            q->v[2][nv] = p->v[2][i];
            q->w[nv] = p->w[i];
            nv++;
        } else {
            map[i] = -1;
        }
    }
    /* cut edges: (inside end, outside end) -> new vertex */
    int ea[P3_MAXV], eb[P3_MAXV], ev[P3_MAXV];
    int ne = 0;
    int nf = 0, ni = 0;
    for (int f = 0; f < p->nf; f++) {
        const int s0 = p->fs[f], len = p->fs[f + 1] - s0;
        const int start = ni;
        int nout = 0;
        if (ni + len <= P3_MAXI) { /* the face copied as it counts (kept if no vertex is cut) */
            for (int k = 0; k < len; k++) {
                const int v = map[p->fi[s0 + k]];
                q->fi[ni + k] = v;
                nout += v < 0;
            }
        } else {
            for (int k = 0; k < len; k++) nout += map[p->fi[s0 + k]] < 0;
        }
        if (nout == len) continue; /* the whole face is cut away */
        if (ni + 2 * len > P3_MAXI) return -2;
        if (nout == 0) { /* the whole face stays */
            ni += len;
            q->fs[nf++] = start;
            if (nf >= P3_MAXF) return -2;
            continue;
        }
        for (int k = 0; k < len; k++) {
            const int a = p->fi[s0 + k], b = p->fi[k + 1 == len ? s0 : s0 + k + 1];
            const int ina = map[a] >= 0, inb = map[b] >= 0;
            if (ina && (ni == start || q->fi[ni - 1] != map[a])) q->fi[ni++] = map[a];
            if (ina != inb) {
                const int vi = ina ? a : b, vo = ina ? b : a;
                int nvx = -1;
                if (d[vi] == 0.0) {
                    nvx = map[vi];
                } else {
                    for (int e = 0; e < ne; e++)
                        if (ea[e] == vi && eb[e] == vo) {
                            nvx = ev[e];
                            break;
                        }
                    if (nvx < 0) {
                        if (nv >= P3_MAXV || ne >= P3_MAXV) return -2;
                        const double t = d[vi] / (d[vi] - d[vo]);
                        for (int c = 0; c < 3; c++)
                            q->v[c][nv] = p->v[c][vi] + (p->v[c][vo] - p->v[c][vi]) * t;
                        q->w[nv] = -1.0;
                        ea[ne] = vi;
                        eb[ne] = vo;
                        ev[ne] = nv;
                        ne++;
                        nvx = nv++;
                    }
                }
                if (ni == start || q->fi[ni - 1] != nvx) q->fi[ni++] = nvx;
            }
        }
        while (ni - start > 1 && q->fi[ni - 1] == q->fi[start]) ni--;
        if (ni > start) {
            if (nf >= P3_MAXF) return -2;
            q->fs[nf++] = start;
        }
    }
    /* the cap: new vertices and inside vertices on the plane */
    int cap[P3_MAXV], nc = 0;
    for (int i = 0; i < p->nv; i++)
        if (d[i] == 0.0) cap[nc++] = map[i];
    for (int e = 0; e < ne; e++) cap[nc++] = ev[e];
    if (nc >= 3) {
        if (nf >= P3_MAXF || ni + nc > P3_MAXI) return -2;
        int ax = 0;
        if (fabs(n[1]) > fabs(n[ax])) ax = 1;
        if (fabs(n[2]) > fabs(n[ax])) ax = 2;
        const int u = ax == 0 ? 1 : 0, w = ax == 2 ? 1 : 2;
        double cu = 0.0, cw = 0.0;
        for (int k = 0; k < nc; k++) {
            cu += q->v[u][cap[k]];
            cw += q->v[w][cap[k]];
        }
        cu /= nc;
        cw /= nc;
        double ang[P3_MAXV];
        for (int k = 0; k < nc; k++) ang[k] = pseudo_angle(q->v[u][cap[k]] - cu, q->v[w][cap[k]] - cw);
        for (int k = 1; k < nc; k++) { /* insertion sort: stable, few items */
            const double a = ang[k];
            const int c = cap[k];
            int j = k - 1;
            while (j >= 0 && ang[j] > a) {
                ang[j + 1] = ang[j];
                cap[j + 1] = cap[j];
                j--;
            }
            ang[j + 1] = a;
            cap[j + 1] = c;
        }
        q->fs[nf++] = ni;
        for (int k = 0; k < nc; k++) q->fi[ni++] = cap[k];
    }
    q->fs[nf] = ni;
    q->nf = nf;
    q->nv = nv;
    return 1;
}

/* The farthest vertex of p from y (the first in vertex order among
 * equals) through p's cached values: a vertex whose w is -1 gets its
 * squared distance to y computed and kept; w of the vertices kept by a
 * cut come with them. fresh: every w is recomputed (the box, whose w
 * belong to the previous site). */
static double far_cached(cfpo3_poly *p, const double y[3], int fresh, int *at)
{
    double far = -1.0;
    int w = -1;
    for (int i = 0; i < p->nv; i++) {
        double d = p->w[i];
        if (fresh || d < 0.0) {
            const double dx = p->v[0][i] - y[0], dy = p->v[1][i] - y[1], dz = p->v[2][i] - y[2];
            d = dx * dx + dy * dy + dz * dz;
            p->w[i] = d;
        }
        if (d > far) far = d, w = i;
    }
    if (at) *at = w;
    return far;
}

double cfpo3_local_solve(const double *y, int m, const double lo[3], const double hi[3], double floor2,
                         double best[3], cfpo3_poly scratch[2], cfpo3_solve_count *count)
{
    return cfpo3_near_solve(y, m, m, lo, hi, floor2, best, scratch, count);
}

/* The planes kept sorted at the front of a cell's list (most cells need
 * only the nearest few). */
#define NEAR_K 12

static void put_plane(double pn[3][CFPO3_MAXM + NEAR_K], double *poff, double *pdd, int at, const double nv[3],
                      double off, double dd)
{
    pn[0][at] = nv[0], pn[1][at] = nv[1], pn[2][at] = nv[2];
    poff[at] = off;
    pdd[at] = dd;
}

double cfpo3_near_solve(const double *y, int m, int cells, const double lo[3], const double hi[3], double floor2,
                        double best[3], cfpo3_poly scratch[2], cfpo3_solve_count *count)
{
    if (m <= 0 || m > CFPO3_MAXM) return -1.0;
    if (cells > m) cells = m;
    double bestd = floor2 > 0.0 ? floor2 : -1.0;
    int found = 0;
    cfpo3_poly box;
    /* the bisectors that can reach the box: normal, offset (+inf once
     * used), squared length */
    double pn[3][CFPO3_MAXM + NEAR_K], poff[CFPO3_MAXM + NEAR_K], pdd[CFPO3_MAXM + NEAR_K];
    cfpo3_poly_box(&box, lo, hi);
    for (int i = 0; i < cells; i++) {
        const double *yi = y + 3 * i;
        double far = far_cached(&box, yi, 1, NULL);
        if (far <= bestd) continue;
        /* One pass over the other sites: the kill test (one bisector puts
         * the whole box on y_j's side: the cell misses S), and the planes
         * whose bisector can reach the box. */
        int killed = 0, np = 0, nr = 0;
        for (int j = 0; j < m; j++) {
            if (j == i) continue;
            const double *yj = y + 3 * j;
            const double nv[3] = {yj[0] - yi[0], yj[1] - yi[1], yj[2] - yi[2]};
            const double dd = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
            const double off = nv[0] * yi[0] + nv[1] * yi[1] + nv[2] * yi[2] + 0.5 * dd;
            double low = 0.0; /* the box's smallest n.c */
            for (int a = 0; a < 3; a++) low += nv[a] * (nv[a] > 0.0 ? lo[a] : hi[a]);
            if (low - off > 1e-12 * (dd + fabs(off))) {
                killed = 1;
                break;
            }
            if (dd >= 4.0 * far) continue;
            /* the NEAR_K nearest kept in the order (squared distance to
             * y_i, index) at the front; the others wait unsorted behind
             * slot NEAR_K (a kept one pushed out joins them) */
            if (np == NEAR_K) {
                if (!(dd < pdd[NEAR_K - 1])) {
                    put_plane(pn, poff, pdd, NEAR_K + nr++, nv, off, dd);
                    continue;
                }
                const double last[3] = {pn[0][NEAR_K - 1], pn[1][NEAR_K - 1], pn[2][NEAR_K - 1]};
                put_plane(pn, poff, pdd, NEAR_K + nr++, last, poff[NEAR_K - 1], pdd[NEAR_K - 1]);
                np--;
            }
            int at = np++;
            while (at > 0 && pdd[at - 1] > dd) {
                pn[0][at] = pn[0][at - 1], pn[1][at] = pn[1][at - 1], pn[2][at] = pn[2][at - 1];
                poff[at] = poff[at - 1];
                pdd[at] = pdd[at - 1];
                at--;
            }
            put_plane(pn, poff, pdd, at, nv, off, dd);
        }
        if (killed) continue;
        if (count) count->cells++;
        /* Lazy clipping: the farthest vertex v of the polytope so far is
         * the cell's answer once no bisector cuts it off (the cell lies
         * inside the polytope); else the polytope is clipped by the plane
         * of the site nearest to y_i among those whose bisector cuts v off
         * (it cuts most), and again. A cell is abandoned once v is no farther than the
         * best. Each plane is applied at most once. */
        cfpo3_poly *cur = &box;
        int which = 0, empty = 0, abandoned = 0, at = -1, first = 0;
        far = far_cached(cur, yi, 0, &at);
        for (;;) {
            if (far <= bestd) {
                abandoned = 1;
                break;
            }
            const double vx = cur->v[0][at], vy = cur->v[1][at], vz = cur->v[2][at];
            /* the first plane in order, not used yet, that cuts v off; a used
             * plane's offset is +inf, and the used ones at the front are passed */
            int k = -1;
            while (first < np && poff[first] == INFINITY) first++;
            for (int q = first; q < np && pdd[q] < 4.0 * far; q++)
                if (pn[0][q] * vx + pn[1][q] * vy + pn[2][q] * vz - poff[q] > 0.0) {
                    k = q;
                    break;
                }
            if (k < 0 && nr > 0) { /* none of the kept: the nearest of the waiting ones */
                double kd = 4.0 * far;
                for (int q = NEAR_K; q < NEAR_K + nr; q++)
                    if (pn[0][q] * vx + pn[1][q] * vy + pn[2][q] * vz - poff[q] > 0.0 && pdd[q] < kd)
                        kd = pdd[q], k = q;
            }
            if (count) count->tests++;
            if (k < 0) break; /* no plane cuts v off: v is the cell's farthest point */
            const double koff = poff[k];
            poff[k] = INFINITY;
            const double nv[3] = {pn[0][k], pn[1][k], pn[2][k]};
            const int r = cfpo3_poly_clip(cur, &scratch[which], nv, koff);
            if (r == 0 || r == -2) continue; /* (rounding or no room: the plane is passed over) */
            if (r == -1) {
                empty = 1;
                break;
            }
            if (count) count->cuts++;
            cur = &scratch[which];
            which ^= 1;
            far = far_cached(cur, yi, 0, &at);
        }
        if (empty || abandoned) continue;
        if (far > bestd) {
            bestd = far;
            found = 1;
            best[0] = cur->v[0][at];
            best[1] = cur->v[1][at];
            best[2] = cur->v[2][at];
        }
    }
    /* clamp into S (a vertex may stray from a face by rounding) */
    if (!found) return -1.0;
    for (int c = 0; c < 3; c++) best[c] = best[c] < lo[c] ? lo[c] : (best[c] > hi[c] ? hi[c] : best[c]);
    return bestd;
}
