/* test_farthest.c - an_farthest (the certificate's solver) against the
 * core's exact LocalCFPO solver and against brute force, on sets large
 * enough to take its grid path (more than AN_FAR_SMALL points): uniform,
 * clustered, collinear (horizontal, vertical, diagonal; and a segment
 * seen from one of its points, with and without it), repeated
 * positions, a cluster with far outliers, and squares inside, around and
 * far from the points. Must hold: the same farthest distance as the core
 * solver (to rounding), the returned point inside the square and at that
 * distance from the set, and no sampled point of the square farther.
 */
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
    an_far_free(&ws);
    free(x);
    free(y);
    return test_report(passed_, failed_);
}
