/* main_bnot.c - the `cfpo-bnot` command: the method of bl_bnot.c with the
 * iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

extern const bl_method bl_bnot;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &bl_bnot); }
