/* bl3.h - the 3-D baselines' common ground: a method's description and the
 * one command line every 3-D baseline command shares (bl3_cli.c).
 *
 * A 3-D baseline makes a set on the unit 3-torus. Direct methods (white,
 * jittered, dart throwing, Bridson, sample elimination) make it at once;
 * iterative ones (FPO) go on until a stop rule holds. The command line is
 * the 2-D baselines' style (-n, -s, -o, -q, the method's own options, the
 * stop rules for iterative methods), the output a 3-D point file
 * (points3.h: .npy n x 3, text, CSV, raw, extended XYZ, LAMMPS) and one
 * SUMMARY line with delta_min and delta_avg over Delta3(n). Dart throwing
 * and Bridson may place fewer or more points than asked: the SUMMARY
 * line's n is the count written. */
#ifndef CFPO_BL3_H
#define CFPO_BL3_H

#include <stddef.h>
#include <stdint.h>

#include "stoprule.h"

#define BL3_MAX_OPTIONS 6

typedef struct {
    const char *cli;   /* --cli VALUE (a number) */
    double def, lo, hi;
    const char *help;  /* one help line or more, with %g for def */
} bl3_option;

/* What a method reports beside its points. */
typedef struct {
    int64_t iterations;  /* -1: direct */
    int converged;       /* 1, 0, -1 not applicable */
    const char *stop;    /* NULL: '-' */
    int64_t trials;      /* darts or candidates drawn; 0 when not relevant */
} bl3_info;

/* Progress of an iterative method: called with iteration 0 (the start) and
 * after each iteration (s->converged as the method defines it); returns a
 * CFPO_STOP_* reason (stoprule.h), CFPO_STOP_NONE to go on. */
typedef int (*bl3_iter_fn)(void *user, const cfpo_iter_stats *s);

typedef struct {
    const char *name, *prog, *about;
    int iterative;
    int noptions;
    bl3_option options[BL3_MAX_OPTIONS];
    /* n asked, seed, the options' values; *xyz malloc'ed (3 *n_out
     * doubles). Iterative methods call cb each iteration and stop when it
     * says so (info->stop from its reason). 0, or -1
     * with one line in err. */
    int (*run)(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user,
               double **xyz, int64_t *n_out, bl3_info *info, char *err, size_t errlen);
    int64_t min_n;
} bl3_method;

/* The command: parses argv against m, runs it, writes -o, prints SUMMARY. */
int bl3_main(int argc, char **argv, const bl3_method *m);

#endif
