/* test_arcs.c - the boundary-arc bookkeeping against a dense scan of the
 * circle: a sampled angle is on a free arc exactly when no neighbour disk
 * covers it (away from the arcs' ends), the total matches the scan's
 * measure, and arcs_pick always lands on a free arc. Also wrapping
 * intervals and the periodic images of the neighbours. */
#include <math.h>

#include "arcs.h"
#include "geom.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static int on_arcs(const arcs *A, double phi)
{
    for (int i = 0; i < A->m; i++)
        if (phi >= A->lo[i] && phi <= A->hi[i]) return 1;
    return 0;
}

int main(void)
{
    const double TWO_PI = 6.283185307179586;
    /* Remove across angle 0: [5.5, 7] means [5.5, 2 pi] and [0, 0.717]. */
    arcs A;
    arcs_full(&A);
    arcs_remove(&A, 5.5, 7.0);
    CHECK(A.m == 1 && fabs(A.lo[0] - (7.0 - TWO_PI)) < 1e-15 && fabs(A.hi[0] - 5.5) < 1e-15,
          "wrapping removal: m=%d [%g, %g]", A.m, A.lo[0], A.hi[0]);
    arcs_remove(&A, 1.0, 2.0);
    CHECK(A.m == 2 && fabs(arcs_total(&A) - (5.5 - (7.0 - TWO_PI) - 1.0)) < 1e-14, "split");
    arcs_remove(&A, -1.0, 6.0);
    CHECK(A.m == 0, "all removed: m=%d", A.m);

    for (uint64_t t = 0; t < 200; t++) {
        const double rho = 0.05;
        /* s near a corner of the torus so neighbours wrap. */
        double sx = cfpo_wrap01(0.98 + 0.04 * cfpo_rand01(9, t, 0));
        double sy = cfpo_wrap01(0.98 + 0.04 * cfpo_rand01(9, t, 1));
        int k = 1 + (int)(cfpo_rand01(9, t, 2) * 8);
        double qx[8], qy[8];
        arcs_full(&A);
        for (int j = 0; j < k; j++) {
            double ang = TWO_PI * cfpo_rand01(9, t, 10 + 2 * (uint64_t)j);
            double d = rho * (1.0 + 1.2 * cfpo_rand01(9, t, 11 + 2 * (uint64_t)j));
            qx[j] = cfpo_wrap01(sx + d * cos(ang));
            qy[j] = cfpo_wrap01(sy + d * sin(ang));
            arcs_cover(&A, sx, sy, qx[j], qy[j], rho);
        }
        const int M = 20000;
        int agree = 1, free_count = 0;
        for (int i = 0; i < M; i++) {
            double phi = (i + 0.5) * TWO_PI / M;
            double px = sx + rho * cos(phi), py = sy + rho * sin(phi);
            double mind = INFINITY;
            for (int j = 0; j < k; j++) {
                double dx = cfpo_torus_diff(qx[j], px), dy = cfpo_torus_diff(qy[j], py);
                mind = fmin(mind, sqrt(dx * dx + dy * dy));
            }
            int is_free = mind > rho;
            free_count += is_free;
            if (fabs(mind - rho) > 1e-9 * rho && is_free != on_arcs(&A, phi)) agree = 0;
        }
        CHECK(agree, "trial %llu: arcs disagree with the scan", (unsigned long long)t);
        CHECK(fabs(arcs_total(&A) - TWO_PI * free_count / M) < 2.0 * TWO_PI * k / M + 1e-12,
              "trial %llu: total %g vs scan %g", (unsigned long long)t, arcs_total(&A),
              TWO_PI * free_count / M);
        int picks_ok = 1;
        if (A.m > 0)
            for (int i = 0; i < 100; i++) picks_ok &= on_arcs(&A, arcs_pick(&A, i / 100.0));
        CHECK(picks_ok, "trial %llu: a pick left the arcs", (unsigned long long)t);
    }
    return test_report(passed_, failed_);
}
