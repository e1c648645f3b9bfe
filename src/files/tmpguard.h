/* tmpguard.h - layer 0 (includes nothing of the project): the one signal
 * handler that removes temporary files and folders.
 *
 * Owns: a registry of paths to remove if the process is ended by SIGINT,
 * SIGTERM or SIGHUP, and the handler that removes them (unlink for files,
 * then rmdir for folders, both async-signal-safe, on paths copied in when
 * registered) before the signal takes its default course. Every command
 * that writes under a temporary name registers here: the commands'
 * temporaries (src/common/cli.c's text files, the point and checkpoint
 * temporaries of src/files/runfiles.c and src/engine/engine_ckpt.c, the baselines'
 * outputs) and cfpo-analyze's temporary output folder (analysis/outdir.c,
 * its files and then the folder), so one process may hold both kinds.
 * Does not own: making or renaming the temporaries (safefile.h, outdir.h).
 *
 * The handler is installed by the first registration (or tmpguard_install)
 * and never by a process that registers nothing: the library and the
 * Python module keep the caller's handlers. Not thread-safe: register
 * from one thread. */
#ifndef CFPO_TMPGUARD_H
#define CFPO_TMPGUARD_H

/* Installs the handler for SIGINT, SIGTERM and SIGHUP (once). */
void tmpguard_install(void);
/* Registers a file (a folder) to remove on a signal; installs the handler.
 * 0, or -1 when the registry is full or the path too long (then it is not
 * guarded; the run goes on). NULL: nothing to register. */
int tmpguard_file(const char *path);
int tmpguard_dir(const char *path);
/* Forgets path (it was renamed into place or removed): a signal no longer
 * touches it. */
void tmpguard_forget(const char *path);
/* Removes everything registered now and forgets it (a command's error
 * exit). Async-signal-safe. */
void tmpguard_clean(void);

#endif
