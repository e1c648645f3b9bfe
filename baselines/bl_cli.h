/* bl_cli.h - the command line of the iterative baselines (cfpo-fpo,
 * cfpo-lfpo, cfpo-ccvt, cfpo-ccdt, cfpo-bnot): cfpo's options (-n,
 * --seed, --max-iter, --tol, --target-min, --target-avg, --time-limit,
 * -o, --trace, -q, -h, -V) and the method's own from its description
 * (bl_method.h), parsed against that table; the run loop (bl_loop.h); the
 * trace with the common columns then the method's, the progress line and
 * one SUMMARY line; exit codes 0/1/2 and one-line errors; no output file
 * unless the run succeeds (bl_run.h).
 * Does not own: any method, its options or their wording (bl_<method>.c). */
#ifndef CFPO_BASELINES_BL_CLI_H
#define CFPO_BASELINES_BL_CLI_H

#include "bl_method.h"

int bl_iter_main(int argc, char **argv, const bl_method *m);

#endif
