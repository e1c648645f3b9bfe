/* cli3.h - the 3-D front end (cli3.c): the options, run and report of
 * `cfpo --dim 3` and of the cfpo3d command, which is the same front end
 * under its own name (docs/cli.md, "Three dimensions"). */
#ifndef CFPO_CLI3_H
#define CFPO_CLI3_H

/* Runs the 3-D command line argv (argv[0] the program, no --dim option)
 * as the command `name` (the prefix of its error lines). Returns the exit
 * status (0, or 3 after a signal with a checkpoint); usage errors and
 * failures print one line and exit (2 and 1) through cli.h. Under mpirun
 * each rank runs it: one brick of the grid per rank (docs/mpi.md). */
int cfpo3_cli_main(const char *name, int argc, char **argv);

/* `cfpo`'s --dim D (or --dim=D), taken out of argv (the rest keeps its
 * order, up to a "--"): 2 (also without the option) or 3; anything else
 * is a usage error of the command prog. */
int cfpo_cli_take_dim(const char *prog, int *argc, char **argv);

#endif
