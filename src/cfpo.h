/* cfpo.h - the public interface of the CFPO sampler.
 *
 * Embed the sampler in a program (a renderer, another sampler) without
 * going through files:
 *
 *     cfpo_options o;
 *     cfpo_options_init(&o);
 *     o.seed = 7;
 *     double *xy = malloc(2 * n * sizeof *xy);
 *     char err[256];
 *     cfpo_result r;
 *     if (cfpo_sample(n, &o, xy, &r, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
 *
 * xy receives n points (x0 y0 x1 y1 ...) on the unit torus [0,1)^2 in id
 * order (cfpo_sample_density below follows a density). The result is a
 * pure function of (n, seed, variant, tol, max_iter): the number of threads and the skipping of unchanged
 * neighbourhoods never change a bit of it. Link with -lcfpo -lm and OpenMP.
 *
 * Layer 4 (the library's front): may include cfpo_types.h only; its
 * implementation, cfpo.c, uses the engine (layer 3). */
#ifndef CFPO_H
#define CFPO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#include "cfpo_types.h"

/* The default tolerance of a variant. */
double cfpo_default_tol(int variant);

void cfpo_options_init(cfpo_options *o);

/* "adaptive", "paper" (alias "cfpo") or "simplified" to CFPO_VARIANT_*:
 * 0, or -1 for another name. */
int cfpo_variant_parse(const char *name, int *variant);
/* The name of a variant ("adaptive", "paper", "simplified", "?"). */
const char *cfpo_variant_name(int variant);

/* Checks n and the options without allocating anything: 0; -1 with a
 * one-line message for an invalid request (n too small, bad tolerance,
 * ...); -2 when the request is valid but exceeds this machine (memory). */
int cfpo_validate(int64_t n, const cfpo_options *o, char *err, size_t errlen);

/* cfpo_validate for one rank of several: options, n, and whether the
 * largest tile (rank_points points in rank_cells cells plus rank_ring halo
 * cells) fits, times the ranks sharing this machine. 0, -1 (invalid) or
 * -2 (memory). */
int cfpo_validate_ranks(int64_t n, const cfpo_options *o, int64_t rank_points, int64_t rank_cells,
                        int64_t rank_ring, int ranks_here, char *err, size_t errlen);

/* Runs the sampler; writes 2n doubles to xy. 0 on success, -1 with a
 * message in err. */
int cfpo_sample(int64_t n, const cfpo_options *o, double *xy, cfpo_result *res, char *err,
                size_t errlen);

/* cfpo_sample under a density (docs/method.md, "Density"): n points on
 * the unit torus whose counts follow rho, given as `cfpo --density` takes
 * it (an image FILE.png / FILE.pgm, a 2-D FILE.npy, cos:..., ramp:...,
 * balzer). o->tol is the move tolerance in local spacings: pass
 * CFPO_DENSITY_TOL for the command's default. The variant must be the
 * adaptive one. The same bytes as `cfpo -n N --density SPEC` with the same
 * seed and tolerance; a flat density gives cfpo_sample's. 0, or -1 with
 * one line in err (a bad density or n too small for it among them). */
int cfpo_sample_density(int64_t n, const cfpo_options *o, const char *density, double *xy, cfpo_result *res,
                        char *err, size_t errlen);

/* The same with the density as w x h non-negative values, row j = y
 * (normalised here; zero-density pixels get no point). */
int cfpo_sample_density_values(int64_t n, const cfpo_options *o, const double *rho, int64_t w, int64_t h, double *xy,
                               cfpo_result *res, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
