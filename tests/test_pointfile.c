/* test_pointfile.c - the point-file module.
 *
 * Round trips of every format are exact (edge values included); every kind
 * of bad file is rejected with a message naming the file and the line or
 * offset; a failed write leaves no file, final or temporary, behind. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "pointfile.h"
#include "testutil.h"

static int passed_, failed_;
static char dir[256];

static const char *path(const char *name)
{
    static char buf[8][512];
    static int k;
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static void put_bytes(const char *p, const void *data, size_t len)
{
    FILE *f = fopen(p, "wb");
    fwrite(data, 1, len, f);
    fclose(f);
}

static int count_files(void)
{
    DIR *d = opendir(dir);
    int c = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.') c++;
    closedir(d);
    return c;
}

static void expect_reject(const char *p, const char *needle, const char *what)
{
    double *xy = NULL;
    size_t n = 0;
    char err[512] = "";
    int rc = pf_read(p, &xy, &n, err, sizeof err);
    const char *base = strrchr(p, '/') + 1;
    CHECK(rc == -1 && strstr(err, base) && strstr(err, needle) && !strchr(err, '\n'),
          "%s: expected a one-line error naming the file and containing '%s', got rc=%d '%s'",
          what, needle, rc, err);
    if (rc == 0) free(xy);
}

static void npy_with_header(const char *p, const char *dict, const void *data, size_t len)
{
    unsigned char pre[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, 0, 0};
    size_t dl = strlen(dict);
    size_t total = 10 + dl + 1, pad = (64 - total % 64) % 64, hl = dl + pad + 1;
    pre[8] = (unsigned char)(hl & 0xff);
    pre[9] = (unsigned char)(hl >> 8);
    FILE *f = fopen(p, "wb");
    fwrite(pre, 1, 10, f);
    fwrite(dict, 1, dl, f);
    for (size_t i = 0; i < pad; i++) fputc(' ', f);
    fputc('\n', f);
    fwrite(data, 1, len, f);
    fclose(f);
}

/* CSV: the header line and one "x,y" a line as written; on reading,
 * blanks around the names and numbers, CRLF, blank lines and no final
 * newline are accepted. */
static void test_csv_layout(void)
{
    const double xy[4] = {0.5, 0.25, 0.125, 0.75};
    char err[512];
    CHECK(pf_write(path("w.csv"), xy, 2, err, sizeof err) == 0, "csv write failed (%s)", err);
    char got[64] = "";
    FILE *f = fopen(path("w.csv"), "rb");
    size_t len = f ? fread(got, 1, sizeof got - 1, f) : 0;
    if (f) fclose(f);
    got[len] = 0;
    CHECK(strcmp(got, "x,y\n0.5,0.25\n0.125,0.75\n") == 0, "csv written as \"%s\"", got);
    const char *csv = "\n x , y \r\n0.25 , 0.5\r\n\n0.75,0.125\n0,0";
    put_bytes(path("c.csv"), csv, strlen(csv));
    double *back = NULL;
    size_t m = 0;
    int r = pf_read(path("c.csv"), &back, &m, err, sizeof err);
    CHECK(r == 0 && m == 3 && back[0] == 0.25 && back[1] == 0.5 && back[3] == 0.125 && back[5] == 0.0,
          "csv with blanks and CRLF misread (%s)", err);
    if (r == 0) free(back);
}

static void test_round_trips(void)
{
    const size_t n = 1000;
    double *xy = malloc(2 * n * sizeof *xy);
    uint64_t s = 88172645463325252ULL;
    for (size_t i = 0; i < 2 * n; i++) {
        s ^= s << 13; s ^= s >> 7; s ^= s << 17;
        xy[i] = (double)(s >> 11) * 0x1.0p-53;
    }
    xy[0] = 0.0;
    xy[1] = nextafter(1.0, 0.0);
    xy[2] = 4.9406564584124654e-324; /* smallest denormal */
    xy[3] = 0.1;
    const char *names[] = {"a.txt", "a.npy", "a.bin", "a.dat", "a.raw", "a.csv", "A.CSV"};
    for (size_t t = 0; t < sizeof names / sizeof *names; t++) {
        char err[512];
        int w = pf_write(path(names[t]), xy, n, err, sizeof err);
        double *back = NULL;
        size_t m = 0;
        int r = pf_read(path(names[t]), &back, &m, err, sizeof err);
        CHECK(w == 0 && r == 0 && m == n && memcmp(back, xy, 2 * n * sizeof *xy) == 0,
              "round trip through %s is not exact (%s)", names[t], err);
        free(back);
    }
    /* .npy data section is exactly the raw file; the header is 64-aligned. */
    struct stat a, b;
    stat(path("a.npy"), &a);
    stat(path("a.bin"), &b);
    CHECK(a.st_size - b.st_size == 128 && (a.st_size - b.st_size) % 64 == 0,
          ".npy header is %lld bytes", (long long)(a.st_size - b.st_size));
    /* Fortran-ordered (n, 2) arrays are read correctly. */
    double col[6] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}; /* x column, then y column */
    npy_with_header(path("f.npy"), "{'descr': '<f8', 'fortran_order': True, 'shape': (3, 2), }", col, sizeof col);
    double *back = NULL;
    size_t m = 0;
    char err[512];
    int r = pf_read(path("f.npy"), &back, &m, err, sizeof err);
    CHECK(r == 0 && m == 3 && back[0] == 0.1 && back[1] == 0.4 && back[4] == 0.3 && back[5] == 0.6,
          "fortran-order .npy misread (%s)", err);
    free(back);
    /* Text with comments, blank lines, CRLF and no final newline. */
    const char *txt = "# header\n\n0.25 0.5\r\n  0.75\t0.125  # trailing comment\n0 0";
    put_bytes(path("c.txt"), txt, strlen(txt));
    r = pf_read(path("c.txt"), &back, &m, err, sizeof err);
    CHECK(r == 0 && m == 3 && back[0] == 0.25 && back[3] == 0.125 && back[5] == 0.0,
          "text with comments misread (%s)", err);
    free(back);
    test_csv_layout();
    free(xy);
}

static void test_rejects(void)
{
    expect_reject(path("missing.npy"), "cannot open", "missing file");
    expect_reject(path("a.png"), "unknown point file format", "unknown extension");
    put_bytes(path("empty.txt"), "", 0);
    expect_reject(path("empty.txt"), "no points", "empty text");
    put_bytes(path("comments.txt"), "# only\n#\n", 9);
    expect_reject(path("comments.txt"), "no points", "comments only");
    static const struct {
        const char *name, *data, *needle;
    } bad_csv[] = {
        {"e.csv", "", "no points"},
        {"h.csv", "x,y\n", "no points"},
        {"nohead.csv", "0.5,0.5\n", "line 1: expected the CSV header"},
        {"head2.csv", "x,y,z\n0.5,0.5\n", "line 1: expected the CSV header"},
        {"yx.csv", "y,x\n0.5,0.5\n", "CSV header"},
        {"space.csv", "x,y\n0.5 0.5\n", "line 2: expected two numbers \"x,y\""},
        {"three.csv", "x,y\n0.5,0.5,0.5\n", "line 2"},
        {"one.csv", "x,y\n0.5,\n", "line 2"},
        {"lead.csv", "x,y\n,0.5\n", "line 2"},
        {"comment.csv", "x,y\n# no comments in CSV\n0.5,0.5\n", "line 2"},
        {"out.csv", "x,y\n0.5,1\n", "outside [0,1)^2"},
        {"nan.csv", "x,y\n0.5,nan\n", "not finite"},
        {"nul.csv", "x,y\n0.5,0.5\0\n", "binary data"},
        {"nulhead.csv", "x,\0y\n0.5,0.5\n", "binary data"},
    };
    for (size_t i = 0; i < sizeof bad_csv / sizeof *bad_csv; i++) {
        const char *d = bad_csv[i].data;
        size_t len = strlen(d);
        if (strstr(bad_csv[i].name, "nul")) len += 1 + strlen(d + len + 1); /* past the NUL */
        put_bytes(path(bad_csv[i].name), d, len);
        expect_reject(path(bad_csv[i].name), bad_csv[i].needle, bad_csv[i].name);
    }
    put_bytes(path("empty.bin"), "", 0);
    expect_reject(path("empty.bin"), "no points", "empty raw");
    put_bytes(path("one.txt"), "0.5 0.5\n0.5\n", 12);
    expect_reject(path("one.txt"), "line 2", "one number on a line");
    put_bytes(path("three.txt"), "0.5 0.5 0.5\n", 12);
    expect_reject(path("three.txt"), "line 1", "three numbers on a line");
    put_bytes(path("words.txt"), "0.1 0.2\nhello world\n", 20);
    expect_reject(path("words.txt"), "line 2", "words");
    put_bytes(path("nan.txt"), "0.1 0.2\n0.3 0.4\nnan 0.5\n", 24);
    expect_reject(path("nan.txt"), "not finite", "NaN in text");
    put_bytes(path("inf.txt"), "inf 0.5\n", 8);
    expect_reject(path("inf.txt"), "not finite", "inf in text");
    put_bytes(path("one.txt"), "1.0 0.5\n", 8);
    expect_reject(path("one.txt"), "outside [0,1)", "x = 1");
    put_bytes(path("neg.txt"), "0.5 -0.001\n", 11);
    expect_reject(path("neg.txt"), "outside [0,1)", "negative y");
    put_bytes(path("nul.txt"), "0.5 0.5\n\0\0\0", 11);
    expect_reject(path("nul.txt"), "binary data", "NUL in text");
    double d[3] = {0.5, 0.5, 0.5};
    put_bytes(path("odd.bin"), d, 24);
    expect_reject(path("odd.bin"), "not a whole number", "raw of 3 doubles");
    double bad[4] = {0.5, 0.5, NAN, 0.1};
    put_bytes(path("nan.bin"), bad, sizeof bad);
    expect_reject(path("nan.bin"), "offset 16", "NaN in raw");
    double big[2] = {0.5, 2.0};
    put_bytes(path("big.f64"), big, sizeof big);
    expect_reject(path("big.f64"), "outside", "2.0 in raw");
    /* .npy */
    put_bytes(path("magic.npy"), "NOTNUMPYFILE....", 16);
    expect_reject(path("magic.npy"), "bad magic", "bad magic");
    put_bytes(path("short.npy"), "\x93NUMPY\x01\x00\x76\x00{'descr'", 17);
    expect_reject(path("short.npy"), "truncated", "truncated header");
    double pts[6] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    npy_with_header(path("i8.npy"), "{'descr': '<i8', 'fortran_order': False, 'shape': (3, 2), }", pts, sizeof pts);
    expect_reject(path("i8.npy"), "float64 or float32", "integer dtype");
    npy_with_header(path("s3.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }", pts, sizeof pts);
    expect_reject(path("s3.npy"), "shape (2, 3)", "shape (2, 3)");
    npy_with_header(path("s1.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }", pts, sizeof pts);
    expect_reject(path("s1.npy"), "shape (6)", "1-D shape");
    npy_with_header(path("s0.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (0, 2), }", pts, 0);
    expect_reject(path("s0.npy"), "no points", "zero rows");
    npy_with_header(path("trunc.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (4, 2), }", pts, sizeof pts);
    expect_reject(path("trunc.npy"), "truncated", "truncated data");
    npy_with_header(path("extra.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", pts, sizeof pts);
    expect_reject(path("extra.npy"), "trailing", "trailing bytes");
    npy_with_header(path("nokey.npy"), "{'descr': '<f8', 'shape': (3, 2), }", pts, sizeof pts);
    expect_reject(path("nokey.npy"), "bad .npy header", "missing key");
    npy_with_header(path("huge.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999, 2), }", pts, sizeof pts);
    expect_reject(path("huge.npy"), "truncated", "absurd shape");
    double out[6] = {0.1, 0.2, 0.3, 1.5, 0.5, 0.6};
    npy_with_header(path("out.npy"), "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }", out, sizeof out);
    expect_reject(path("out.npy"), "point 1", "coordinate out of range in npy");
    mkdir(path("adir.txt"), 0755);
    expect_reject(path("adir.txt"), "not a regular file", "a directory");
}

static void test_failed_writes(void)
{
    int before = count_files();
    char err[512];
    double xy[4] = {0.1, 0.2, 0.3, 0.4};
    CHECK(pf_write(path("nodir/x.npy"), xy, 2, err, sizeof err) == -1 && strstr(err, "nodir/x.npy"),
          "write into a missing folder: '%s'", err);
    CHECK(pf_write(path("x.jpeg"), xy, 2, err, sizeof err) == -1 && strstr(err, "unknown output format"),
          "unknown output extension: '%s'", err);
    CHECK(pf_write(path("adir.txt"), xy, 2, err, sizeof err) == -1 && strstr(err, "directory"),
          "write onto a directory: '%s'", err);
    /* Announcing 3 points and writing 2 fails at commit and leaves nothing. */
    pf_writer *w = pf_writer_open(path("short.bin"), 3, err, sizeof err);
    pf_writer_put(w, xy, 2, err, sizeof err);
    CHECK(pf_writer_commit(w, err, sizeof err) == -1, "short write committed");
    /* Abort leaves nothing either. */
    w = pf_writer_open(path("aborted.txt"), 2, err, sizeof err);
    pf_writer_put(w, xy, 2, err, sizeof err);
    pf_writer_abort(w);
    CHECK(count_files() == before, "failed writes left files behind (%d -> %d)", before, count_files());
    /* A failed write does not destroy an existing file of that name. */
    pf_write(path("keep.bin"), xy, 2, err, sizeof err);
    w = pf_writer_open(path("keep.bin"), 5, err, sizeof err);
    pf_writer_abort(w);
    double *back;
    size_t m;
    CHECK(pf_read(path("keep.bin"), &back, &m, err, sizeof err) == 0 && m == 2,
          "aborted rewrite damaged the existing file");
    if (m == 2) free(back);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/cfpo-test-pf-XXXXXX");
    if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
    test_round_trips();
    test_rejects();
    test_failed_writes();
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    return test_report(passed_, failed_);
}
