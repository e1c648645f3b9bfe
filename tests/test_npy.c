/* test_npy.c - the strict .npy reader (src/files/npy.c through pf_read): every
 * file numpy's format specification allows for an (n, 2) float64 or
 * float32 array is read with exactly numpy's values; headers numpy reads
 * differently or refuses are refused with one line naming the file. The
 * expectations were checked against numpy's reader (np.load); the test
 * itself needs no Python. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "pointfile.h"
#include "testutil.h"

static int passed_, failed_;
static char dir[256];
static const double pts[6] = {0.125, 0.25, 0.5, 0.75, 0.0, 0.9990234375}; /* exact in float32 too */

static const char *path(const char *name)
{
    static char buf[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* A .npy of version major.minor with header text `dict` padded with
 * spaces and '\n' to a multiple of 64 (pad = 0: no padding, no newline),
 * then the 6 values of pts as itemsize bytes, big- or little-endian,
 * row- or column-major. */
static void npy(const char *p, int major, int minor, const char *dict, int pad, int itemsize, int big,
                int fortran)
{
    FILE *f = fopen(p, "wb");
    const size_t pre = major == 1 ? 10 : 12, dl = strlen(dict);
    size_t hl = dl;
    if (pad) hl = dl + 1 + (64 - (pre + dl + 1) % 64) % 64;
    unsigned char m[12] = {0x93, 'N', 'U', 'M', 'P', 'Y', (unsigned char)major, (unsigned char)minor,
                           (unsigned char)hl, (unsigned char)(hl >> 8), (unsigned char)(hl >> 16), 0};
    fwrite(m, 1, pre, f);
    fwrite(dict, 1, dl, f);
    for (size_t i = dl; pad && i + 1 < hl; i++) fputc(' ', f);
    if (pad) fputc('\n', f);
    for (int j = 0; j < 6; j++) {
        int idx = fortran ? (j % 3) * 2 + j / 3 : j;
        unsigned char b[8];
        if (itemsize == 8) memcpy(b, &pts[idx], 8);
        else { float v = (float)pts[idx]; memcpy(b, &v, 4); }
        for (int k = 0; k < itemsize; k++) fputc(b[big ? itemsize - 1 - k : k], f);
    }
    fclose(f);
}

static void accepted(const char *what, const char *name)
{
    double *xy = NULL;
    size_t n = 0;
    char err[512] = "";
    int rc = pf_read(path(name), &xy, &n, err, sizeof err);
    CHECK(rc == 0 && n == 3 && memcmp(xy, pts, sizeof pts) == 0, "%s: rc %d n %zu '%s'", what, rc, n, err);
    if (rc == 0) free(xy);
    unlink(path(name));
}

static void refused(const char *what, const char *name, const char *needle)
{
    double *xy = NULL;
    size_t n = 0;
    char err[512] = "";
    int rc = pf_read(path(name), &xy, &n, err, sizeof err);
    CHECK(rc == -1 && strstr(err, name) && strstr(err, needle) && !strchr(err, '\n'),
          "%s: expected a one-line error naming %s with '%s', got rc %d '%s'", what, name, needle, rc, err);
    if (rc == 0) free(xy);
    unlink(path(name));
}

#define OK_DICT "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }"

/* One header, refused. */
static void bad(const char *what, const char *dict, const char *needle)
{
    npy(path("bad.npy"), 1, 0, dict, 1, 8, 0, 0);
    refused(what, "bad.npy", needle);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/cfpo-npy-XXXXXX");
    if (!mkdtemp(dir)) return 1;

    /* What numpy writes, all three versions. */
    npy(path("v1.npy"), 1, 0, OK_DICT, 1, 8, 0, 0);
    accepted("version 1.0", "v1.npy");
    npy(path("v2.npy"), 2, 0, OK_DICT, 1, 8, 0, 0);
    accepted("version 2.0", "v2.npy");
    npy(path("v3.npy"), 3, 0, OK_DICT, 1, 8, 0, 0);
    accepted("version 3.0", "v3.npy");
    /* Byte orders and float32. */
    npy(path("be.npy"), 1, 0, "{'descr': '>f8', 'fortran_order': False, 'shape': (3, 2), }", 1, 8, 1, 0);
    accepted("big-endian float64", "be.npy");
    npy(path("f4.npy"), 1, 0, "{'descr': '<f4', 'fortran_order': False, 'shape': (3, 2), }", 1, 4, 0, 0);
    accepted("float32", "f4.npy");
    npy(path("bf4.npy"), 1, 0, "{'descr': '>f4', 'fortran_order': False, 'shape': (3, 2), }", 1, 4, 1, 0);
    accepted("big-endian float32", "bf4.npy");
    npy(path("d.npy"), 1, 0, "{'descr': '<d', 'fortran_order': False, 'shape': (3, 2), }", 1, 8, 0, 0);
    accepted("descr '<d'", "d.npy");
    npy(path("fo.npy"), 1, 0, "{'descr': '<f8', 'fortran_order': True, 'shape': (3, 2), }", 1, 8, 0, 1);
    accepted("fortran order", "fo.npy");
    /* Other spellings of the same literal. */
    npy(path("q.npy"), 1, 0, "{\"shape\":(3,2),\"descr\":\"<f8\",\"fortran_order\":False}", 1, 8, 0, 0);
    accepted("double quotes, other key order, no spaces", "q.npy");
    npy(path("ws.npy"), 1, 0, "  {\n 'descr' : '<f8' ,\n\t'fortran_order' : False ,\r\n 'shape' : ( 3 , 2 , ) \n}", 1, 8, 0, 0);
    accepted("whitespace and line ends between tokens", "ws.npy");
    npy(path("np.npy"), 1, 0, OK_DICT, 0, 8, 0, 0);
    accepted("header without padding or newline", "np.npy");

    /* What the audit found: numpy reads these differently or refuses them. */
    bad("duplicate key", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), 'shape': (1, 2), }", "twice");
    bad("'TrueX'", "{'descr': '<f8', 'fortran_order': TrueX, 'shape': (3, 2), }", "True or False");
    bad("'Falsey'", "{'descr': '<f8', 'fortran_order': Falsey, 'shape': (3, 2), }", "True or False");
    bad("junk after the brace", OK_DICT " junk", "after the closing brace");
    bad("a second dict after the brace", OK_DICT "{}", "after the closing brace");
    bad("a comment after the brace", OK_DICT " # note", "after the closing brace");
    /* Keys. */
    bad("missing key", "{'descr': '<f8', 'shape': (3, 2), }", "missing key 'fortran_order'");
    bad("extra key", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), 'x': 1}", "unexpected key");
    bad("key prefix", "{'descr': '<f8', 'fortran_orderly': False, 'shape': (3, 2), }", "unexpected key");
    bad("empty dict", "{}", "missing key");
    bad("not a dict", "['descr', '<f8']", "not a dict");
    bad("unclosed dict", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), ", "expected a quoted string");
    bad("no comma between entries", "{'descr': '<f8' 'fortran_order': False, 'shape': (3, 2)}", "concatenated");
    bad("missing colon", "{'descr' '<f8', 'fortran_order': False, 'shape': (3, 2)}", "concatenated");
    /* Values. */
    bad("integer dtype", "{'descr': '<i8', 'fortran_order': False, 'shape': (3, 2), }", "descr '<i8'");
    bad("'|f8'", "{'descr': '|f8', 'fortran_order': False, 'shape': (3, 2), }", "descr '|f8'");
    bad("float16", "{'descr': '<f2', 'fortran_order': False, 'shape': (3, 2), }", "descr");
    bad("concatenated descr", "{'descr': '<f' '8', 'fortran_order': False, 'shape': (3, 2), }", "concatenated");
    bad("escaped descr", "{'descr': '<\\x66\\x38', 'fortran_order': False, 'shape': (3, 2), }", "unsupported character");
    npy(path("unterm.npy"), 1, 0, "{'descr': '<", 0, 8, 0, 0);
    refused("unterminated string", "unterm.npy", "unterminated");
    bad("fortran_order 1", "{'descr': '<f8', 'fortran_order': 1, 'shape': (3, 2), }", "True or False");
    bad("shape with a leading zero", "{'descr': '<f8', 'fortran_order': False, 'shape': (03, 2), }", "leading zero");
    bad("negative shape", "{'descr': '<f8', 'fortran_order': False, 'shape': (-3, 2), }", "non-negative");
    bad("float shape", "{'descr': '<f8', 'fortran_order': False, 'shape': (3.0, 2), }", "plain integer");
    bad("Python 2 long", "{'descr': '<f8', 'fortran_order': False, 'shape': (3L, 2), }", "plain integer");
    bad("hex shape", "{'descr': '<f8', 'fortran_order': False, 'shape': (0x3, 2), }", "plain integer");
    bad("underscore shape", "{'descr': '<f8', 'fortran_order': False, 'shape': (1_0, 2), }", "plain integer");
    bad("three dimensions", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2, 1), }", "more than two");
    bad("list shape", "{'descr': '<f8', 'fortran_order': False, 'shape': [3, 2], }", "not a tuple");
    bad("shape (2, 3)", "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }", "shape (2, 3)");
    bad("shape (6)", "{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }", "shape (6)");
    bad("shape 2^64", "{'descr': '<f8', 'fortran_order': False, 'shape': (18446744073709551616, 2), }", "too large");
    bad("non-ASCII", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), '\xc3\xa9': 1}", "unsupported character");
    bad("form feed", "{'descr': '<f8',\f'fortran_order': False, 'shape': (3, 2), }", "expected a quoted string");
    /* Versions and sizes. */
    npy(path("v11.npy"), 1, 1, OK_DICT, 1, 8, 0, 0);
    refused("version 1.1", "v11.npy", "version 1.1");
    npy(path("v4.npy"), 4, 0, OK_DICT, 1, 8, 0, 0);
    refused("version 4.0", "v4.npy", "version 4.0");
    npy(path("v0.npy"), 0, 0, OK_DICT, 1, 8, 0, 0);
    refused("version 0.0", "v0.npy", "version 0.0");
    char big[10200];
    snprintf(big, sizeof big, "%s", OK_DICT);
    memset(big + strlen(big), ' ', sizeof big - 1 - strlen(big));
    big[sizeof big - 1] = '\0';
    npy(path("huge.npy"), 2, 0, big, 1, 8, 0, 0);
    refused("header over numpy's 10,000-byte limit", "huge.npy", "limit");
    FILE *f = fopen(path("hl.npy"), "wb");
    fwrite("\x93NUMPY\x02\x00\x00\x01\x00\x00{", 1, 13, f);
    fclose(f);
    refused("header length past the end", "hl.npy", "truncated");

    rmdir(dir);
    return test_report(passed_, failed_);
}
