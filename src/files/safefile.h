/* safefile.h - layer 0 (includes nothing of the project): a file written
 * whole or not at all. Every file the suite writes goes to a temporary
 * beside its final name (PATH.tmp.XXXXXX, same folder, so the last step is
 * an atomic rename) and is renamed into place only when it was written
 * whole; on failure the temporary is removed. The one place that does
 * this: the trace and other text files (cli_atomic), the point writer
 * (pointfile) and the shared MPI-IO file (comm) all come here. Removing
 * the temporaries on a signal is tmpguard.h's (the callers register them). */
#ifndef CFPO_SAFEFILE_H
#define CFPO_SAFEFILE_H

#include <stddef.h>
#include <stdio.h>

/* Creates the empty temporary of `path`, mode 0644 (a result is for
 * sharing). Returns its descriptor and the malloc'ed name in *tmp; -1 with
 * "PATH: is a directory" or "PATH: cannot create file: REASON" in err. */
int safefile_create(const char *path, char **tmp, char *err, size_t errlen);

/* Puts tmp in place of path. 0, or -1 with errno set (tmp is then
 * removed). */
int safefile_replace(const char *tmp, const char *path);

/* A stdio stream on such a temporary. */
typedef struct {
    FILE *f;
    char *path, *tmp;
} safefile;

/* mode: "w" or "wb". 0, or -1 with a message (nothing left behind). */
int safefile_open(safefile *a, const char *path, const char *mode, char *err, size_t errlen);
/* Flushes, closes and renames into place. 0, or -1 with "PATH: write
 * failed: REASON" (the temporary is removed). */
int safefile_commit(safefile *a, char *err, size_t errlen);
/* The two halves of safefile_commit, for a run that writes several files
 * and replaces none unless all were written whole: finish (flush and close;
 * the temporary stays, the error as safefile_commit's), then publish (the
 * rename). */
int safefile_finish(safefile *a, char *err, size_t errlen);
int safefile_publish(safefile *a, char *err, size_t errlen);
/* Closes and removes the temporary (nothing when a holds none). */
void safefile_abort(safefile *a);

#endif
