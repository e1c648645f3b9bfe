/* test_density.c - the density input (src/density/density.c, pgm.c, png_read.c,
 * density_analytic.c), its measure (src/density/dens_measure.c) and the start
 * (src/density/dens_start.c):
 *  - PGM P5 (8 and 16 bits) and P2, PNG (written here by libpng) and .npy
 *    read to the values written, image row 0 at the top (y near 1), dark
 *    dense, ':invert' light dense; normalised to mean 1; the hash the same
 *    for the same values and different for others;
 *  - each bad input refused with one line: truncated, bad magic, values
 *    above maxval, negative / NaN / infinite / all zero, contrast beyond
 *    the limit, unknown names and parameters;
 *  - the named fields: their contrast (cos a=0.9: 19, ramp: 16, balzer:
 *    256), mean 1;
 *  - the measure: equal to today's delta_min / delta_avg (cfpo_nn_stats)
 *    when rho = 1, and to brute force under a non-uniform density (the
 *    ramp 1:256 too, through the engine's kept near bounds);
 *  - the start: exactly n points, none on a zero pixel, deterministic. */
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dens_measure.h"
#include "dens_start.h"
#include "density.h"
#include "geom.h"
#include "hilbert.h"
#include "rng.h"
#include "stats.h"
#include "testutil.h"

static int passed_, failed_;
static const char *dir;

static void put(const char *name, const void *b, size_t n)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *f = fopen(p, "wb");
    fwrite(b, 1, n, f);
    fclose(f);
}

static int load(const char *name, cfpo_density *d, char *err)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return cfpo_density_load(p, d, err, 512);
}

static int refused(const char *spec, const char *needle)
{
    char err[512] = "", p[512];
    cfpo_density d;
    if (strstr(spec, ".png") || strstr(spec, ".pgm") || strstr(spec, ".npy")) snprintf(p, sizeof p, "%s/%s", dir, spec);
    else snprintf(p, sizeof p, "%s", spec);
    int rc = cfpo_density_load(p, &d, err, sizeof err);
    if (rc == 0) { cfpo_density_free(&d); return 0; }
    if (strchr(err, '\n') || !strstr(err, needle)) { fprintf(stderr, "message: %s\n", err); return 0; }
    return 1;
}

static void images(void)
{
    char err[512];
    cfpo_density a, b, c, e;
    /* 3 x 2, top row dark: 0 0 0 / 255 255 255 -> top dense, bottom empty */
    const unsigned char p5[] = "P5\n# c\n3 2\n255\n\0\0\0\377\377\377";
    put("a.pgm", p5, sizeof p5 - 1);
    CHECK(load("a.pgm", &a, err) == 0, "%s", err);
    CHECK(a.w == 3 && a.h == 2 && a.rho[0] == 0 && a.rho[3] == 2 && a.support == 0.5,
          "P5: row 0 of the file is y near 1, dark dense, mean 1 (%g %g)", a.rho[0], a.rho[3]);
    CHECK(cfpo_density_at(&a, 0.1, 0.9) == 2 && cfpo_density_at(&a, 0.1, 0.1) == 0, "lookup orientation");
    const char p2[] = "P2 3 2 255\n0 0 0\n255 255 255\n";
    put("b.pgm", p2, sizeof p2 - 1);
    CHECK(load("b.pgm", &b, err) == 0 && b.hash == a.hash, "P2 = P5: same hash");
    const unsigned char p16[] = "P5 3 2 65535 \0\0\0\0\0\0\377\377\377\377\377\377";
    put("c.pgm", p16, sizeof p16 - 1);
    CHECK(load("c.pgm", &c, err) == 0 && c.hash == a.hash, "16-bit P5 = 8-bit: same hash (%s)", err);
    /* PNG written by libpng: 4 x 1 grey 0 64 128 255 */
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    im.width = 4;
    im.height = 1;
    im.format = PNG_FORMAT_GRAY;
    const unsigned char px[4] = {0, 64, 128, 255};
    png_alloc_size_t sz = 0;
    png_image_write_to_memory(&im, NULL, &sz, 0, px, 0, NULL);
    unsigned char *mem = malloc(sz);
    CHECK(png_image_write_to_memory(&im, mem, &sz, 0, px, 0, NULL), "libpng writes");
    put("d.png", mem, sz);
    CHECK(load("d.png", &e, err) == 0, "%s", err);
    const double s = (255 + 191 + 127) / 4.0;
    CHECK(fabs(e.rho[0] - 255 / s) < 1e-12 && fabs(e.rho[2] - 127 / s) < 1e-12 && e.rho[3] == 0,
          "PNG: dark dense, normalised (%g %g %g)", e.rho[0], e.rho[2], e.rho[3]);
    cfpo_density_free(&e);
    char p[512];
    snprintf(p, sizeof p, "%s/d.png:invert", dir);
    CHECK(cfpo_density_load(p, &e, err, sizeof err) == 0 && e.rho[0] == 0 && fabs(e.rho[3] - 255 / (447 / 4.0)) < 1e-12,
          ":invert: light dense");
    cfpo_density_free(&e);
    put("t.png", mem, sz / 2);
    CHECK(refused("t.png", "unreadable PNG"), "truncated PNG");
    free(mem);
    put("t.pgm", p5, sizeof p5 - 3);
    CHECK(refused("t.pgm", "truncated PGM data"), "truncated PGM");
    put("m.pgm", "P6 1 1 255\n\0\0\0", 14);
    CHECK(refused("m.pgm", "not a PGM"), "colour PPM");
    put("v.pgm", "P2 1 1 10\n11\n", 13);
    CHECK(refused("v.pgm", "above maxval"), "value above maxval");
    put("x.pgm", "P5 1 1 255\n\0\0", 13);
    CHECK(refused("x.pgm", "data after"), "trailing data");
    put("w.pgm", "P5 1 1 255\n\377", 12);
    CHECK(refused("w.pgm", "zero everywhere"), "all-white image: zero density");
    put("big.pgm", "P5 100000 100000 255\n", 21);
    CHECK(refused("big.pgm", "too large"), "image too large");
    CHECK(refused("missing.png", "cannot open"), "missing file");
    CHECK(refused("a.npy:invert", ":invert"), ":invert on an array");
    CHECK(a.hash != e.hash, "different densities, different hashes");
    cfpo_density_free(&a);
    cfpo_density_free(&b);
    cfpo_density_free(&c);
}

static void npy(void)
{
    /* (2, 3) float64: row j = y */
    unsigned char buf[128 + 48];
    memset(buf, ' ', 128);
    const char *h = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }";
    memcpy(buf, "\x93NUMPY\x01\x00\x76\x00", 10);
    memcpy(buf + 10, h, strlen(h));
    buf[127] = '\n';
    double v[6] = {1, 2, 3, 4, 5, 6};
    memcpy(buf + 128, v, 48);
    put("a.npy", buf, sizeof buf);
    char err[512];
    cfpo_density d;
    CHECK(load("a.npy", &d, err) == 0 && d.w == 3 && d.h == 2 && fabs(d.rho[5] - 6 / 3.5) < 1e-12 &&
          fabs(cfpo_density_at(&d, 0.9, 0.9) - 6 / 3.5) < 1e-12, ".npy: row j = y (%s)", err);
    cfpo_density_free(&d);
    put("t.npy", buf, sizeof buf - 1);
    CHECK(refused("t.npy", "truncated"), "truncated .npy");
    double bad[3] = {-1, NAN, INFINITY};
    const char *why[3] = {"non-negative", "non-negative", "non-negative"};
    for (int k = 0; k < 3; k++) {
        memcpy(buf + 128 + 8, &bad[k], 8);
        put("b.npy", buf, sizeof buf);
        CHECK(refused("b.npy", why[k]), "value %g refused", bad[k]);
    }
    memset(buf + 128, 0, 48);
    put("z.npy", buf, sizeof buf);
    CHECK(refused("z.npy", "zero everywhere"), "all-zero array");
    v[0] = 1e-3;
    memcpy(buf + 128, v, 48);
    put("c.npy", buf, sizeof buf);
    CHECK(refused("c.npy", "contrast 1:6000 "), "contrast beyond the limit names it");
}

static void named(void)
{
    char err[512];
    struct { const char *spec; double contrast; } t[] = {
        {"cos:a=0.9", 19}, {"ramp:contrast=16", 16}, {"balzer", 256}, {"cos:a=0", 1}, {"ramp", 16}};
    for (int k = 0; k < 5; k++) {
        cfpo_density d;
        int rc = cfpo_density_load(t[k].spec, &d, err, sizeof err);
        CHECK(rc == 0, "%s: %s", t[k].spec, err);
        if (rc) continue;
        double sum = 0;
        for (int64_t p = 0; p < d.w * d.h; p++) sum += d.rho[p];
        const double c = d.rho_max / d.rho_min;
        CHECK(fabs(sum / (double)(d.w * d.h) - 1) < 1e-12 && fabs(c - t[k].contrast) < 0.01 * t[k].contrast,
              "%s: mean %.15g contrast %g", t[k].spec, sum / (double)(d.w * d.h), c);
        cfpo_density_free(&d);
    }
    CHECK(refused("ramp:contrast=300", "beyond the limit 1:256"), "ramp 1:300 refused");
    CHECK(refused("cos:a=2", "a='2'"), "cos a=2 refused");
    CHECK(refused("cos:b=1", "'b'"), "unknown parameter refused");
    CHECK(refused("cos:kx=0.5", "whole number"), "kx not whole");
    CHECK(refused("swirl", "not an image"), "unknown name refused");
}

/* cfpo_dens_nn on xy against the O(n^2) pair measure, each point's;
 * with `near`, cfpo_dens_nn_q with d's pyramid of minima and that store
 * of the grid's near bounds, as the engine measures. */
static void brute_measure(const cfpo_density *d, const double *xy, size_t n, double *m, const char *what,
                          cfpo_dens_nn_near *near)
{
    double b0, b1;
    if (near) {
        cfpo_dens_qbound qlow;
        if (cfpo_dens_qbound_build_min(&qlow, d) != 0) {
            CHECK(0, "%s: out of memory", what);
            return;
        }
        const int rc = cfpo_dens_nn_q(d, &qlow, near, xy, NULL, n, m, &b0, &b1, 0);
        cfpo_dens_nn_near_free(near);
        cfpo_dens_qbound_free(&qlow);
        if (rc != 0) {
            CHECK(0, "%s: the measure ran out of memory", what);
            return;
        }
    } else {
        cfpo_dens_nn(d, xy, n, m, &b0, &b1);
    }
    double worst = 0, mn = INFINITY, D = cfpo_delta_bound((double)n);
    for (size_t i = 0; i < n; i++) {
        double best = INFINITY;
        const double qi = sqrt(sqrt(cfpo_density_at(d, xy[2 * i], xy[2 * i + 1])));
        for (size_t j = 0; j < n; j++) {
            if (j == i) continue;
            const double qj = sqrt(sqrt(cfpo_density_at(d, xy[2 * j], xy[2 * j + 1])));
            const double v = sqrt(cfpo_torus_dist2(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1])) * qi * qj / D;
            if (v < best) best = v;
        }
        if (fabs(best - m[i]) > worst) worst = fabs(best - m[i]);
        if (best < mn) mn = best;
    }
    CHECK(worst < 1e-12 && fabs(mn - b0) < 1e-12, "%s: each point's measure against brute force: %g", what, worst);
}

static void measure(void)
{
    const size_t n = 3000;
    double *xy = malloc(n * 2 * sizeof *xy), *m = malloc(n * sizeof *m);
    for (size_t i = 0; i < 2 * n; i++) xy[i] = cfpo_rand01(3, 1, i);
    char err[512];
    cfpo_density u, d;
    CHECK(cfpo_density_load("cos:a=0,res=16", &u, err, sizeof err) == 0, "%s", err);
    double a0, a1, b0, b1;
    cfpo_nn_stats(xy, n, NULL, &a0, &a1);
    cfpo_dens_nn(&u, xy, n, NULL, &b0, &b1);
    CHECK(fabs(a0 - b0) <= 1e-12 * a0 && fabs(a1 - b1) <= 1e-12 * a1,
          "rho = 1: delta_min %.17g / %.17g, delta_avg %.17g / %.17g", a0, b0, a1, b1);
    /* each point's measure against brute force: uniform points on the
     * ramp 1:16, and points that follow Balzer's field (1:256), where a
     * dense region's points stop their search by the smallest q near
     * them, not the density's */
    CHECK(cfpo_density_load("ramp:contrast=16,res=64", &d, err, sizeof err) == 0, "%s", err);
    brute_measure(&d, xy, n, m, "ramp", NULL);
    cfpo_density bz;
    CHECK(cfpo_density_load("balzer", &bz, err, sizeof err) == 0, "%s", err);
    cfpo_dens_start(&bz, (int64_t)n, 7, xy);
    brute_measure(&bz, xy, n, m, "balzer, points that follow it", NULL);
    cfpo_density_free(&bz);
    /* the ramp 1:256 with points that follow it, through the engine's
     * kept near bounds: there most points stop their search by the
     * pyramid's finer bounds and their own place in their cell */
    cfpo_density r256;
    CHECK(cfpo_density_load("ramp:contrast=256", &r256, err, sizeof err) == 0, "%s", err);
    cfpo_dens_start(&r256, (int64_t)n, 9, xy);
    cfpo_dens_nn_near keep = {0};
    brute_measure(&r256, xy, n, m, "ramp 1:256, points that follow it, near bounds kept", &keep);
    brute_measure(&r256, xy, n, m, "ramp 1:256, points that follow it", NULL);
    cfpo_density_free(&r256);
    /* the start: exactly n, none on zero pixels, deterministic */
    cfpo_density z;
    double v[16 * 16];
    for (int k = 0; k < 256; k++) v[k] = (k % 16 < 4) ? 0 : 1 + (k % 7);
    cfpo_density_from_values(v, 16, 16, "z", &z, err, sizeof err);
    double *s2 = malloc(n * 2 * sizeof *s2);
    cfpo_dens_start(&z, (int64_t)n, 5, xy);
    cfpo_dens_start(&z, (int64_t)n, 5, s2);
    size_t off = 0;
    for (size_t i = 0; i < n; i++) off += !(cfpo_density_at(&z, xy[2 * i], xy[2 * i + 1]) > 0);
    CHECK(off == 0 && memcmp(xy, s2, n * 2 * sizeof *xy) == 0, "start: %zu points on zero pixels", off);
    free(xy); free(m); free(s2);
    cfpo_density_free(&u);
    cfpo_density_free(&d);
    cfpo_density_free(&z);
}

typedef struct { uint64_t key; uint32_t pix; } keyed_pix;

static int by_key(const void *a, const void *b)
{
    const keyed_pix *p = a, *q = b;
    return p->key < q->key ? -1 : p->key > q->key;
}

/* The start's walk along the curve gives the order of sorting the
 * positive pixels by cfpo_hilbert's index, on square, oblong, odd and
 * one-row rasters with zero pixels; a walk that turned one square the
 * wrong way, or skipped one, would differ. */
static void hilbert_walk(void)
{
    const int shape[][2] = {{1, 1}, {2, 2}, {16, 16}, {300, 77}, {77, 300}, {1000, 5}, {1, 129}, {64, 63}};
    for (size_t c = 0; c < sizeof shape / sizeof shape[0]; c++) {
        const int w = shape[c][0], h = shape[c][1];
        double *v = malloc((size_t)(w * h) * sizeof *v);
        for (int k = 0; k < w * h; k++) v[k] = cfpo_rand01(11, (uint64_t)c, (uint64_t)k) < 0.2 && k ? 0 : 1 + k % 5;
        cfpo_density d;
        char err[256];
        CHECK(cfpo_density_from_values(v, w, h, "walk", &d, err, sizeof err) == 0, "%s", err);
        uint64_t s = 1;
        while (s < (uint64_t)w || s < (uint64_t)h) s *= 2;
        keyed_pix *ref = malloc((size_t)(w * h) * sizeof *ref);
        uint32_t *got = malloc((size_t)(w * h) * sizeof *got);
        int64_t m = 0;
        for (int j = 0; j < h; j++)
            for (int i = 0; i < w; i++)
                if (d.rho[j * w + i] > 0) ref[m++] = (keyed_pix){cfpo_hilbert(s, (uint64_t)i, (uint64_t)j), (uint32_t)(j * w + i)};
        qsort(ref, (size_t)m, sizeof *ref, by_key);
        const int64_t mg = cfpo_dens_hilbert_order(&d, got);
        int64_t bad = mg == m ? 0 : 1;
        for (int64_t t = 0; t < m && t < mg; t++) bad += got[t] != ref[t].pix;
        CHECK(bad == 0, "Hilbert walk on %d x %d: %lld of %lld pixels out of the sorted order (%lld found)", w, h,
              (long long)bad, (long long)m, (long long)mg);
        free(v); free(ref); free(got);
        cfpo_density_free(&d);
    }
}

int main(int argc, char **argv)
{
    dir = argc > 1 ? argv[1] : ".";
    images();
    npy();
    named();
    measure();
    hilbert_walk();
    return test_report(passed_, failed_);
}
