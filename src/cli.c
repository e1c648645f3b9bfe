/* cli.c - see cli.h. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ------------------------------------------------------------- numbers */

static int parse_exact_real(const char *s, long double *out)
{
    if (!s || !*s) return -1;
    const char *caret = strchr(s, '^');
    char *end;
    errno = 0;
    if (caret) { /* a^b with integer a, b */
        long long a = strtoll(s, &end, 10);
        if (end != caret || errno) return -1;
        long long b = strtoll(caret + 1, &end, 10);
        if (*end || errno || caret[1] == '\0' || b < 0 || b > 200) return -1;
        long double v = 1;
        for (long long i = 0; i < b; i++) v *= (long double)a;
        *out = v;
        return 0;
    }
    long double v = strtold(s, &end);
    if (end == s || *end || errno == ERANGE) return -1;
    *out = v;
    return 0;
}

int cli_parse_i64(const char *s, int64_t lo, int64_t hi, int64_t *out)
{
    if (!s || !*s) return -1;
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (*end || errno) {
        long double r;
        if (parse_exact_real(s, &r) != 0 || r != floorl(r) || r < (long double)INT64_MIN ||
            r > (long double)INT64_MAX)
            return -1;
        v = (long long)r;
    }
    if (v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

int cli_parse_u64(const char *s, uint64_t *out)
{
    if (!s || !*s || *s == '-' || *s == '+' || *s == ' ') return -1;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 0);
    if (*end || errno) return -1;
    *out = v;
    return 0;
}

int cli_parse_double(const char *s, double lo, double hi, double *out)
{
    if (!s || !*s) return -1;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno == ERANGE || !isfinite(v) || v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

/* ------------------------------------------------- errors and clean-up */

#define MAX_GUARDED 4
static char guarded[MAX_GUARDED][4096];
static volatile sig_atomic_t guarded_used[MAX_GUARDED];

static void remove_guarded(void)
{
    for (int i = 0; i < MAX_GUARDED; i++)
        if (guarded_used[i]) unlink(guarded[i]);
}

static void on_signal(int sig)
{
    remove_guarded(); /* unlink is async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);
}

void cli_guard_tmp(const char *path)
{
    static int installed = 0;
    if (!installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigaction(SIGINT, &sa, NULL);
        sigaction(SIGTERM, &sa, NULL);
        sigaction(SIGHUP, &sa, NULL);
        installed = 1;
    }
    if (!path) return;
    for (int i = 0; i < MAX_GUARDED; i++)
        if (!guarded_used[i] && strlen(path) < sizeof guarded[i]) {
            strcpy(guarded[i], path);
            guarded_used[i] = 1;
            return;
        }
}

void cli_unguard_tmp(const char *path)
{
    if (!path) return;
    for (int i = 0; i < MAX_GUARDED; i++)
        if (guarded_used[i] && strcmp(guarded[i], path) == 0) guarded_used[i] = 0;
}

static int errors_quiet;
static void (*exit_hook)(void);

void cli_set_exit(int quiet, void (*hook)(void))
{
    errors_quiet = quiet;
    exit_hook = hook;
}

static void leave(int code) __attribute__((noreturn));
static void leave(int code)
{
    if (exit_hook) exit_hook();
    exit(code);
}

static void vreport(const char *prog, const char *fmt, va_list ap)
{
    fflush(stdout);
    if (errors_quiet) return;
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void cli_usage_error(const char *prog, const char *fmt, ...)
{
    remove_guarded();
    fflush(stdout);
    if (!errors_quiet) {
        fprintf(stderr, "%s: ", prog);
        va_list ap;
        va_start(ap, fmt);
        vfprintf(stderr, fmt, ap);
        va_end(ap);
        fprintf(stderr, " (see %s --help)\n", prog);
    }
    leave(CLI_USAGE);
}

void cli_fail(const char *prog, const char *fmt, ...)
{
    remove_guarded();
    va_list ap;
    va_start(ap, fmt);
    vreport(prog, fmt, ap);
    va_end(ap);
    leave(CLI_FAIL);
}

int64_t cli_arg_points(const char *prog, const char *s)
{
    int64_t v;
    if (cli_parse_i64(s, 1, INT64_MAX, &v) != 0)
        cli_usage_error(prog, "-n: '%s' is not a positive whole number", s);
    return v;
}

uint64_t cli_arg_seed(const char *prog, const char *s)
{
    uint64_t v;
    if (cli_parse_u64(s, &v) != 0)
        cli_usage_error(prog, "--seed: '%s' is not a non-negative 64-bit integer", s);
    return v;
}

/* ------------------------------------------------------ time, memory */

double cli_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double cli_physical_memory(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    return (pages > 0 && size > 0) ? (double)pages * (double)size : INFINITY;
}

uint64_t cli_peak_rss(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) return 0;
    return (uint64_t)ru.ru_maxrss * 1024u; /* Linux reports KiB */
}

/* ------------------------------------------------------------ progress */

void cli_progress_init(cli_progress *p, int quiet)
{
    p->enabled = !quiet && isatty(STDERR_FILENO);
    p->shown = 0;
    p->last = -1;
}

void cli_progress_line(cli_progress *p, int force, const char *fmt, ...)
{
    if (!p->enabled) return;
    double t = cli_now();
    if (!force && p->last >= 0 && t - p->last < 0.1) return; /* at most 10 lines/s */
    p->last = t;
    va_list ap;
    va_start(ap, fmt);
    fputs("\r\033[K", stderr);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fflush(stderr);
    p->shown = 1;
}

void cli_progress_end(cli_progress *p)
{
    if (p->enabled && p->shown) fputc('\n', stderr);
    p->shown = 0;
}

/* ------------------------------------------------------------ summary */

void cli_print_summary(FILE *f, const cli_summary *s)
{
    fprintf(f, "SUMMARY method=%s variant=%s n=%lld seed=%llu threads=%d ranks=%d", s->method,
            s->variant ? s->variant : "-", (long long)s->n, (unsigned long long)s->seed,
            s->threads, s->ranks);
    if (s->iterations >= 0) fprintf(f, " iterations=%lld", (long long)s->iterations);
    else fprintf(f, " iterations=-");
    fprintf(f, " seconds=%.6f delta_min=%.6f delta_avg=%.6f converged=%s peak_bytes=%llu "
            "bytes_per_point=%.1f stop=%s\n", s->seconds, s->delta_min, s->delta_avg,
            s->converged < 0 ? "-" : (s->converged ? "yes" : "no"),
            (unsigned long long)s->peak_bytes, s->n > 0 ? (double)s->peak_bytes / (double)s->n : 0.0,
            s->stop ? s->stop : "-");
    fflush(f);
}

/* --------------------------------------------------------- atomic files */

int cli_atomic_open(cli_atomic *a, const char *path, char *err, size_t errlen)
{
    if (atomic_open(a, path, "w", err, errlen) != 0) return -1;
    cli_guard_tmp(a->tmp);
    return 0;
}

int cli_atomic_commit(cli_atomic *a, char *err, size_t errlen)
{
    char *tmp = a->tmp ? strdup(a->tmp) : NULL;
    const int rc = atomic_commit(a, err, errlen); /* renamed or removed */
    if (tmp) cli_unguard_tmp(tmp);
    free(tmp);
    return rc;
}

void cli_atomic_abort(cli_atomic *a)
{
    if (a->tmp) cli_unguard_tmp(a->tmp);
    atomic_abort(a);
}
