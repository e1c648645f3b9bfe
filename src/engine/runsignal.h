/* runsignal.h - layer 0 (includes nothing of the project): the batch
 * schedulers' warning signals.
 *
 * Owns: a handler for SIGTERM and SIGUSR1 that only notes the signal, for
 * a run that can save its state: the run loop (run_loop.c) then writes a
 * checkpoint at the next iteration boundary and the command exits with
 * status 3 (docs/cli.md). Installed only by a run that has a checkpoint
 * file; otherwise SIGTERM keeps tmpguard's handler (temporaries removed,
 * then the default action) and SIGUSR1 its default. */
#ifndef CFPO_RUNSIGNAL_H
#define CFPO_RUNSIGNAL_H

/* Catches SIGTERM and SIGUSR1 from now on (idempotent). */
void runsignal_install(void);
/* The signal caught (SIGTERM or SIGUSR1), 0 when none. */
int runsignal_caught(void);
/* Puts back the handlers that were there before runsignal_install. */
void runsignal_restore(void);

#endif
