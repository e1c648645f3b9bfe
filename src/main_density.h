/* main_density.h - layer 5: `cfpo --density SPEC`, the run under a density
 * (main.c hands it the parsed command line). One rank only for now. */
#ifndef CFPO_MAIN_DENSITY_H
#define CFPO_MAIN_DENSITY_H

#include <stdint.h>

#include "cfpo_types.h"

typedef struct {
    const char *spec;        /* --density, or NULL (a --resume of a density checkpoint needs it) */
    int64_t n;               /* -n, or -1 */
    cfpo_options o;          /* seed, threads, max_iter, tol (given_tol says if set), stop, progress */
    int given_seed, given_tol;
    const char *out, *trace, *checkpoint, *resume, *init;
    int every, quiet;
    int ranks;
} cfpo_density_cmd;

/* Runs it; returns the exit status (errors: one line, no file left). */
int cfpo_density_main(const cfpo_density_cmd *c);

#endif
