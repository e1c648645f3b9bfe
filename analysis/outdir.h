/* outdir.h - the output folder, all or nothing.
 *
 * Owns: writing every output into a temporary folder beside the final one
 * ("<DIR>.tmp.<pid>") and renaming it into place only when everything is
 * written; removing the temporary folder on failure and (registered with
 * the suite's one signal handler, src/files/tmpguard.h) on SIGINT, SIGTERM and
 * SIGHUP; replacing an earlier output folder of this tool (one that
 * holds stats.json and nothing but the names below), never anything else.
 * Does not own: what goes into the files (report.c). */
#ifndef AN_OUTDIR_H
#define AN_OUTDIR_H

#include <stddef.h>

/* The only names written into an output folder, then the pictures plot.gp
 * makes there (accepted, and removed, when an earlier folder is replaced). */
#define AN_OUT_NAMES {"spectrum.txt", "raps.txt", "nn_hist.txt", "stats.json", "plot.gp", "pcf.txt", "pcf.gp", \
                      "density.txt", "dda_raps.txt", "dda_spectrum.txt", "prefixes.txt", "spectrum.png", "raps.png", "nn_hist.png", \
                      "pcf.png"}
#define AN_OUT_WRITTEN 11 /* density.txt, dda_raps.txt, dda_spectrum.txt: with --density only;
                            prefixes.txt with --prefixes only */
#define AN_OUT_COUNT 15

typedef struct {
    char *final, *tmp;
    int created; /* the temporary folder exists */
} an_outdir;

/* Checks `path` (absent, or an earlier output folder) and creates the
 * temporary folder. 0, or -1 with a message naming the folder. */
int an_outdir_begin(an_outdir *o, const char *path, char *err, size_t errlen);
/* Path of file `name` (one of the first AN_OUT_WRITTEN names) inside the temporary folder;
 * malloc'ed, or NULL when out of memory. */
char *an_outdir_file(const an_outdir *o, const char *name);
/* Rewrites a message about a file of the temporary folder to name the
 * output folder instead (the temporary is an implementation detail). */
void an_outdir_message(const an_outdir *o, char *msg, size_t cap);
/* Renames the temporary folder into place. 0, or -1 with a message (the
 * temporary folder is then removed). */
int an_outdir_commit(an_outdir *o, char *err, size_t errlen);
/* Removes the temporary folder. Safe to call twice. */
void an_outdir_abort(an_outdir *o);

#endif
