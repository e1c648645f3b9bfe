/* test_bnot_rule.c - BNOT's authors' schedule (bnot.h, bnot_rule.cpp):
 *  - the stopping rule, on a traced run without the breaker: the phase of
 *    every step is the phase before it; the coarse phase ends at the first
 *    iteration whose norm is <= 2 tau, tau = 0.03 epsilon / n; the run
 *    stops at the first fine iteration with norm <= tau; the capacities
 *    then hold to tau (2-norm of A - 1/n);
 *  - a round cap reached in the coarse phase ends the run at exactly that
 *    iteration, with the norm still above 2 tau;
 *  - the regularity breaker: on a lattice (congruent cells, equal
 *    weights) every site is regular, a break moves them (100 teleported)
 *    and, the capacities solved again, leaves far fewer regular; a
 *    lattice half beside a jittered half has regular sites, all in the
 *    lattice half away from the seam; a random set (its capacities
 *    solved) and one after 10 iterations at 2,048 sites have none, and
 *    a break leaves them untouched (at a few hundred sites the threshold,
 *    relative to the cells' moments about 3/n, already finds a few in an
 *    optimised set);
 *  - the schedule, breaker rounds included, is deterministic per seed,
 *    and another seed gives other points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bnot.h"
#include "rng.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static double res_norm(const bnot_engine *E, int64_t n)
{
    const double *A = bnot_areas(E);
    double s = 0;
    for (int64_t i = 0; i < n; i++) s += (A[i] - 1.0 / (double)n) * (A[i] - 1.0 / (double)n);
    return sqrt(s);
}

static void rule_stops(int64_t n)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.breaker = 0;
    r.round_iters = 500;
    char err[256];
    bnot_engine *E = bnot_create_rule(n, NULL, 7, 0, 1e-3, &r, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    const double tau = 0.03 * r.epsilon / (double)n;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    int coarse_end = 0, it, bad_norm = 0, early = 0;
    for (it = 1; it <= 1000 && !s.converged; it++) {
        const int phase = bnot_phase(E);
        bnot_iterate(E, &s);
        CHECK(bnot_step_phase(E) == phase, "iteration %d: step phase %d, phase before %d", it, bnot_step_phase(E), phase);
        const double g = bnot_grad_norm(E);
        if (phase == 1) {
            if (g <= 2 * tau) coarse_end = it;
            if (g <= 2 * tau && bnot_phase(E) != 2) early++;
            if (g > 2 * tau && bnot_phase(E) != 1) early++;
        } else {
            if (g > tau && s.converged) early++;
            if (g <= tau && !s.converged) early++;
        }
        if (!(g > 0) || !isfinite(g)) bad_norm++;
    }
    CHECK(s.converged, "n=%lld: the schedule did not stop in 1000 iterations", (long long)n);
    CHECK(coarse_end > 1, "n=%lld: the coarse phase never met 2 tau", (long long)n);
    CHECK(early == 0, "n=%lld: %d iterations where the phase or the stop disagrees with the norm", (long long)n, early);
    CHECK(bad_norm == 0, "n=%lld: %d norms not positive and finite", (long long)n, bad_norm);
    CHECK(bnot_phase(E) == 3, "n=%lld: phase %d at the end", (long long)n, bnot_phase(E));
    CHECK(res_norm(E, n) < tau, "n=%lld: |A - 1/n| = %.3g > tau %.3g at the end", (long long)n, res_norm(E, n), tau);
    CHECK(s.delta_min > 0.7 && s.delta_avg > 0.85, "n=%lld: delta %.3f / %.3f at the end", (long long)n, s.delta_min,
          s.delta_avg);
    printf("rule n=%lld: coarse phase ended at iteration %d, stopped at %d: delta %.4f / %.4f\n", (long long)n,
           coarse_end, it - 1, s.delta_min, s.delta_avg);
    bnot_free(E);
}

static void rule_round_cap(int64_t n)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.round_iters = 6;
    char err[256];
    bnot_engine *E = bnot_create_rule(n, NULL, 3, 0, 1e-3, &r, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    int it;
    for (it = 1; it <= 100 && !s.converged; it++) bnot_iterate(E, &s);
    CHECK(it - 1 == 6, "n=%lld: a round cap of 6 in the coarse phase stopped after %d iterations", (long long)n, it - 1);
    CHECK(bnot_grad_norm(E) > 2 * 0.03 * r.epsilon / (double)n, "n=%lld: the coarse phase had met 2 tau (%.3g)",
          (long long)n, bnot_grad_norm(E));
    CHECK(bnot_breaks(E) == 0, "n=%lld: the breaker ran after a capped coarse phase", (long long)n);
    bnot_free(E);
}

/* k x m sites, odd rows shifted by half a column: congruent cells */
static double *lattice(int k, int m)
{
    double *xy = malloc(2 * (size_t)k * (size_t)m * sizeof *xy);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < k; i++) {
            xy[2 * (j * k + i)] = (i + 0.25 + 0.5 * (j & 1)) / k;
            xy[2 * (j * k + i) + 1] = (j + 0.5) / m;
        }
    return xy;
}

static bnot_engine *rule_from(int64_t n, const double *xy, uint64_t seed)
{
    bnot_rule r;
    bnot_rule_init(&r);
    char err[256];
    bnot_engine *E = bnot_create_rule(n, xy, seed, 0, 1e-3, &r, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    return E;
}

static void breaker_lattice(int k, int m)
{
    const int64_t n = (int64_t)k * m;
    double *xy = lattice(k, m);
    bnot_engine *E = rule_from(n, xy, 5);
    if (!E) { free(xy); return; }
    const int64_t before = bnot_regular_sites(E, NULL);
    CHECK(before == n, "lattice %dx%d: %lld of %lld sites regular", k, m, (long long)before, (long long)n);
    const int64_t found = bnot_break_regularity(E);
    CHECK(found == n, "lattice: the break found %lld", (long long)found);
    const double *p = bnot_points(E);
    int64_t moved = 0, far = 0;
    for (int64_t i = 0; i < n; i++) {
        double dx = fabs(p[2 * i] - xy[2 * i]), dy = fabs(p[2 * i + 1] - xy[2 * i + 1]);
        dx = fmin(dx, 1 - dx);
        dy = fmin(dy, 1 - dy);
        const double d = hypot(dx, dy);
        if (d > 0) moved++;
        if (d > 1.0 / (double)n * (1 + 1e-9)) far++;
    }
    CHECK(moved == n, "lattice: %lld of %lld sites moved by the break", (long long)moved, (long long)n);
    CHECK(far <= 100 && far >= 90, "lattice: %lld sites moved beyond the jitter radius (100 teleported)", (long long)far);
    const int64_t after = bnot_regular_sites(E, NULL);
    CHECK(after < n / 4, "lattice: %lld of %lld sites still regular after the break", (long long)after, (long long)n);
    printf("breaker lattice %dx%d: %lld regular, %lld teleported beyond the jitter, %lld regular after\n", k, m,
           (long long)before, (long long)far, (long long)after);
    bnot_free(E);
    free(xy);
}

/* The lattice with its sites of x >= 1/2 jittered by up to a fifth of a
 * column: regular sites exist, and all lie at x < 1/2 - 2 columns away
 * from the jittered half (either seam, the torus wraps). */
static void breaker_patch(int k, int m)
{
    const int64_t n = (int64_t)k * m;
    double *xy = lattice(k, m);
    for (int64_t i = 0; i < n; i++)
        if (xy[2 * i] >= 0.5) {
            xy[2 * i] += 0.2 / k * (2 * cfpo_rand01(4, 1, (uint64_t)(2 * i)) - 1);
            xy[2 * i + 1] += 0.2 / m * (2 * cfpo_rand01(4, 1, (uint64_t)(2 * i + 1)) - 1);
        }
    bnot_engine *E = rule_from(n, xy, 5);
    if (!E) { free(xy); return; }
    unsigned char *flag = malloc((size_t)n);
    const int64_t cnt = bnot_regular_sites(E, flag);
    int64_t wrong = 0;
    for (int64_t i = 0; i < n; i++)
        if (flag[i] && (xy[2 * i] >= 0.5 || xy[2 * i] < 1.0 / k)) wrong++;
    CHECK(cnt > 0, "patch: no regular site in the lattice half");
    CHECK(wrong == 0, "patch: %lld regular sites in or beside the jittered half", (long long)wrong);
    printf("breaker patch %dx%d: %lld regular sites, all in the lattice half\n", k, m, (long long)cnt);
    free(flag);
    bnot_free(E);
    free(xy);
}

static void breaker_random(int64_t n, int iters)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.breaker = 0;
    char err[256];
    bnot_engine *E = bnot_create_rule(n, NULL, 11, 0, 1e-3, &r, err, sizeof err);
    CHECK(E != NULL, "create: %s", err);
    if (!E) return;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    for (int it = 0; it < iters; it++) bnot_iterate(E, &s);
    double *before = malloc(2 * (size_t)n * sizeof *before);
    memcpy(before, bnot_points(E), 2 * (size_t)n * sizeof *before);
    CHECK(bnot_regular_sites(E, NULL) == 0, "random n=%lld: %lld regular sites", (long long)n,
          (long long)bnot_regular_sites(E, NULL));
    CHECK(bnot_break_regularity(E) == 0, "random n=%lld: the break found regular sites", (long long)n);
    CHECK(memcmp(before, bnot_points(E), 2 * (size_t)n * sizeof *before) == 0, "random: the break moved sites");
    free(before);
    bnot_free(E);
}

static void rule_determinism(void)
{
    bnot_rule r;
    bnot_rule_init(&r);
    r.round_iters = 500;
    r.max_rounds = 3;
    char err[256];
    const int64_t n = 200;
    bnot_engine *A = bnot_create_rule(n, NULL, 1, 0, 1e-3, &r, err, sizeof err);
    bnot_engine *B = bnot_create_rule(n, NULL, 1, 0, 1e-3, &r, err, sizeof err);
    bnot_engine *C = bnot_create_rule(n, NULL, 2, 0, 1e-3, &r, err, sizeof err);
    CHECK(A && B && C, "create: %s", err);
    if (!A || !B || !C) return;
    cfpo_iter_stats s;
    int done[3] = {0, 0, 0};
    for (int it = 0; it < 3000 && !(done[0] && done[1] && done[2]); it++) {
        bnot_engine *e[3] = {A, B, C};
        for (int j = 0; j < 3; j++)
            if (!done[j]) {
                memset(&s, 0, sizeof s);
                bnot_iterate(e[j], &s);
                done[j] = s.converged;
            }
    }
    CHECK(done[0] && done[1] && done[2], "determinism: a run did not stop");
    CHECK(bnot_breaks(A) >= 1, "determinism: no breaker round at n = 200 (breaks %lld)", (long long)bnot_breaks(A));
    CHECK(bnot_breaks(A) == bnot_breaks(B) && bnot_round(A) == bnot_round(B), "same seed, other rounds");
    CHECK(memcmp(bnot_points(A), bnot_points(B), 2 * (size_t)n * sizeof(double)) == 0, "same seed, other points");
    CHECK(memcmp(bnot_points(A), bnot_points(C), 2 * (size_t)n * sizeof(double)) != 0, "seeds 1 and 2: same points");
    bnot_free(A);
    bnot_free(B);
    bnot_free(C);
}

int main(void)
{
    rule_stops(256);
    rule_round_cap(2048);
    breaker_lattice(24, 28);
    breaker_patch(24, 28);
    breaker_random(300, 0);
    breaker_random(2048, 10);
    rule_determinism();
    return test_report(passed_, failed_);
}
