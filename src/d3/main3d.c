/* main3d.c - the cfpo3d command: `cfpo --dim 3` under its own name (the
 * front end is cli3.c; docs/cli.md, "Three dimensions"); under mpirun one
 * brick of the grid per rank. */
#include "cli.h"
#include "cli3.h"
#include "comm.h"

int main(int argc, char **argv)
{
    comm_init(&argc, &argv);
    cli_set_exit(comm_rank() != 0, comm_finalize);
    const int rc = cfpo3_cli_main("cfpo3d", argc, argv);
    comm_finalize();
    return rc;
}
