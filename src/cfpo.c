/* cfpo.c - layer 5, library side: the functions of the public header. */
#define _DEFAULT_SOURCE
#include "cfpo.h"

#include <string.h>

#include <math.h>
#include <stdio.h>
#include <unistd.h>

#include "cli.h"
#include "density.h"
#include "engine.h"
#include "engines.h"
#include "run_loop.h"
#include "grid.h"
#include "policy.h"

double cfpo_default_tol(int variant)
{
    return cfpo_policy_default_tol(variant, 0);
}

void cfpo_options_init(cfpo_options *o)
{
    o->seed = 1;
    o->variant = CFPO_VARIANT_ADAPTIVE;
    o->threads = 0;
    o->max_iter = CFPO_DEFAULT_MAX_ITER;
    o->tol = cfpo_default_tol(o->variant);
    o->skip = 1;
    o->stop.target_min = o->stop.target_avg = o->stop.time_limit = 0;
    o->progress = NULL;
    o->user = NULL;
    o->lazy_measure = 0;
}

int cfpo_variant_parse(const char *name, int *variant)
{
    if (strcmp(name, "adaptive") == 0) *variant = CFPO_VARIANT_ADAPTIVE;
    else if (strcmp(name, "paper") == 0 || strcmp(name, "cfpo") == 0) *variant = CFPO_VARIANT_PAPER;
    else if (strcmp(name, "simplified") == 0) *variant = CFPO_VARIANT_SIMPLIFIED;
    else if (strcmp(name, "hyperuniform") == 0) *variant = CFPO_VARIANT_HYPERUNIFORM;
    else return -1;
    return 0;
}

const char *cfpo_variant_name(int variant)
{
    switch (variant) {
    case CFPO_VARIANT_ADAPTIVE: return "adaptive";
    case CFPO_VARIANT_PAPER: return "paper";
    case CFPO_VARIANT_SIMPLIFIED: return "simplified";
    case CFPO_VARIANT_HYPERUNIFORM: return "hyperuniform";
    default: return "?";
    }
}

static int validate_options(const cfpo_options *o, char *err, size_t errlen)
{
    if (o->variant != CFPO_VARIANT_PAPER && o->variant != CFPO_VARIANT_SIMPLIFIED &&
        o->variant != CFPO_VARIANT_ADAPTIVE && o->variant != CFPO_VARIANT_HYPERUNIFORM) {
        snprintf(err, errlen, "unknown variant %d", o->variant);
        return -1;
    }
    if (!(o->tol >= 0 && o->tol <= CFPO_TOL_MAX)) {
        snprintf(err, errlen, "tolerance %g is out of range [0, %g]", o->tol, CFPO_TOL_MAX);
        return -1;
    }
    if (o->threads < 0 || o->threads > 4096) {
        snprintf(err, errlen, "thread count %d is out of range 0..4096", o->threads);
        return -1;
    }
    if (o->max_iter < 0) {
        snprintf(err, errlen, "max_iter %d is negative", o->max_iter);
        return -1;
    }
    return 0;
}

int cfpo_validate_ranks(int64_t n, const cfpo_options *o, int64_t rank_points, int64_t rank_cells,
                        int64_t rank_ring, int ranks_here, char *err, size_t errlen)
{
    if (validate_options(o, err, errlen) != 0) return -1;
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o->variant, o->seed, err, errlen) != 0) return -1;
    if (rank_points >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld puts about %lld points on one rank (at most %lld); use more ranks",
                 (long long)n, (long long)rank_points, (long long)UINT32_MAX - 1);
        return -1;
    }
    double need = (double)cfpo_engine_bytes_local(rank_points, rank_cells, rank_ring, o->threads) *
                  (ranks_here > 0 ? ranks_here : 1);
    double have = cli_physical_memory();
    if (need > 0.9 * have) {
        snprintf(err, errlen, "n = %lld is too large for memory: the ranks on this machine need %.1f GB, "
                 "it has %.1f GB", (long long)n, need / 1e9, have / 1e9);
        return -2;
    }
    return 0;
}

int cfpo_validate(int64_t n, const cfpo_options *o, char *err, size_t errlen)
{
    if (validate_options(o, err, errlen) != 0) return -1;
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, o->variant, o->seed, err, errlen) != 0) return -1;
    /* Bucket offsets are 32-bit: one process holds fewer than 2^32 points. */
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large for one process (at most %lld; use MPI ranks)",
                 (long long)n, (long long)UINT32_MAX - 1);
        return -1;
    }
    double need = (double)cfpo_engine_bytes(n, o->variant, o->threads), have = cli_physical_memory();
    if (need > 0.9 * have) {
        snprintf(err, errlen, "n = %lld is too large for memory: needs %.1f GB, this machine has "
                 "%.1f GB", (long long)n, need / 1e9, have / 1e9);
        return -2;
    }
    return 0;
}

/* One run through the one interface (engines.h, run_loop.h); d may be NULL. */
static int sample(int64_t n, const cfpo_options *o, const cfpo_density *d, double *xy, cfpo_result *res, char *err,
                  size_t errlen)
{
    if (validate_options(o, err, errlen) != 0) return -1;
    if (d && !cfpo_density_is_flat(d)) {
        if (o->variant != CFPO_VARIANT_ADAPTIVE) {
            snprintf(err, errlen, "variant %s does not go with a density (the density run has one variant)",
                     cfpo_variant_name(o->variant));
            return -1;
        }
        if (cfpo_density_check_n(d, n, err, errlen) != 0) return -1;
    }
    cfpo_engine_config cfg;
    memset(&cfg, 0, sizeof cfg);
    cfpo_run_engine R;
    if (cfpo_engines_open(n, o, &cfg, d, cli_now(), &R, err, errlen) != 0) return -1;
    cfpo_result r;
    const int rc = cfpo_run_loop(&R, NULL, 0, &r, err, errlen);
    if (rc == 0) R.ops->copy(R.E, xy);
    R.ops->free(R.E);
    if (rc == 0 && res) *res = r;
    return rc;
}

int cfpo_sample(int64_t n, const cfpo_options *o, double *xy, cfpo_result *res, char *err, size_t errlen)
{
    return sample(n, o, NULL, xy, res, err, errlen);
}

int cfpo_sample_density(int64_t n, const cfpo_options *o, const char *density, double *xy, cfpo_result *res,
                        char *err, size_t errlen)
{
    cfpo_density d;
    if (cfpo_density_load(density, &d, err, errlen) != 0) return -1;
    const int rc = sample(n, o, &d, xy, res, err, errlen);
    cfpo_density_free(&d);
    return rc;
}

int cfpo_sample_density_values(int64_t n, const cfpo_options *o, const double *rho, int64_t w, int64_t h, double *xy,
                               cfpo_result *res, char *err, size_t errlen)
{
    cfpo_density d;
    if (cfpo_density_from_values(rho, w, h, "density", &d, err, errlen) != 0) return -1;
    const int rc = sample(n, o, &d, xy, res, err, errlen);
    cfpo_density_free(&d);
    return rc;
}
