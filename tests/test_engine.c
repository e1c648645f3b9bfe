/* test_engine.c - the grid, the stratified start and the engine.
 *
 * Properties: g obeys DESIGN.md's constraints for every n; the start puts
 * 1 or 2 points in every cell with unique ids; the Feistel permutation is
 * a bijection; delta(X) never decreases after any phase; outputs are
 * byte-identical for 1, 2, 3 and 4 threads and with skipping on or off;
 * different seeds differ; the engine's statistics equal brute force;
 * cfpo_sample equals the engine; small n work or are refused cleanly. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "engine.h"
#include "grid.h"
#include "rng.h"
#include "start.h"
#include "stats.h"
#include "testutil.h"

static int passed_, failed_;

static void brute_deltas(const double *xy, int64_t n, double *dmin, double *davg)
{
    double mn = INFINITY, sum = 0;
    for (int64_t i = 0; i < n; i++) {
        double best = INFINITY;
        for (int64_t j = 0; j < n; j++)
            if (j != i) best = fmin(best, cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]));
        best = sqrt(best);
        mn = fmin(mn, best);
        sum += best;
    }
    double D = cfpo_delta_bound((double)n);
    *dmin = mn / D;
    *davg = sum / (double)n / D;
}

static void test_grid_choice(void)
{
    int bad = 0;
    for (int variant = 0; variant < 3; variant++)
        for (int64_t n = 1; n < 200000; n += (n < 2000 ? 1 : n / 97)) {
            cfpo_grid G;
            char err[256];
            int rc = cfpo_grid_init(&G, n, variant, 1, err, sizeof err);
            if (n < cfpo_grid_min_n(variant)) {
                if (rc == 0 || strstr(err, "too small") == NULL) bad++;
                continue;
            }
            if (rc != 0) { bad++; continue; }
            if (G.g % G.period != 0 || !(G.L > G.delta) || G.g * G.g > n) bad++;
            if (variant == CFPO_VARIANT_SIMPLIFIED && G.g < 4) bad++;
            /* g^2 within one multiple-of-period step of 0.8 n */
            double ideal = sqrt(0.8 * (double)n);
            if (n > 1000 && fabs((double)G.g - ideal) > G.period + 0.5) bad++;
        }
    CHECK(bad == 0, "grid choice violated a constraint %d times", bad);
}

static void test_permutation(void)
{
    uint64_t Ns[] = {1, 2, 3, 9, 10, 81, 1000, 4096, 12345};
    for (size_t t = 0; t < sizeof Ns / sizeof *Ns; t++) {
        uint64_t N = Ns[t];
        unsigned char *seen = calloc(N, 1);
        int ok = 1;
        for (uint64_t v = 0; v < N; v++) {
            uint64_t p = cfpo_permute(v, N, 42 + t);
            if (p >= N || seen[p]) ok = 0;
            else seen[p] = 1;
        }
        free(seen);
        CHECK(ok, "cfpo_permute is not a bijection of [0, %llu)", (unsigned long long)N);
    }
}

static void test_start(void)
{
    int64_t ns[] = {11, 100, 1000, 4096, 65536 + 7};
    for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
        int64_t n = ns[t];
        cfpo_grid G;
        char err[256];
        cfpo_grid_init(&G, n, CFPO_VARIANT_FULL, 9, err, sizeof err);
        int64_t total = 0, twos = 0, bad = 0;
        for (int64_t c = 0; c < G.g * G.g; c++) {
            uint64_t cnt = cfpo_grid_cell_count(&G, (uint64_t)c);
            if (cnt < 1 || cnt > 2) bad++;
            twos += cnt == 2;
            total += (int64_t)cnt;
            for (uint64_t k = 0; k < cnt; k++) {
                double x, y;
                cfpo_grid_cell_point(&G, c % G.g, c / G.g, k, &x, &y);
                if (cfpo_grid_cx(&G, x) != c % G.g || cfpo_grid_cy(&G, y) != c / G.g) bad++;
            }
        }
        CHECK(total == n && bad == 0 && twos == n - G.g * G.g,
              "start for n=%lld: %lld points, %lld bad cells/points", (long long)n,
              (long long)total, (long long)bad);
    }
}

/* The adaptive start: n points, each in the cell it is filed under, sorted
 * by cell; any cut into bands of rows gives the same points (so any rank
 * count makes the same start); different seeds differ. */
static void test_adaptive_start(void)
{
    int64_t ns[] = {11, 100, 1000, 4096, 65536 + 7};
    for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
        int64_t n = ns[t];
        cfpo_grid G;
        char err[256];
        cfpo_grid_init(&G, n, CFPO_VARIANT_ADAPTIVE, 9, err, sizeof err);
        cfpo_start_pt *all = NULL;
        int64_t m = cfpo_start_band(&G, 0, G.g, 1, 1, &all);
        int64_t bad = 0;
        for (int64_t i = 0; i < m; i++) {
            const cfpo_start_pt *p = &all[i];
            if (!(p->x >= 0 && p->x < 1 && p->y >= 0 && p->y < 1)) bad++;
            if (cfpo_grid_cy(&G, p->y) * G.g + cfpo_grid_cx(&G, p->x) != p->cell) bad++;
            if (i && (all[i - 1].cell > p->cell || (all[i - 1].cell == p->cell && all[i - 1].key >= p->key))) bad++;
        }
        CHECK(m == n && bad == 0, "adaptive start n=%lld: %lld points, %lld bad", (long long)n, (long long)m,
              (long long)bad);
        /* bands of 1, 2, ... rows, concatenated, made by 1, 2 or 3 threads */
        int64_t k = 0, diff = 0;
        for (int64_t y0 = 0, w = 1; y0 < G.g; y0 += w, w++) {
            int64_t y1 = y0 + w < G.g ? y0 + w : G.g;
            cfpo_start_pt *b = NULL;
            int64_t mb = cfpo_start_band(&G, y0, y1, (int)(w % 3) + 1, 1, &b);
            for (int64_t i = 0; i < mb; i++, k++)
                if (k >= m || memcmp(&b[i], &all[k], sizeof *b) != 0) diff++;
            free(b);
        }
        CHECK(k == m && diff == 0, "adaptive start n=%lld: bands give %lld points, %lld differ", (long long)n,
              (long long)k, (long long)diff);
        cfpo_grid G2 = G;
        G2.seed = 10;
        cfpo_start_pt *o = NULL;
        int64_t m2 = cfpo_start_band(&G2, 0, G2.g, 2, 1, &o);
        int64_t same = 0;
        for (int64_t i = 0; i < m2 && i < m; i++) same += o[i].x == all[i].x;
        CHECK(m2 == n && same < 3, "adaptive start n=%lld: seeds 9 and 10 share %lld points", (long long)n,
              (long long)same);
        free(o);
        free(all);
    }
}

static double *run_points(int64_t n, uint64_t seed, int threads, int skip, int variant,
                          int max_iter, cfpo_result *res)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = seed;
    o.threads = threads;
    o.skip = skip;
    o.variant = variant;
    o.max_iter = max_iter;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    char err[256];
    cfpo_result r;
    if (cfpo_sample(n, &o, xy, &r, err, sizeof err) != 0) {
        fprintf(stderr, "cfpo_sample: %s\n", err);
        exit(1);
    }
    if (res) *res = r;
    return xy;
}

static void test_monotone(int variant)
{
    const int64_t n = 4096;
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 5;
    o.variant = variant;
    o.threads = 2;
    char err[256];
    /* The adaptive start is relaxed already (delta_min about 0.75,
     * start_relax.h), which leaves the phases little to raise: that
     * variant starts here from uniform random points instead, so that the
     * growth check below still asks the phases to lift a low start. */
    cfpo_engine_config cfg = {0};
    double *white = NULL;
    if (variant == CFPO_VARIANT_ADAPTIVE) {
        white = malloc(2 * (size_t)n * sizeof *white);
        for (int64_t k = 0; k < 2 * n; k++) white[k] = cfpo_rand01(o.seed, 77, (uint64_t)k);
        cfg.start_xy = white;
    }
    cfpo_engine *E = cfpo_engine_create_ex(n, &o, &cfg, err, sizeof err);
    free(white);
    double prev, avg;
    cfpo_engine_deltas(E, &prev, &avg);
    int decreases = 0, phases = 0;
    const int ncol = cfpo_engine_grid(E)->period * cfpo_engine_grid(E)->period;
    double first = prev;
    /* Paper and simplified: S is within L - Delta(n) of the cell, so no
     * phase lowers delta(X). Adaptive: S reaches L - delta(X) at the
     * iteration's start, so no phase takes delta(X) below that value (it
     * may dip below a higher value reached earlier in the iteration). */
    for (int it = 0; it < 40; it++) {
        cfpo_engine_begin(E);
        const double at_start = prev;
        for (int c = 0; c < ncol; c++) {
            int64_t solved;
            cfpo_engine_phase(E, c, &solved);
            double dmin;
            cfpo_engine_deltas(E, &dmin, &avg);
            const double floor_ = variant == CFPO_VARIANT_ADAPTIVE ? at_start : prev;
            if (dmin < floor_) {
                decreases++;
                fprintf(stderr, "delta_min fell from %.17g to %.17g (iteration %d, phase %d)\n", floor_, dmin, it, c);
            }
            prev = dmin;
            phases++;
        }
    }
    CHECK(decreases == 0, "%s: delta_min decreased in %d of %d phases",
          cfpo_variant_name(variant), decreases, phases);
    CHECK(prev > first + 0.3, "%s: delta_min did not grow (%.4f -> %.4f)",
          cfpo_variant_name(variant), first, prev);
    /* Statistics from the engine's buckets equal brute force. */
    double *xy = malloc(2 * n * sizeof *xy);
    cfpo_engine_points(E, xy);
    double bmin, bavg, emin, eavg, smin, savg;
    brute_deltas(xy, n, &bmin, &bavg);
    cfpo_engine_deltas(E, &emin, &eavg);
    cfpo_nn_stats(xy, (size_t)n, NULL, &smin, &savg);
    /* The engine sums distances in units of Delta / 2^24 (an exact sum, the
     * same for any split into ranks): each term is off by at most 3e-8. Its
     * delta_min is brute force's up to rounding: the shifted grid's last
     * cell wraps, and its points near 0 are read as x + 1, off by up to
     * 2^-53 each, so a distance by up to 2^-51.5 (4e-16) in torus units,
     * 3e-14 after division by Delta(4096) = 0.0168. */
    CHECK(fabs(emin - bmin) < 3e-14 && fabs(eavg - bavg) < 4e-8, "engine deltas %.17g %.17g, brute %.17g %.17g",
          emin, eavg, bmin, bavg);
    CHECK(smin == bmin && fabs(savg - bavg) < 1e-12, "cfpo_nn_stats %.17g %.17g, brute %.17g %.17g",
          smin, savg, bmin, bavg);
    free(xy);
    cfpo_engine_free(E);
}

/* Nearest-neighbour distance of point i among the n points (brute force). */
static double nearest_of(const double *xy, int64_t n, int64_t i)
{
    double best = INFINITY;
    for (int64_t j = 0; j < n; j++) {
        if (j == i) continue;
        double dx = fabs(xy[2 * i] - xy[2 * j]), dy = fabs(xy[2 * i + 1] - xy[2 * j + 1]);
        dx = fmin(dx, 1 - dx);
        dy = fmin(dy, 1 - dy);
        best = fmin(best, dx * dx + dy * dy);
    }
    return sqrt(best);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The n nearest-neighbour distances of xy (brute force), ascending. */
static void sorted_nn(const double *xy, int64_t n, double *out)
{
    for (int64_t i = 0; i < n; i++) out[i] = nearest_of(xy, n, i);
    qsort(out, (size_t)n, sizeof *out, cmp_double);
}

/* The adaptive variant's moves, over-relaxed (docs/method.md), phase by
 * phase. Each move takes a point farther than before from every other
 * point, by more than tol L, so the ascending list of all nearest-neighbour
 * distances rises in lexicographic order with every move, and so with
 * every phase that moves a point (measured by brute force over the whole
 * set); no point leaves the torus; the bytes are the same for 1 and 3
 * threads. */
static void test_relaxed_moves(void)
{
    const int64_t n = 2048;
    const int iters = 6;
    double *fin[2] = {NULL, NULL};
    for (int k = 0; k < 2; k++) {
        cfpo_options o;
        cfpo_options_init(&o);
        o.seed = 21;
        o.threads = k ? 3 : 1;
        char err[256];
        cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
        const int ncol = cfpo_engine_grid(E)->period * cfpo_engine_grid(E)->period;
        double *a = malloc(2 * n * sizeof(double)), *b = malloc(2 * n * sizeof(double));
        double *na = malloc(n * sizeof(double)), *nb = malloc(n * sizeof(double));
        cfpo_engine_points(E, a);
        sorted_nn(a, n, na);
        int64_t moved = 0, outside = 0, phases = 0, not_up = 0;
        for (int it = 1; it <= iters; it++) {
            cfpo_engine_begin(E);
            for (int c = 0; c < ncol; c++) {
                int64_t solved;
                const int64_t m = cfpo_engine_phase(E, c, &solved);
                cfpo_engine_points(E, b);
                if (k == 0) {
                    for (int64_t i = 0; i < n; i++)
                        outside += !(b[2 * i] >= 0 && b[2 * i] < 1 && b[2 * i + 1] >= 0 && b[2 * i + 1] < 1);
                    sorted_nn(b, n, nb);
                    int64_t j = 0;
                    while (j < n && nb[j] == na[j]) j++;
                    if (m > 0) {
                        phases++;
                        moved += m;
                        if (!(j < n && nb[j] > na[j])) {
                            not_up++;
                            fprintf(stderr, "iteration %d phase %d: sorted nn list did not rise at %lld\n", it, c,
                                    (long long)j);
                        }
                    }
                    memcpy(na, nb, n * sizeof(double));
                }
                memcpy(a, b, 2 * n * sizeof(double));
            }
        }
        if (k == 0) {
            CHECK(moved > (int64_t)iters * n / 2, "adaptive: only %lld moves in %d iterations", (long long)moved, iters);
            CHECK(not_up == 0 && outside == 0,
                  "adaptive: the sorted nearest-neighbour distances did not rise in %lld of %lld phases with moves; "
                  "%lld points outside",
                  (long long)not_up, (long long)phases, (long long)outside);
        }
        fin[k] = a;
        free(b);
        free(na);
        free(nb);
        cfpo_engine_free(E);
    }
    CHECK(memcmp(fin[0], fin[1], 2 * n * sizeof(double)) == 0, "adaptive moves: 1 and 3 threads differ");
    free(fin[0]);
    free(fin[1]);
}

static void test_determinism(void)
{
    const int64_t n = 4096;
    cfpo_result r1;
    double *ref = run_points(n, 3, 1, 1, CFPO_VARIANT_FULL, 10000, &r1);
    CHECK(r1.converged, "reference run did not converge in %d iterations", r1.iterations);
    for (int t = 2; t <= 4; t++) {
        cfpo_result r;
        double *xy = run_points(n, 3, t, 1, CFPO_VARIANT_FULL, 10000, &r);
        CHECK(memcmp(xy, ref, 2 * n * sizeof *xy) == 0 && r.iterations == r1.iterations,
              "%d threads differ from 1 thread", t);
        free(xy);
    }
    cfpo_result rn;
    double *noskip = run_points(n, 3, 2, 0, CFPO_VARIANT_FULL, 10000, &rn);
    CHECK(memcmp(noskip, ref, 2 * n * sizeof *noskip) == 0 && rn.iterations == r1.iterations,
          "skipping off differs from skipping on");
    free(noskip);
    double *other = run_points(n, 4, 2, 1, CFPO_VARIANT_FULL, 10000, NULL);
    size_t same = 0;
    for (int64_t i = 0; i < 2 * n; i++) same += other[i] == ref[i];
    CHECK(same < 10, "seeds 3 and 4 share %zu coordinates", same);
    free(other);
    /* Adaptive variant (start, margin): the same bytes for any thread
     * count and with skipping off. */
    cfpo_result a1, a3;
    double *ad1 = run_points(n, 3, 1, 1, CFPO_VARIANT_ADAPTIVE, 10000, &a1);
    double *ad3 = run_points(n, 3, 3, 0, CFPO_VARIANT_ADAPTIVE, 10000, &a3);
    CHECK(a1.converged && memcmp(ad1, ad3, 2 * n * sizeof *ad1) == 0 && a1.iterations == a3.iterations,
          "adaptive: 1 thread vs 3 threads without skipping differ (or no convergence)");
    CHECK(memcmp(ad1, ref, 2 * n * sizeof *ad1) != 0, "adaptive equals the paper variant");
    free(ad1);
    free(ad3);
    /* Simplified variant: deterministic too. */
    double *s1 = run_points(n, 3, 1, 1, CFPO_VARIANT_SIMPLIFIED, 200, NULL);
    double *s2 = run_points(n, 3, 3, 0, CFPO_VARIANT_SIMPLIFIED, 200, NULL);
    CHECK(memcmp(s1, s2, 2 * n * sizeof *s1) == 0, "simplified: 1 vs 3 threads / skip differ");
    free(s1);
    free(s2);
    /* Every coordinate on the torus. */
    int outside = 0;
    for (int64_t i = 0; i < 2 * n; i++) outside += !(ref[i] >= 0 && ref[i] < 1);
    CHECK(outside == 0, "%d coordinates outside [0,1)", outside);
    free(ref);
}

static void test_small_n(void)
{
    int64_t ns[] = {1, 2, 10, 11, 12, 19, 20, 100, 101, 997, 1009};
    for (size_t t = 0; t < sizeof ns / sizeof *ns; t++)
        for (int variant = 0; variant < 3; variant++) {
            int64_t n = ns[t];
            cfpo_options o;
            cfpo_options_init(&o);
            o.variant = variant;
            o.threads = 2;
            char err[256] = "";
            int v = cfpo_validate(n, &o, err, sizeof err);
            if (n < cfpo_grid_min_n(variant)) {
                CHECK(v == -1 && strstr(err, "too small"), "n=%lld variant %d: not refused (%s)",
                      (long long)n, variant, err);
                continue;
            }
            CHECK(v == 0, "n=%lld variant %d refused: %s", (long long)n, variant, err);
            double *xy = malloc(2 * (size_t)n * sizeof *xy);
            cfpo_result r;
            int rc = cfpo_sample(n, &o, xy, &r, err, sizeof err);
            int ok = rc == 0 && r.converged && r.delta_min > 0.5;
            for (int64_t i = 0; i < 2 * n; i++) ok &= xy[i] >= 0 && xy[i] < 1;
            CHECK(ok, "n=%lld variant %d: rc %d converged %d delta_min %.3f", (long long)n,
                  variant, rc, r.converged, r.delta_min);
            free(xy);
        }
}

static void test_api_matches_engine(void)
{
    const int64_t n = 2000;
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 11;
    o.threads = 2;
    char err[256];
    cfpo_engine *E = cfpo_engine_create(n, &o, err, sizeof err);
    cfpo_result r;
    cfpo_engine_run(E, &r, err, sizeof err);
    double *a = malloc(2 * n * sizeof *a);
    cfpo_engine_points(E, a);
    cfpo_engine_free(E);
    double *b = run_points(n, 11, 2, 1, CFPO_VARIANT_ADAPTIVE, o.max_iter, NULL);
    CHECK(memcmp(a, b, 2 * n * sizeof *a) == 0, "cfpo_sample differs from the engine");
    free(a);
    free(b);
    /* Validation errors. */
    cfpo_options bad = o;
    bad.tol = -1;
    CHECK(cfpo_validate(1000, &bad, err, sizeof err) == -1 && strstr(err, "tolerance"), "tol -1 accepted");
    bad = o;
    bad.variant = 7;
    CHECK(cfpo_validate(1000, &bad, err, sizeof err) == -1 && strstr(err, "variant"), "variant 7 accepted");
    CHECK(cfpo_validate((int64_t)1 << 40, &o, err, sizeof err) != 0 && strstr(err, "too large"),
          "n = 2^40 accepted on one process");
}

int main(void)
{
    test_grid_choice();
    test_permutation();
    test_start();
    test_monotone(CFPO_VARIANT_FULL);
    test_monotone(CFPO_VARIANT_SIMPLIFIED);
    test_monotone(CFPO_VARIANT_ADAPTIVE);
    test_adaptive_start();
    test_relaxed_moves();
    test_determinism();
    test_small_n();
    test_api_matches_engine();
    return test_report(passed_, failed_);
}
