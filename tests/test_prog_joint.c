/* test_prog_joint.c - the bounded joint move of a progressive set
 * (src/prog_joint.c) against brute force on the torus:
 *  - cfpo_prog_measure (src/prog_measure.c): every prefix's delta_min and delta_avg, each in its
 *    own Delta(m), equal the O(m^2) values;
 *  - cfpo_prog_joint: after every sweep (the callback, measured again by
 *    brute force from the points as they are) no prefix's delta_min is
 *    below its value after the sweep before, for several targets, with and
 *    without the hold distance; with hold H, no point's nearest distance in
 *    any prefix falls below the smaller of its start value and H Delta(m);
 *    the points do move and the full set rises; the same bytes twice;
 *    also with the local solve, the delta_avg term of the score, the soft
 *    minimum, the circumcentre candidates and the pair moves (setting 7);
 *  - the same bytes for 1, 2 and 3 threads (the coloured cells, 4,000
 *    points, the local solve and the delta_avg term on);
 *  - the polish (floor > 0): after every sweep, by brute force, each
 *    prefix below the full set is at or above the smaller of its value at
 *    the polish's start and the floor, and the full set's delta_min never
 *    falls; some prefix does fall below its start (the floor is not the
 *    joint move's) and the full set rises; the same bytes for 1-3 threads;
 *  - the monotonicity check can fail: a set with one point moved onto its
 *    neighbour is caught. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "prog_joint.h"
#include "prog_measure.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

/* Point i's nearest distance within the first m points. */
static double nn(const double *xy, int64_t m, int64_t i)
{
    double b = INFINITY;
    for (int64_t j = 0; j < m; j++)
        if (j != i && tu_torus_dist(xy + 2 * i, xy + 2 * j) < b) b = tu_torus_dist(xy + 2 * i, xy + 2 * j);
    return b;
}

static void brute(const double *xy, const int64_t *sizes, int K, double *dmin, double *davg)
{
    for (int k = 0; k < K; k++) {
        double lo = INFINITY, sum = 0;
        for (int64_t i = 0; i < sizes[k]; i++) {
            const double d = nn(xy, sizes[k], i);
            lo = d < lo ? d : lo;
            sum += d;
        }
        const double D = cfpo_delta_bound((double)sizes[k]);
        dmin[k] = lo / D;
        davg[k] = sum / (double)sizes[k] / D;
    }
}

typedef struct {
    const double *xy;
    const int64_t *sizes;
    int K;
    double last[8];
    int sweeps, fell, mismatch;
    int64_t moved;
} watch;

static void on_sweep(int sweep, int64_t moved, const double *dmin, const double *davg, int K, void *user)
{
    watch *w = user;
    double bm[8], ba[8];
    brute(w->xy, w->sizes, K, bm, ba);
    for (int k = 0; k < K; k++) {
        if (fabs(bm[k] - dmin[k]) > 1e-12 || fabs(ba[k] - davg[k]) > 1e-12) w->mismatch++;
        if (sweep > 0 && bm[k] < w->last[k]) w->fell++;
        w->last[k] = bm[k];
    }
    w->sweeps = sweep;
    w->moved += moved;
}

/* The polish's watch: the full set as on_sweep's (it never falls), each
 * smaller prefix against min(its start, the floor). */
typedef struct {
    watch w;
    const double *start;
    double floor;
    int below;
} pw_watch;

static void on_polish_sweep(int sweep, int64_t moved, const double *dmin, const double *davg, int K, void *user)
{
    pw_watch *p = user;
    double bm[8], ba[8];
    brute(p->w.xy, p->w.sizes, K, bm, ba);
    for (int k = 0; k < K; k++) {
        if (fabs(bm[k] - dmin[k]) > 1e-12 || fabs(ba[k] - davg[k]) > 1e-12) p->w.mismatch++;
        if (k < K - 1 && bm[k] < fmin(p->start[k], p->floor) * (1 - 1e-12)) p->below++;
    }
    if (sweep > 0 && bm[K - 1] < p->w.last[K - 1]) p->w.fell++;
    p->w.last[K - 1] = bm[K - 1];
    p->w.sweeps = sweep;
    p->w.moved += moved;
}

static void uniform(double *xy, int64_t n, uint64_t seed)
{
    for (int64_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(seed, 7, (uint64_t)i);
}

int main(void)
{
    static const int64_t sizes[5] = {32, 64, 128, 256, 400};
    const int K = 5, n = 400;
    double *xy = malloc(2 * n * sizeof *xy), *xy0 = malloc(2 * n * sizeof *xy0), *again = malloc(2 * n * sizeof *again);
    char err[128];
    /* the measure against brute force */
    {
        uniform(xy, n, 3);
        double dm[5], da[5], bm[5], ba[5];
        CHECK(cfpo_prog_measure(xy, sizes, K, dm, da, err, sizeof err) == 0, "measure failed: %s", err);
        brute(xy, sizes, K, bm, ba);
        int same = 1;
        for (int k = 0; k < K; k++) same &= fabs(dm[k] - bm[k]) <= 1e-12 && fabs(da[k] - ba[k]) <= 1e-12;
        CHECK(same, "cfpo_prog_measure differs from brute force");
    }
    /* the joint move: no prefix's delta_min falls, for several settings */
    /* target_prefix, target_full, hold, solve steps, avg weight, soft temperature, circumcentre neighbours */
    static const double set[8][7] = {{0.78, 0.90, 0, 0, 0, 0, 0},    {0.5, 0.7, 0, 0, 0, 0, 0},
                                     {0.78, 0.90, 0.86, 0, 0, 0, 0}, {1.0, 1.2, 0.5, 0, 0, 0, 0},
                                     {0.78, 0.90, 0, 8, 0, 0, 0},    {0.78, 0.90, 0, 4, 1.0, 0, 0},
                                     {0.78, 0.90, 0, 0, 0, 0.03, 8}, {0.78, 0.90, 0, 0, 0, 0, 0}};
    for (int c = 0; c < 8; c++) {
        uniform(xy0, n, 10 + (uint64_t)c);
        memcpy(xy, xy0, 2 * n * sizeof *xy);
        watch w = {.xy = xy, .sizes = sizes, .K = K};
        cfpo_prog_joint_options jo = {.sweeps = 6, .target_prefix = set[c][0], .target_full = set[c][1],
                                      .hold = set[c][2], .solve = (int)set[c][3], .avg = set[c][4],
                                      .soft = set[c][5], .circum = (int)set[c][6],
                                      .pairs = c == 7 ? 8 : 0, .seed = 5,
                                      .sweep_done = on_sweep, .user = &w};
        double dm[5], da[5], start[5], sa[5];
        brute(xy0, sizes, K, start, sa);
        CHECK(cfpo_prog_joint(xy, sizes, K, &jo, dm, da, err, sizeof err) == 0, "joint failed: %s", err);
        CHECK(w.mismatch == 0, "setting %d: the sweep's measures differ from brute force", c);
        CHECK(w.fell == 0, "setting %d: a prefix's delta_min fell during a sweep", c);
        CHECK(w.sweeps == 6 && w.moved > 0, "setting %d: %d sweeps, %lld moves", c, w.sweeps, (long long)w.moved);
        CHECK(dm[K - 1] > start[K - 1], "setting %d: the full set did not rise (%.4f -> %.4f)", c, start[K - 1],
              dm[K - 1]);
        if (set[c][2] > 0) { /* the hold: every point's nearest distance in each prefix */
            int held = 1;
            for (int k = 0; k < K; k++) {
                const double H = set[c][2] * cfpo_delta_bound((double)sizes[k]);
                for (int64_t i = 0; i < sizes[k]; i++) {
                    const double a = nn(xy0, sizes[k], i), b = nn(xy, sizes[k], i);
                    if (b < fmin(a, H) * (1 - 1e-12)) held = 0;
                }
            }
            CHECK(held, "setting %d: a point's nearest distance fell below its hold", c);
        }
        memcpy(again, xy0, 2 * n * sizeof *again);
        jo.sweep_done = NULL;
        cfpo_prog_joint(again, sizes, K, &jo, dm, da, err, sizeof err);
        CHECK(memcmp(again, xy, 2 * n * sizeof *xy) == 0, "setting %d: not the same bytes twice", c);
    }
    /* the same bytes for 1, 2 and 3 threads */
    {
        static const int64_t big[5] = {250, 500, 1000, 2000, 4000};
        const int64_t nb = 4000;
        double *ref = malloc(2 * nb * sizeof *ref), *alt = malloc(2 * nb * sizeof *alt), dm[5], da[5];
        uniform(ref, nb, 21);
        memcpy(alt, ref, 2 * nb * sizeof *alt);
        cfpo_prog_joint_options jo = {
            .sweeps = 3, .solve = 4, .avg = 0.5, .soft = 0.03, .circum = 6, .pairs = 4, .seed = 9, .threads = 1};
        CHECK(cfpo_prog_joint(ref, big, 5, &jo, dm, da, err, sizeof err) == 0, "joint (1 thread) failed: %s", err);
        double *init = malloc(2 * nb * sizeof *init);
        uniform(init, nb, 21);
        CHECK(memcmp(init, ref, 2 * nb * sizeof *ref) != 0, "the 4,000-point move moved nothing");
        for (int t = 2; t <= 3; t++) {
            memcpy(alt, init, 2 * nb * sizeof *alt);
            jo.threads = t;
            CHECK(cfpo_prog_joint(alt, big, 5, &jo, dm, da, err, sizeof err) == 0, "joint (%d threads) failed: %s", t, err);
            CHECK(memcmp(alt, ref, 2 * nb * sizeof *ref) == 0, "%d threads: not the bytes of 1 thread", t);
        }
        free(init);
        free(ref);
        free(alt);
    }
    /* the polish: the prefixes below the full set may fall to the floor, no further */
    {
        uniform(xy0, n, 40);
        cfpo_prog_joint_options pre = {.sweeps = 30, .seed = 6};
        double dm[5], da[5], start[5], sa[5];
        CHECK(cfpo_prog_joint(xy0, sizes, K, &pre, dm, da, err, sizeof err) == 0, "joint failed: %s", err);
        brute(xy0, sizes, K, start, sa);
        double fl = INFINITY; /* a floor below some prefix, so that it may fall */
        for (int k = 0; k < K - 1; k++) fl = fmin(fl, start[k]);
        fl += 0.02;
        memcpy(xy, xy0, 2 * n * sizeof *xy);
        pw_watch pw = {.w = {.xy = xy, .sizes = sizes, .K = K}, .start = start, .floor = fl};
        cfpo_prog_joint_options jo = {.sweeps = 10, .floor = fl, .seed = 8, .sweep_done = on_polish_sweep, .user = &pw};
        CHECK(cfpo_prog_joint(xy, sizes, K, &jo, dm, da, err, sizeof err) == 0, "polish failed: %s", err);
        CHECK(pw.w.mismatch == 0, "polish: the sweep's measures differ from brute force");
        CHECK(pw.below == 0, "polish: a prefix fell below min(its start, the floor %.3f)", fl);
        CHECK(pw.w.fell == 0, "polish: the full set's delta_min fell during a sweep");
        CHECK(dm[K - 1] > start[K - 1], "polish: the full set did not rise (%.4f -> %.4f)", start[K - 1], dm[K - 1]);
        int gave = 0;
        for (int k = 0; k < K - 1; k++) gave |= dm[k] < start[k];
        CHECK(gave, "polish: no prefix gave up delta_min (the floor was not used)");
        static const int64_t big[5] = {250, 500, 1000, 2000, 4000};
        const int64_t nb = 4000;
        double *ref = malloc(2 * nb * sizeof *ref), *alt = malloc(2 * nb * sizeof *alt);
        double *init = malloc(2 * nb * sizeof *init);
        uniform(init, nb, 23);
        cfpo_prog_joint_options po = {.sweeps = 3, .floor = 0.5, .seed = 4, .threads = 1};
        memcpy(ref, init, 2 * nb * sizeof *ref);
        CHECK(cfpo_prog_joint(ref, big, 5, &po, dm, da, err, sizeof err) == 0, "polish (1 thread) failed: %s", err);
        CHECK(memcmp(init, ref, 2 * nb * sizeof *ref) != 0, "the 4,000-point polish moved nothing");
        for (int t = 2; t <= 3; t++) {
            memcpy(alt, init, 2 * nb * sizeof *alt);
            po.threads = t;
            CHECK(cfpo_prog_joint(alt, big, 5, &po, dm, da, err, sizeof err) == 0, "polish (%d threads) failed: %s", t,
                  err);
            CHECK(memcmp(alt, ref, 2 * nb * sizeof *ref) == 0, "polish, %d threads: not the bytes of 1 thread", t);
        }
        free(init);
        free(ref);
        free(alt);
    }
    /* the check can fail: a point put next to its neighbour lowers a prefix */
    {
        double before[5], after[5], a2[5];
        brute(xy, sizes, K, before, a2);
        xy[2 * 40] = xy[2 * 3] + 1e-4;
        xy[2 * 40 + 1] = xy[2 * 3 + 1];
        brute(xy, sizes, K, after, a2);
        int fell = 0;
        for (int k = 0; k < K; k++) fell |= after[k] < before[k];
        CHECK(fell, "a point moved onto its neighbour did not lower any prefix");
    }
    free(xy);
    free(xy0);
    free(again);
    return test_report(passed_, failed_);
}
