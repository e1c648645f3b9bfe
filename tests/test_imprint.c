/* test_imprint.c - the grid does not print itself on the set (issue 44).
 *
 * The adaptive variant's first sweeps write the grid into the set: each
 * sweep under one grid adds a density wave of the cell's period, which the
 * later sweeps cannot erase once the set is jammed (docs/tried.md, "What
 * writes the grid imprint"). The schedule moves the grid, on each axis
 * apart, before every one of the first iterations so that consecutive
 * prints cancel (docs/method.md, "The uniform schedule", item 3). This test
 * makes 262,144 points for IMPRINT_ITERS iterations on three seeds and
 * measures P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n directly at the cell
 * grid's frequencies (0, g), (g, 0), the start lattice's (0, 4g/3),
 * (4g/3, 0) and the cells' diagonals (g, g), (-g, g), each over the mean
 * of P on its own ring (up to 96 integer vectors of the same rounded
 * length, the axis vectors left out), as scripts/imprint.c does. Each
 * ratio's median over the three seeds must stay below IMPRINT_BOUND. White
 * noise gives ratios spread as Exp(1) (P(ratio > 60) = e^-60); the
 * schedule of one grid for four sweeps gave 322-361 at (0, g) after two
 * sweeps, and a grid kept for the second sweep 305-392, on every seed
 * (docs/results/2026-11-28-imprint-fix.md). A cause of the print is in the
 * schedule and marks every seed; one seed's two-sweep ratio also carries
 * the start's own transient (15-73 at (0, g) over seeds 1-3 with the fix),
 * so the median is judged, not each seed
 * (docs/results/2026-11-29-start-modes.md).
 *
 * Second, the first sweep's own print (issue 44, 2026-11-29): the start
 * is relaxed without a grid before the first sweep (start_relax.h), so
 * that sweep makes short moves and prints little. After one iteration the
 * largest of ten ratios (the six above and the colours' period (0, g/3),
 * (0, 2g/3), (g/3, 0), (2g/3, 0)) must stay below FIRST_BOUND on every
 * seed. Without the relaxation the first sweep writes 1,461 at (0, 2g/3)
 * and 457 at (0, g) on seed 1 (at 1,048,576 points 5,913 and 1,510);
 * with it 47 and 51 (docs/results/2026-11-29-imprint10.md).
 *
 * Third, the sweep's colour order (issue 44): colours solved in row order
 * give each row of colours its turn together, and the second sweep prints
 * the colours' period on y. After two iterations the median over the
 * three seeds of P(0, g/3) and of P(g/3, 0) over their ring's mean must
 * stay below COLOUR_BOUND. In row order (0, g/3) is 14.3, 26.2 and 22.9 on
 * seeds 1-3 (median 22.9); in the balanced order (policy.h) at most 9.4
 * (docs/results/2026-11-29-imprint11.md).
 *
 * Fourth, the print's removal (gridmodes.h, issue 44, 2026-11-30): a print
 * written in the first sweeps and left there until the neighbourhoods
 * settle stays, at its phase, for hundreds of sweeps; at 262,144 points
 * the sweeps' own prints are within the noise, so the test writes one: the
 * set after one iteration, given density waves of relative size 5% at
 * (0, g) and (g, 0) (382-393 times the ring's mean), is the start of a run of
 * UNPRINT_ITERS iterations, whose removals before iterations 2-9 must take
 * P(0, g) and P(g, 0) to below UNPRINT_BOUND times their ring's mean.
 * Without the removals they end at 7.3 and 9.6 times, with them at 0.8
 * and 0.9 (docs/results/2026-11-30-unprint19.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cfpo.h"
#include "engine.h"
#include "testutil.h"
#include "../analysis/ring_power.h"

#define IMPRINT_N 262144
#define IMPRINT_ITERS 2
#define IMPRINT_BOUND 60.0
#define FIRST_BOUND 200.0
#define COLOUR_BOUND 15.0
#define UNPRINT_ITERS 9
#define UNPRINT_BOUND 5.0

static int passed_, failed_;

/* The set of `iters` iterations, seed `seed`, into xy: 0, or -1 (said). */
static int sample(double *xy, int64_t n, int seed, int iters)
{
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = (uint64_t)seed;
    o.max_iter = iters;
    char err[256];
    cfpo_result r;
    if (cfpo_sample(n, &o, xy, &r, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (r.iterations != iters) {
        fprintf(stderr, "seed %d: %d iterations, not %d\n", seed, r.iterations, iters);
        return -1;
    }
    return 0;
}

/* The largest of the ten ratios after one iteration, seed `seed`; -1 on
 * failure. */
static double first_sweep(double *xy, int64_t n, int g, int seed, const char **at)
{
    if (sample(xy, n, seed, 1) != 0) return -1;
    const int g3 = (int)lround(g / 3.0), g23 = (int)lround(2.0 * g / 3.0), g4 = (int)lround(4.0 * g / 3.0);
    const int gd = (int)lround(g * sqrt(2.0));
    static const char *name[10] = {"(0,g)", "(g,0)", "(0,4g/3)", "(4g/3,0)", "(g,g)", "(-g,g)",
                                   "(0,g/3)", "(g/3,0)", "(0,2g/3)", "(2g/3,0)"};
    const int vec[10][2] = {{0, g}, {g, 0}, {0, g4}, {g4, 0}, {g, g}, {-g, g}, {0, g3}, {g3, 0}, {0, g23}, {g23, 0}};
    const int rad[10] = {g, g, g4, g4, gd, gd, g3, g3, g23, g23};
    double worst = 0;
    printf("seed %d, after 1 iteration:", seed);
    for (int v = 0; v < 10; v++) {
        const double q = rp_power(xy, n, vec[v][0], vec[v][1]) / rp_ring_mean(xy, n, rad[v]);
        printf(" %s %.1f", name[v], q);
        if (!(q <= worst)) worst = q, *at = name[v]; /* a NaN is the worst */
    }
    printf("\n");
    return worst;
}

/* The planted waves' largest P / ring mean after UNPRINT_ITERS
 * iterations (fourth part); -1 on failure. */
static double planted(double *xy, int64_t n, int g)
{
    if (sample(xy, n, 1, 1) != 0) return -1;
    for (int64_t i = 0; i < n; i++)
        for (int a = 0; a < 2; a++) {
            const double v = xy[2 * i + a] + 0.05 * sin(2 * M_PI * g * xy[2 * i + a] + a) / (2 * M_PI * g);
            xy[2 * i + a] = v - floor(v);
        }
    const double m = rp_ring_mean(xy, n, g);
    printf("planted: P(0,g) / ring mean %.1f, P(g,0) %.1f\n", rp_power(xy, n, 0, g) / m, rp_power(xy, n, g, 0) / m);
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 1;
    o.threads = 2;
    char err[256];
    cfpo_engine_config cfg = {0};
    cfg.start_xy = xy;
    cfpo_engine *E = cfpo_engine_create_ex(n, &o, &cfg, err, sizeof err);
    if (!E) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    for (int k = 0; k < UNPRINT_ITERS; k++) {
        cfpo_iter_stats st;
        cfpo_engine_iterate(E, &st);
    }
    cfpo_engine_points(E, xy);
    cfpo_engine_free(E);
    const double m2 = rp_ring_mean(xy, n, g), a = rp_power(xy, n, 0, g) / m2, b = rp_power(xy, n, g, 0) / m2;
    printf("after %d iterations: P(0,g) / ring mean %.1f, P(g,0) %.1f\n", UNPRINT_ITERS, a, b);
    return isfinite(a) && isfinite(b) ? fmax(a, b) : -1;
}

int main(void)
{
    const int64_t n = IMPRINT_N;
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy) return 1;
    /* cfpo's grid at this n (docs/method.md): g = 3 round(sqrt(0.8 n) / 3) */
    const int g = 3 * (int)lround(sqrt(0.8 * (double)n) / 3), g4 = (int)lround(4.0 * g / 3.0);
    const int gd = (int)lround(g * sqrt(2.0));
    const int vec[6][2] = {{0, g}, {g, 0}, {0, g4}, {g4, 0}, {g, g}, {-g, g}};
    const char *name[6] = {"(0,g)", "(g,0)", "(0,4g/3)", "(4g/3,0)", "(g,g)", "(-g,g)"};
    double q[3][6], qc[3][2];
    const int g3 = (int)lround(g / 3.0);
    for (int seed = 1; seed <= 3; seed++) {
        if (sample(xy, n, seed, IMPRINT_ITERS) != 0) {
            free(xy);
            return 1;
        }
        const double mg = rp_ring_mean(xy, n, g), m4 = rp_ring_mean(xy, n, g4), md = rp_ring_mean(xy, n, gd);
        const double ring[6] = {mg, mg, m4, m4, md, md};
        printf("seed %d, g %d, after %d iterations: P / ring mean", seed, g, IMPRINT_ITERS);
        for (int v = 0; v < 6; v++) {
            q[seed - 1][v] = rp_power(xy, n, vec[v][0], vec[v][1]) / ring[v];
            printf(" %s %.1f", name[v], q[seed - 1][v]);
        }
        const double m3 = rp_ring_mean(xy, n, g3);
        qc[seed - 1][0] = rp_power(xy, n, 0, g3) / m3;
        qc[seed - 1][1] = rp_power(xy, n, g3, 0) / m3;
        printf(" (0,g/3) %.1f (g/3,0) %.1f\n", qc[seed - 1][0], qc[seed - 1][1]);
    }
    for (int v = 0; v < 6; v++) {
        const double a = q[0][v], b = q[1][v], c = q[2][v];
        CHECK(isfinite(a) && isfinite(b) && isfinite(c), "%s: a ratio is not a number", name[v]);
        const double med = fmax(fmin(a, b), fmin(fmax(a, b), c));
        printf("median %s %.1f\n", name[v], med);
        CHECK(med < IMPRINT_BOUND, "the grid's print P%s / ring mean, median of seeds 1-3 = %.1f >= %.0f", name[v], med,
              IMPRINT_BOUND);
    }
    for (int v = 0; v < 2; v++) {
        const double a = qc[0][v], b = qc[1][v], c = qc[2][v];
        const double med = isfinite(a) && isfinite(b) && isfinite(c) ? fmax(fmin(a, b), fmin(fmax(a, b), c)) : NAN;
        printf("median %s %.1f\n", v ? "(g/3,0)" : "(0,g/3)", med);
        CHECK(med < COLOUR_BOUND, "the colours' print P%s / ring mean, median of seeds 1-3 = %.1f, not below %.0f",
              v ? "(g/3,0)" : "(0,g/3)", med, COLOUR_BOUND);
    }
    for (int seed = 1; seed <= 3; seed++) {
        const char *at = "-";
        const double w = first_sweep(xy, n, g, seed, &at);
        CHECK(w >= 0 && w < FIRST_BOUND, "seed %d: the first sweep's print, P%s / ring mean = %.1f, not below %.0f",
              seed, at, w, FIRST_BOUND);
    }
    const double w = planted(xy, n, g);
    CHECK(w >= 0 && w < UNPRINT_BOUND, "a print written after the first sweep: P / ring mean %.1f after %d iterations, "
          "not below %.0f", w, UNPRINT_ITERS, UNPRINT_BOUND);
    free(xy);
    return test_report(passed_, failed_);
}
