/* cli3.h - the 3-D front end (cli3.c): the options, run and report of
 * `cfpo --dim 3` and of the cfpo3d command, which is the same front end
 * under its own name (docs/cli.md, "Three dimensions"). */
#ifndef CFPO_CLI3_H
#define CFPO_CLI3_H

/* Runs the 3-D command line argv (argv[0] the program, no --dim option)
 * as the command `name` (the prefix of its error lines). Returns the exit
 * status (0, or 3 after a signal with a checkpoint); usage errors and
 * failures print one line and exit (2 and 1) through cli.h. One process:
 * the caller refuses several MPI ranks. */
int cfpo3_cli_main(const char *name, int argc, char **argv);

#endif
