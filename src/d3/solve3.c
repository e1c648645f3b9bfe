/* solve3.c - see solve3.h. The solve clips each cell lazily (the
 * farthest vertex's cutting bisectors only, the deepest cut first). The
 * clipping: Sutherland-Hodgman on every face
 * loop, a cut edge's new vertex made once (looked up among the cut edges
 * of its outside vertex, computed from the inside end), and the cap face on the
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

/* cfpo3_poly_clip; with y, also the farthest vertex of q from y (the
 * first in vertex order among equals) into *far, *at, every w of q then
 * the squared distance to y (those of p must be already). */
static int clip_far(const cfpo3_poly *p, cfpo3_poly *q, const double n[3], double off, const double *y, double *far,
                    int *at)
{
    double fbest = -1.0;
    int fat = -1;
    double d[P3_MAXV];
    int out = 0;
    for (int i = 0; i < p->nv; i++) /* apart from the count, so that it vectorises */
        d[i] = n[0] * p->v[0][i] + n[1] * p->v[1][i] + n[2] * p->v[2][i] - off;
    for (int i = 0; i < p->nv; i++) out += d[i] > 0.0;
    if (out == 0) return 0;
    if (out == p->nv) return -1;
    /* inside vertices keep their coordinates under new indices; each
     * outside vertex heads a list of the cut edges that end in it */
    int map[P3_MAXV], head[P3_MAXV];
    int nv = 0;
    for (int i = 0; i < p->nv; i++) {
        if (d[i] <= 0.0) {
            map[i] = nv;
            q->v[0][nv] = p->v[0][i];
            q->v[1][nv] = p->v[1][i];
            q->v[2][nv] = p->v[2][i];
            q->w[nv] = p->w[i];
            if (p->w[i] > fbest) fbest = p->w[i], fat = nv;
            nv++;
        } else {
            map[i] = -1;
            head[i] = -1;
        }
    }
    /* cut edges: (inside end, outside end) -> new vertex, in the order made */
    int ea[P3_MAXV], enx[P3_MAXV], ev[P3_MAXV];
    int ne = 0;
    int nf = 0, ni = 0;
    for (int f = 0; f < p->nf; f++) {
        const int s0 = p->fs[f], len = p->fs[f + 1] - s0;
        const int *pf = p->fi + s0;
        const int start = ni;
        int nout = 0;
        if (ni + len <= P3_MAXI) { /* the face copied as it counts (kept if no vertex is cut) */
            for (int k = 0; k < len; k++) {
                const int v = map[pf[k]];
                q->fi[ni + k] = v;
                nout += v < 0;
            }
        } else {
            for (int k = 0; k < len; k++) nout += map[pf[k]] < 0;
        }
        if (nout == len) continue; /* the whole face is cut away */
        if (ni + 2 * len > P3_MAXI) return -2;
        if (nout == 0) { /* the whole face stays */
            ni += len;
            q->fs[nf++] = start;
            if (nf >= P3_MAXF) return -2;
            continue;
        }
        int a = pf[0], ma = map[a];
        for (int k = 0; k < len; k++) {
            const int b = pf[k + 1 == len ? 0 : k + 1], mb = map[b];
            if (ma >= 0 && (ni == start || q->fi[ni - 1] != ma)) q->fi[ni++] = ma;
            if ((ma >= 0) != (mb >= 0)) {
                const int vi = ma >= 0 ? a : b, vo = ma >= 0 ? b : a;
                int nvx = -1;
                if (d[vi] == 0.0) {
                    nvx = map[vi];
                } else {
                    for (int e = head[vo]; e >= 0; e = enx[e])
                        if (ea[e] == vi) {
                            nvx = ev[e];
                            break;
                        }
                    if (nvx < 0) {
                        if (nv >= P3_MAXV || ne >= P3_MAXV) return -2;
                        const double t = d[vi] / (d[vi] - d[vo]);
                        for (int c = 0; c < 3; c++)
                            q->v[c][nv] = p->v[c][vi] + (p->v[c][vo] - p->v[c][vi]) * t;
                        if (y) {
                            const double dx = q->v[0][nv] - y[0], dy = q->v[1][nv] - y[1], dz = q->v[2][nv] - y[2];
                            const double dw = dx * dx + dy * dy + dz * dz;
                            q->w[nv] = dw;
                            if (dw > fbest) fbest = dw, fat = nv;
                        } else {
                            q->w[nv] = -1.0;
                        }
                        ea[ne] = vi;
                        enx[ne] = head[vo];
                        head[vo] = ne;
                        ev[ne] = nv;
                        ne++;
                        nvx = nv++;
                    }
                }
                if (ni == start || q->fi[ni - 1] != nvx) q->fi[ni++] = nvx;
            }
            a = b, ma = mb;
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
    if (y) *far = fbest, *at = fat;
    return 1;
}

int cfpo3_poly_clip(const cfpo3_poly *p, cfpo3_poly *q, const double n[3], double off)
{
    return clip_far(p, q, n, off, NULL, NULL, NULL);
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

double cfpo3_near_solve(const double *y, int m, int cells, const double lo[3], const double hi[3], double floor2,
                        double best[3], cfpo3_poly scratch[2], cfpo3_solve_count *count)
{
    if (m <= 0 || m > CFPO3_MAXM) return -1.0;
    if (cells > m) cells = m;
    double bestd = floor2 > 0.0 ? floor2 : -1.0;
    int found = 0;
    cfpo3_poly box;
    /* the sites by axis (so that the per-site loops vectorise) and, for
     * the cell being clipped, every site's bisector: normal, offset,
     * squared length and the box's smallest n.c */
    double ys[3][CFPO3_MAXM];
    double an[3][CFPO3_MAXM], aoff[CFPO3_MAXM], add[CFPO3_MAXM], alow[CFPO3_MAXM];
    /* the bisectors that can reach the box, in site order: normal,
     * offset (+inf once used), squared length */
    double pn[3][CFPO3_MAXM], poff[CFPO3_MAXM], pdd[CFPO3_MAXM];
    double score[CFPO3_MAXM];
    for (int j = 0; j < m; j++) ys[0][j] = y[3 * j], ys[1][j] = y[3 * j + 1], ys[2][j] = y[3 * j + 2];
    cfpo3_poly_box(&box, lo, hi);
    for (int i = 0; i < cells; i++) {
        const double *yi = y + 3 * i;
        double far = far_cached(&box, yi, 1, NULL);
        if (far <= bestd) continue;
        const double far4 = 4.0 * far;
        const double yi0 = yi[0], yi1 = yi[1], yi2 = yi[2];
        const double lo0 = lo[0], lo1 = lo[1], lo2 = lo[2], hi0 = hi[0], hi1 = hi[1], hi2 = hi[2];
        /* every site's bisector at once (element-wise: the same bits in
         * any vector width) */
        for (int j = 0; j < m; j++) {
            const double n0 = ys[0][j] - yi0, n1 = ys[1][j] - yi1, n2 = ys[2][j] - yi2;
            const double dd = n0 * n0 + n1 * n1 + n2 * n2;
            an[0][j] = n0, an[1][j] = n1, an[2][j] = n2;
            add[j] = dd;
            aoff[j] = n0 * yi0 + n1 * yi1 + n2 * yi2 + 0.5 * dd;
            alow[j] = n0 * (n0 > 0.0 ? lo0 : hi0) + n1 * (n1 > 0.0 ? lo1 : hi1) + n2 * (n2 > 0.0 ? lo2 : hi2);
        }
        /* The kill test (one bisector puts the whole box on y_j's side:
         * the cell misses S), and the planes whose bisector can reach the
         * box. A bisector with |y_j - y_i| >= 2 far lies beyond the box's
         * farthest corner from y_i, so it can neither cut nor kill. */
        int killed = 0, ns = 0;
        for (int j = 0; j < m; j++) {
            if (j == i || !(add[j] < far4)) continue;
            const double dd = add[j], off = aoff[j];
            if (alow[j] - off > 1e-12 * (dd + fabs(off))) {
                killed = 1;
                break;
            }
            const int sl = ns++;
            pn[0][sl] = an[0][j], pn[1][sl] = an[1][j], pn[2][sl] = an[2][j];
            poff[sl] = off;
            pdd[sl] = dd;
        }
        if (killed) continue;
        if (count) count->cells++;
        /* Lazy clipping: the farthest vertex v of the polytope so far is
         * the cell's answer once no bisector cuts it off (the cell lies
         * inside the polytope); else the polytope is clipped by the
         * bisector that v lies deepest beyond (Euclidean distance), and
         * again. A cell is abandoned once v is no farther than the best.
         * Each plane is applied at most once. */
        cfpo3_poly *cur = &box;
        int which = 0, empty = 0, abandoned = 0, at = -1;
        far = far_cached(cur, yi, 0, &at);
        for (;;) {
            if (far <= bestd) {
                abandoned = 1;
                break;
            }
            const double vx = cur->v[0][at], vy = cur->v[1][at], vz = cur->v[2][at];
            const double f4 = 4.0 * far;
            /* among the planes not used yet, the one v lies deepest beyond
             * (the largest (n.v - off)^2 / |n|^2, the first in site order
             * among equals); a used plane's offset is +inf */
            /* each plane's depth score (element-wise, so the same bits
             * in any vector width), then the first plane of the largest */
            for (int sl = 0; sl < ns; sl++) {
                const double dv = pn[0][sl] * vx + pn[1][sl] * vy + pn[2][sl] * vz - poff[sl];
                score[sl] = (dv > 0.0 && pdd[sl] < f4) ? dv * dv / pdd[sl] : -1.0;
            }
            double kb = -0.5;
            for (int sl = 0; sl < ns; sl++) kb = score[sl] > kb ? score[sl] : kb;
            int k = -1;
            if (kb > -0.5)
                for (int sl = 0; sl < ns; sl++)
                    if (score[sl] == kb) {
                        k = sl;
                        break;
                    }
            if (count) count->tests++;
            if (k < 0) break; /* no plane cuts v off: v is the cell's farthest point */
            const double koff = poff[k];
            poff[k] = INFINITY;
            const double nv[3] = {pn[0][k], pn[1][k], pn[2][k]};
            double nfar;
            int nat;
            const int r = clip_far(cur, &scratch[which], nv, koff, yi, &nfar, &nat);
            if (r == 0 || r == -2) continue; /* (rounding or no room: the plane is passed over) */
            if (r == -1) {
                empty = 1;
                break;
            }
            if (count) count->cuts++;
            cur = &scratch[which];
            which ^= 1;
            far = nfar, at = nat;
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
