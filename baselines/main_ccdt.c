/* main_ccdt.c - the `cfpo-ccdt` command: the method of bl_ccdt.c with the
 * iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

extern const bl_method bl_ccdt;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &bl_ccdt); }
