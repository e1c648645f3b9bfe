/* pd_check.c - see pd_check.h. */
#include "pd_check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geom.h"
#include "pdgrid.h"

const pd_names pd_cli_names = {"-n N", "--radius", "--radius R", "--rel-radius", "--max-fails"};
const pd_names pd_py_names = {"n", "radius", "radius", "rel_radius", "max_fails"};

void pd_params_of(const bl_method *m, const bl_value *v, uint64_t seed, pd_params *p, double *radius, double *rel)
{
    const int ifails = bl_option_index(m, "max-fails"), ik = bl_option_index(m, "candidates");
    const int iplain = bl_option_index(m, "plain");
    memset(p, 0, sizeof *p);
    p->seed = seed;
    p->k = ik >= 0 ? (int)v[ik].i : 0;
    p->plain = iplain >= 0 ? (int)v[iplain].i : 0;
    p->max_fails = ifails >= 0 ? (uint64_t)v[ifails].i : 0;
    *radius = v[bl_option_index(m, "radius")].d;
    *rel = v[bl_option_index(m, "rel-radius")].d;
}

int pd_check_args(int kind, int64_t n, double radius, double rel, const pd_names *w, char *err, size_t errlen)
{
    if (radius > 0 && rel > 0) {
        snprintf(err, errlen, "give %s or %s, not both", w->radius, w->rel);
        return -1;
    }
    if (n < 0 && kind == PD_DART) {
        snprintf(err, errlen, "the number of points is required: %s", w->n_required);
        return -1;
    }
    if (n < 0 && radius < 0) {
        snprintf(err, errlen, "%s or %s is required", w->n_required, w->radius_required);
        return -1;
    }
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large for one process (at most %lld)", (long long)n,
                 (long long)UINT32_MAX - 1);
        return -1;
    }
    return 0;
}

int pd_setup(int kind, int64_t n, double radius, double rel, double rel_default, const pd_names *w, pd_params *p,
             char *err, size_t errlen)
{
    if (radius < 0) radius = (rel > 0 ? rel : rel_default) * cfpo_delta_bound((double)n);
    /* DT: r < 1/2 keeps the periodic distance meaningful; BS and Bridson
     * look 2 rho around a sample, which must stay below 1/2. */
    const double rmax = kind == PD_DART ? 0.5 : 0.25 / (1.0 + PD_RHO_EPS);
    if (!(radius < rmax)) {
        snprintf(err, errlen, "radius %g is too large for the unit torus (must be below %g%s%s)", radius, rmax,
                 n > 0 ? "; use more points or a smaller " : "", n > 0 ? w->rel : "");
        return -1;
    }
    if (pdgrid_cells(radius) > 4294967295.0) {
        snprintf(err, errlen, "radius %g is too small: the grid would need %.3g cells", radius, pdgrid_cells(radius));
        return -1;
    }
    if (p->density && !(radius / sqrt(p->density->rho_min) < rmax)) {
        snprintf(err, errlen, "radius %g is too large for the unit torus at the density's sparsest pixel "
                 "(r / sqrt(rho_min) = %g, must be below %g); use more points or a smaller %s", radius,
                 radius / sqrt(p->density->rho_min), rmax, w->rel);
        return -1;
    }
    p->r = radius;
    if (kind == PD_DART) p->target = n;
    else p->target = n > 0 ? n : (int64_t)(2.0 * rel_default * rel_default / (sqrt(3.0) * radius * radius)) + 1;
    p->report_step = p->target / 64 > 0 ? p->target / 64 : 1;
    return 0;
}

int pd_sample(int kind, const pd_params *p, pd_result *res, char *err, size_t errlen)
{
    if (kind == PD_DART && p->density) return dart_density_sample(p, res, err, errlen);
    return kind == PD_DART ? dart_sample(p, res, err, errlen)
         : kind == PD_BS   ? bs_sample(p, res, err, errlen)
                           : bridson_sample(p, res, err, errlen);
}

int pd_verdict(int kind, const pd_result *res, int64_t n, const pd_params *p, const pd_names *w, char *err,
               size_t errlen)
{
    if (res->saturated) {
        snprintf(err, errlen,
                 "saturated: placed %lld of %lld points at radius r = %.9g (%.4f Delta(n)); "
                 "%llu consecutive darts were rejected. Use a smaller %s or %s, or a larger %s",
                 (long long)res->n, (long long)n, p->r, p->r / cfpo_delta_bound((double)n),
                 (unsigned long long)p->max_fails, w->rel, w->radius, w->max_fails);
        return -1;
    }
    if (res->n < 2 && kind != PD_DART) {
        snprintf(err, errlen, "radius %g leaves only %lld point(s)", p->r, (long long)res->n);
        return -1;
    }
    return 0;
}
