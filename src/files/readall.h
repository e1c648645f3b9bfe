/* readall.h - layer 0 (includes nothing of the project): a whole file read
 * into memory, for the readers that parse a buffer (a density's file, the
 * 3-D point files and checkpoints, the solver's capture files). Each
 * caller words its own one-line errors from the status.
 * Owns: the read loop, its growth, its size limit and its clean-up. */
#ifndef CFPO_READALL_H
#define CFPO_READALL_H

#include <stddef.h>

typedef enum {
    READALL_OK = 0,
    READALL_OPEN,   /* cannot be opened (errno says why) */
    READALL_MEMORY, /* out of memory */
    READALL_LARGE,  /* more than max bytes */
    READALL_READ    /* a read error (a folder reads as one) */
} readall_status;

/* The bytes of path into *buf (malloc'ed, at least one byte, so never NULL
 * on success; the caller frees it) and their count into *len: READALL_OK.
 * max: the most bytes accepted, 0 for no limit. On any other status
 * nothing is left allocated and the file is closed. */
readall_status readall(const char *path, size_t max, unsigned char **buf, size_t *len);

#endif
