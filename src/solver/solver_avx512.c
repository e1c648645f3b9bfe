/* solver_avx512.c - LocalCFPO with AVX-512 (host only, x86-64): the same
 * answer, bit for bit, as cfpo_local_solve_hd of solver_impl.h and as the
 * AVX2 route of solver_avx2.c, whose proof of the bits this route shares.
 * geom.c picks it at run time where the CPU has AVX-512 F and DQ, AVX2
 * and BMI2.
 *
 * What differs from the AVX2 route is where a small polygon (up to 8
 * vertices) lives: in two 8-lane registers, x and y, from the first cut
 * of a cell to its last, instead of in memory. The AVX2 cut writes its
 * output vertex by vertex and the next cut reads it back a register at a
 * time, a load that cannot take its value from those narrower stores and
 * waits for them to reach the cache; on the cut's critical path that wait
 * costs about as much as the arithmetic. Here the output is assembled in
 * registers: the kept vertices and the crossings are interleaved in
 * vertex order (v0, crossing of edge 0, v1, ...) by two lane permutations,
 * each half compressed to its set lanes, and the upper half expanded in
 * after the lower. A polygon that grows past 8 vertices (rare) goes to
 * memory and the plain cut, as in the AVX2 route.
 *
 * The bits: every lane computes the side values, the crossing parameter
 * and the crossing point by the same operations in the same order as the
 * plain loop (no fused multiply-add: the build uses -ffp-contract=off and
 * these intrinsics are separate multiplies and adds), with the same tests
 * (<= 0 keeps a vertex, a strict sign change makes a crossing) and the
 * same output order, so every polygon is the same list of doubles. The
 * farthest vertex is a maximum of numbers that are never NaN (a NaN
 * distance leaves the running maximum as it was, as in the AVX2 route),
 * so its order does not matter; the final choice of the best vertex is
 * the plain loop's, in vertex order. */
#include "geom.h"

#include "solver_impl.h"
#include "solver_simd.h"
#include "solver_cut512.h"

#if CFPO_SOLVER_AVX2

#include <immintrin.h>
#include <string.h>

/* cfpo_solve_cells_hd of solver_impl.h, bit for bit (the structure of
 * cfpo_solve_cells_avx2, the small polygon in registers). */
T512 double cfpo_solve_cells_avx512(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                                   double hy, double floor2, double *cx, double *cy, double *scratch, int cells)
{
    const size_t cap = 2 * ((size_t)m + 8), half = (size_t)m + 8;
    double *px = scratch, *py = px + m, *key = py + m;
    double *bufa = key + m + 8, *bufb = bufa + cap, *sd = bufb + cap;
    int k = cfpo_order_by_hint_hd(yx, yy, m, skip, hx, hy, px, py, key, bufa);

    *cx = 0.5 * (S.x0 + S.x1);
    *cy = 0.5 * (S.y0 + S.y1);
    if (k == 0) return INFINITY;

    const double corner[4][2] = {{S.x0, S.y0}, {S.x1, S.y0}, {S.x1, S.y1}, {S.x0, S.y1}};
    const double A = fmax(fmax(fabs(S.x0), fabs(S.x1)), fmax(fabs(S.y0), fabs(S.y1)));
    const __m512d SX = _mm512_set_pd(0, 0, 0, 0, S.x0, S.x1, S.x1, S.x0);
    const __m512d SY = _mm512_set_pd(0, 0, 0, 0, S.y1, S.y1, S.y0, S.y0);
    double best = floor2;
    double bx = *cx, by = *cy;
    int found = 0;
    double spx[24], spy[24];

    const int kc = cells < k ? cells : k;
    for (int i = 0; i < kc; i++) {
        const double ax = px[i], ay = py[i];
        const double ub = cfpo_corner_far2_hd(corner, ax, ay);
        if (ub <= best) continue;
        if (cells > 1 && cfpo_simd_cell_empty(px, py, k, ax, ay, corner, A)) continue;

        /* The polygon: small (<= 8 vertices) in PX, PY; else in the
         * scratch buffers (x at 0, y at half). */
        __m512d PX = SX, PY = SY;
        double *x = bufa, *y = bufa + half, *ox = bufb, *oy = bufb + half;
        int small = 1, nv = 4, alive = 1;
        double far2 = ub;
        for (int j = 0; j < k && alive; j++) {
            if (j == i) continue;
            double nx, ny, mx, my;
            if (!cfpo_bisector_hd(px[j], py[j], ax, ay, far2, &nx, &ny, &mx, &my)) continue;
            int nn;
            if (small) {
                nn = cut8(&PX, &PY, nv, mx, my, nx, ny, ax, ay, spx, spy, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
                if (nn > 8) { /* move to the large buffers */
                    memcpy(x, spx, (size_t)nn * sizeof *spx);
                    memcpy(y, spy, (size_t)nn * sizeof *spy);
                    small = 0;
                }
            } else {
                nn = cfpo_simd_cut_large(x, y, nv, mx, my, nx, ny, ax, ay, sd, ox, oy, &far2);
                if (nn < 0) continue;
                if (nn == 0) { alive = 0; break; }
                double *t = x; x = ox; ox = t;
                t = y; y = oy; oy = t;
            }
            nv = nn;
            if (far2 <= best) alive = 0;
        }
        if (!alive) continue;
        if (small) {
            _mm512_storeu_pd(spx, PX);
            _mm512_storeu_pd(spy, PY);
            x = spx;
            y = spy;
        }
        found |= cfpo_simd_best_vertex(x, y, nv, ax, ay, &best, &bx, &by);
    }
    if (!found) return -1.0;
    return cfpo_solve_finish_hd(bx, by, S, yx, yy, m, skip, cx, cy);
}

int cfpo_solver_avx512_usable(void)
{
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt");
}

#else

double cfpo_solve_cells_avx512(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                               double hy, double floor2, double *cx, double *cy, double *scratch, int cells)
{
    return cfpo_solve_cells_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, cells);
}

int cfpo_solver_avx512_usable(void) { return 0; }

#endif

double cfpo_local_solve_avx512(const double *yx, const double *yy, int m, int skip, cfpo_square S, double hx,
                               double hy, double floor2, double *cx, double *cy, double *scratch)
{
    return cfpo_solve_cells_avx512(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch, m);
}
