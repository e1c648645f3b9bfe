/* bnot.cpp - see bnot.h. BNOT on CGAL's Regular_triangulation_2: the
 * engine's making (the start, the first diagram and solve), the run to a
 * move tolerance (bnot_iterate; the authors' schedule is bnot_rule.cpp),
 * and the engine's accessors. The power diagram and the capacity solve
 * are bnot_power.cpp. */
#include "bnot_types.hpp"

static bnot_engine *make(int64_t n, const double *xy, uint64_t seed, double L, double tol, double cap_tol,
                         const bnot_rule *rule, const cfpo_density *dens, int flags, char *err, size_t errlen)
{
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return nullptr;
    }
    bnot_engine *E = new (std::nothrow) bnot_engine;
    if (!E) {
        snprintf(err, errlen, "out of memory");
        return nullptr;
    }
    try {
        const size_t N = (size_t)n;
        E->n = n;
        E->L = L;
        E->tol = tol;
        E->cap_tol = cap_tol;
        bnot_rule_init(&E->rule);
        E->rule.epsilon = 0;
        if (rule && rule->epsilon > 0) {
            E->rule = *rule;
            E->rng_seed = seed;
            E->phase = COARSE;
            E->max_newton = rule->max_newton;
            E->gthr = 2 * 0.03 * rule->epsilon / (double)n;
            E->res_tol = E->gthr;
        }
        E->target = 1.0 / (double)n;
        E->margin = std::min(1.0, 3.0 / std::sqrt((double)n));
        E->xy.resize(2 * N);
        for (int64_t i = 0; i < 2 * n; i++)
            E->xy[(size_t)i] = xy ? xy[i] : cfpo_rand01(seed, START_STREAM, (uint64_t)i);
        if (dens) {
            E->dens = dens;
            /* the uniform start thinned to rho: for rho = 1 the same points */
            dens_draw draw;
            if (!xy) {
                if (dens_draw_init(&draw, dens) != 0) throw std::bad_alloc();
                for (int64_t k = 0; k < n; k++)
                    dens_draw_at(&draw, seed, START_DENS_STREAM, (uint64_t)k, &E->xy[2 * k], &E->xy[2 * k + 1]);
                dens_draw_free(&draw);
            }
            E->pixels = (flags & BNOT_DENS_PIXELS) || !(dens->support == 1.0 && dens->rho_min == dens->rho_max);
            if (E->pixels && dens_poly_init(&E->dp, dens) != 0) throw std::bad_alloc();
        }
        E->w.assign(N, 0.0);
        E->area.assign(N, 0.0);
        E->mom.assign(N, 0.0);
        E->cen.assign(2 * N, 0.0);
        E->rowp.assign(N + 1, 0);
        E->diag.assign(N, 0.0);
        E->r.assign(N, 0.0);
        E->z = E->p = E->q = E->d = E->r;
        bnot_build(E);
        if (E->empty) {
            snprintf(err, errlen, "the start has %lld coinciding points", (long long)E->empty);
            delete E;
            return nullptr;
        }
        bnot_solve(E);
        E->energy_moved = E->energy;
    } catch (const std::bad_alloc &) {
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        delete E;
        return nullptr;
    }
    return E;
}

extern "C" {

bnot_engine *bnot_create(int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, seed, err, errlen) != 0) return nullptr;
    return make(n, nullptr, seed, G.L, tol, BNOT_CAP_TOL, nullptr, nullptr, 0, err, errlen);
}

bnot_engine *bnot_create_rule(int64_t n, const double *xy, uint64_t seed, double L, double tol,
                              const bnot_rule *r, char *err, size_t errlen)
{
    return bnot_create_density(n, xy, seed, L, tol, r, nullptr, 0, err, errlen);
}

bnot_engine *bnot_create_density(int64_t n, const double *xy, uint64_t seed, double L, double tol,
                                 const bnot_rule *r, const cfpo_density *d, int flags, char *err, size_t errlen)
{
    bnot_rule def;
    bnot_rule_init(&def);
    if (!r) r = &def;
    if (d && !(r->epsilon > 0)) { /* the run to a move tolerance */
        if (!(L > 0)) {
            cfpo_grid G;
            if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, seed, err, errlen) != 0) return nullptr;
            L = G.L;
        }
        return make(n, xy, seed, L, tol, BNOT_CAP_TOL, nullptr, d, flags, err, errlen);
    }
    if (!(r->epsilon > 0) || r->max_rounds < 1 || r->round_iters < 1 || r->max_newton < 1 || r->max_teleport < 0 ||
        !(r->jitter >= 0)) {
        snprintf(err, errlen, "bad BNOT schedule (epsilon %g, rounds %d, round iterations %d, Newton steps %d)",
                 r->epsilon, r->max_rounds, r->round_iters, r->max_newton);
        return nullptr;
    }
    if (!(L > 0)) {
        cfpo_grid G;
        if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, seed, err, errlen) != 0) return nullptr;
        L = G.L;
    }
    return make(n, xy, seed, L, tol, BNOT_CAP_TOL, r, d, flags, err, errlen);
}

bnot_engine *bnot_create_from(int64_t n, const double *xy, double L, double tol, double cap_tol, char *err,
                              size_t errlen)
{
    return make(n, xy, 0, L, tol, cap_tol, nullptr, nullptr, 0, err, errlen);
}

void bnot_free(bnot_engine *E) { delete E; }

void bnot_iterate(bnot_engine *E, cfpo_iter_stats *s)
{
    if (E->phase != TOL_RUN) {
        bnot_rule_iterate(E, s);
        return;
    }
    const double t0 = cli_now();
    const double tolL = E->tol * E->L;
    double maxd2 = 0, moved_energy = E->energy;
    int64_t moved = 0;
    for (int64_t i = 0; i < E->n; i++) {
        const double dx = E->cen[2 * i], dy = E->cen[2 * i + 1], d2 = dx * dx + dy * dy;
        moved_energy -= E->area[(size_t)i] * d2;
        maxd2 = std::max(maxd2, d2);
        if (d2 > tolL * tolL) moved++;
        E->xy[2 * i] = cfpo_wrap01(E->xy[2 * i] + dx);
        E->xy[2 * i + 1] = cfpo_wrap01(E->xy[2 * i + 1] + dy);
    }
    E->energy_moved = moved_energy;
    bnot_solve(E);
    s->moved = moved;
    s->solved = E->n;
    s->max_disp = std::sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = cfpo_net_converged(moved, s->max_disp, E->tol);
    bnot_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

double bnot_energy(const bnot_engine *E) { return E->energy; }
double bnot_energy_moved(const bnot_engine *E) { return E->energy_moved; }
double bnot_energy_nsm(const bnot_engine *E) { return 0.5 * (double)E->n * E->energy; }
double bnot_cap_err(const bnot_engine *E) { return E->cap_err; }
int bnot_newton_steps(const bnot_engine *E) { return E->newton; }
int64_t bnot_cg_iterations(const bnot_engine *E) { return E->cg_iters; }
int bnot_solve_ok(const bnot_engine *E) { return E->ok; }
const double *bnot_areas(const bnot_engine *E) { return E->area.data(); }
const double *bnot_weights(const bnot_engine *E) { return E->w.data(); }

const double *bnot_centroids(const bnot_engine *E)
{
    E->abscen.resize(2 * (size_t)E->n);
    for (int64_t i = 0; i < 2 * E->n; i++) E->abscen[(size_t)i] = E->xy[(size_t)i] + E->cen[(size_t)i];
    return E->abscen.data();
}


const double *bnot_points(const bnot_engine *E) { return E->xy.data(); }

void bnot_check(const bnot_engine *E, bnot_check_info *c)
{
    c->valid = E->T.is_valid() ? 1 : 0;
    c->empty = 0;
    c->area_sum = 0;
    for (int64_t i = 0; i < E->n; i++) {
        if (E->vh[(size_t)i] == Vertex_handle() || E->vh[(size_t)i]->is_hidden() || !(E->area[(size_t)i] > 0))
            c->empty++;
        c->area_sum += E->area[(size_t)i];
    }
    c->margin = E->margin;
}

} // extern "C"
