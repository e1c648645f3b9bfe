/* test_d3_engine.c - the 3-D engine's invariants (src/d3/): the k nearest
 * neighbours against brute force; delta_min never falls, iteration after
 * iteration, by brute force over all pairs, from the jittered start (near
 * phase and exact solve) and from white noise; the same bytes for 1, 2
 * and 3 threads and with or without skipping, in the near phase, with the
 * exact solve and across the switch between them; a resume from a
 * checkpoint gives the bytes of the uninterrupted run (also across a grid
 * shift and around the switch), and a corrupt checkpoint
 * is refused; Steinhardt's Q6 of FCC, BCC and simple cubic lattices
 * against their known values, and of white noise. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine3.h"
#include "nn3.h"
#include "q6.h"
#include "rng.h"
#include "solve3.h"
#include "testutil.h"

static int passed_, failed_;

static double pd2(const double *p, size_t i, size_t j)
{
    double s = 0.0;
    for (int a = 0; a < 3; a++) {
        const double d = cfpo3_pdiff(p[3 * i + a], p[3 * j + a]);
        s += d * d;
    }
    return s;
}

static double brute_min(const double *p, size_t n)
{
    double b = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            const double d = pd2(p, i, j);
            if (d < b) b = d;
        }
    return sqrt(b) / cfpo3_delta_bound((double)n);
}

static void random_set(double *p, size_t n, uint64_t seed)
{
    for (size_t i = 0; i < 3 * n; i++) p[i] = cfpo_rand01(seed, 5, i);
}

static void test_knn(void)
{
    const size_t n = 700;
    const int k = 12;
    double *p = malloc(sizeof(double) * 3 * n), *d2 = malloc(sizeof(double) * k * n);
    int64_t *idx = malloc(sizeof(int64_t) * k * n);
    random_set(p, n, 3);
    CHECK(cfpo3_knn(p, n, k, idx, d2) == 0, "knn failed");
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        /* brute force: the k smallest (d, id) */
        double bd[12];
        int64_t bi[12];
        int c = 0;
        for (size_t j = 0; j < n; j++) {
            if (j == i) continue;
            const double d = pd2(p, i, j);
            if (c == k && (d > bd[k - 1] || (d == bd[k - 1] && (int64_t)j > bi[k - 1]))) continue;
            int at = c < k ? c++ : k - 1;
            while (at > 0 && (bd[at - 1] > d || (bd[at - 1] == d && bi[at - 1] > (int64_t)j))) {
                bd[at] = bd[at - 1], bi[at] = bi[at - 1];
                at--;
            }
            bd[at] = d, bi[at] = (int64_t)j;
        }
        for (int a = 0; a < k; a++) bad += bi[a] != idx[k * i + a] || bd[a] != d2[k * i + a];
    }
    CHECK(bad == 0, "knn: %d of %zu neighbours differ from brute force", bad, k * n);
    free(p), free(d2), free(idx);
}

/* Runs `iters` iterations and checks delta_min against brute force after each. */
static void never_falls(cfpo3_engine *e, int iters, const char *what)
{
    const size_t n = (size_t)cfpo3_n(e);
    double prev = brute_min(cfpo3_points(e), n), dmin, davg;
    cfpo3_measure(e, &dmin, &davg);
    CHECK(fabs(dmin - prev) < 1e-12, "%s: engine delta_min %.15f, brute force %.15f", what, dmin, prev);
    int falls = 0, mism = 0, moved = 0;
    for (int k = 0; k < iters; k++) {
        cfpo_iter_stats st;
        CHECK(cfpo3_step(e, &st) == 0, "%s: step failed", what);
        const double b = brute_min(cfpo3_points(e), n);
        falls += b < prev;
        mism += fabs(b - st.delta_min) > 1e-12;
        moved += st.moved > 0;
        prev = b;
    }
    CHECK(falls == 0, "%s: delta_min fell in %d of %d iterations", what, falls, iters);
    CHECK(mism == 0, "%s: the engine's delta_min differs from brute force in %d iterations", what, mism);
    CHECK(moved > 0, "%s: nothing moved", what);
}

static cfpo3_engine *make_near(int64_t n, int threads, int skip, int near)
{
    cfpo3_options o;
    cfpo3_options_default(&o);
    o.seed = 7;
    o.threads = threads;
    o.skip = skip;
    o.near = near;
    char err[256];
    cfpo3_engine *e = cfpo3_create(n, &o, err, sizeof err);
    if (!e) fprintf(stderr, "%s\n", err);
    return e;
}

static cfpo3_engine *make(int64_t n, int threads, int skip) { return make_near(n, threads, skip, 1); }

static void run(cfpo3_engine *e, int k)
{
    cfpo_iter_stats st;
    for (int i = 0; i < k; i++) cfpo3_step(e, &st);
}

static int same(const cfpo3_engine *a, const cfpo3_engine *b)
{
    return cfpo3_n(a) == cfpo3_n(b) &&
           memcmp(cfpo3_points(a), cfpo3_points(b), sizeof(double) * 3 * (size_t)cfpo3_n(a)) == 0;
}

static void test_lattice_q6(const char *name, int kind, int side, int k, double want)
{
    static const double fcc[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    static const double bcc[2][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}};
    const int nb = kind == 0 ? 4 : kind == 1 ? 2 : 1;
    const size_t n = (size_t)nb * side * side * side;
    double *p = malloc(sizeof(double) * 3 * n);
    size_t m = 0;
    for (int i = 0; i < side; i++)
        for (int j = 0; j < side; j++)
            for (int l = 0; l < side; l++)
                for (int b = 0; b < nb; b++) {
                    const double *o = kind == 0 ? fcc[b] : kind == 1 ? bcc[b] : fcc[0];
                    p[3 * m] = (i + o[0] + 0.25) / side;
                    p[3 * m + 1] = (j + o[1] + 0.25) / side;
                    p[3 * m + 2] = (l + o[2] + 0.25) / side;
                    m++;
                }
    cfpo3_q6_result r;
    CHECK(cfpo3_q6(p, n, k, 0.7, 8, &r) == 0, "%s: q6 failed", name);
    CHECK(fabs(r.q6_global - want) < 5e-4 && fabs(r.q6_local - want) < 5e-4,
          "%s: Q6 %.5f, local %.5f, expected %.4f", name, r.q6_global, r.q6_local, want);
    if (k >= 8) CHECK(r.crystal == (int64_t)n, "%s: %lld of %zu crystal-like", name, (long long)r.crystal, n);
    printf("%s (%zu points, %d neighbours): Q6 %.5f\n", name, n, k, r.q6_global);
    free(p);
}

int main(void)
{
    test_knn();
    {
        cfpo3_engine *e = make(324, 0, 1);
        never_falls(e, 8, "jittered start");
        cfpo3_free(e);
        e = make_near(324, 0, 1, 0);
        never_falls(e, 4, "jittered start, exact solve");
        cfpo3_free(e);
        const size_t n = 324;
        double *p = malloc(sizeof(double) * 3 * n);
        random_set(p, n, 11);
        cfpo3_options o;
        cfpo3_options_default(&o);
        char err[256];
        e = cfpo3_create_given(p, (int64_t)n, &o, err, sizeof err);
        never_falls(e, 6, "white noise");
        cfpo3_free(e);
        free(p);
    }
    {
        cfpo3_engine *a = make(324, 1, 1), *b = make(324, 2, 1), *c = make(324, 3, 1), *d = make(324, 2, 0);
        run(a, 6), run(b, 6), run(c, 6), run(d, 6);
        CHECK(same(a, b) && same(a, c), "threads 1, 2, 3 give different bytes");
        CHECK(same(a, d), "skipping changes the bytes");
        /* resume: after 3 (before no shift) and after 4 (before a shift) */
        char path[64];
        snprintf(path, sizeof path, "/tmp/test_d3_ckpt_%d.bin", (int)getpid());
        for (int at = 3; at <= 4; at++) {
            cfpo3_engine *r = make(324, 2, 1);
            run(r, at);
            char err[256];
            CHECK(cfpo3_checkpoint_write(r, path, err, sizeof err) == 0, "checkpoint write: %s", err);
            cfpo3_free(r);
            r = cfpo3_checkpoint_read(path, 3, err, sizeof err);
            CHECK(r != NULL, "checkpoint read: %s", err);
            if (r) {
                CHECK(cfpo3_iterations(r) == at, "resumed at %d, not %d", cfpo3_iterations(r), at);
                run(r, 6 - at);
                CHECK(same(a, r), "resume after %d iterations differs from the uninterrupted run", at);
                cfpo3_free(r);
            }
        }
        /* corrupt checkpoints: every flipped byte, a truncated file */
        {
            FILE *f = fopen(path, "rb");
            unsigned char *buf = malloc(64 + 24 * 324);
            const size_t len = fread(buf, 1, 64 + 24 * 324, f);
            fclose(f);
            int taken = 0;
            char err[256];
            for (size_t at = 0; at < len; at += 7) {
                buf[at] ^= 0x10;
                cfpo3_engine *r = cfpo3_checkpoint_parse(buf, len, "x", 1, err, sizeof err);
                taken += r != NULL;
                cfpo3_free(r);
                buf[at] ^= 0x10;
            }
            CHECK(taken == 0, "%d corrupt checkpoints accepted", taken);
            cfpo3_engine *r = cfpo3_checkpoint_parse(buf, len - 24, "x", 1, err, sizeof err);
            CHECK(r == NULL, "a truncated checkpoint accepted");
            cfpo3_free(r);
            r = cfpo3_checkpoint_parse(buf, len, "x", 1, err, sizeof err);
            CHECK(r != NULL, "the intact checkpoint refused: %s", err);
            cfpo3_free(r);
            free(buf);
        }
        unlink(path);
        cfpo3_free(a), cfpo3_free(b), cfpo3_free(c), cfpo3_free(d);
    }
    /* the exact solve from the start: threads and skipping; the switch from
     * the near phase to the exact solve: threads, and a resume at it (the
     * checkpoint says the near phase is over) and after its first exact
     * iteration */
    {
        cfpo3_engine *a = make_near(324, 1, 1, 0), *b = make_near(324, 3, 1, 0), *d = make_near(324, 2, 0, 0);
        run(a, 3), run(b, 3), run(d, 3);
        CHECK(same(a, b) && same(a, d), "exact solve: threads 1, 3 or no skipping give different bytes");
        cfpo3_free(a), cfpo3_free(b), cfpo3_free(d);
        a = make(324, 1, 1);
        int sw = 0; /* the first exact iteration */
        cfpo_iter_stats st;
        for (int i = 0; i < 400 && !sw; i++) {
            cfpo3_step(a, &st);
            CHECK(!(st.near && st.converged), "a near iteration said converged");
            if (!st.near) sw = st.iteration;
        }
        CHECK(sw > 1, "the near phase never ended (or never ran)");
        if (sw > 1) {
            run(a, 1);
            b = make(324, 3, 1);
            run(b, sw + 1);
            CHECK(same(a, b), "threads 1, 3 differ across the switch to the exact solve");
            cfpo3_free(b);
            char path[64];
            snprintf(path, sizeof path, "/tmp/test_d3_sw_%d.bin", (int)getpid());
            for (int at = sw - 1; at <= sw; at++) {
                cfpo3_engine *r = make(324, 2, 1);
                run(r, at);
                char err[256];
                CHECK(cfpo3_checkpoint_write(r, path, err, sizeof err) == 0, "checkpoint write: %s", err);
                cfpo3_free(r);
                r = cfpo3_checkpoint_read(path, 2, err, sizeof err);
                CHECK(r != NULL, "checkpoint read: %s", err);
                if (r) {
                    run(r, sw + 1 - at);
                    CHECK(same(a, r), "resume after %d iterations (first exact one %d) differs", at, sw);
                    cfpo3_free(r);
                }
            }
            unlink(path);
            printf("near phase over after %d iterations (324 points)\n", sw - 1);
        }
        cfpo3_free(a);
    }
    /* Q6 of lattices (Steinhardt et al. 1983; the neighbour counts fixed) */
    test_lattice_q6("FCC", 0, 4, 12, 0.57452);
    test_lattice_q6("BCC", 1, 5, 14, 0.51069);
    test_lattice_q6("SC", 2, 6, 6, 0.35355);
    {
        const size_t n = 3000;
        double *p = malloc(sizeof(double) * 3 * n);
        random_set(p, n, 21);
        cfpo3_q6_result r;
        CHECK(cfpo3_q6(p, n, 12, 0.7, 8, &r) == 0, "q6 failed");
        CHECK(r.q6_global < 0.03 && r.crystal_frac < 0.01, "white noise: Q6 %.4f, crystal-like %.4f",
              r.q6_global, r.crystal_frac);
        printf("white noise (3000 points): Q6 %.5f, crystal-like %lld\n", r.q6_global, (long long)r.crystal);
        free(p);
    }
    /* too few points */
    {
        cfpo3_options o;
        cfpo3_options_default(&o);
        char err[256];
        CHECK(cfpo3_create(cfpo3_grid_min_n() - 1, &o, err, sizeof err) == NULL && strstr(err, "too small"),
              "n below the minimum accepted");
        cfpo3_engine *e = cfpo3_create(cfpo3_grid_min_n(), &o, err, sizeof err);
        CHECK(e != NULL, "the smallest n refused: %s", err);
        if (e) never_falls(e, 5, "smallest n");
        cfpo3_free(e);
    }
    return test_report(passed_, failed_);
}
