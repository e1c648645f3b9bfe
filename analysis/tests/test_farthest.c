/* test_farthest.c - an_farthest (the certificate's solver) against the
 * core's exact LocalCFPO solver and against brute force, on sets large
 * enough to take its grid path (more than AN_FAR_SMALL points): uniform,
 * clustered, collinear (horizontal, vertical, diagonal; and a segment
 * seen from one of its points, with and without it), repeated
 * positions, a cluster with far outliers, and squares inside, around and
 * far from the points. Must hold: the same farthest distance as the core
 * solver (to rounding), the returned point inside the square and at that
 * distance from the set, and no sampled point of the square farther.
 *
 * an_farthest_poly (the farthest point of a convex polygon, by the tree)
 * against an exact brute force written here (each point's Voronoi region,
 * cut from the polygon by the bisectors with every other point, at its
 * farthest vertex), on convex hulls of random points, triangles, long thin
 * rectangles, a 200-gon close to a circle and the unit square (also
 * against the core's solver), for 1 to 600 points: uniform, a 1e-3 cluster
 * far from the polygon and two inside it (a square, a triangle), a line,
 * a diagonal, a few positions repeated, a dyadic lattice (exact ties).
 * Must hold: the brute force's value to 1e-12 (relative), the point inside
 * the polygon (to 1e-12) at exactly the value's distance from the set, no
 * sampled point of the polygon farther. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "farthest.h"
#include "geom.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

static void one(const char *what, const double *yx, const double *yy, size_t m, cfpo_square S, an_far_ws *ws)
{
    double cx, cy, rx, ry;
    const double hx = 0.5 * (S.x0 + S.x1), hy = 0.5 * (S.y0 + S.y1);
    const double got = an_farthest(yx, yy, m, S, hx, hy, &cx, &cy, ws);
    double *scratch = malloc(cfpo_solver_scratch(m) * sizeof *scratch);
    const double ref = cfpo_local_solve(yx, yy, (int)m, -1, S, hx, hy, -1, &rx, &ry, scratch);
    free(scratch);
    const double side = S.x1 - S.x0;
    CHECK(got >= 0 && fabs(sqrt(got) - sqrt(ref)) <= 1e-12 * (side + 1), "%s (m = %zu): %.17g against the core's %.17g",
          what, m, sqrt(got), sqrt(ref));
    CHECK(cx >= S.x0 && cx <= S.x1 && cy >= S.y0 && cy <= S.y1, "%s: point (%g, %g) outside the square", what, cx, cy);
    CHECK(fabs(cfpo_min_dist2(cx, cy, yx, yy, (int)m, -1) - got) <= 1e-15, "%s: value is not the point's distance", what);
    double worst = 0;
    for (int a = 0; a <= 60; a++)
        for (int b = 0; b <= 60; b++) {
            const double px = S.x0 + side * a / 60, py = S.y0 + (S.y1 - S.y0) * b / 60;
            const double d2 = cfpo_min_dist2(px, py, yx, yy, (int)m, -1);
            if (d2 > worst) worst = d2;
        }
    CHECK(worst <= got * (1 + 1e-12), "%s: a sampled point is farther (%g > %g)", what, sqrt(worst), sqrt(got));
}

/* ---- an_farthest_poly ---- */

/* The polygon p (n vertices) cut to the side of the bisector of a and b
 * nearer a, into q: Sutherland-Hodgman on f(v) = (v - (a + b) / 2).(b - a). */
static int cut(const double *p, int n, double *q, double ax, double ay, double bx, double by)
{
    const double nx = bx - ax, ny = by - ay, mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    int k = 0;
    for (int v = 0; v < n; v++) {
        const int u = (v + 1) % n;
        const double fv = (p[2 * v] - mx) * nx + (p[2 * v + 1] - my) * ny;
        const double fu = (p[2 * u] - mx) * nx + (p[2 * u + 1] - my) * ny;
        if (fv <= 0) { q[2 * k] = p[2 * v]; q[2 * k + 1] = p[2 * v + 1]; k++; }
        if ((fv < 0) != (fu < 0) && fv != 0 && fu != 0) {
            const double t = fv / (fv - fu);
            q[2 * k] = p[2 * v] + t * (p[2 * u] - p[2 * v]);
            q[2 * k + 1] = p[2 * v + 1] + t * (p[2 * u + 1] - p[2 * v + 1]);
            k++;
        }
    }
    return k;
}

/* The largest distance from the set over the polygon: for each position
 * a (repeats once), the polygon cut by every other position's bisector,
 * its farthest vertex from a. O(m^2 nv), no pruning. */
static double brute_poly(const double *yx, const double *yy, size_t m, const double *P, int nv)
{
    double *R = malloc(2 * (m + (size_t)nv + 2) * sizeof *R), *U = malloc(2 * (m + (size_t)nv + 2) * sizeof *U);
    double best = -1;
    for (size_t a = 0; a < m; a++) {
        size_t e = 0;
        while (e < a && (yx[e] != yx[a] || yy[e] != yy[a])) e++;
        if (e < a) continue; /* a repeat: the same region */
        memcpy(R, P, 2 * (size_t)nv * sizeof *R);
        int nr = nv;
        for (size_t b = 0; b < m && nr > 0; b++) {
            if (yx[b] == yx[a] && yy[b] == yy[a]) continue;
            nr = cut(R, nr, U, yx[a], yy[a], yx[b], yy[b]);
            double *t = R; R = U; U = t;
        }
        for (int v = 0; v < nr; v++) {
            const double dx = R[2 * v] - yx[a], dy = R[2 * v + 1] - yy[a];
            best = fmax(best, dx * dx + dy * dy);
        }
    }
    free(R);
    free(U);
    return best;
}

static double cross(double ax, double ay, double bx, double by, double cx, double cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int cmp_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return p[1] < q[1] ? -1 : (p[1] > q[1]);
}

/* Convex hull of k points (Andrew's monotone chain), counter-clockwise
 * with no collinear vertices, into h; returns its count. Sorts pts. */
static int hull(double *pts, int k, double *h)
{
    qsort(pts, (size_t)k, 2 * sizeof *pts, cmp_xy);
    int c = 0;
    for (int pass = 0; pass < 2; pass++) {
        const int base = c;
        for (int t = 0; t < k; t++) {
            const int i = pass ? k - 1 - t : t;
            while (c >= base + 2 && cross(h[2 * c - 4], h[2 * c - 3], h[2 * c - 2], h[2 * c - 1], pts[2 * i],
                                          pts[2 * i + 1]) <= 0)
                c--;
            h[2 * c] = pts[2 * i];
            h[2 * c + 1] = pts[2 * i + 1];
            c++;
        }
        c--; /* the last point starts the other chain */
    }
    return c;
}

/* The largest squared distance from the set over a sample of the polygon:
 * each triangle of a fan from vertex 0 on a barycentric grid (edges and
 * vertices included), about 1,500 points in all. */
static double sample_poly(const double *yx, const double *yy, size_t m, const double *P, int nv)
{
    int G = (int)sqrt(3000.0 / (nv - 2));
    if (G < 4) G = 4;
    double worst = 0;
    for (int t = 1; t + 1 < nv; t++)
        for (int a = 0; a <= G; a++)
            for (int b = 0; a + b <= G; b++) {
                const double u = (double)a / G, v = (double)b / G, w = 1 - u - v;
                const double px = w * P[0] + u * P[2 * t] + v * P[2 * t + 2];
                const double py = w * P[1] + u * P[2 * t + 1] + v * P[2 * t + 3];
                worst = fmax(worst, cfpo_min_dist2(px, py, yx, yy, (int)m, -1));
            }
    return worst;
}

static void one_poly(const char *what, const double *yx, const double *yy, size_t m, const double *P, int nv,
                     an_far_ws *ws)
{
    double cx = NAN, cy = NAN;
    double mx = 0, my = 0; /* a point inside: the vertices' mean */
    for (int v = 0; v < nv; v++) { mx += P[2 * v] / nv; my += P[2 * v + 1] / nv; }
    const double got = an_farthest_poly(yx, yy, m, P, nv, mx, my, &cx, &cy, ws);
    const double ref = brute_poly(yx, yy, m, P, nv);
    CHECK(got >= 0 && fabs(got - ref) <= 1e-12 * ref, "%s (m = %zu, %d vertices): %.17g against brute force %.17g",
          what, m, nv, sqrt(got), sqrt(ref));
    /* Inside: on the inner side of every edge, to 1e-12 of the edge's
     * length. */
    double out = 0;
    for (int e = 0; e < nv; e++) {
        const int f = (e + 1) % nv;
        const double len = hypot(P[2 * f] - P[2 * e], P[2 * f + 1] - P[2 * e + 1]);
        out = fmax(out, -cross(P[2 * e], P[2 * e + 1], P[2 * f], P[2 * f + 1], cx, cy) / len);
    }
    CHECK(out <= 1e-12, "%s (m = %zu): point (%.17g, %.17g) %g outside the polygon", what, m, cx, cy, out);
    double d2 = INFINITY;
    for (size_t j = 0; j < m; j++) {
        const double dx = cx - yx[j], dy = cy - yy[j];
        d2 = fmin(d2, dx * dx + dy * dy);
    }
    CHECK(d2 == got, "%s (m = %zu): value %.17g, the point's distance %.17g", what, m, got, d2);
    const double worst = sample_poly(yx, yy, m, P, nv);
    CHECK(worst <= got * (1 + 1e-12), "%s (m = %zu): a sampled point is farther (%.17g > %.17g)", what, m,
          sqrt(worst), sqrt(got));
}

/* The polygons: hulls of random points, triangles, thin rectangles (two
 * tilts), a 200-gon, the unit square; returns the count, vertices in P. */
static int polygon(int kind, uint64_t seed, double *P)
{
    double pts[2 * 24];
    switch (kind) {
    case 0: case 1: /* hull of 24 points in [0.15, 0.85)^2 */
        for (int t = 0; t < 48; t++) pts[t] = 0.15 + 0.7 * cfpo_rand01(seed, 100 + (uint64_t)kind, (uint64_t)t);
        return hull(pts, 24, P);
    case 2: case 3: { /* a triangle, counter-clockwise */
        for (int t = 0; t < 6; t++) pts[t] = cfpo_rand01(seed, 100 + (uint64_t)kind, (uint64_t)t);
        const int k = hull(pts, 3, P);
        return k == 3 ? k : 0;
    }
    case 4: case 5: { /* 0.6 x 1e-3 rectangle, tilted */
        const double a = kind == 4 ? 0.3 : 1.2, c = cos(a), s = sin(a), hl = 0.3, hw = 5e-4;
        const double u[4][2] = {{-hl, -hw}, {hl, -hw}, {hl, hw}, {-hl, hw}};
        for (int v = 0; v < 4; v++) {
            P[2 * v] = 0.5 + c * u[v][0] - s * u[v][1];
            P[2 * v + 1] = 0.5 + s * u[v][0] + c * u[v][1];
        }
        return 4;
    }
    case 6: /* a 200-gon of radius 0.3 */
        for (int v = 0; v < 200; v++) {
            P[2 * v] = 0.5 + 0.3 * cos(2 * M_PI * v / 200);
            P[2 * v + 1] = 0.5 + 0.3 * sin(2 * M_PI * v / 200);
        }
        return 200;
    default: {
        const double sq[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        memcpy(P, sq, sizeof sq);
        return 4;
    }
    }
}

static void poly_tests(an_far_ws *ws)
{
    const size_t M = 600, ms[] = {1, 2, 3, 10, 129, 600};
    double *x = malloc(M * sizeof *x), *y = malloc(M * sizeof *y), P[2 * 200];
    char what[96];
    static const char *sets[] = {"uniform",  "far cluster", "inner cluster", "triangle cluster",
                                 "line",     "diagonal",    "repeats",       "dyadic lattice"};
    for (int kind = 0; kind < 8; kind++)
        for (size_t a = 0; a < sizeof ms / sizeof ms[0]; a++) {
            const size_t m = ms[a];
            for (size_t i = 0; i < m; i++) {
                const double u = cfpo_rand01(13, (uint64_t)kind, 2 * i), v = cfpo_rand01(13, (uint64_t)kind, 2 * i + 1);
                switch (kind) {
                case 0: x[i] = u; y[i] = v; break;
                case 1: x[i] = 0.02 + 1e-3 * u; y[i] = 0.97 + 1e-3 * v; break; /* in the square only */
                case 2: x[i] = 0.5 + 1e-3 * u; y[i] = 0.5 + 1e-3 * v; break;
                case 3: /* a right triangle, its long side towards the farthest point */
                    x[i] = 0.42 + 1e-3 * (u + v > 1 ? 1 - u : u);
                    y[i] = 0.44 + 1e-3 * (u + v > 1 ? 1 - v : v);
                    break;
                case 4: x[i] = u; y[i] = 0.47; break;
                case 5: x[i] = 0.1 + 0.8 * u; y[i] = 0.05 + 0.8 * u; break;
                case 6: x[i] = i % 3 == 0 ? 0.3 : i % 3 == 1 ? 0.62 : 0.5; y[i] = i % 3 == 2 ? 0.8 : 0.4; break;
                default: { /* c x c over the square, c a power of 2, repeated: exact
                            * bisectors, Voronoi vertices on several of them */
                    size_t c = 1;
                    while (4 * c * c <= m) c *= 2;
                    x[i] = ((double)(i % (c * c) % c) + 0.5) / (double)c;
                    y[i] = ((double)(i % (c * c) / c) + 0.5) / (double)c;
                    break;
                }
                }
            }
            for (int pk = 0; pk < 8; pk++) {
                /* the big sets on fewer polygons, to keep the brute force short */
                if (m == 600 && pk % 2) continue;
                const int nv = polygon(pk, 17 + a, P);
                if (nv < 3) continue;
                snprintf(what, sizeof what, "poly: %s, polygon %d", sets[kind], pk);
                one_poly(what, x, y, m, P, nv, ws);
                if (pk == 7 && m > 0) { /* the unit square: the core's solver too */
                    double cx, cy, rx, ry;
                    const cfpo_square S = {0, 0, 1, 1};
                    double *scratch = malloc(cfpo_solver_scratch(m) * sizeof *scratch);
                    const double ref = cfpo_local_solve(x, y, (int)m, -1, S, 0.5, 0.5, -1, &rx, &ry, scratch);
                    double mx = 0, my = 0;
                    for (int v = 0; v < nv; v++) { mx += P[2 * v] / nv; my += P[2 * v + 1] / nv; }
                    const double got = an_farthest_poly(x, y, m, P, nv, mx, my, &cx, &cy, ws);
                    free(scratch);
                    CHECK(fabs(got - ref) <= 1e-12 * ref, "%s (m = %zu): %.17g against the core's %.17g", what, m,
                          sqrt(got), sqrt(ref));
                }
            }
        }
    /* No points: a failure (m >= 1 is required), not a value. */
    double cx, cy;
    CHECK(an_farthest_poly(x, y, 0, P, polygon(7, 0, P), 0.5, 0.5, &cx, &cy, ws) == -1, "poly: no points");
    free(x);
    free(y);
}

int main(void)
{
    an_far_ws ws = {0};
    const size_t M = 600;
    double *x = malloc(M * sizeof *x), *y = malloc(M * sizeof *y);
    const cfpo_square sq[] = {{0.4, 0.4, 0.6, 0.6}, {0.0, 0.0, 1.0, 1.0}, {0.45, 0.45, 0.55, 0.55},
                              {0.9, 0.1, 0.95, 0.15}, {0.2, 0.7, 0.8, 0.75}};
    char what[96];
    for (int kind = 0; kind < 10; kind++) {
        for (size_t m = AN_FAR_SMALL + 1; m <= M; m += 157) {
            for (size_t i = 0; i < m; i++) {
                const double u = cfpo_rand01(11, (uint64_t)kind, 2 * i), v = cfpo_rand01(11, (uint64_t)kind, 2 * i + 1);
                switch (kind) {
                case 0: x[i] = u; y[i] = v; break;                                   /* uniform */
                case 1: x[i] = 0.5 + 1e-3 * u; y[i] = 0.5 + 1e-3 * v; break;         /* cluster */
                case 2: x[i] = u; y[i] = 0.5; break;                                  /* horizontal line */
                case 3: x[i] = 0.5; y[i] = u; break;                                  /* vertical line */
                case 4: x[i] = 0.2 + 0.6 * u; y[i] = 0.2 + 0.6 * u; break;           /* diagonal */
                case 5: x[i] = i % 3 ? 0.3 : 0.6; y[i] = i % 2 ? 0.5 : 0.52; break;  /* 4 spots, many copies */
                case 6: x[i] = 0.5 + 1e-9 * u; y[i] = 0.5 + 1e-9 * v;                /* tiny cluster + outliers */
                        if (i % 50 == 0) { x[i] = u; y[i] = v; }
                        break;
                case 7: x[i] = floor(u * 8) / 8; y[i] = floor(v * 8) / 8; break;    /* lattice with repeats */
                case 8: x[i] = 0.5 + 0.05 * cos(6.283185307179586 * (double)i / (double)m); /* a circle: */
                        y[i] = 0.5 + 0.05 * sin(6.283185307179586 * (double)i / (double)m); /* all on the hull */
                        break;
                default: x[i] = 0.5 + 0.05 * cos(6.283185307179586 * u);                /* a circle, random */
                         y[i] = 0.5 + 0.05 * sin(6.283185307179586 * u);                /* angles */
                         if (i % 7 == 0) { x[i] = 0.5 + 0.03 * u; y[i] = 0.5 + 0.03 * v; } /* and inside */
                         break;
                }
            }
            for (size_t s = 0; s < sizeof sq / sizeof sq[0]; s++) {
                snprintf(what, sizeof what, "set kind %d, square %zu", kind, s);
                one(what, x, y, m, sq[s], &ws);
            }
        }
    }
    /* A segment's point's neighbourhood (the theorem's D(x) on a line):
     * the square centred on one of its points, with and without that
     * point; the answer is decided by a few points (farsub.c). */
    for (int dir = 0; dir < 3; dir++)
        for (size_t m = 150; m <= M; m += 150) {
            const double dx = dir == 1 ? 0 : 1.0 / (double)m, dy = dir == 0 ? 0 : 0.7 / (double)m;
            for (size_t i = 0; i < m; i++) { x[i] = 0.1 + dx * (double)i; y[i] = 0.2 + dy * (double)i; }
            const size_t c = m / 3;
            for (int skip = 0; skip < 2; skip++) {
                const double e = 0.1 + 0.05 * skip;
                const cfpo_square Sc = {x[c] - e, y[c] - e, x[c] + e, y[c] + e};
                if (skip) { x[c] = x[m - 1]; y[c] = y[m - 1]; }
                snprintf(what, sizeof what, "segment %d, centred on a point%s", dir, skip ? ", left out" : "");
                one(what, x, y, m - (size_t)skip, Sc, &ws);
            }
        }
    /* One point, many copies: the answer is the square's farthest corner. */
    for (size_t i = 0; i < M; i++) { x[i] = 0.25; y[i] = 0.5; }
    double cx, cy;
    const cfpo_square S = {0, 0, 1, 1};
    const double r2 = an_farthest(x, y, M, S, 0.5, 0.5, &cx, &cy, &ws);
    CHECK(r2 == 0.75 * 0.75 + 0.25 && cx == 1 && (cy == 0 || cy == 1), "600 copies: %g at (%g, %g)", r2, cx, cy);
    /* No points: infinity and the square's centre, as the core solver. */
    CHECK(an_farthest(x, y, 0, S, 0.5, 0.5, &cx, &cy, &ws) == INFINITY && cx == 0.5 && cy == 0.5, "no points");
    poly_tests(&ws);
    an_far_free(&ws);
    free(x);
    free(y);
    return test_report(passed_, failed_);
}
