/* atomic.h - layer 0 (includes nothing of the project): a file written
 * whole or not at all. Every file the suite writes goes to a temporary
 * beside its final name (PATH.tmp.XXXXXX, same folder, so the last step is
 * an atomic rename) and is renamed into place only when it was written
 * whole; on failure the temporary is removed. The one place that does
 * this: the trace and other text files (cli_atomic), the point writer
 * (pointfile) and the shared MPI-IO file (comm) all come here. */
#ifndef CFPO_ATOMIC_H
#define CFPO_ATOMIC_H

#include <stddef.h>
#include <stdio.h>

/* Creates the empty temporary of `path`, mode 0644 (a result is for
 * sharing). Returns its descriptor and the malloc'ed name in *tmp; -1 with
 * "PATH: is a directory" or "PATH: cannot create file: REASON" in err. */
int atomic_create(const char *path, char **tmp, char *err, size_t errlen);

/* Puts tmp in place of path. 0, or -1 with errno set (tmp is then
 * removed). */
int atomic_replace(const char *tmp, const char *path);

/* A stdio stream on such a temporary. */
typedef struct {
    FILE *f;
    char *path, *tmp;
} atomic_file;

/* mode: "w" or "wb". 0, or -1 with a message (nothing left behind). */
int atomic_open(atomic_file *a, const char *path, const char *mode, char *err, size_t errlen);
/* Flushes, closes and renames into place. 0, or -1 with "PATH: write
 * failed: REASON" (the temporary is removed). */
int atomic_commit(atomic_file *a, char *err, size_t errlen);
/* The two halves of atomic_commit, for a run that writes several files
 * and replaces none unless all were written whole: finish (flush and close;
 * the temporary stays, the error as atomic_commit's), then publish (the
 * rename). */
int atomic_finish(atomic_file *a, char *err, size_t errlen);
int atomic_publish(atomic_file *a, char *err, size_t errlen);
/* Closes and removes the temporary (nothing when a holds none). */
void atomic_abort(atomic_file *a);

#endif
