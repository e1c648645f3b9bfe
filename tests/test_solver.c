/* test_solver.c - LocalCFPO against brute force.
 *
 * For each configuration: the solver's point must lie in S, its returned
 * value must equal the objective recomputed at that point, and no point of
 * S found by brute force (a dense grid, then hill climbing with shrinking
 * steps from the best grid points) may beat it. 10,000+ configurations,
 * degenerate ones included. Also checks the pruned mode (floor2) against
 * the plain mode. Then the AVX2 solver (where the CPU has it) against the
 * plain one, bit for bit (value and point), on all of these and on
 * 200,000 more: random, lattices with jitter down to 1e-15, many-sided
 * cells (polygons past the 8 vertices of the branch-free cut), points
 * on S's corners and edges, far and huge coordinates, every floor mode.
 * The near solve (cfpo_near_solve), searching one and two cells, on the
 * same configurations against an exact enumeration of the vertices of the
 * Voronoi cells it searches, never above LocalCFPO, equal to it when
 * LocalCFPO's point lies in a searched cell, and AVX2 against plain bit
 * for bit too. */
#include "geom.h"
#include "solver_simd.h"
#include "testutil.h"

#include <string.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static uint64_t rs = 0x1234567ULL;
static double urand(void)
{
    rs ^= rs << 13; rs ^= rs >> 7; rs ^= rs << 17;
    return (double)(rs >> 11) * 0x1.0p-53;
}

static double f2(double x, double y, const double *yx, const double *yy, int m)
{
    return cfpo_min_dist2(x, y, yx, yy, m, -1);
}

static double brute(const double *yx, const double *yy, int m, cfpo_square S, double *bxo, double *byo)
{
    enum { G = 48, TOP = 6 };
    double tv[TOP], tx[TOP], ty[TOP];
    for (int t = 0; t < TOP; t++) tv[t] = -1;
    for (int a = 0; a <= G; a++)
        for (int b = 0; b <= G; b++) {
            double x = S.x0 + (S.x1 - S.x0) * a / G, y = S.y0 + (S.y1 - S.y0) * b / G;
            double v = f2(x, y, yx, yy, m);
            int t = TOP - 1;
            if (v <= tv[t]) continue;
            while (t > 0 && tv[t - 1] < v) { tv[t] = tv[t - 1]; tx[t] = tx[t - 1]; ty[t] = ty[t - 1]; t--; }
            tv[t] = v; tx[t] = x; ty[t] = y;
        }
    double best = -1, bx = 0, by = 0;
    for (int t = 0; t < TOP; t++) {
        if (tv[t] < 0) continue;
        double x = tx[t], y = ty[t], v = tv[t];
        double h = (S.x1 - S.x0) / G;
        while (h > 1e-13) {
            int improved = 0;
            for (int d = 0; d < 8; d++) {
                static const int D[8][2] = {{1,0},{-1,0},{0,1},{0,-1},{1,1},{1,-1},{-1,1},{-1,-1}};
                double nx = x + h * D[d][0], ny = y + h * D[d][1];
                if (nx < S.x0) nx = S.x0;
                if (nx > S.x1) nx = S.x1;
                if (ny < S.y0) ny = S.y0;
                if (ny > S.y1) ny = S.y1;
                double nv = f2(nx, ny, yx, yy, m);
                if (nv > v) { v = nv; x = nx; y = ny; improved = 1; }
            }
            if (!improved) h *= 0.5;
        }
        if (v > best) { best = v; bx = x; by = y; }
    }
    *bxo = bx; *byo = by;
    return best;
}

enum { MAXM = 40 };

static int avx2_ok, avx512_ok, same_calls;

/* The AVX2 and AVX-512 solvers against the plain one (LocalCFPO, then the
 * near solve of one and of two cells) on the same call: the same bits? */
static int same_bits(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx, double hy,
                     double floor2, const char *kind)
{
    if (!avx2_ok) return 0;
    for (int w = 0; w < 3; w++) {
        const int cells = w ? w : m;
        double sa[10 * (MAXM + 8)], sb[10 * (MAXM + 8)];
        double ax, ay, bx, by;
        double va = cfpo_solve_cells_plain(yx, yy, m, skip, S, hx, hy, floor2, &ax, &ay, sa, cells);
        for (int route = 0; route < 1 + avx512_ok; route++) {
            double vb = route ? cfpo_solve_cells_avx512(yx, yy, m, skip, S, hx, hy, floor2, &bx, &by, sb, cells)
                              : cfpo_solve_cells_avx2(yx, yy, m, skip, S, hx, hy, floor2, &bx, &by, sb, cells);
            same_calls++;
            if (memcmp(&va, &vb, 8) || memcmp(&ax, &bx, 8) || memcmp(&ay, &by, 8)) {
                fprintf(stderr,
                        "%s: %s %s (%d cells) %.17g at (%.17g, %.17g), plain %.17g at (%.17g, %.17g), m=%d skip=%d "
                        "floor2=%.17g\n",
                        kind, route ? "AVX-512" : "AVX2", w ? "near solve" : "solver", cells, vb, bx, by, va, ax, ay,
                        m, skip, floor2);
                return 1;
            }
        }
    }
    return 0;
}

/* The index of the point of Y nearest to (hx, hy) other than `not`, the
 * first on ties; -1 if there is none. */
static int nearest(const double *yx, const double *yy, int m, double hx, double hy, int not)
{
    int b = -1;
    for (int j = 0; j < m; j++)
        if (j != not && (b < 0 || f2(hx, hy, yx + j, yy + j, 1) < f2(hx, hy, yx + b, yy + b, 1))) b = j;
    return b;
}

/* Whether c lies in S and in the closed Voronoi cell of y_a (up to tol,
 * squared distances). */
static int in_cell(const double *yx, const double *yy, int m, int a, cfpo_square S, double cx, double cy, double tol)
{
    const double e = tol * (S.x1 - S.x0);
    if (cx < S.x0 - e || cx > S.x1 + e || cy < S.y0 - e || cy > S.y1 + e) return 0;
    return f2(cx, cy, yx + a, yy + a, 1) <= f2(cx, cy, yx, yy, m) + tol * (S.x1 - S.x0) * (S.x1 - S.x0);
}

/* The farthest point from y_a of its Voronoi cell clipped to S, by
 * enumeration: S's corners, each bisector (y_a, y_j) met with S's edges,
 * each two bisectors met; the largest |c - y_a|^2 over those in the cell.
 * Shares no code with the clipping solvers. -1 when no candidate is. */
static double brute_cell(const double *yx, const double *yy, int m, int a, cfpo_square S)
{
    double best = -1;
    const double ax = yx[a], ay = yy[a];
    double cand[2 * MAXM * MAXM + 64][2];
    int nc = 0;
    const double cx4[4] = {S.x0, S.x1, S.x1, S.x0}, cy4[4] = {S.y0, S.y0, S.y1, S.y1};
    for (int c = 0; c < 4; c++) cand[nc][0] = cx4[c], cand[nc][1] = cy4[c], nc++;
    /* bisector j: n . c = d with n = y_j - y_a, d = (|y_j|^2 - |y_a|^2) / 2 */
    double bn[MAXM][2], bd[MAXM];
    int nb = 0;
    for (int j = 0; j < m; j++) {
        const double nx = yx[j] - ax, ny = yy[j] - ay;
        if (nx == 0 && ny == 0) continue;
        bn[nb][0] = nx, bn[nb][1] = ny;
        bd[nb++] = 0.5 * ((yx[j] * yx[j] + yy[j] * yy[j]) - (ax * ax + ay * ay));
    }
    for (int j = 0; j < nb; j++) {
        if (bn[j][1] != 0) /* meets x = S.x0 and x = S.x1 */
            for (int e = 0; e < 2; e++) {
                const double x = e ? S.x1 : S.x0;
                cand[nc][0] = x, cand[nc][1] = (bd[j] - bn[j][0] * x) / bn[j][1], nc++;
            }
        if (bn[j][0] != 0)
            for (int e = 0; e < 2; e++) {
                const double y = e ? S.y1 : S.y0;
                cand[nc][0] = (bd[j] - bn[j][1] * y) / bn[j][0], cand[nc][1] = y, nc++;
            }
        for (int k = j + 1; k < nb; k++) {
            const double det = bn[j][0] * bn[k][1] - bn[j][1] * bn[k][0];
            if (det == 0) continue;
            cand[nc][0] = (bd[j] * bn[k][1] - bd[k] * bn[j][1]) / det;
            cand[nc][1] = (bn[j][0] * bd[k] - bn[k][0] * bd[j]) / det;
            nc++;
        }
    }
    for (int c = 0; c < nc; c++) {
        if (!in_cell(yx, yy, m, a, S, cand[c][0], cand[c][1], 1e-9)) continue;
        const double v = f2(cand[c][0], cand[c][1], yx + a, yy + a, 1);
        if (v > best) best = v;
    }
    return best;
}

/* The near solve of `cells` cells (1 or 2) on one configuration (no point
 * skipped, no floor) with LocalCFPO's answer v at (cx, cy). The cells
 * searched are those of the nearest and the second-nearest point of Y to
 * the hint (the first on ties). */
static int check_near(const double *yx, const double *yy, int m, cfpo_square S, double hx, double hy, double v,
                      double cx, double cy, int cells, const char *kind)
{
    if (m == 0) return 0;
    double scratch[10 * (MAXM + 8)], nx, ny;
    const double vn = cfpo_near_solve(yx, yy, m, -1, S, hx, hy, -1.0, &nx, &ny, scratch, cells);
    const int a = nearest(yx, yy, m, hx, hy, -1), b = cells > 1 ? nearest(yx, yy, m, hx, hy, a) : -1;
    const double scale = (S.x1 - S.x0) * (S.x1 - S.x0);
    double ref = brute_cell(yx, yy, m, a, S);
    if (b >= 0) ref = fmax(ref, brute_cell(yx, yy, m, b, S));
    int bad = 0;
    if (vn > v + 1e-12 * scale) { /* rounding: the same vertex, clipped from another cell */
        fprintf(stderr, "%s: near solve (%d cells) %.17g above LocalCFPO's %.17g\n", kind, cells, vn, v);
        bad = 1;
    }
    if (!(in_cell(yx, yy, m, a, S, nx, ny, 1e-12) || (b >= 0 && in_cell(yx, yy, m, b, S, nx, ny, 1e-12))) ||
        vn != f2(nx, ny, yx, yy, m)) {
        fprintf(stderr, "%s: near solve's point (%.17g, %.17g) not in a searched cell, or value %.17g != %.17g\n",
                kind, nx, ny, vn, f2(nx, ny, yx, yy, m));
        bad = 1;
    }
    if (fabs(vn - ref) > 1e-9 * scale) {
        fprintf(stderr, "%s: near solve (%d cells) %.17g, enumeration of the cells %.17g, m=%d\n", kind, cells, vn,
                ref, m);
        bad = 1;
    }
    if ((in_cell(yx, yy, m, a, S, cx, cy, 0) || (b >= 0 && in_cell(yx, yy, m, b, S, cx, cy, 0))) &&
        vn < v - 1e-12 * scale) {
        fprintf(stderr, "%s: LocalCFPO's point is in a near cell, but near solve (%d cells) %.17g < %.17g\n", kind,
                cells, vn, v);
        bad = 1;
    }
    return bad;
}

/* Every floor mode and a skipped index: the same bits? */
static int same_all(const double *yx, const double *yy, int m, cfpo_square S, double hx, double hy, double v,
                    const char *kind)
{
    const double floors[5] = {-1.0, 0.0, 0.5 * v, v, v * (1 + 1e-9)};
    int bad = 0;
    for (int f = 0; f < 5; f++) bad |= same_bits(yx, yy, m, -1, S, hx, hy, floors[f], kind);
    if (m > 1) bad |= same_bits(yx, yy, m, m / 2, S, hx, hy, -1.0, kind);
    return bad;
}

static int check(const double *yx, const double *yy, int m, cfpo_square S, double hx, double hy,
                 const char *kind, double *worst_gap)
{
    double scratch[10 * (MAXM + 8)];
    double cx, cy;
    double v = cfpo_local_solve(yx, yy, m, -1, S, hx, hy, -1.0, &cx, &cy, scratch);
    double bx, by;
    double vb = brute(yx, yy, m, S, &bx, &by);
    double scale = (S.x1 - S.x0) * (S.x1 - S.x0);
    int bad = 0;
    if (!(cx >= S.x0 && cx <= S.x1 && cy >= S.y0 && cy <= S.y1)) {
        fprintf(stderr, "%s: solver point (%.17g, %.17g) outside S\n", kind, cx, cy);
        bad = 1;
    }
    if (v != f2(cx, cy, yx, yy, m)) {
        fprintf(stderr, "%s: returned value %.17g != objective %.17g\n", kind, v, f2(cx, cy, yx, yy, m));
        bad = 1;
    }
    if (vb > v + 1e-12 * scale) {
        fprintf(stderr, "%s: brute force beats solver: %.17g > %.17g at (%.17g, %.17g), m=%d\n", kind,
                vb, v, bx, by, m);
        bad = 1;
    }
    double gap = (v - vb) / scale;
    if (gap > *worst_gap) *worst_gap = gap;
    /* Pruned mode: with a floor below the optimum it must find the same
     * value; with a floor at or above it, it must report nothing better. */
    double c2x, c2y;
    double vp = cfpo_local_solve(yx, yy, m, -1, S, hx, hy, 0.5 * v, &c2x, &c2y, scratch);
    if (vp != v) {
        fprintf(stderr, "%s: pruned solve found %.17g, plain %.17g\n", kind, vp, v);
        bad = 1;
    }
    double vq = cfpo_local_solve(yx, yy, m, -1, S, hx, hy, v * (1 + 1e-9), &c2x, &c2y, scratch);
    if (vq > v * (1 + 1e-9)) {
        fprintf(stderr, "%s: pruned solve above an unbeatable floor: %.17g\n", kind, vq);
        bad = 1;
    }
    bad |= same_all(yx, yy, m, S, hx, hy, v, kind);
    for (int cells = 1; cells <= 2; cells++) bad |= check_near(yx, yy, m, S, hx, hy, v, cx, cy, cells, kind);
    return bad;
}

/* More configurations for the AVX2 comparison alone. Returns failures. */
static int avx2_more(int count)
{
    double yx[MAXM], yy[MAXM];
    int bad = 0;
    for (int it = 0; it < count; it++) {
        const double mg = (it % 3 == 0) ? 0.04 : (it % 3 == 1 ? 0.0 : 0.4 * urand());
        cfpo_square S = {-mg, -mg, 1 + mg, 1 + mg};
        int m = 2 + (int)(urand() * (MAXM - 2));
        const char *name = "avx2-random";
        switch (it % 6) {
        case 0: /* uniform in the 3x3 block, any count up to MAXM */
            for (int j = 0; j < m; j++) { yx[j] = -1 + 3 * urand(); yy[j] = -1 + 3 * urand(); }
            break;
        case 1: { /* a lattice jittered by 10^-15 .. 10^-3: near-ties */
            name = "avx2-lattice";
            const double jit = pow(10.0, -15 + 12 * urand());
            m = 0;
            for (int a = -1; a <= 2; a++)
                for (int b = -1; b <= 2; b++) {
                    yx[m] = a * 0.5 + jit * (urand() - 0.5);
                    yy[m] = b * 0.5 + jit * (urand() - 0.5);
                    m++;
                }
            break;
        }
        case 2: { /* a point with a ring around it: a cell of up to MAXM - 1 sides */
            name = "avx2-many-sided";
            const double ox = 0.5 + 0.2 * (urand() - 0.5), oy = 0.5 + 0.2 * (urand() - 0.5);
            const double r = 0.05 + 0.5 * urand();
            yx[0] = ox;
            yy[0] = oy;
            for (int j = 1; j < m; j++) {
                const double a = (it % 12 == 2) ? 6.283185307179586 * j / (m - 1) : 6.283185307179586 * urand();
                yx[j] = ox + r * cos(a);
                yy[j] = oy + r * sin(a);
            }
            break;
        }
        case 3: /* on S's corners and edges, and duplicated */
            name = "avx2-boundary";
            for (int j = 0; j < m; j++) {
                const double c[3] = {S.x0, S.x1, S.x0 + (S.x1 - S.x0) * urand()};
                yx[j] = c[(int)(urand() * 3)];
                yy[j] = c[(int)(urand() * 3)];
                if (j > 0 && urand() < 0.2) { yx[j] = yx[j - 1]; yy[j] = yy[j - 1]; }
            }
            break;
        case 4: { /* the whole problem scaled: tiny and huge frames */
            name = "avx2-scaled";
            const double sc = pow(2.0, (int)(urand() * 120) - 60);
            S = (cfpo_square){S.x0 * sc, S.y0 * sc, S.x1 * sc, S.y1 * sc};
            for (int j = 0; j < m; j++) { yx[j] = (-1 + 3 * urand()) * sc; yy[j] = (-1 + 3 * urand()) * sc; }
            break;
        }
        default: { /* far from the origin: a frame offset by up to 10^6 */
            name = "avx2-offset";
            const double o = pow(10.0, 6 * urand());
            S = (cfpo_square){S.x0 + o, S.y0 - o, S.x1 + o, S.y1 - o};
            for (int j = 0; j < m; j++) { yx[j] = o - 1 + 3 * urand(); yy[j] = -o - 1 + 3 * urand(); }
            break;
        }
        }
        const double hx = S.x0 + (S.x1 - S.x0) * urand(), hy = S.y0 + (S.y1 - S.y0) * urand();
        double sc[10 * (MAXM + 8)], cx, cy;
        const double v = cfpo_local_solve_plain(yx, yy, m, -1, S, hx, hy, -1.0, &cx, &cy, sc);
        bad += same_all(yx, yy, m, S, hx, hy, v, name);
    }
    return bad;
}

int main(void)
{
    double yx[MAXM], yy[MAXM];
    int failures = 0, total = 0;
    avx2_ok = cfpo_solver_avx2_usable();
    avx512_ok = avx2_ok && cfpo_solver_avx512_usable();
    double worst_gap = 0;
    const double L = 1.0;
    for (int it = 0; it < 12000; it++) {
        int kind = it % 8;
        double margin = (it % 3 == 0) ? 0.04 : (it % 3 == 1 ? 0.0 : 0.3 * urand());
        cfpo_square S = {-margin * L, -margin * L, L + margin * L, L + margin * L};
        int m = 1 + (int)(urand() * 20);
        const char *name = "random";
        switch (kind) {
        case 0: /* uniform in the 3x3 block */
            for (int j = 0; j < m; j++) { yx[j] = -L + 3 * L * urand(); yy[j] = -L + 3 * L * urand(); }
            break;
        case 1: { /* jittered lattice, the usual CFPO neighbourhood */
            name = "lattice";
            m = 0;
            for (int a = -1; a <= 1; a++)
                for (int b = -1; b <= 1; b++) {
                    int c = 1 + (urand() < 0.25);
                    for (int t = 0; t < c && m < MAXM; t++) {
                        yx[m] = (a + urand()) * L;
                        yy[m] = (b + urand()) * L;
                        m++;
                    }
                }
            break;
        }
        case 2: { /* collinear */
            name = "collinear";
            double ox = L * urand(), oy = L * urand(), ang = 6.283185307179586 * urand();
            if (it % 16 == 2) ang = 0; /* axis-parallel line */
            for (int j = 0; j < m; j++) {
                double t = -1.5 + 3 * urand();
                yx[j] = ox + t * cos(ang);
                yy[j] = oy + t * sin(ang);
            }
            break;
        }
        case 3: { /* cocircular, centred in or near S */
            name = "cocircular";
            double ox = L * (0.5 + 0.2 * (urand() - 0.5)), oy = L * (0.5 + 0.2 * (urand() - 0.5));
            double r = 0.3 + urand();
            int regular = it % 16 == 3;
            for (int j = 0; j < m; j++) {
                double a = regular ? 6.283185307179586 * j / m : 6.283185307179586 * urand();
                yx[j] = ox + r * cos(a);
                yy[j] = oy + r * sin(a);
            }
            break;
        }
        case 4: /* on the boundary of S */
            name = "on-boundary";
            for (int j = 0; j < m; j++) {
                double t = S.x0 + (S.x1 - S.x0) * urand();
                switch ((int)(urand() * 4)) {
                case 0: yx[j] = S.x0; yy[j] = t; break;
                case 1: yx[j] = S.x1; yy[j] = t; break;
                case 2: yx[j] = t; yy[j] = S.y0; break;
                default: yx[j] = t; yy[j] = S.y1; break;
                }
            }
            break;
        case 5: /* very few neighbours */
            name = "few";
            m = 1 + it % 3;
            for (int j = 0; j < m; j++) { yx[j] = -L + 3 * L * urand(); yy[j] = -L + 3 * L * urand(); }
            break;
        case 6: /* duplicates and exact lattice (ties everywhere) */
            name = "degenerate";
            m = 0;
            for (int a = -1; a <= 1; a++)
                for (int b = -1; b <= 1; b++) {
                    yx[m] = (a + 0.5) * L;
                    yy[m] = (b + 0.5) * L;
                    m++;
                }
            if (it % 16 == 6) { yx[m] = yx[0]; yy[m] = yy[0]; m++; } /* a duplicate */
            if (it % 32 == 14) m = 8; /* hole at a lattice site */
            break;
        default: /* neighbourhood of a point near the torus seam, unwrapped */
            name = "seam";
            for (int j = 0; j < m; j++) {
                double gx = 1.0 - 1e-9 * urand() + (urand() - 0.5) * 2.5 * L / 64;
                double gy = 1e-9 * urand() + (urand() - 0.5) * 2.5 * L / 64;
                yx[j] = cfpo_torus_diff(gx, 1.0 - L / 64 / 2) * 64; /* local frame of the seam cell */
                yy[j] = cfpo_torus_diff(gy, 0.0) * 64;
            }
            break;
        }
        double hx = S.x0 + (S.x1 - S.x0) * urand(), hy = S.y0 + (S.y1 - S.y0) * urand();
        total++;
        if (check(yx, yy, m, S, hx, hy, name, &worst_gap)) failures++;
    }
    /* Empty Y: no point to be far from. */
    {
        double scratch[10 * 8], cx, cy;
        cfpo_square S = {0, 0, 1, 1};
        double v = cfpo_local_solve(yx, yy, 0, -1, S, 0.5, 0.5, -1, &cx, &cy, scratch);
        total++;
        if (!isinf(v)) { fprintf(stderr, "empty Y: expected +inf, got %g\n", v); failures++; }
        /* skip index removes the only point */
        yx[0] = 0.3; yy[0] = 0.3;
        v = cfpo_local_solve(yx, yy, 1, 0, S, 0.5, 0.5, -1, &cx, &cy, scratch);
        total++;
        if (!isinf(v)) { fprintf(stderr, "skip: expected +inf, got %g\n", v); failures++; }
    }
    /* Known answers: one point at a corner of the unit square -> opposite
     * corner; four points at the corners -> the centre. */
    {
        double scratch[10 * 16], cx, cy;
        cfpo_square S = {0, 0, 1, 1};
        double ax[4] = {0, 1, 1, 0}, ay[4] = {0, 0, 1, 1};
        double v = cfpo_local_solve(ax, ay, 1, -1, S, 0.5, 0.5, -1, &cx, &cy, scratch);
        total++;
        if (v != 2.0 || cx != 1.0 || cy != 1.0) { fprintf(stderr, "one point: got %g at (%g,%g)\n", v, cx, cy); failures++; }
        v = cfpo_local_solve(ax, ay, 4, -1, S, 0.1, 0.2, -1, &cx, &cy, scratch);
        total++;
        if (fabs(v - 0.5) > 1e-15 || fabs(cx - 0.5) > 1e-15 || fabs(cy - 0.5) > 1e-15) {
            fprintf(stderr, "four corners: got %g at (%g,%g)\n", v, cx, cy);
            failures++;
        }
    }
    {
        const int more = 200000, bad = avx2_more(more);
        total += more;
        failures += bad;
    }
    if (avx2_ok)
        printf("AVX2%s solver vs plain solver: %d calls compared bit for bit\n", avx512_ok ? " and AVX-512" : "",
               same_calls);
    else printf("AVX2 solver vs plain solver: not compared (no AVX2 on this CPU or build)\n");
    printf("solver vs brute force: %d configurations, worst solver-minus-brute gap %.3g (relative to |S|^2)\n",
           total, worst_gap);
    return test_report(total - failures, failures);
}
