/* cli.h - layer 2 (includes safefile.h and tmpguard.h, layer 0):
 * conventions shared by every command of the suite (cfpo, the baselines,
 * the analysis tools).
 *
 * Owns: strict number parsing, the one-line error messages and exit codes
 * (0 success, 1 runtime failure, 2 usage error; the temporaries registered
 * with tmpguard removed first), the progress line on a terminal, the
 * machine-readable summary line, peak memory, and whole-or-nothing text
 * files (for traces) guarded by tmpguard.
 * Does not own: any method's options beyond these helpers, the signal
 * handler (tmpguard.c). */
#ifndef CFPO_CLI_H
#define CFPO_CLI_H

#include <stdarg.h>
#include <stdint.h>

#include "safefile.h"
#include "tmpguard.h"
#include <stdio.h>

enum { CLI_OK = 0, CLI_FAIL = 1, CLI_USAGE = 2 };

/* Strict parsers: the whole string must be a number within [lo, hi].
 * 0 on success, -1 otherwise (nothing printed). Decimal only: no sign, no
 * spaces, no hexadecimal, no octal (leading zeros are decimal: 010 is 10).
 * Whole numbers (both integer parsers, seeds included): DIGITS, or the
 * exact forms 2^20 (DIGITS^DIGITS) and 1e6 / 2.5e3 (DIGITS[.DIGITS]eDIGITS)
 * when the value is a whole number that fits. Reals: DIGITS[.DIGITS] or
 * .DIGITS with an optional exponent e[+-]DIGITS, finite, subnormals
 * included (1e-320), no inf or nan. */
int cli_parse_i64(const char *s, int64_t lo, int64_t hi, int64_t *out);
int cli_parse_u64(const char *s, uint64_t *out);
int cli_parse_double(const char *s, double lo, double hi, double *out);

/* The options every sampler shares, parsed or refused with the suite's
 * usage error: -n (a positive whole number, 2^20 and 1e6 forms too) and
 * --seed (a 64-bit unsigned integer). */
int64_t cli_arg_points(const char *prog, const char *s);
uint64_t cli_arg_seed(const char *prog, const char *s);

/* One line "prog: message" on stderr, then exit 2 (the line ends with a
 * pointer to --help) or 1.
 * Temporary files registered with tmpguard are removed first. */
struct option;
/* The usage error for an option getopt_long refused (arg: the argument it
 * stopped at, argv[optind - 1]): "--name=VALUE" of an option that takes
 * none, an unknown long option, or an unknown short one. Never returns. */
void cli_bad_option(const char *prog, const struct option *longopts, const char *arg) __attribute__((noreturn));

void cli_usage_error(const char *prog, const char *fmt, ...)
    __attribute__((noreturn, format(printf, 2, 3)));
void cli_fail(const char *prog, const char *fmt, ...)
    __attribute__((noreturn, format(printf, 2, 3)));

/* For programs run on several ranks that all reach the same error: quiet
 * = 1 on all but one rank keeps the message to one line; hook (may be
 * NULL) runs before exit, e.g. to end MPI cleanly. */
void cli_set_exit(int quiet, void (*hook)(void));

/* Peak resident memory of this process in bytes (0 if unknown). */
uint64_t cli_peak_rss(void);

/* This machine's physical memory in bytes (+inf if unknown). */
double cli_physical_memory(void);

/* Wall clock in seconds. */
double cli_now(void);

/* Progress on stderr, only when stderr is a terminal and not quiet: one
 * line rewritten in place, ended by cli_progress_end. */
typedef struct {
    int enabled;
    int shown;
    double last;
} cli_progress;
void cli_progress_init(cli_progress *p, int quiet);
void cli_progress_line(cli_progress *p, int force, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void cli_progress_end(cli_progress *p);

/* The summary line every method prints on stdout at the end:
 *   SUMMARY method=cfpo variant=cfpo n=4096 seed=1 threads=2 ranks=1
 *   iterations=424 seconds=1.58 delta_min=0.9242 delta_avg=0.9304
 *   converged=yes peak_bytes=... bytes_per_point=... stop=converged
 * Fields that do not apply to a method are given as '-'. */
typedef struct {
    const char *method, *variant;
    int64_t n;
    uint64_t seed;
    int threads, ranks;
    int64_t iterations;   /* -1: not iterative */
    double seconds;
    double delta_min, delta_avg;
    int converged;        /* 1 yes, 0 no, -1 not applicable */
    uint64_t peak_bytes;
    const char *stop;     /* which rule stopped the run (NULL: '-') */
} cli_summary;
void cli_print_summary(FILE *f, const cli_summary *s);
/* The same line with more fields after stop (extra: " k=v ...", or NULL). */
void cli_print_summary_ex(FILE *f, const cli_summary *s, const char *extra);

/* A file (text or binary: opened "wb", the same bytes on POSIX) written
 * under a temporary name (registered with tmpguard, so a signal or an
 * error exit removes it) and renamed on commit: safefile.h's file. */
typedef safefile cli_atomic;
int cli_atomic_open(cli_atomic *a, const char *path, char *err, size_t errlen);
int cli_atomic_commit(cli_atomic *a, char *err, size_t errlen);
void cli_atomic_abort(cli_atomic *a);

#endif
