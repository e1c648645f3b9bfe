/* main_gbn.c - the `cfpo-gbn` command: the method of bl_gbn.c with the
 * iterative baselines' command line (bl_cli.h). */
#include "bl_cli.h"

extern const bl_method bl_gbn;

int main(int argc, char **argv) { return bl_iter_main(argc, argv, &bl_gbn); }
