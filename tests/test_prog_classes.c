/* test_prog_classes.c - the classes of `--classes K` by colouring
 * (src/prog_colour.c) and the class-aware joint move (src/prog_joint.c,
 * classes) against brute force on the torus:
 *  - the colouring keeps the set (the same points, sorted) and gives each
 *    class its size; it lowers the close same-class pairs; the same bytes
 *    twice;
 *  - its last step (the classes back to their sizes) by the tournament
 *    tree makes the relabels of the reference scan of every point: the
 *    same bytes, on sets where it relabels points (equal and unequal
 *    class sizes), each class its size and every point kept once;
 *  - the class move, with circumcentres, the local ascent and class swaps:
 *    after every sweep (brute force from the points as they are) each
 *    class's delta_min in its own Delta(n/K) never falls, nor the union's
 *    in Delta(n) (no union floor), or the union's never below min(its
 *    value, the floor) (with one); the sweep's reported measures are the
 *    brute force's; some class rises; the same bytes for 1, 2 and 3
 *    threads;
 *  - the check can fail: two points of one class put close lower the
 *    class's delta_min. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "prog_colour.h"
#include "prog_joint.h"
#include "rng.h"
#include "test_spread.h"
#include "testutil.h"

static int passed_, failed_;

/* delta_min of the points [lo, hi) in Delta(hi - lo). */
static double dmin_of(const double *xy, int64_t lo, int64_t hi)
{
    double b = INFINITY;
    for (int64_t i = lo; i < hi; i++)
        for (int64_t j = i + 1; j < hi; j++) b = fmin(b, tu_torus_dist(xy + 2 * i, xy + 2 * j));
    return b / cfpo_delta_bound((double)(hi - lo));
}

/* Each class's delta_min, then the union's (K + 1 values). */
static void brute(const double *xy, const int64_t *sizes, int K, double *dm)
{
    for (int c = 0; c < K; c++) dm[c] = dmin_of(xy, c ? sizes[c - 1] : 0, sizes[c]);
    dm[K] = dmin_of(xy, 0, sizes[K - 1]);
}

typedef struct {
    const double *xy;
    const int64_t *sizes;
    int K;
    double floor; /* the union's floor (0: none) */
    double start[9], last[9];
    int sweeps, fell, mismatch;
    int64_t moved;
} watch;

static void on_sweep(int sweep, int64_t moved, const double *dmin, const double *davg, int NG, void *user)
{
    (void)davg;
    watch *w = user;
    double bm[9];
    brute(w->xy, w->sizes, w->K, bm);
    for (int k = 0; k < NG; k++) {
        if (fabs(bm[k] - dmin[k]) > 1e-12) w->mismatch++;
        const double lo = k == w->K && w->floor > 0 ? fmin(w->last[k], w->floor) : w->last[k];
        if (sweep > 0 && bm[k] < lo * (1 - 1e-12)) w->fell++;
        if (sweep == 0) w->start[k] = bm[k];
        w->last[k] = bm[k];
    }
    w->sweeps = sweep;
    w->moved += moved;
}

static int cmp_pt(const void *a, const void *b)
{
    const double *p = a, *q = b;
    return p[0] < q[0] ? -1 : p[0] > q[0] ? 1 : p[1] < q[1] ? -1 : p[1] > q[1];
}

int main(void)
{
    char err[256];
    enum { N = 400, K = 4 };
    static const int64_t sizes[K] = {100, 200, 300, 400};
    double *xy = malloc(2 * N * sizeof *xy), *xy0 = malloc(2 * N * sizeof *xy0), *again = malloc(2 * N * sizeof *again);
    double *a = malloc(2 * N * sizeof *a), *b = malloc(2 * N * sizeof *b);
    /* the colouring */
    tu_spread(xy0, N, 3);
    memcpy(xy, xy0, 2 * N * sizeof *xy);
    cfpo_prog_colour_options co = {0};
    CHECK(cfpo_prog_colour(xy, sizes, K, &co, err, sizeof err) == 0, "colour failed: %s", err);
    memcpy(a, xy0, 2 * N * sizeof *a);
    memcpy(b, xy, 2 * N * sizeof *b);
    qsort(a, N, 2 * sizeof *a, cmp_pt);
    qsort(b, N, 2 * sizeof *b, cmp_pt);
    CHECK(memcmp(a, b, 2 * N * sizeof *a) == 0, "the colouring changed the set");
    CHECK(co.close_end <= co.close_start, "the local passes raised the close pairs (%lld -> %lld)",
          (long long)co.close_start, (long long)co.close_end);
    double bm[K + 1], b0[K + 1];
    brute(xy, sizes, K, bm);
    memcpy(again, xy0, 2 * N * sizeof *again); /* id-order blocks of the grid: a poor colouring */
    brute(again, sizes, K, b0);
    double wc = INFINITY, w0 = INFINITY;
    for (int c = 0; c < K; c++) wc = fmin(wc, bm[c]), w0 = fmin(w0, b0[c]);
    CHECK(wc > w0, "the colouring's worst class %.3f is not above that of id-order blocks %.3f", wc, w0);
    CHECK(fabs(bm[K] - b0[K]) < 1e-12, "the colouring changed the union's delta_min");
    memcpy(again, xy0, 2 * N * sizeof *again);
    cfpo_prog_colour_options co2 = {0};
    cfpo_prog_colour(again, sizes, K, &co2, err, sizeof err);
    CHECK(memcmp(again, xy, 2 * N * sizeof *xy) == 0, "the colouring: not the same bytes twice");
    memcpy(xy0, xy, 2 * N * sizeof *xy0); /* the coloured start of the moves */

    /* the sizes restored by the tree: the reference scan's relabels */
    {
        enum { NR = 6000 };
        static const int64_t eq[K] = {1500, 3000, 4500, 6000}, uneq[3] = {900, 3000, 6000};
        double *init = malloc(2 * NR * sizeof *init), *ref = malloc(2 * NR * sizeof *ref),
               *alt = malloc(2 * NR * sizeof *alt), *sa = malloc(2 * NR * sizeof *sa), *sb = malloc(2 * NR * sizeof *sb);
        int64_t relabels = 0;
        for (int t = 0; t < 6; t++) {
            const int k = t % 2 ? 3 : K;
            const int64_t *sz = t % 2 ? uneq : eq;
            tu_spread(init, NR, 20 + (uint64_t)t);
            memcpy(ref, init, 2 * NR * sizeof *ref);
            memcpy(alt, init, 2 * NR * sizeof *alt);
            cfpo_prog_colour_options cs = {.restore_scan = 1, .reach = 1.0 + 0.1 * t}, ct = {.reach = 1.0 + 0.1 * t};
            CHECK(cfpo_prog_colour(ref, sz, k, &cs, err, sizeof err) == 0, "colour (scan) failed: %s", err);
            CHECK(cfpo_prog_colour(alt, sz, k, &ct, err, sizeof err) == 0, "colour (tree) failed: %s", err);
            CHECK(cs.restores == ct.restores, "set %d: %lld relabels by the scan, %lld by the tree", t,
                  (long long)cs.restores, (long long)ct.restores);
            CHECK(memcmp(ref, alt, 2 * NR * sizeof *ref) == 0, "set %d: the tree's colouring is not the scan's bytes", t);
            memcpy(sa, init, 2 * NR * sizeof *sa);
            memcpy(sb, alt, 2 * NR * sizeof *sb);
            qsort(sa, NR, 2 * sizeof *sa, cmp_pt);
            qsort(sb, NR, 2 * sizeof *sb, cmp_pt);
            CHECK(memcmp(sa, sb, 2 * NR * sizeof *sa) == 0, "set %d: a point lost or doubled (or a class not its size)", t);
            relabels += ct.restores;
        }
        CHECK(relabels >= 20, "only %lld relabels to restore the sizes: the check is empty", (long long)relabels);
        free(init);
        free(ref);
        free(alt);
        free(sa);
        free(sb);
    }

    /* the class move: no class falls, the union not below min(its value, floor) */
    static const double floors[3] = {0, 0.80, 0};
    for (int s = 0; s < 3; s++) {
        memcpy(xy, xy0, 2 * N * sizeof *xy);
        watch w = {.xy = xy, .sizes = sizes, .K = K, .floor = floors[s]};
        cfpo_prog_joint_options jo = {.sweeps = 8, .classes = 1, .circum = s == 2 ? 0 : 10, .solve = s == 2 ? 0 : 8,
                                      .swaps = 8, .pairs = s == 1 ? 4 : 0, .floor = floors[s], .target_prefix = 0.80,
                                      .target_full = 0.88,
                                      .seed = 5 + (uint64_t)s, .sweep_done = on_sweep, .user = &w};
        double dm[K + 1], da[K + 1];
        CHECK(cfpo_prog_joint(xy, sizes, K, &jo, dm, da, err, sizeof err) == 0, "class move failed: %s", err);
        CHECK(w.mismatch == 0, "setting %d: the sweep's measures differ from brute force", s);
        CHECK(w.fell == 0, "setting %d: a class's or the union's delta_min fell during a sweep", s);
        CHECK(w.sweeps >= 1 && w.moved > 0, "setting %d: %d sweeps, %lld moves", s, w.sweeps, (long long)w.moved);
        double rise = 0;
        for (int c = 0; c < K; c++) rise = fmax(rise, w.last[c] - w.start[c]);
        CHECK(rise > 0, "setting %d: no class rose", s);
        if (floors[s] > 0)
            CHECK(w.last[K] >= fmin(w.start[K], floors[s]) * (1 - 1e-12), "setting %d: the union fell below its floor", s);
    }
    /* the same bytes for 1, 2 and 3 threads (4,000 points, swaps on) */
    {
        enum { NB = 4000 };
        static const int64_t big[K] = {1000, 2000, 3000, 4000};
        double *ref = malloc(2 * NB * sizeof *ref), *alt = malloc(2 * NB * sizeof *alt), *init = malloc(2 * NB * sizeof *init);
        tu_spread(init, NB, 9);
        cfpo_prog_colour_options cb = {0};
        CHECK(cfpo_prog_colour(init, big, K, &cb, err, sizeof err) == 0, "colour failed: %s", err);
        cfpo_prog_joint_options jo = {.sweeps = 3, .classes = 1, .circum = 8, .solve = 6, .swaps = 8, .floor = 0.8,
                                      .target_prefix = 0.80, .target_full = 0.88, .seed = 9, .threads = 1};
        double dm[K + 1], da[K + 1];
        memcpy(ref, init, 2 * NB * sizeof *ref);
        CHECK(cfpo_prog_joint(ref, big, K, &jo, dm, da, err, sizeof err) == 0, "class move (1 thread) failed: %s", err);
        CHECK(memcmp(init, ref, 2 * NB * sizeof *ref) != 0, "the 4,000-point class move moved nothing");
        for (int t = 2; t <= 3; t++) {
            memcpy(alt, init, 2 * NB * sizeof *alt);
            jo.threads = t;
            CHECK(cfpo_prog_joint(alt, big, K, &jo, dm, da, err, sizeof err) == 0, "class move (%d threads) failed: %s",
                  t, err);
            CHECK(memcmp(alt, ref, 2 * NB * sizeof *ref) == 0, "%d threads: not the bytes of 1 thread", t);
        }
        free(ref);
        free(alt);
        free(init);
    }
    /* the check can fail: a point put next to one of its class lowers the class */
    {
        double before[K + 1], after[K + 1];
        brute(xy, sizes, K, before);
        xy[2 * 150] = xy[2 * 120] + 1e-4;
        xy[2 * 150 + 1] = xy[2 * 120 + 1];
        brute(xy, sizes, K, after);
        CHECK(after[1] < before[1], "a point moved onto one of its class did not lower the class");
    }
    free(xy);
    free(xy0);
    free(again);
    free(a);
    free(b);
    return test_report(passed_, failed_);
}
