/* pointfile.c - see pointfile.h. Text and CSV numbers are written with 17
 * significant digits, so every format round-trips doubles exactly. */
#define _POSIX_C_SOURCE 200809L
#include "pointfile.h"
#include "npy.h"

#include "safefile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || errlen == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

static const char *ext_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    return (dot && dot != base) ? dot : "";
}

pf_format pf_format_of(const char *path)
{
    const char *e = ext_of(path);
    static const char *text[] = {".txt", ".dat", ".pts", ".xy"};
    static const char *raw[] = {".bin", ".raw", ".f64"};
    for (size_t i = 0; i < sizeof text / sizeof *text; i++)
        if (strcasecmp(e, text[i]) == 0) return PF_TEXT;
    for (size_t i = 0; i < sizeof raw / sizeof *raw; i++)
        if (strcasecmp(e, raw[i]) == 0) return PF_RAW;
    if (strcasecmp(e, ".npy") == 0) return PF_NPY;
    if (strcasecmp(e, ".csv") == 0) return PF_CSV;
    return PF_UNKNOWN;
}

const char *pf_format_name(pf_format f)
{
    switch (f) {
    case PF_TEXT: return "text";
    case PF_NPY: return "npy";
    case PF_RAW: return "raw";
    case PF_CSV: return "csv";
    default: return "unknown";
    }
}

int pf_format_is_text(pf_format f) { return f == PF_TEXT || f == PF_CSV; }

/* The first line of a CSV point file. */
#define CSV_HEADER "x,y"


static int host_is_little_endian(void)
{
    const uint16_t one = 1;
    unsigned char b;
    memcpy(&b, &one, 1);
    return b == 1;
}

static double swap_double(double v)
{
    uint64_t u;
    memcpy(&u, &v, 8);
    u = __builtin_bswap64(u);
    memcpy(&v, &u, 8);
    return v;
}

/* ------------------------------------------------------------------ writer */

struct pf_writer {
    safefile a;  /* the temporary and the final name */
    pf_format fmt;
    size_t n, written;
};

const char *pf_writer_tmpname(const pf_writer *w) { return w ? w->a.tmp : NULL; }

size_t pf_header(pf_format fmt, size_t n, unsigned char *buf, size_t cap)
{
    if (fmt != PF_NPY) return 0;
    char dict[128];
    int len = snprintf(dict, sizeof dict,
                       "{'descr': '<f8', 'fortran_order': False, 'shape': (%zu, 2), }", n);
    /* magic(6) + version(2) + header length(2) + dict + padding + '\n' is a
     * multiple of 64. */
    size_t total = 10 + (size_t)len + 1;
    size_t pad = (64 - total % 64) % 64;
    size_t hlen = (size_t)len + pad + 1;
    if (10 + hlen > cap) return 0;
    unsigned char pre[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0,
                             (unsigned char)(hlen & 0xff), (unsigned char)(hlen >> 8)};
    memcpy(buf, pre, 10);
    memcpy(buf + 10, dict, (size_t)len);
    memset(buf + 10 + len, ' ', pad);
    buf[10 + hlen - 1] = '\n';
    return 10 + hlen;
}

static int write_npy_header(FILE *f, size_t n)
{
    unsigned char h[PF_HEADER_MAX];
    size_t len = pf_header(PF_NPY, n, h, sizeof h);
    return len && fwrite(h, 1, len, f) == len ? 0 : -1;
}

pf_writer *pf_writer_open(const char *path, size_t n, char *err, size_t errlen)
{
    pf_format fmt = pf_format_of(path);
    if (fmt == PF_UNKNOWN) {
        set_err(err, errlen, "%s: unknown output format (use " PF_EXTENSIONS ")", path);
        return NULL;
    }
    pf_writer *w = calloc(1, sizeof *w);
    if (!w) { set_err(err, errlen, "%s: out of memory", path); return NULL; }
    if (safefile_open(&w->a, path, "wb", err, errlen) != 0) {
        free(w);
        return NULL;
    }
    w->fmt = fmt;
    w->n = n;
    if ((fmt == PF_NPY && write_npy_header(w->a.f, n) != 0) ||
        (fmt == PF_CSV && fputs(CSV_HEADER "\n", w->a.f) < 0)) {
        set_err(err, errlen, "%s: write failed: %s", path, strerror(errno));
        pf_writer_abort(w);
        return NULL;
    }
    return w;
}

int pf_writer_put(pf_writer *w, const double *xy, size_t count, char *err, size_t errlen)
{
    if (w->written + count > w->n) {
        set_err(err, errlen, "%s: more points written than announced (%zu)", w->a.path, w->n);
        return -1;
    }
    int ok = 1;
    if (pf_format_is_text(w->fmt)) {
        const char *line = w->fmt == PF_CSV ? "%.17g,%.17g\n" : "%.17g %.17g\n";
        for (size_t i = 0; i < count && ok; i++)
            ok = fprintf(w->a.f, line, xy[2 * i], xy[2 * i + 1]) > 0;
    } else if (host_is_little_endian()) {
        ok = fwrite(xy, sizeof(double), 2 * count, w->a.f) == 2 * count;
    } else {
        for (size_t i = 0; i < 2 * count && ok; i++) {
            double v = swap_double(xy[i]);
            ok = fwrite(&v, sizeof v, 1, w->a.f) == 1;
        }
    }
    if (!ok) {
        set_err(err, errlen, "%s: write failed: %s", w->a.path, strerror(errno));
        return -1;
    }
    w->written += count;
    return 0;
}

int pf_writer_finish(pf_writer *w, char *err, size_t errlen)
{
    if (w->written != w->n) {
        set_err(err, errlen, "%s: %zu points written, %zu announced", w->a.path, w->written, w->n);
        safefile_abort(&w->a);
        return -1;
    }
    return safefile_finish(&w->a, err, errlen);
}

int pf_writer_publish(pf_writer *w, char *err, size_t errlen)
{
    const int rc = w->a.tmp ? safefile_publish(&w->a, err, errlen) : -1;
    free(w);
    return rc;
}

int pf_writer_commit(pf_writer *w, char *err, size_t errlen)
{
    if (pf_writer_finish(w, err, errlen) != 0) {
        pf_writer_abort(w);
        return -1;
    }
    return pf_writer_publish(w, err, errlen);
}

void pf_writer_abort(pf_writer *w)
{
    if (!w) return;
    safefile_abort(&w->a);
    free(w);
}

int pf_write(const char *path, const double *xy, size_t n, char *err, size_t errlen)
{
    pf_writer *w = pf_writer_open(path, n, err, errlen);
    if (!w) return -1;
    if (pf_writer_put(w, xy, n, err, errlen) != 0) { pf_writer_abort(w); return -1; }
    return pf_writer_commit(w, err, errlen);
}

/* ------------------------------------------------------------------ reader */

static int check_point(const char *path, const char *where, size_t idx, double x, double y,
                       char *err, size_t errlen)
{
    if (!isfinite(x) || !isfinite(y)) {
        set_err(err, errlen, "%s: %s: point %zu is not finite (%g, %g)", path, where, idx, x, y);
        return -1;
    }
    if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0)) {
        set_err(err, errlen, "%s: %s: point %zu (%.17g, %.17g) is outside [0,1)^2", path, where,
                idx, x, y);
        return -1;
    }
    return 0;
}

static int read_all(const char *path, unsigned char **buf, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        set_err(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || S_ISDIR(st.st_mode)) {
        set_err(err, errlen, "%s: not a regular file", path);
        fclose(f);
        return -1;
    }
    size_t cap = st.st_size > 0 ? (size_t)st.st_size + 1 : 4096, n = 0;
    unsigned char *b = malloc(cap);
    if (!b) { set_err(err, errlen, "%s: out of memory", path); fclose(f); return -1; }
    for (;;) {
        size_t got = fread(b + n, 1, cap - n, f);
        n += got;
        if (got == 0) break;
        if (n + 1 >= cap) {
            unsigned char *nb = realloc(b, cap * 2);
            if (!nb) { set_err(err, errlen, "%s: out of memory", path); free(b); fclose(f); return -1; }
            b = nb;
            cap *= 2;
        }
    }
    if (ferror(f)) {
        set_err(err, errlen, "%s: read error: %s", path, strerror(errno));
        free(b);
        fclose(f);
        return -1;
    }
    fclose(f);
    *buf = b;
    *len = n;
    return 0;
}

static int skip_blanks(char **p)
{
    while (**p == ' ' || **p == '\t' || **p == '\r') (*p)++;
    return **p;
}

/* One point line: "x y" (text: blanks between, '#' starts a comment) or
 * "x,y" (CSV: blanks allowed around the comma, no comments). 0 or -1. */
static int parse_pair(char *p, int csv, double *x, double *y)
{
    char *e1, *e2;
    *x = strtod(p, &e1);
    if (e1 == p) return -1;
    char *q = e1;
    if (csv) {
        if (skip_blanks(&q) != ',') return -1;
        q++;
        skip_blanks(&q);
        if (*q == '\0') return -1;
    }
    *y = strtod(q, &e2);
    if (e2 == q) return -1;
    const int end = skip_blanks(&e2);
    return end == '\0' || (!csv && end == '#') ? 0 : -1;
}

/* The CSV header: the first line not blank must be "x,y" (blanks around
 * the names allowed). *pos moves past it. 0 or -1. */
static int csv_header(const char *path, unsigned char *buf, size_t len, size_t *pos, size_t *line,
                      char *err, size_t errlen)
{
    while (*pos < len) {
        size_t end = *pos;
        while (end < len && buf[end] != '\n') end++;
        (*line)++;
        const size_t span = end - *pos;
        buf[end] = '\0';
        char *p = (char *)buf + *pos;
        *pos = end + 1;
        if (memchr(p, '\0', span)) {
            set_err(err, errlen, "%s: line %zu: binary data in a text file", path, *line);
            return -1;
        }
        if (skip_blanks(&p) == '\0') continue;
        static const char want[] = CSV_HEADER; /* its characters, blanks allowed between */
        size_t k = 0;
        while (want[k] && skip_blanks(&p) == want[k]) p++, k++;
        if (!want[k] && skip_blanks(&p) == '\0') return 0;
        set_err(err, errlen, "%s: line %zu: expected the CSV header \"" CSV_HEADER "\"", path, *line);
        return -1;
    }
    set_err(err, errlen, "%s: contains no points (not even the CSV header \"" CSV_HEADER "\")", path);
    return -1;
}

static int parse_text(const char *path, int csv, unsigned char *buf, size_t len, double **out, size_t *nout,
                      char *err, size_t errlen)
{
    size_t cap = 1024, n = 0, line = 0;
    double *xy = malloc(cap * 2 * sizeof *xy);
    if (!xy) { set_err(err, errlen, "%s: out of memory", path); return -1; }
    size_t pos = 0;
    if (csv && csv_header(path, buf, len, &pos, &line, err, errlen) != 0) {
        free(xy);
        return -1;
    }
    while (pos < len) {
        size_t end = pos;
        while (end < len && buf[end] != '\n') end++;
        line++;
        /* A NUL inside a text file is corruption, not a line end. */
        if (memchr(buf + pos, '\0', end - pos)) {
            set_err(err, errlen, "%s: line %zu: binary data in a text file", path, line);
            free(xy);
            return -1;
        }
        buf[end] = '\0'; /* read_all leaves a spare byte after the data */
        char *p = (char *)buf + pos;
        const int first = skip_blanks(&p);
        if (first != '\0' && (csv || first != '#')) {
            double x, y;
            if (parse_pair(p, csv, &x, &y) != 0) {
                set_err(err, errlen, csv ? "%s: line %zu: expected two numbers \"x,y\""
                                         : "%s: line %zu: expected two numbers \"x y\"", path, line);
                free(xy);
                return -1;
            }
            char where[32];
            snprintf(where, sizeof where, "line %zu", line);
            if (check_point(path, where, n, x, y, err, errlen) != 0) { free(xy); return -1; }
            if (n == cap) {
                double *nx = realloc(xy, cap * 4 * sizeof *xy);
                if (!nx) { set_err(err, errlen, "%s: out of memory", path); free(xy); return -1; }
                xy = nx;
                cap *= 2;
            }
            xy[2 * n] = x;
            xy[2 * n + 1] = y;
            n++;
        }
        pos = end + 1;
    }
    if (n == 0) {
        set_err(err, errlen, "%s: contains no points", path);
        free(xy);
        return -1;
    }
    *out = xy;
    *nout = n;
    return 0;
}

/* n points from data: itemsize 8 (float64) or 4 (float32), big- or
 * little-endian, row-major (x y x y ...) or column-major (all x, all y). */
static int decode_pairs(const char *path, const unsigned char *data, size_t n, int itemsize, int big,
                        int fortran, size_t offset, double **out, char *err, size_t errlen)
{
    double *xy = malloc(n * 2 * sizeof *xy);
    if (!xy) { set_err(err, errlen, "%s: out of memory", path); return -1; }
    const int swap = big == host_is_little_endian();
    for (size_t i = 0; i < n; i++) {
        double v[2];
        size_t at[2];
        for (int k = 0; k < 2; k++) {
            size_t idx = fortran ? (size_t)k * n + i : 2 * i + (size_t)k;
            at[k] = idx * (size_t)itemsize;
            unsigned char b[8];
            memcpy(b, data + at[k], (size_t)itemsize);
            if (swap)
                for (int j = 0; j < itemsize / 2; j++) {
                    unsigned char t = b[j];
                    b[j] = b[itemsize - 1 - j];
                    b[itemsize - 1 - j] = t;
                }
            if (itemsize == 8) memcpy(&v[k], b, 8);
            else { float f; memcpy(&f, b, 4); v[k] = (double)f; }
        }
        char where[48];
        snprintf(where, sizeof where, "offset %zu", offset + at[0]);
        if (check_point(path, where, i, v[0], v[1], err, errlen) != 0) {
            free(xy);
            return -1;
        }
        xy[2 * i] = v[0];
        xy[2 * i + 1] = v[1];
    }
    *out = xy;
    return 0;
}

static int parse_raw(const char *path, const unsigned char *buf, size_t len, double **out,
                     size_t *nout, char *err, size_t errlen)
{
    if (len == 0) {
        set_err(err, errlen, "%s: contains no points", path);
        return -1;
    }
    if (len % 16 != 0) {
        set_err(err, errlen, "%s: size %zu bytes is not a whole number of (x, y) float64 pairs "
                "(truncated at offset %zu?)", path, len, len - len % 16);
        return -1;
    }
    *nout = len / 16;
    return decode_pairs(path, buf, len / 16, 8, 0, 0, 0, out, err, errlen);
}

static int parse_npy(const char *path, const unsigned char *buf, size_t len, double **out,
                     size_t *nout, char *err, size_t errlen)
{
    npy_info h;
    if (npy_parse_header(path, buf, len, &h, err, errlen) != 0) return -1;
    if (h.n == 0) { set_err(err, errlen, "%s: contains no points", path); return -1; }
    const size_t have = len - h.data, item = 2 * (size_t)h.itemsize;
    if (h.n > have / item || have != h.n * item) {
        if (h.n > have / item)
            set_err(err, errlen, "%s: truncated: shape (%zu, 2) needs %zu data bytes, file has %zu "
                    "after the header", path, h.n, h.n * item, have);
        else
            set_err(err, errlen, "%s: %zu bytes of trailing garbage after the data", path, have - h.n * item);
        return -1;
    }
    if (decode_pairs(path, buf + h.data, h.n, h.itemsize, h.big_endian, h.fortran, h.data, out, err, errlen) != 0)
        return -1;
    *nout = h.n;
    return 0;
}

static int parse_any(pf_format fmt, const char *path, unsigned char *buf, size_t len, double **xy, size_t *n,
                     char *err, size_t errlen)
{
    if (pf_format_is_text(fmt)) return parse_text(path, fmt == PF_CSV, buf, len, xy, n, err, errlen);
    if (fmt == PF_RAW) return parse_raw(path, buf, len, xy, n, err, errlen);
    if (fmt == PF_NPY) return parse_npy(path, buf, len, xy, n, err, errlen);
    set_err(err, errlen, "%s: unknown point file format (use " PF_EXTENSIONS ")", path);
    return -1;
}

int pf_read_buffer(pf_format fmt, const char *name, const unsigned char *buf, size_t len, double **xy,
                   size_t *n, char *err, size_t errlen)
{
    unsigned char *copy = malloc(len + 1); /* the text reader ends lines in place */
    if (!copy) { set_err(err, errlen, "%s: out of memory", name); return -1; }
    if (len) memcpy(copy, buf, len);
    int rc = parse_any(fmt, name, copy, len, xy, n, err, errlen);
    free(copy);
    return rc;
}

int pf_read(const char *path, double **xy, size_t *n, char *err, size_t errlen)
{
    pf_format fmt = pf_format_of(path);
    if (fmt == PF_UNKNOWN) {
        set_err(err, errlen, "%s: unknown point file format (use " PF_EXTENSIONS ")", path);
        return -1;
    }
    unsigned char *buf;
    size_t len;
    if (read_all(path, &buf, &len, err, errlen) != 0) return -1;
    int rc = parse_any(fmt, path, buf, len, xy, n, err, errlen);
    free(buf);
    return rc;
}
