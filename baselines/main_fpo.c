/* main_fpo.c - the `cfpo-fpo` and `cfpo-lfpo` commands: the methods of
 * bl_fpo.c with the iterative baselines' command line (bl_cli.h). Built
 * twice: FPO_METHOD names the row (bl_fpo or bl_lfpo). */
#include "bl_cli.h"

#ifndef FPO_METHOD
#define FPO_METHOD bl_fpo
#endif

extern const bl_method FPO_METHOD;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &FPO_METHOD); }
