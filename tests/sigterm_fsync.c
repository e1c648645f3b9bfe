/* sigterm_fsync.c - LD_PRELOAD shim for test_checkpoint.sh: the first
 * fsync of the process raises SIGTERM instead, so the signal arrives
 * exactly while a file is being committed. */
#define _GNU_SOURCE
#include <signal.h>
#include <unistd.h>

int fsync(int fd)
{
    (void)fd;
    raise(SIGTERM);
    return 0;
}
