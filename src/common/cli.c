/* cli.c - see cli.h. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ------------------------------------------------------------- numbers */

/* The one grammar of every number on every command line (no sign, no
 * spaces, no hexadecimal or octal; leading zeros are decimal: 010 is ten):
 *   whole numbers  DIGITS | DIGITS '^' DIGITS | DIGITS ['.' DIGITS] (e|E) DIGITS
 *                  (the last two only when the value is a whole number that
 *                  fits, e.g. 2^20, 1e6, 2.5e3; never rounded)
 *   reals          DIGITS ['.' [DIGITS]] | '.' DIGITS, then optionally
 *                  (e|E) ['+'|'-'] DIGITS; finite and representable
 *                  (subnormal values such as 1e-320 are; 1e-400 is not). */

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* DIGITS as an exact unsigned value; *p advanced past them. -1 when there
 * are none or they overflow. */
static int digits_u64(const char **p, uint64_t *out)
{
    const char *s = *p;
    uint64_t v = 0;
    if (!is_digit(*s)) return -1;
    for (; is_digit(*s); s++)
        if (__builtin_mul_overflow(v, 10u, &v) || __builtin_add_overflow(v, (uint64_t)(*s - '0'), &v))
            return -1;
    *p = s;
    *out = v;
    return 0;
}

static int pow_u64(uint64_t base, uint64_t e, uint64_t *out)
{
    uint64_t v = 1;
    for (uint64_t i = 0; i < e; i++) {
        if (__builtin_mul_overflow(v, base, &v)) return -1;
        if (v <= 1 && i > 0) break; /* 0 and 1 stay put: no long loops */
    }
    *out = e == 0 ? 1 : v;
    return 0;
}

/* A whole number in [0, 2^64) by the grammar above. */
static int parse_whole(const char *s, uint64_t *out)
{
    if (!s) return -1;
    const char *p = s;
    uint64_t a;
    if (digits_u64(&p, &a) != 0) return -1;
    if (*p == '\0') { *out = a; return 0; }
    if (*p == '^') {
        p++;
        uint64_t b;
        if (digits_u64(&p, &b) != 0 || *p) return -1;
        return pow_u64(a, b, out);
    }
    /* mantissa DIGITS ['.' DIGITS] then e DIGITS: digits d of the mantissa
     * with f of them after the point, value d * 10^(e - f). */
    uint64_t d = a;
    uint64_t f = 0;
    if (*p == '.') {
        p++;
        if (!is_digit(*p)) return -1;
        for (; is_digit(*p); p++, f++)
            if (__builtin_mul_overflow(d, 10u, &d) || __builtin_add_overflow(d, (uint64_t)(*p - '0'), &d))
                return -1;
    }
    if (*p != 'e' && *p != 'E') return -1;
    p++;
    uint64_t e;
    if (digits_u64(&p, &e) != 0 || *p) return -1;
    while (f > e) { /* fewer places than the point moved: the dropped digits must be 0 */
        if (d % 10 != 0) return -1;
        d /= 10;
        f--;
    }
    if (d == 0) { *out = 0; return 0; }
    uint64_t scale;
    if (pow_u64(10, e - f, &scale) != 0) return -1;
    if (__builtin_mul_overflow(d, scale, out)) return -1;
    return 0;
}

int cli_parse_i64(const char *s, int64_t lo, int64_t hi, int64_t *out)
{
    uint64_t v;
    if (parse_whole(s, &v) != 0 || v > (uint64_t)INT64_MAX) return -1;
    if ((int64_t)v < lo || (int64_t)v > hi) return -1;
    *out = (int64_t)v;
    return 0;
}

int cli_parse_u64(const char *s, uint64_t *out)
{
    return parse_whole(s, out);
}

int cli_parse_double(const char *s, double lo, double hi, double *out)
{
    if (!s) return -1;
    const char *p = s;
    int nd = 0;
    for (; is_digit(*p); p++) nd++;
    if (*p == '.') {
        p++;
        for (; is_digit(*p); p++) nd++;
    }
    if (nd == 0) return -1;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!is_digit(*p)) return -1;
        while (is_digit(*p)) p++;
    }
    if (*p) return -1;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || !isfinite(v)) return -1;
    /* ERANGE on a finite non-zero result is a subnormal: exact enough, and
     * representable. On a zero result the value underflowed: refused. */
    if (errno == ERANGE && v == 0) return -1;
    if (v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

/* ------------------------------------------------- errors and clean-up */

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
    tmpguard_clean();
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
    tmpguard_clean();
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

void cli_bad_option(const char *prog, const struct option *longopts, const char *arg)
{
    if (strncmp(arg, "--", 2) == 0) {
        const char *eq = strchr(arg, '=');
        const size_t len = eq ? (size_t)(eq - arg - 2) : strlen(arg + 2);
        for (const struct option *o = longopts; eq && o->name; o++)
            if (o->has_arg == no_argument && strlen(o->name) == len && strncmp(o->name, arg + 2, len) == 0)
                cli_usage_error(prog, "option '--%s' takes no value", o->name);
        cli_usage_error(prog, "unknown option '%.*s'", (int)(len + 2), arg);
    }
    if (optopt) cli_usage_error(prog, "unknown option '-%c'", optopt);
    cli_usage_error(prog, "unknown option '%s'", arg);
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

void cli_print_summary(FILE *f, const cli_summary *s) { cli_print_summary_ex(f, s, NULL); }

void cli_print_summary_ex(FILE *f, const cli_summary *s, const char *extra)
{
    fprintf(f, "SUMMARY method=%s variant=%s n=%lld seed=%llu threads=%d ranks=%d", s->method,
            s->variant ? s->variant : "-", (long long)s->n, (unsigned long long)s->seed,
            s->threads, s->ranks);
    if (s->iterations >= 0) fprintf(f, " iterations=%lld", (long long)s->iterations);
    else fprintf(f, " iterations=-");
    fprintf(f, " seconds=%.6f delta_min=%.6f delta_avg=%.6f converged=%s peak_bytes=%llu "
            "bytes_per_point=%.1f stop=%s%s\n", s->seconds, s->delta_min, s->delta_avg,
            s->converged < 0 ? "-" : (s->converged ? "yes" : "no"),
            (unsigned long long)s->peak_bytes, s->n > 0 ? (double)s->peak_bytes / (double)s->n : 0.0,
            s->stop ? s->stop : "-", extra ? extra : "");
    fflush(f);
}

/* ------------------------------------------------- whole-or-nothing text files */

int cli_atomic_open(cli_atomic *a, const char *path, char *err, size_t errlen)
{
    if (safefile_open(a, path, "wb", err, errlen) != 0) return -1;
    tmpguard_file(a->tmp);
    return 0;
}

int cli_atomic_commit(cli_atomic *a, char *err, size_t errlen)
{
    char *tmp = a->tmp ? strdup(a->tmp) : NULL;
    const int rc = safefile_commit(a, err, errlen); /* renamed or removed */
    if (tmp) tmpguard_forget(tmp);
    free(tmp);
    return rc;
}

void cli_atomic_abort(cli_atomic *a)
{
    if (a->tmp) tmpguard_forget(a->tmp);
    safefile_abort(a);
}
