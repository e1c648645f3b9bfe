/* main_direct.c - the commands `cfpo-white`, `cfpo-jitter` and
 * `cfpo-sobol`: the method DIRECT_METHOD (bl_direct.c) with the
 * iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

#ifndef DIRECT_METHOD
#define DIRECT_METHOD bl_white
#endif

extern const bl_method DIRECT_METHOD;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &DIRECT_METHOD); }
