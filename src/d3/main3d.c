/* main3d.c - the cfpo3d command: `cfpo --dim 3` under its own name (the
 * front end is cli3.c; docs/cli.md, "Three dimensions"). */
#include "cli3.h"

int main(int argc, char **argv) { return cfpo3_cli_main("cfpo3d", argc, argv); }
