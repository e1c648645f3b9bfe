/* pd_check.h - the one radius check of the Poisson-disk samplers (dart,
 * bs, bridson), shared by their command (pd_main.c) and the Python binding:
 * the radius from -n or given, its bounds on the unit torus and for the
 * grid, the expected count, the call of the sampler, and the verdict on its
 * result (saturation, too few points). The messages name the options as
 * the caller spells them (pd_names).
 * Does not own: the samplers (pd.h), the options' table (bl_pd.c). */
#ifndef CFPO_BASELINES_PD_CHECK_H
#define CFPO_BASELINES_PD_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include "bl_method.h"
#include "pd.h"

enum { PD_DART = 0, PD_BS = 1, PD_BRIDSON = 2 };

/* Default relative radii r / Delta(n) (baselines/README.md, "Radii", says
 * how they were measured). */
#define PD_DART_REL 0.75
#define PD_BS_REL 0.8495
#define PD_BRIDSON_REL 0.7755
/* Dart throwing's saturation cap on consecutive rejected darts. */
#define PD_DART_MAX_FAILS 1000000

/* How the caller spells the options in messages. */
typedef struct {
    const char *n_required;      /* "-n N" */
    const char *radius;          /* "--radius" */
    const char *radius_required; /* "--radius R" */
    const char *rel;             /* "--rel-radius" */
    const char *max_fails;       /* "--max-fails" */
} pd_names;

extern const pd_names pd_cli_names, pd_py_names;

/* The sampler's parameters from a Poisson-disk method's option values v
 * (bl_pd.c) and the seed; *radius and *rel as given (-1: not given). */
void pd_params_of(const bl_method *m, const bl_value *v, uint64_t seed, pd_params *p, double *radius, double *rel);

/* The checks of the arguments before the radius: n (-1: not given),
 * radius and rel (-1: not given). 0, or -1 with the message. */
int pd_check_args(int kind, int64_t n, double radius, double rel, const pd_names *w, char *err, size_t errlen);

/* Sets p->r, p->target and p->report_step for sampler `kind` from
 * arguments that passed pd_check_args (rel_default where rel is not
 * given). 0, or -1 with the message of a radius out of bounds. */
int pd_setup(int kind, int64_t n, double radius, double rel, double rel_default, const pd_names *w, pd_params *p,
             char *err, size_t errlen);

/* Runs sampler `kind`. 0, or -1 with a message (out of memory). */
int pd_sample(int kind, const pd_params *p, pd_result *res, char *err, size_t errlen);

/* The verdict on a result: 0, or -1 with the message (dart throwing
 * saturated before n points, or a maximal set of fewer than 2 points). */
int pd_verdict(int kind, const pd_result *res, int64_t n, const pd_params *p, const pd_names *w, char *err,
               size_t errlen);

#endif
