/* pd.h - the interface the three Poisson-disk samplers share: dart
 * throwing (dart.c), boundary sampling (bsample.c) and Bridson (bridson.c).
 *
 * Every sampler works on the unit torus with the periodic distance, takes
 * its randomness from the counter-based generator (rng.h: each draw is a
 * pure function of the seed, the sampler's stream and a running counter,
 * so a seed gives the same points on every machine), guarantees that every
 * pair of its points is at least r apart (cfpo_torus_dist2 >= r^2, the
 * test's own arithmetic), and returns the points in the order placed.
 * BS and Bridson return maximal sets: every point of the torus lies within
 * rho = r (1 + PD_RHO_EPS) of a sample (see arcs.h). */
#ifndef CFPO_BASELINES_PD_H
#define CFPO_BASELINES_PD_H

#include <stddef.h>
#include <stdint.h>

#include "density.h"

/* BS and Bridson place new samples at distance rho = r (1 + PD_RHO_EPS)
 * from their parent and track coverage by disks of radius rho: the margin
 * keeps every placed point at least r from the others in spite of
 * rounding, and costs a covering radius at most 1e-9 relative above r. */
#define PD_RHO_EPS 0x1p-30

/* Progress: called when the count crosses a multiple of report_step and
 * every 2^22 trials; trials = darts (DT) or candidates (BS, Bridson);
 * active = samples still on the front (BS, Bridson) or the current run of
 * consecutive rejected darts (DT). */
typedef void (*pd_report_fn)(void *user, int64_t placed, uint64_t trials, int64_t active);

typedef struct {
    uint64_t seed;
    double r;             /* the Poisson-disk radius: minimum distance */
    int64_t target;       /* DT: points to place; BS/Bridson: expected count (a size hint) */
    uint64_t max_fails;   /* DT: consecutive rejected darts that mean saturation */
    int k;                /* Bridson: candidates per active sample (30) */
    int plain;            /* Bridson: 1 = the 2007 algorithm only (not maximal) */
    int64_t report_step;
    pd_report_fn report;
    void *user;
    const cfpo_density *density; /* DT only: adaptive dart throwing
                           * (dart_density.c), NULL: uniform */
} pd_params;

typedef struct {
    double *xy;           /* malloc'ed, 2 n doubles; the caller frees it */
    int64_t n;
    uint64_t trials;
    int saturated;        /* DT: stopped by max_fails before target */
} pd_result;

/* 0 on success; -1 with a message (out of memory). DT's saturation is a
 * success with res->saturated = 1 and res->n < target. */
int dart_sample(const pd_params *p, pd_result *res, char *err, size_t errlen);
/* DT under p->density: every pair has d^2 q_i q_j >= r^2, q = sqrt(rho). */
int dart_density_sample(const pd_params *p, pd_result *res, char *err, size_t errlen);
int bs_sample(const pd_params *p, pd_result *res, char *err, size_t errlen);
int bridson_sample(const pd_params *p, pd_result *res, char *err, size_t errlen);

#endif
