/* bnot_rule.cpp - the authors' schedule of BNOT (bnot.h): the two-phase
 * stopping rule on the gradient norm and the regularity breaker between
 * rounds. The diagram and the capacity solve are bnot_power.cpp's.
 *
 * One iteration here is one position step of the current phase with the
 * solve that follows it, so the trace's rows are the reference's
 * iterations: the norm is measured right after the step, on the weights
 * the step was taken with (a triangulation of the moved sites), as the
 * reference measures it; the solve for the next step comes after. */
#include "bnot_types.hpp"

extern "C" void bnot_rule_init(bnot_rule *r)
{
    r->epsilon = BNOT_DEFAULT_EPSILON;
    r->breaker = 1;
    r->max_rounds = BNOT_DEFAULT_MAX_ROUNDS;
    r->max_teleport = 100;
    r->round_iters = BNOT_DEFAULT_ROUND_ITERS;
    r->max_newton = 20;
    r->jitter = 1.0;
}

static double tau(const bnot_engine *E) { return 0.03 * E->rule.epsilon / (double)E->n; }

/* |g| on the current diagram: sqrt(sum_i (2 A_i |c_i - x_i|)^2) */
static double grad_norm(const bnot_engine *E)
{
    double s = 0;
    for (int64_t i = 0; i < E->n; i++) {
        const double a = 2 * E->area[(size_t)i], cx = E->cen[2 * i], cy = E->cen[2 * i + 1];
        s += a * a * (cx * cx + cy * cy);
    }
    return std::sqrt(s);
}

/* F = E - sum_i w_i (A_i - 1/n): the functional the fine step lowers with
 * the weights fixed (its gradient in x_i is 2 A_i (x_i - c_i)). */
static double dual(const bnot_engine *E)
{
    double s = E->energy;
    for (int64_t i = 0; i < E->n; i++) s -= E->w[(size_t)i] * (E->area[(size_t)i] - E->target);
    return s;
}

static double rnd(bnot_engine *E) { return cfpo_rand01(E->rng_seed, BREAK_STREAM, E->rng_ctr++); }

/* Every site by its own step (the caller has x0 = xy and the step in
 * E->stepv): sites at x0 + a step; moved counts and the largest move. */
static void place(bnot_engine *E, double a, int64_t *moved, double *maxd2)
{
    const double tolL = E->tol * E->L;
    *moved = 0;
    *maxd2 = 0;
    for (int64_t i = 0; i < E->n; i++) {
        const double dx = a * E->stepv[2 * i], dy = a * E->stepv[2 * i + 1], d2 = dx * dx + dy * dy;
        *maxd2 = std::max(*maxd2, d2);
        if (d2 > tolL * tolL) (*moved)++;
        E->xy[2 * i] = cfpo_wrap01(E->xy0[2 * i] + dx);
        E->xy[2 * i + 1] = cfpo_wrap01(E->xy0[2 * i + 1] + dy);
    }
}

/* Coarse: the Lloyd step (the weights were reset before the last solve). */
static void coarse_step(bnot_engine *E, int64_t *moved, double *maxd2)
{
    E->xy0 = E->xy;
    E->stepv = E->cen;
    place(E, 1.0, moved, maxd2);
    bnot_build(E);
}

/* Fine: x_i + a 2 A_i (c_i - x_i), a = n/2, n/4, ... (at most 100 tries)
 * until every cell stays and F fell by 1e-4 a |g|^2; no move if none. */
static void fine_step(bnot_engine *E, int64_t *moved, double *maxd2)
{
    const int64_t n = E->n;
    E->xy0 = E->xy;
    E->stepv.resize(2 * (size_t)n);
    double g2 = 0;
    for (int64_t i = 0; i < n; i++) {
        const double a = 2 * E->area[(size_t)i];
        E->stepv[2 * i] = a * E->cen[2 * i];
        E->stepv[2 * i + 1] = a * E->cen[2 * i + 1];
        g2 += E->stepv[2 * i] * E->stepv[2 * i] + E->stepv[2 * i + 1] * E->stepv[2 * i + 1];
    }
    const double F0 = dual(E);
    double a = 0.5 * (double)n;
    for (int k = 0; k < 100; k++, a *= 0.5) {
        place(E, a, moved, maxd2);
        bnot_build(E);
        if (E->empty == 0 && dual(E) <= F0 - 1e-4 * a * g2) return;
    }
    place(E, 0.0, moved, maxd2);
    bnot_build(E);
}

static void set_phase(bnot_engine *E, int phase)
{
    E->phase = phase;
    E->gthr = phase == COARSE ? 2 * tau(E) : phase == FINE ? tau(E) : 0;
    E->res_tol = phase == COARSE ? 2 * tau(E) : tau(E);
}

extern "C" int64_t bnot_regular_sites(bnot_engine *E, unsigned char *flag)
{
    const double C = 1.0 / (double)E->n, thr = 0.25 * C * C * C;
    int64_t cnt = 0;
    for (int64_t i = 0; i < E->n; i++) {
        const int64_t b = E->rowp[(size_t)i], e = E->rowp[(size_t)i + 1];
        int reg = 0;
        if (E->area[(size_t)i] > 0 && e > b) {
            double dev = 0;
            for (int64_t k = b; k < e; k++) dev += std::fabs(E->mom[(size_t)i] - E->mom[E->col[(size_t)k]]);
            reg = dev / (double)(e - b) < thr;
        }
        if (flag) flag[i] = (unsigned char)reg;
        cnt += reg;
    }
    return cnt;
}

extern "C" int64_t bnot_break_regularity(bnot_engine *E)
{
    const int64_t n = E->n;
    E->flag.assign((size_t)n, 0);
    const int64_t k = bnot_regular_sites(E, E->flag.data());
    E->last_regular = k;
    if (k == 0) return 0;
    E->pick.clear();
    for (int64_t i = 0; i < n; i++)
        if (E->flag[(size_t)i] == 1) {
            E->pick.push_back((uint32_t)i);
            for (int64_t j = E->rowp[(size_t)i]; j < E->rowp[(size_t)i + 1]; j++)
                if (!E->flag[E->col[(size_t)j]]) E->flag[E->col[(size_t)j]] = 2;
        }
    const double r = E->rule.jitter / (double)n;
    if (r > 0)
        for (int64_t i = 0; i < n; i++) {
            if (!E->flag[(size_t)i]) continue;
            const double ang = 2 * M_PI * rnd(E), rad = r * rnd(E);
            E->xy[2 * i] = cfpo_wrap01(E->xy[2 * i] + rad * std::cos(ang));
            E->xy[2 * i + 1] = cfpo_wrap01(E->xy[2 * i + 1] + rad * std::sin(ang));
        }
    /* min(max_teleport, k) distinct regular sites: a partial shuffle */
    const size_t t = std::min<size_t>((size_t)E->rule.max_teleport, E->pick.size());
    for (size_t j = 0; j < t; j++) {
        const size_t m = j + std::min(E->pick.size() - j - 1, (size_t)(rnd(E) * (double)(E->pick.size() - j)));
        std::swap(E->pick[j], E->pick[m]);
        const uint32_t i = E->pick[j];
        E->xy[2 * (size_t)i] = rnd(E);
        E->xy[2 * (size_t)i + 1] = rnd(E);
    }
    E->breaks++;
    std::fill(E->w.begin(), E->w.end(), 0.0);
    const double keep = E->res_tol;
    E->res_tol = 2 * tau(E);
    bnot_solve(E);
    E->res_tol = keep;
    return k;
}

/* The round is over: break the regularity and start a new round, or end. */
static int end_round(bnot_engine *E)
{
    if (E->rule.breaker && E->round < E->rule.max_rounds && bnot_break_regularity(E) > 0) {
        E->round++;
        E->round_iter = 0;
        set_phase(E, COARSE);
        return 0;
    }
    set_phase(E, DONE);
    bnot_solve(E);
    return 1;
}

void bnot_rule_iterate(bnot_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    int64_t moved = 0;
    double maxd2 = 0;
    int done = 0;
    E->round_iter++;
    E->step_phase = E->phase;
    if (E->phase == COARSE) {
        coarse_step(E, &moved, &maxd2);
        E->gnorm = grad_norm(E);
        if (E->gnorm <= 2 * tau(E)) {
            set_phase(E, FINE);
            bnot_solve(E);
        } else if (E->round_iter >= E->rule.round_iters) {
            set_phase(E, DONE); /* the reference returns here, no breaker */
            bnot_solve(E);
            done = 1;
        } else {
            std::fill(E->w.begin(), E->w.end(), 0.0);
            bnot_solve(E);
        }
    } else if (E->phase == FINE) {
        fine_step(E, &moved, &maxd2);
        E->gnorm = grad_norm(E);
        if (E->gnorm <= tau(E) || E->round_iter >= E->rule.round_iters) done = end_round(E);
        else bnot_solve(E);
    } else {
        done = 1;
    }
    E->energy_moved = E->energy;
    s->moved = moved;
    s->solved = E->n;
    s->max_disp = std::sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = done;
    bnot_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

extern "C" {
double bnot_grad_norm(const bnot_engine *E) { return E->gnorm; }
int bnot_phase(const bnot_engine *E) { return E->phase; }
int bnot_step_phase(const bnot_engine *E) { return E->step_phase; }
int bnot_round(const bnot_engine *E) { return E->round; }
int64_t bnot_breaks(const bnot_engine *E) { return E->breaks; }
int64_t bnot_last_regular(const bnot_engine *E) { return E->last_regular; }
}
