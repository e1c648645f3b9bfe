/* test_dens_engine.c - CFPO under a density (src/density/dens_engine.c):
 *  - the smallest symmetric measure over all pairs, by brute force, never
 *    falls across any accepted move (one thread, every move checked), on
 *    several densities, one with zero-density pixels, one nearly flat
 *    (past iteration 7, where its blocks take the uniform path's near
 *    solve), and two on levels of finer cells (dens_levels.h), where the
 *    outside bound takes its tiers;
 *  - exactly n points, none on a zero-density pixel;
 *  - the same bytes for 1, 2 and 3 threads;
 *  - counts follow the density: count fidelity on cos a=0.9 and the ramp
 *    1:16 (n = 4096, 40 iterations) within the tolerance stated below;
 *  - the quality rises: locally normalised delta_min >= 0.8 after those
 *    40 iterations;
 *  - a lazy measure (cfpo_options.lazy_measure) gives the same points and
 *    result, measuring only where the stop rules read. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "density_measures.h"
#include "cfpo.h"
#include "dens_engine.h"
#include "dens_ops.h"
#include "run_loop.h"
#include "dens_measure.h"
#include "density.h"
#include "geom.h"
#include "testutil.h"

static int passed_, failed_;

static double brute_min(const cfpo_density *d, const double *xy, int64_t n)
{
    double best = INFINITY;
    for (int64_t i = 0; i < n; i++) {
        const double qi = sqrt(sqrt(cfpo_density_at(d, xy[2 * i], xy[2 * i + 1])));
        for (int64_t j = i + 1; j < n; j++) {
            const double qj = sqrt(sqrt(cfpo_density_at(d, xy[2 * j], xy[2 * j + 1])));
            const double m = sqrt(cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1])) * qi * qj;
            if (m < best) best = m;
        }
    }
    return best / cfpo_delta_bound((double)n);
}

typedef struct {
    const cfpo_density *d;
    int64_t n;
    double last;
    int64_t moves, falls;
} watch;

static void on_move(const double *xy, int64_t id, void *user)
{
    (void)id;
    watch *w = user;
    const double m = brute_min(w->d, xy, w->n);
    if (m < w->last * (1 - 1e-12)) w->falls++;
    if (m > w->last) w->last = m;
    w->moves++;
}

static cfpo_options opts(int threads, int iters)
{
    cfpo_options o;
    memset(&o, 0, sizeof o);
    o.seed = 7;
    o.threads = threads;
    o.max_iter = iters;
    o.tol = 1e-4;
    o.skip = 1;
    return o;
}

/* The run of the command (the one loop over the density engine's table)
 * to o's iteration cap; R->E's engine stays for its points. 0 or -1. */
static int run(const cfpo_density *d, int64_t n, const cfpo_options *o, cfpo_run_engine *R, cfpo_result *r,
               char *err, size_t errlen)
{
    if (cfpo_dens_open(d, n, o, NULL, 0, 0, 0, R, err, errlen) != 0) return -1;
    return cfpo_run_loop(R, NULL, 0, r, err, errlen);
}

static const double *points_of(cfpo_run_engine *R, double *xy, int64_t n)
{
    R->ops->copy(R->E, xy);
    (void)n;
    return xy;
}

static void never_falls_on(const cfpo_density *dd, const char *spec, int64_t n, int iters, int levels);

static void never_falls(const char *spec, int64_t n, int iters)
{
    char err[512];
    cfpo_density d;
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    never_falls_on(&d, spec, n, iters, 0);
    cfpo_density_free(&d);
}

/* The same on d, which must take at least `levels` levels of cells
 * (dens_levels.h) when levels > 1. */
static void never_falls_on(const cfpo_density *dd, const char *spec, int64_t n, int iters, int levels)
{
    char err[512];
    const cfpo_density d = *dd;
    cfpo_options o = opts(1, iters);
    cfpo_dens_engine *E = cfpo_dens_create(&d, n, &o, NULL, 0, err, sizeof err);
    CHECK(E != NULL, "%s: %s", spec, err);
    if (!E) return;
    if (levels > 1)
        CHECK(cfpo_dens_levels_count(E) >= levels, "%s: %d levels of cells, not %d", spec, cfpo_dens_levels_count(E),
              levels);
    watch w = {&d, n, brute_min(&d, cfpo_dens_points(E), n), 0, 0};
    const double first = w.last;
    cfpo_dens_on_move(E, on_move, &w);
    cfpo_iter_stats s;
    for (int it = 0; it < iters; it++) cfpo_dens_iterate(E, &s);
    CHECK(w.falls == 0, "%s: the smallest measure fell in %lld of %lld moves", spec, (long long)w.falls, (long long)w.moves);
    CHECK(w.moves > n, "%s: only %lld moves in %d iterations", spec, (long long)w.moves, iters);
    CHECK(w.last > first, "%s: the smallest measure did not rise (%g -> %g)", spec, first, w.last);
    /* the engine's measure is the brute force's */
    double dmin, davg;
    cfpo_dens_nn(&d, cfpo_dens_points(E), (size_t)n, NULL, &dmin, &davg);
    CHECK(fabs(dmin - brute_min(&d, cfpo_dens_points(E), n)) < 1e-12, "%s: delta_min %.15g vs brute force %.15g", spec,
          dmin, brute_min(&d, cfpo_dens_points(E), n));
    printf("%s n=%lld, %d levels: %lld moves, smallest measure %.4f -> %.4f, never fell\n", spec, (long long)n,
           cfpo_dens_levels_count(E), (long long)w.moves, first, w.last);
    cfpo_dens_free(E);
}

static void never_falls_on_spec(const char *spec, int64_t n, int iters, int levels)
{
    char err[512];
    cfpo_density d;
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    never_falls_on(&d, spec, n, iters, levels);
    cfpo_density_free(&d);
}

/* The skip changes no byte on the levels of cells: a cell is solved
 * again only when a move's old or new place lay in its 3 x 3 block since
 * its last solve (the phase stamps, dens_levels.h), and the points after
 * `iters` iterations are those of solving every cell every iteration
 * (--no-skip), while fewer points were solved. */
static void skip_same(const char *spec, int64_t n, int iters, int levels)
{
    char err[512];
    cfpo_density d;
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    double *xy[2] = {NULL, NULL};
    int64_t solved[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        cfpo_options o = opts(2, iters);
        o.skip = k == 0;
        o.tol = 2e-3; /* moves gaining more than 0.002 spacings: many cells settle */
        cfpo_dens_engine *E = cfpo_dens_create(&d, n, &o, NULL, 0, err, sizeof err);
        CHECK(E != NULL, "%s: %s", spec, err);
        if (!E) break;
        CHECK(cfpo_dens_levels_count(E) >= levels, "%s: %d levels of cells, not %d", spec, cfpo_dens_levels_count(E),
              levels);
        cfpo_iter_stats s;
        for (int it = 0; it < iters; it++) {
            cfpo_dens_iterate(E, &s);
            solved[k] += s.solved;
        }
        xy[k] = malloc((size_t)n * 2 * sizeof *xy[k]);
        if (xy[k]) memcpy(xy[k], cfpo_dens_points(E), (size_t)n * 2 * sizeof *xy[k]);
        cfpo_dens_free(E);
    }
    if (xy[0] && xy[1]) {
        CHECK(memcmp(xy[0], xy[1], (size_t)n * 2 * sizeof *xy[0]) == 0, "%s: the skip changed the points", spec);
        CHECK(solved[0] < solved[1] * 9 / 10, "%s: the skip solved %lld points of %lld", spec, (long long)solved[0],
              (long long)solved[1]);
        printf("%s n=%lld, %d iterations: the same points with and without the skip (%lld and %lld solved)\n", spec,
               (long long)n, iters, (long long)solved[0], (long long)solved[1]);
    }
    free(xy[0]);
    free(xy[1]);
    cfpo_density_free(&d);
}

/* A 64 x 64 array with a zero disc and a 1:40 step. */
static void zero_disc(cfpo_density *d)
{
    double v[64 * 64];
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            const double x = (i + 0.5) / 64 - 0.5, y = (j + 0.5) / 64 - 0.5;
            v[j * 64 + i] = x * x + y * y < 0.04 ? 0 : (i < 32 ? 1 : 40);
        }
    char err[256];
    if (cfpo_density_from_values(v, 64, 64, "disc", d, err, sizeof err) != 0) CHECK(0, "%s", err);
}

static void support_and_threads(void)
{
    cfpo_density d;
    zero_disc(&d);
    char err[512];
    const int64_t n = 2000;
    double *ref = NULL;
    double *p = malloc((size_t)n * 2 * sizeof *p);
    for (int t = 1; t <= 3 && p; t++) {
        cfpo_options o = opts(t, 12);
        cfpo_run_engine R;
        cfpo_result r;
        const int rc = run(&d, n, &o, &R, &r, err, sizeof err);
        CHECK(rc == 0, "%s", err);
        if (rc != 0) break;
        points_of(&R, p, n);
        if (t == 1) {
            ref = malloc((size_t)n * 2 * sizeof *ref);
            memcpy(ref, p, (size_t)n * 2 * sizeof *ref);
            int64_t off = 0, outside = 0;
            for (int64_t i = 0; i < n; i++) {
                if (!(cfpo_density_at(&d, p[2 * i], p[2 * i + 1]) > 0)) off++;
                if (!(p[2 * i] >= 0 && p[2 * i] < 1 && p[2 * i + 1] >= 0 && p[2 * i + 1] < 1)) outside++;
            }
            CHECK(off == 0 && outside == 0, "%lld points on zero-density pixels, %lld off the torus", (long long)off,
                  (long long)outside);
        } else CHECK(memcmp(ref, p, (size_t)n * 2 * sizeof *ref) == 0, "%d threads: other bytes than 1 thread", t);
        R.ops->free(R.E);
    }
    free(p);
    free(ref);
    cfpo_density_free(&d);
}

/* Counts follow the density: relative error of the points in each of
 * 8 x 8 blocks (64 points a block on average) against n times the block's
 * mass. Tolerance: rms 0.06, max 0.25 (a uniform random set has rms about
 * 1/sqrt(64) = 0.125; the start, systematic along a Hilbert curve, about
 * 0.03). */
static void fidelity(const char *spec)
{
    char err[512];
    cfpo_density d;
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s", err); return; }
    const int64_t n = 4096;
    cfpo_options o = opts(2, 40);
    o.tol = 0;
    cfpo_run_engine R;
    cfpo_result r;
    const int rc = run(&d, n, &o, &R, &r, err, sizeof err);
    CHECK(rc == 0, "%s: %s", spec, err);
    if (rc != 0) { cfpo_density_free(&d); return; }
    double *xy = malloc((size_t)n * 2 * sizeof *xy);
    if (!xy) { R.ops->free(R.E); cfpo_density_free(&d); return; }
    points_of(&R, xy, n);
    double rms, mx;
    size_t off;
    an_density_fidelity(&d, xy, (size_t)n, 8, &rms, &mx, &off);
    CHECK(rms < 0.06 && mx < 0.25 && off == 0, "%s: count fidelity rms %.4f max %.4f off %zu", spec, rms, mx, off);
    CHECK(r.delta_min >= 0.8, "%s: delta_min %.4f after %d iterations", spec, r.delta_min, r.iterations);
    printf("%s n=4096, %d iterations: delta_min %.4f delta_avg %.4f, fidelity rms %.4f max %.4f\n", spec, r.iterations,
           r.delta_min, r.delta_avg, rms, mx);
    free(xy);
    R.ops->free(R.E);
    cfpo_density_free(&d);
}

/* The library's front (cfpo.h): cfpo_sample_density gives the bytes of
 * the one loop over the density engine; cfpo_sample_density_values of a
 * flat array gives cfpo_sample's (the uniform torus); a bad density and n
 * too small for one are refused with one line. */
static void library(void)
{
    char err[512];
    const int64_t n = 2000;
    cfpo_density d;
    if (cfpo_density_load("cos:a=0.9,res=64", &d, err, sizeof err) != 0) { CHECK(0, "%s", err); return; }
    cfpo_options o = opts(2, 10);
    o.variant = CFPO_VARIANT_ADAPTIVE;
    double *a = malloc((size_t)n * 2 * sizeof *a), *b = malloc((size_t)n * 2 * sizeof *b);
    cfpo_run_engine R;
    cfpo_result r, r2;
    if (!a || !b || run(&d, n, &o, &R, &r, err, sizeof err) != 0) {
        CHECK(0, "reference run: %s", err);
        free(a); free(b); cfpo_density_free(&d);
        return;
    }
    points_of(&R, a, n);
    R.ops->free(R.E);
    CHECK(cfpo_sample_density(n, &o, "cos:a=0.9,res=64", b, &r2, err, sizeof err) == 0, "%s", err);
    CHECK(memcmp(a, b, (size_t)n * 2 * sizeof *a) == 0 && r2.iterations == r.iterations,
          "cfpo_sample_density: other bytes than the engine's run");
    double flat[16];
    for (int i = 0; i < 16; i++) flat[i] = 3.0;
    cfpo_options u;
    cfpo_options_init(&u);
    u.max_iter = 10;
    u.threads = 2;
    CHECK(cfpo_sample(n, &u, a, &r, err, sizeof err) == 0, "%s", err);
    CHECK(cfpo_sample_density_values(n, &u, flat, 4, 4, b, &r2, err, sizeof err) == 0, "%s", err);
    CHECK(memcmp(a, b, (size_t)n * 2 * sizeof *a) == 0, "a flat density: other bytes than cfpo_sample's");
    err[0] = 0;
    CHECK(cfpo_sample_density(n, &o, "swirl", b, &r2, err, sizeof err) == -1 && err[0] && !strchr(err, '\n'),
          "a bad density: '%s'", err);
    err[0] = 0;
    cfpo_options pv = o;
    pv.variant = CFPO_VARIANT_PAPER;
    CHECK(cfpo_sample_density(n, &pv, "cos:a=0.9,res=64", b, &r2, err, sizeof err) == -1 && strstr(err, "variant"),
          "another variant under a density: '%s'", err);
    err[0] = 0;
    CHECK(cfpo_sample_density(50, &o, "ramp:contrast=200", b, &r2, err, sizeof err) == -1 && strstr(err, "too small"),
          "n too small for the density: '%s'", err);
    free(a); free(b);
    cfpo_density_free(&d);
}

/* What a progress callback saw: each iteration's deltas and stale flag. */
typedef struct {
    int n;
    double dmin[128], davg[128];
    int stale[128];
} seen_log;

static int log_iteration(const cfpo_iter_stats *s, void *user)
{
    seen_log *g = user;
    if (s->iteration == g->n && g->n < 128) {
        g->dmin[g->n] = s->delta_min;
        g->davg[g->n] = s->delta_avg;
        g->stale[g->n] = s->stale;
        g->n++;
    }
    return 0;
}

/* o.lazy_measure (cfpo_types.h): the same points, iterations, stop and
 * result as measuring every iteration; the set measured at iteration 0,
 * at each stall window's end and nowhere else (the callback sees the last
 * measured values, flagged stale); with a target set, every iteration.
 * To an iteration cap that ends off a window, and to the run's own stop. */
static void lazy_measure(const char *spec, int64_t n)
{
    char err[512];
    cfpo_density d;
    if (cfpo_density_load(spec, &d, err, sizeof err) != 0) { CHECK(0, "%s: %s", spec, err); return; }
    double *a = malloc((size_t)n * 2 * sizeof *a), *b = malloc((size_t)n * 2 * sizeof *b);
    const int caps[3] = {37, 20, 100000}; /* 20 with a target never met */
    for (int c = 0; c < 3 && a && b; c++) {
        seen_log ge = {0}, gl = {0};
        cfpo_result re, rl;
        cfpo_run_engine R;
        int ok = 1;
        for (int lazy = 0; lazy < 2 && ok; lazy++) {
            cfpo_options o = opts(2, caps[c]);
            if (c == 1) o.stop.target_min = 0.999;
            o.lazy_measure = lazy;
            o.progress = log_iteration;
            o.user = lazy ? &gl : &ge;
            ok = run(&d, n, &o, &R, lazy ? &rl : &re, err, sizeof err) == 0;
            CHECK(ok, "%s lazy=%d: %s", spec, lazy, err);
            if (ok) points_of(&R, lazy ? b : a, n);
            R.ops->free(R.E);
        }
        if (!ok) continue;
        CHECK(memcmp(a, b, (size_t)n * 2 * sizeof *a) == 0, "%s cap %d: lazy measures moved other points", spec,
              caps[c]);
        CHECK(rl.iterations == re.iterations && rl.stop == re.stop && rl.converged == re.converged &&
                  rl.delta_min == re.delta_min && rl.delta_avg == re.delta_avg,
              "%s cap %d: lazy result %d it %.9f %.9f, eager %d it %.9f %.9f", spec, caps[c], rl.iterations,
              rl.delta_min, rl.delta_avg, re.iterations, re.delta_min, re.delta_avg);
        CHECK(gl.n == re.iterations + 1 && ge.n == gl.n, "%s cap %d: callbacks %d and %d for %d iterations", spec,
              caps[c], gl.n, ge.n, re.iterations);
        int bad = 0, last = 0, stale = 0;
        for (int k = 0; k < gl.n && k < ge.n; k++) {
            const int want = c != 1 && k % 16 != 0; /* stale off the windows, unless a target is set */
            bad += ge.stale[k] != 0 || gl.stale[k] != want;
            if (!gl.stale[k]) last = k;
            stale += gl.stale[k];
            bad += gl.dmin[k] != ge.dmin[last] || gl.davg[k] != ge.davg[last];
        }
        CHECK(bad == 0, "%s cap %d: %d iterations measured where they should not, or other values", spec, caps[c],
              bad);
        CHECK(c == 1 || stale > 0, "%s cap %d: nothing left unmeasured", spec, caps[c]);
    }
    free(a); free(b);
    cfpo_density_free(&d);
}

int main(void)
{
    library();
    lazy_measure("cos:a=0.9,res=64", 1200);
    lazy_measure("ramp:contrast=64,res=64", 1500);
    never_falls("cos:a=0.9,res=64", 300, 6);
    never_falls("ramp:contrast=16,res=64", 300, 6);
    never_falls("balzer:res=64", 500, 4);
    never_falls("cos:a=0,res=16", 200, 6);
    never_falls("cos:a=0.9,kx=2,ky=1,res=64", 400, 4);
    /* nearly flat: the uniform path's near solve (one polygon from
     * iteration 7, no fall-back; policy.h) */
    never_falls("cos:a=0.01,res=64", 300, 10);
    /* cells sized to the local spacing (dens_levels.h): finer levels
     * whose blocks need the tiers of the outside bound, on a smooth 1:64
     * and beside a sharp 1:40 step and a zero disc */
    never_falls_on_spec("ramp:contrast=64,res=64", 800, 6, 3);
    {
        cfpo_density z;
        zero_disc(&z);
        never_falls_on(&z, "disc", 900, 6, 2);
        cfpo_density_free(&z);
    }
    support_and_threads();
    skip_same("ramp:contrast=256,res=64", 2500, 40, 3);
    fidelity("cos:a=0.9");
    fidelity("ramp:contrast=16");
    return test_report(passed_, failed_);
}
