/* main_ccvt.c - the `cfpo-ccvt` command: the method of bl_ccvt.c with the
 * iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

extern const bl_method bl_ccvt;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &bl_ccvt); }
