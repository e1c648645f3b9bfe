/* main_lloyd.c - the `cfpo-lloyd` command: the method of bl_lloyd.c with
 * the iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

extern const bl_method bl_lloyd;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &bl_lloyd); }
