/* test_farprep.c - the prepared solver (an_far_prep_*) against an_farthest
 * on the same set: with nothing left out, and with one copy of a position
 * left out (the certificate's second property), on clusters, clusters with
 * repeated positions, a uniform patch, a line and two clusters, for squares
 * that hold the set, cut it, or lie beside it. Must hold: the same farthest
 * distance (to rounding), the point inside the square at that distance
 * from the set; the prepared form must answer most left-out cases itself
 * (so the comparison is not empty), and must recognise only the very set
 * it was given. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "farthest.h"
#include "geom.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

/* The set without one copy of position e (index e of the set). */
static size_t without(const double *yx, const double *yy, size_t m, size_t e, double *ox, double *oy)
{
    size_t k = 0;
    for (size_t t = 0; t < m; t++)
        if (t != e) { ox[k] = yx[t]; oy[k] = yy[t]; k++; }
    return k;
}

static void compare(const char *what, const double *yx, const double *yy, size_t m, uint64_t seed, double least)
{
    an_far_prep P = {0};
    an_far_ws ws = {0}, ref = {0};
    double *ox = malloc(m * sizeof *ox), *oy = malloc(m * sizeof *oy);
    CHECK(an_far_prep_set(&P, yx, yy, m) == 0 && an_far_prep_build(&P) == 0, "%s: prepare", what);
    CHECK(an_far_prep_same(&P, yx, yy, m), "%s: its own set not recognised", what);
    size_t own = 0, tried = 0, bad = 0;
    for (int q = 0; q < 40; q++) {
        const size_t c = (size_t)(cfpo_rand01(seed, (uint64_t)q, 0) * (double)m) % m;
        /* 1e-3 .. 0.1, and for the last ten 1e-5 .. 1e-4: squares inside the
         * set, where the cells of the left-out point's neighbours decide. */
        const double half = q < 30 ? 1e-3 * pow(100.0, cfpo_rand01(seed, (uint64_t)q, 1))
                                   : 1e-5 * pow(10.0, cfpo_rand01(seed, (uint64_t)q, 1));
        const cfpo_square S = {yx[c] - half, yy[c] - half, yx[c] + half, yy[c] + half};
        double cx, cy, rx, ry;
        const double got = an_far_prep_solve(&P, S, 0, 0, 0, NULL, &cx, &cy, &ws);
        const double at[2] = {cx, cy};
        const double want = an_farthest(yx, yy, m, S, yx[c], yy[c], &rx, &ry, &ref);
        if (!(got >= 0 && fabs(sqrt(got) - sqrt(want)) <= 1e-12 * (2 * half + 1))) bad++;
        CHECK(cx >= S.x0 && cx <= S.x1 && cy >= S.y0 && cy <= S.y1, "%s: point outside the square", what);
        CHECK(fabs(cfpo_min_dist2(cx, cy, yx, yy, (int)m, -1) - got) <= 1e-15, "%s: value is not the point's distance",
              what);
        /* The centre's own point left out (as the certificate does), and
         * another point; from scratch and from the answer above. */
        for (int k = 0; k < 4; k++) {
            const size_t e = k % 2 == 0 ? c : (size_t)(cfpo_rand01(seed, (uint64_t)q, 2) * (double)m) % m;
            const size_t m2 = without(yx, yy, m, e, ox, oy);
            const double g2 = an_far_prep_solve(&P, S, 1, yx[e], yy[e], k < 2 ? NULL : at, &cx, &cy, &ws);
            tried++;
            if (g2 == -3) continue;
            own++;
            const double w2 = an_farthest(ox, oy, m2, S, yx[e], yy[e], &rx, &ry, &ref);
            if (!(g2 >= 0 && fabs(sqrt(g2) - sqrt(w2)) <= 1e-12 * (2 * half + 1))) {
                bad++;
                fprintf(stderr, "  %s: square %d, point %zu left out: %.17g against %.17g\n", what, q, e, sqrt(g2),
                        sqrt(w2));
            }
            CHECK(fabs(cfpo_min_dist2(cx, cy, ox, oy, (int)m2, -1) - g2) <= 1e-15,
                  "%s: left-out value is not the point's distance", what);
        }
    }
    CHECK(bad == 0, "%s: %zu answers differ from an_farthest", what, bad);
    CHECK((double)own >= least * (double)tried, "%s: the prepared form answered only %zu of %zu left-out cases", what,
          own, tried);
    printf("%-28s m=%-5zu prepared answered %zu of %zu left-out cases\n", what, m, own, tried);
    ox[0] = yx[0];
    CHECK(an_far_prep_same(&P, yx, yy, m) && !an_far_prep_same(&P, yx, yy, m - 1), "%s: sameness by length", what);
    for (size_t t = 0; t < m; t++) { ox[t] = yx[t]; oy[t] = yy[t]; }
    ox[m / 2] = nextafter(ox[m / 2], 1.0);
    CHECK(!an_far_prep_same(&P, ox, oy, m), "%s: a moved point not noticed", what);
    an_far_prep_free(&P);
    an_far_free(&ws);
    an_far_free(&ref);
    free(ox);
    free(oy);
}

int main(void)
{
    const size_t N = 1000;
    double *yx = malloc(N * sizeof *yx), *yy = malloc(N * sizeof *yy);
    for (size_t i = 0; i < N; i++) {
        yx[i] = 0.5 + 1e-3 * cfpo_rand01(3, i, 0);
        yy[i] = 0.5 + 1e-3 * cfpo_rand01(3, i, 1);
    }
    compare("cluster 1e-3", yx, yy, 300, 11, 0.75);
    compare("cluster 1e-3", yx, yy, 1000, 12, 0.75);
    for (size_t i = 0; i < 400; i++) { yx[i] = yx[i % 150]; yy[i] = yy[i % 150]; }
    compare("cluster, repeated positions", yx, yy, 400, 13, 0.75);
    for (size_t i = 0; i < 400; i++) {
        yx[i] = 0.4 + 0.2 * cfpo_rand01(4, i, 0);
        yy[i] = 0.4 + 0.2 * cfpo_rand01(4, i, 1);
    }
    compare("uniform patch", yx, yy, 400, 14, 0.75);
    for (size_t i = 0; i < 300; i++) { yx[i] = 0.3 + 1e-3 * (double)i; yy[i] = 0.5; }
    compare("line", yx, yy, 300, 15, 0); /* every cell of a line is a strip: never bounded */
    for (size_t i = 0; i < 400; i++) {
        const double o = i % 2 ? 0.02 : 0;
        yx[i] = 0.5 + o + 1e-3 * cfpo_rand01(5, i, 0);
        yy[i] = 0.5 + o + 1e-3 * cfpo_rand01(5, i, 1);
    }
    compare("two clusters", yx, yy, 400, 16, 0.75);
    for (size_t i = 0; i < 400; i++) { /* every cell unbounded: left-out cases are not for the prepared form */
        yx[i] = 0.5 + 0.005 * cos(6.283185307179586 * (double)i / 400);
        yy[i] = 0.5 + 0.005 * sin(6.283185307179586 * (double)i / 400);
    }
    compare("circle", yx, yy, 400, 17, 0);
    free(yx);
    free(yy);
    return test_report(passed_, failed_);
}
