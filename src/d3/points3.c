/* points3.c - see points3.h. */
#include "points3.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "npy.h"
#include "readall.h"
#include "cli.h"
#include "safefile.h"

/* .gro coordinates: decimals (GROMACS's fixed layout: %8.3f), and the box
 * below which they fit their columns (4 digits before the point). */
#define GRO_DECIMALS 3
#define GRO_MAX_BOX 9999.0

static int ends_with(const char *s, const char *suf)
{
    const size_t a = strlen(s), b = strlen(suf);
    return a > b && strcmp(s + a - b, suf) == 0;
}

p3_format p3_format_of(const char *path)
{
    if (ends_with(path, ".npy")) return P3F_NPY;
    if (ends_with(path, ".txt") || ends_with(path, ".dat") || ends_with(path, ".pts")) return P3F_TEXT;
    if (ends_with(path, ".csv")) return P3F_CSV;
    if (ends_with(path, ".bin") || ends_with(path, ".raw") || ends_with(path, ".f64")) return P3F_RAW;
    if (ends_with(path, ".xyz") || ends_with(path, ".extxyz")) return P3F_XYZ;
    if (ends_with(path, ".data") || ends_with(path, ".lmp")) return P3F_LAMMPS;
    if (ends_with(path, ".gro")) return P3F_GRO;
    return P3F_UNKNOWN;
}

int p3_format_readable(p3_format f) { return f == P3F_NPY || f == P3F_TEXT || f == P3F_CSV || f == P3F_RAW; }

int p3_probe(const char *path, char *err, size_t errlen)
{
    if (p3_format_of(path) == P3F_UNKNOWN) {
        snprintf(err, errlen, "%s: unknown output format (use " P3_EXTENSIONS ")", path);
        return -1;
    }
    char *tmp = NULL;
    const int fd = safefile_create(path, &tmp, err, errlen);
    if (fd < 0) return -1;
    close(fd);
    unlink(tmp);
    free(tmp);
    return 0;
}

int p3_check_box(const char *path, double box, char *err, size_t errlen)
{
    if (!(box > 0.0) || !isfinite(box)) {
        snprintf(err, errlen, "%s: the box side must be positive and finite", path);
        return -1;
    }
    if (p3_format_of(path) == P3F_GRO && !(box < GRO_MAX_BOX)) {
        snprintf(err, errlen, "%s: a .gro box must be below %g nm (its coordinate columns), not %g", path,
                 GRO_MAX_BOX, box);
        return -1;
    }
    return 0;
}

/* One .gro atom line: residue number, residue name, atom name, atom
 * number (both numbers modulo 10^5, as GROMACS writes them), then x y z in
 * nm with GRO_DECIMALS decimals in fields GRO_DECIMALS + 5 wide (GROMACS
 * infers the precision from the distance between the decimal points). */
static int gro_line(FILE *f, size_t i, const double *x, double box)
{
    const int id = (int)((i + 1) % 100000);
    return fprintf(f, "%5d%-5s%5s%5d%*.*f%*.*f%*.*f\n", id, "SPH", "X", id, GRO_DECIMALS + 5, GRO_DECIMALS,
                   x[0] * box, GRO_DECIMALS + 5, GRO_DECIMALS, x[1] * box, GRO_DECIMALS + 5, GRO_DECIMALS,
                   x[2] * box);
}

static int write_body(FILE *f, p3_format fmt, const double *p, size_t n, double box)
{
    if (fmt == P3F_NPY) {
        char dict[128];
        const int len = snprintf(dict, sizeof dict, "{'descr': '<f8', 'fortran_order': False, 'shape': (%zu, 3), }", n);
        const size_t total = 10 + (size_t)len + 1, pad = (64 - total % 64) % 64, hlen = (size_t)len + pad + 1;
        unsigned char pre[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, (unsigned char)(hlen & 0xff),
                                 (unsigned char)(hlen >> 8)};
        if (fwrite(pre, 1, 10, f) != 10 || fwrite(dict, 1, (size_t)len, f) != (size_t)len) return -1;
        for (size_t i = 0; i < pad; i++)
            if (fputc(' ', f) == EOF) return -1;
        if (fputc('\n', f) == EOF) return -1;
    }
    if (fmt == P3F_NPY || fmt == P3F_RAW) return fwrite(p, sizeof(double), 3 * n, f) == 3 * n ? 0 : -1;
    if (fmt == P3F_CSV && fputs("x,y,z\n", f) < 0) return -1;
    if (fmt == P3F_XYZ &&
        fprintf(f, "%zu\nLattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" Properties=species:S:1:pos:R:3 pbc=\"T T T\"\n",
                n, box, box, box) < 0)
        return -1;
    if (fmt == P3F_LAMMPS &&
        fprintf(f, "LAMMPS data file: %zu points on the periodic box of side %.17g (cfpo3d)\n\n"
                   "%zu atoms\n1 atom types\n\n0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\n"
                   "Masses\n\n1 1\n\nAtoms # atomic\n\n",
                n, box, n, box, box, box) < 0)
        return -1;
    if (fmt == P3F_GRO && fprintf(f, "CFPO: %zu points on the periodic box of side %.17g nm\n%zu\n", n, box, n) < 0)
        return -1;
    for (size_t i = 0; i < n; i++) {
        const double *x = p + 3 * i;
        int r;
        switch (fmt) {
        case P3F_CSV: r = fprintf(f, "%.17g,%.17g,%.17g\n", x[0], x[1], x[2]); break;
        case P3F_XYZ: r = fprintf(f, "X %.17g %.17g %.17g\n", x[0] * box, x[1] * box, x[2] * box); break;
        case P3F_LAMMPS:
            r = fprintf(f, "%zu 1 %.17g %.17g %.17g\n", i + 1, x[0] * box, x[1] * box, x[2] * box);
            break;
        case P3F_GRO: r = gro_line(f, i, x, box); break;
        default: r = fprintf(f, "%.17g %.17g %.17g\n", x[0], x[1], x[2]); break;
        }
        if (r < 0) return -1;
    }
    if (fmt == P3F_GRO && fprintf(f, "%.*f %.*f %.*f\n", GRO_DECIMALS, box, GRO_DECIMALS, box, GRO_DECIMALS, box) < 0)
        return -1;
    return 0;
}

int p3_write(const char *path, const double *xyz, size_t n, double box, char *err, size_t errlen)
{
    const p3_format fmt = p3_format_of(path);
    if (fmt == P3F_UNKNOWN) {
        snprintf(err, errlen, "%s: unknown output format (use " P3_EXTENSIONS ")", path);
        return -1;
    }
    if (p3_check_box(path, box, err, errlen) != 0) return -1;
    cli_atomic f;
    if (cli_atomic_open(&f, path, err, errlen) != 0) return -1;
    if (write_body(f.f, fmt, xyz, n, box) != 0) {
        snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
        cli_atomic_abort(&f);
        return -1;
    }
    return cli_atomic_commit(&f, err, errlen);
}

/* ------------------------------------------------------------------ reading */

static int check(const char *name, const char *where, double v, char *err, size_t errlen)
{
    if (!(v >= 0.0 && v < 1.0)) {
        snprintf(err, errlen, "%s: %s: coordinate %.17g is outside [0,1)", name, where, v);
        return -1;
    }
    return 0;
}

static int grow(double **p, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap * 2 : 3 * 1024;
    while (c < need) c *= 2;
    double *q = realloc(*p, c * sizeof *q);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int read_text(const char *name, const unsigned char *buf, size_t len, int csv, double **out, size_t *nout,
                     char *err, size_t errlen)
{
    double *p = NULL;
    size_t cap = 0, n = 0, pos = 0, line = 0;
    char tmp[128];
    while (pos < len) {
        size_t end = pos;
        while (end < len && buf[end] != '\n') end++;
        line++;
        const unsigned char *s = buf + pos, *e = buf + end;
        while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
        const int skip = s == e || (!csv && *s == '#') || (csv && line == 1 && (*s == 'x' || *s == 'X'));
        if (!skip) {
            double v[3];
            int k = 0;
            while (k < 3) {
                while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
                const unsigned char *t = s;
                while (t < e && *t != ' ' && *t != '\t' && *t != '\r' && *t != ',') t++;
                if (t == s || (size_t)(t - s) >= sizeof tmp) break;
                memcpy(tmp, s, (size_t)(t - s));
                tmp[t - s] = '\0';
                char *stop;
                errno = 0;
                v[k] = strtod(tmp, &stop);
                if (*stop != '\0' || errno != 0 || strchr(tmp, 'x') || strchr(tmp, 'X') ||
                    strchr(tmp, 'n') || strchr(tmp, 'N'))
                    break;
                k++;
                s = t;
                while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
                if (csv && k < 3) {
                    if (s < e && *s == ',') s++;
                    else break;
                }
            }
            while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
            if (k < 3 || s != e) {
                snprintf(err, errlen, "%s: line %zu: expected three numbers", name, line);
                free(p);
                return -1;
            }
            char where[32];
            snprintf(where, sizeof where, "line %zu", line);
            for (int a = 0; a < 3; a++)
                if (check(name, where, v[a], err, errlen) != 0) {
                    free(p);
                    return -1;
                }
            if (grow(&p, &cap, 3 * n + 3) != 0) {
                snprintf(err, errlen, "%s: out of memory", name);
                free(p);
                return -1;
            }
            memcpy(p + 3 * n, v, sizeof v);
            n++;
        }
        pos = end + 1;
    }
    if (n == 0) {
        snprintf(err, errlen, "%s: contains no points", name);
        free(p);
        return -1;
    }
    *out = p;
    *nout = n;
    return 0;
}

static int decode(const char *name, const unsigned char *data, size_t n, int itemsize, int big, int fortran,
                  double **out, char *err, size_t errlen)
{
    double *p = malloc(3 * n * sizeof *p + 1);
    if (!p) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    const uint16_t probe = 1;
    const int little = *(const unsigned char *)&probe == 1;
    const int swap = big == little;
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < 3; k++) {
            const size_t idx = fortran ? k * n + i : 3 * i + k;
            unsigned char b[8];
            memcpy(b, data + idx * (size_t)itemsize, (size_t)itemsize);
            if (swap)
                for (int j = 0; j < itemsize / 2; j++) {
                    const unsigned char t = b[j];
                    b[j] = b[itemsize - 1 - j];
                    b[itemsize - 1 - j] = t;
                }
            double v;
            if (itemsize == 8) memcpy(&v, b, 8);
            else {
                float fv;
                memcpy(&fv, b, 4);
                v = (double)fv;
            }
            char where[48];
            snprintf(where, sizeof where, "point %zu", i);
            if (check(name, where, v, err, errlen) != 0) {
                free(p);
                return -1;
            }
            p[3 * i + k] = v;
        }
    *out = p;
    return 0;
}

int p3_read_buffer(p3_format fmt, const char *name, const unsigned char *buf, size_t len, double **xyz,
                   size_t *n, char *err, size_t errlen)
{
    *xyz = NULL;
    *n = 0;
    if (fmt == P3F_TEXT || fmt == P3F_CSV) {
        if (len > 0 && memchr(buf, '\0', len)) {
            snprintf(err, errlen, "%s: binary data in a text file", name);
            return -1;
        }
        return read_text(name, buf, len, fmt == P3F_CSV, xyz, n, err, errlen);
    }
    if (fmt == P3F_RAW) {
        if (len == 0 || len % 24 != 0) {
            snprintf(err, errlen, "%s: size %zu is not a positive multiple of 24 bytes (x y z float64)", name, len);
            return -1;
        }
        if (decode(name, buf, len / 24, 8, 0, 0, xyz, err, errlen) != 0) return -1;
        *n = len / 24;
        return 0;
    }
    if (fmt == P3F_NPY) {
        npy_info info;
        if (npy_parse_header_2d(name, buf, len, &info, err, errlen) != 0) return -1;
        if (info.data > len) {
            snprintf(err, errlen, "%s: truncated header", name);
            return -1;
        }
        if (info.cols != 3) {
            snprintf(err, errlen, "%s: expected an (n, 3) array, found %zu columns", name, info.cols);
            return -1;
        }
        if (info.n == 0) {
            snprintf(err, errlen, "%s: contains no points", name);
            return -1;
        }
        if (info.n > (len - info.data) / 3 / (size_t)info.itemsize ||
            len - info.data != info.n * 3 * (size_t)info.itemsize) {
            snprintf(err, errlen, "%s: data length does not match the shape (%zu, 3)", name, info.n);
            return -1;
        }
        if (decode(name, buf + info.data, info.n, info.itemsize, info.big_endian, info.fortran, xyz, err,
                   errlen) != 0)
            return -1;
        *n = info.n;
        return 0;
    }
    snprintf(err, errlen, "%s: cannot read this format (--init reads .npy, text, CSV, raw)", name);
    return -1;
}

int p3_read(const char *path, double **xyz, size_t *n, char *err, size_t errlen)
{
    const p3_format fmt = p3_format_of(path);
    if (!p3_format_readable(fmt)) {
        snprintf(err, errlen, "%s: cannot read this format (--init reads .npy, text, CSV, raw)", path);
        return -1;
    }
    unsigned char *buf;
    size_t len;
    switch (readall(path, 0, &buf, &len)) {
    case READALL_OK: break;
    case READALL_OPEN: snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno)); return -1;
    case READALL_MEMORY:
    case READALL_LARGE: snprintf(err, errlen, "%s: out of memory", path); return -1;
    case READALL_READ: snprintf(err, errlen, "%s: read error (is it a folder?)", path); return -1;
    }
    const int rc = p3_read_buffer(fmt, path, buf, len, xyz, n, err, errlen);
    free(buf);
    return rc;
}
