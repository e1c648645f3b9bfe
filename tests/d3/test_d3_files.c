/* test_d3_files.c - 3-D point files (src/d3/points3.c): round trips
 * through .npy, text, CSV and raw give the same doubles; the extended XYZ
 * and LAMMPS files, parsed here independently, hold n points times the box
 * side and the periodic cell; so does the GROMACS .gro file, read as
 * GROMACS reads it (fixed columns, the precision from the distance between
 * the decimal points), to its 3 decimals (GROMACS's fixed layout); bad files are refused with one line; a
 * failed write leaves nothing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "points3.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;
static char dir[64];

static const char *at(const char *name)
{
    static char buf[4][256];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static int exists(const char *p)
{
    struct stat s;
    return stat(p, &s) == 0;
}

static void roundtrip(const char *name, const double *p, size_t n)
{
    char err[512];
    CHECK(p3_write(at(name), p, n, 1.0, err, sizeof err) == 0, "%s: %s", name, err);
    double *q = NULL;
    size_t m = 0;
    CHECK(p3_read(at(name), &q, &m, err, sizeof err) == 0, "%s: read: %s", name, err);
    CHECK(m == n && q && memcmp(p, q, sizeof(double) * 3 * n) == 0, "%s: round trip differs", name);
    free(q);
}

/* Reads an extended XYZ file back: the count, the Lattice, the points. */
static int read_xyz(const char *path, double box, const double *p, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[512];
    size_t cnt = 0;
    int ok = fgets(line, sizeof line, f) && sscanf(line, "%zu", &cnt) == 1 && cnt == n;
    char want[256];
    snprintf(want, sizeof want, "Lattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" Properties=species:S:1:pos:R:3", box,
             box, box);
    ok = ok && fgets(line, sizeof line, f) && strstr(line, want) && strstr(line, "pbc=\"T T T\"");
    for (size_t i = 0; ok && i < n; i++) {
        char sp[8];
        double x, y, z;
        ok = fgets(line, sizeof line, f) && sscanf(line, "%7s %lf %lf %lf", sp, &x, &y, &z) == 4 &&
             strcmp(sp, "X") == 0 && x == p[3 * i] * box && y == p[3 * i + 1] * box && z == p[3 * i + 2] * box;
    }
    ok = ok && !fgets(line, sizeof line, f);
    fclose(f);
    return ok ? 0 : -1;
}

/* Reads a LAMMPS data file back as read_data does: title, header lines
 * (value before keyword), sections, atoms "id type x y z". */
static int read_lammps(const char *path, double box, const double *p, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[512];
    size_t atoms = 0;
    int types = 0, bounds = 0, seen = 0;
    int ok = fgets(line, sizeof line, f) != NULL; /* title */
    while (ok && fgets(line, sizeof line, f)) {
        double lo, hi;
        char k1[16], k2[16];
        if (line[0] == '\n') continue;
        if (strstr(line, " atoms\n") && sscanf(line, "%zu", &atoms) == 1) continue;
        if (strstr(line, " atom types\n") && sscanf(line, "%d", &types) == 1) continue;
        if (sscanf(line, "%lf %lf %15s %15s", &lo, &hi, k1, k2) == 4 && strstr(k1, "lo")) {
            ok = lo == 0.0 && hi == box;
            bounds++;
            continue;
        }
        if (strncmp(line, "Masses", 6) == 0) {
            ok = fgets(line, sizeof line, f) && fgets(line, sizeof line, f) && strncmp(line, "1 1", 3) == 0;
            continue;
        }
        if (strncmp(line, "Atoms # atomic", 14) == 0) {
            ok = fgets(line, sizeof line, f) != NULL; /* the skipped line */
            for (size_t i = 0; ok && i < n; i++) {
                size_t id;
                int ty;
                double x, y, z;
                ok = fgets(line, sizeof line, f) && sscanf(line, "%zu %d %lf %lf %lf", &id, &ty, &x, &y, &z) == 5 &&
                     id == i + 1 && ty == 1 && x == p[3 * i] * box && y == p[3 * i + 1] * box &&
                     z == p[3 * i + 2] * box && x >= 0.0 && x < box;
                seen++;
            }
            continue;
        }
        ok = 0;
    }
    fclose(f);
    return ok && atoms == n && types == 1 && bounds == 3 && (size_t)seen == n ? 0 : -1;
}

/* Reads a .gro file back as GROMACS does: title, count, then per atom the
 * residue number (5 columns), residue and atom names (5 + 5), atom number
 * (5) and x y z from column 20, each field as wide as the distance
 * between the first two decimal points; the last line the box. Each
 * coordinate within half a unit of the 3rd decimal of p times box. */
static int read_gro(const char *path, double box, const double *p, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[512];
    size_t cnt = 0;
    int ok = fgets(line, sizeof line, f) && fgets(line, sizeof line, f) && sscanf(line, "%zu", &cnt) == 1 && cnt == n;
    const double tol = 0.5e-3 + 1e-12 * box;
    for (size_t i = 0; ok && i < n; i++) {
        ok = fgets(line, sizeof line, f) && strlen(line) > 20;
        if (!ok) break;
        const char *d1 = strchr(line + 20, '.'), *d2 = d1 ? strchr(d1 + 1, '.') : NULL;
        ok = d1 && d2;
        if (!ok) break;
        const int w = (int)(d2 - d1);
        char num[6], field[64];
        memcpy(num, line, 5);
        num[5] = 0;
        ok = atoi(num) == (int)((i + 1) % 100000) && strncmp(line + 5, "SPH  ", 5) == 0 &&
             strncmp(line + 10, "    X", 5) == 0 && w == 8 && strlen(line) == 20 + 3 * (size_t)w + 1;
        memcpy(num, line + 15, 5);
        ok = ok && atoi(num) == (int)((i + 1) % 100000);
        for (int k = 0; ok && k < 3; k++) {
            memcpy(field, line + 20 + k * w, (size_t)w);
            field[w] = 0;
            const double v = atof(field);
            ok = fabs(v - p[3 * i + k] * box) <= tol && v >= 0.0 && v <= box;
        }
    }
    double a = 0, b = 0, c = 0;
    ok = ok && fgets(line, sizeof line, f) && sscanf(line, "%lf %lf %lf", &a, &b, &c) == 3 && fabs(a - box) <= tol &&
         a == b && b == c && !fgets(line, sizeof line, f);
    fclose(f);
    return ok ? 0 : -1;
}

static void refused(const char *name, const char *bytes, size_t len, const char *pat)
{
    FILE *f = fopen(at(name), "wb");
    fwrite(bytes, 1, len, f);
    fclose(f);
    double *q = NULL;
    size_t m = 0;
    char err[512] = "";
    const int rc = p3_read(at(name), &q, &m, err, sizeof err);
    CHECK(rc != 0 && strstr(err, pat) && !strchr(err, '\n'), "%s: accepted or wrong message '%s'", name, err);
    free(q);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/test_d3_files_%d", (int)getpid());
    mkdir(dir, 0700);
    const size_t n = 257;
    double *p = malloc(sizeof(double) * 3 * n);
    for (size_t i = 0; i < 3 * n; i++) p[i] = cfpo_rand01(4, 1, i);
    p[0] = 0.0;
    p[1] = 0x1.fffffffffffffp-1; /* the largest double below 1 */
    p[2] = 1e-300;
    roundtrip("a.npy", p, n);
    roundtrip("a.txt", p, n);
    roundtrip("a.csv", p, n);
    roundtrip("a.raw", p, n);
    char err[512];
    for (int b = 0; b < 2; b++) {
        const double box = b ? 12.5 : 1.0;
        CHECK(p3_write(at("a.xyz"), p, n, box, err, sizeof err) == 0, "xyz: %s", err);
        CHECK(read_xyz(at("a.xyz"), box, p, n) == 0, "xyz file (box %g) does not read back", box);
        CHECK(p3_write(at("a.data"), p, n, box, err, sizeof err) == 0, "lammps: %s", err);
        CHECK(read_lammps(at("a.data"), box, p, n) == 0, "LAMMPS file (box %g) does not read back", box);
    }
    for (int b = 0; b < 3; b++) {
        const double box = b == 0 ? 1.0 : b == 1 ? 3.25 : 9998.5;
        CHECK(p3_write(at("a.gro"), p, n, box, err, sizeof err) == 0, "gro: %s", err);
        CHECK(read_gro(at("a.gro"), box, p, n) == 0, ".gro file (box %g) does not read back", box);
    }
    CHECK(p3_write(at("c.gro"), p, n, 1e4, err, sizeof err) != 0 && strstr(err, "below") && !exists(at("c.gro")),
          ".gro box 1e4 (wider than its columns) accepted");
    CHECK(p3_check_box("a.xyz", 1e4, err, sizeof err) == 0 && p3_check_box("a.gro", 0.5, err, sizeof err) == 0 &&
          p3_check_box("a.npy", -1.0, err, sizeof err) != 0, "p3_check_box");
    /* bad writes leave nothing */
    CHECK(p3_write(at("a.xyz"), p, n, 0.0, err, sizeof err) != 0, "box 0 accepted");
    CHECK(p3_write(at("a.xyz"), p, n, NAN, err, sizeof err) != 0, "box NaN accepted");
    CHECK(p3_write(at("b.png"), p, n, 1.0, err, sizeof err) != 0 && !exists(at("b.png")), "unknown extension written");
    CHECK(p3_write(at("none/b.npy"), p, n, 1.0, err, sizeof err) != 0 && !strchr(err, '\n'), "missing folder");
    /* bad reads */
    refused("b.txt", "0.1 0.2\n", 8, "expected three numbers");
    refused("c.txt", "0.1 0.2 1.0\n", 12, "outside [0,1)");
    refused("d.txt", "0.1 0.2 nan\n", 12, "expected three numbers");
    refused("e.txt", "# only a comment\n", 17, "no points");
    refused("f.txt", "0.1 0.2 0.3 0.4\n", 16, "expected three numbers");
    refused("g.raw", "0123456789abcdef", 16, "multiple of 24");
    refused("h.csv", "x,y,z\n0.1,0.2\n", 14, "expected three numbers");
    {
        /* a 2-column .npy */
        const char hdr[] = "\x93NUMPY\x01\x00\x76\x00{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2), }";
        char buf[128 + 16];
        memset(buf, ' ', sizeof buf);
        memcpy(buf, hdr, sizeof hdr - 1);
        buf[127] = '\n';
        memset(buf + 128, 0, 16);
        refused("i.npy", buf, sizeof buf, "(n, 3)");
    }
    refused("j.xyz", "1\n\nX 0 0 0\n", 10, "cannot read this format");
    /* remove the folder */
    const char *names[] = {"a.npy", "a.txt", "a.csv", "a.raw", "a.xyz", "a.data", "a.gro", "b.txt", "c.txt", "d.txt",
                           "e.txt", "f.txt", "g.raw", "h.csv", "i.npy", "j.xyz"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) unlink(at(names[i]));
    CHECK(rmdir(dir) == 0, "temporary files left in %s", dir);
    free(p);
    return test_report(passed_, failed_);
}
