/* dens_ckpt.c - layer 3: the density run's checkpoint (dens_ckpt.h). */
#include "dens_ckpt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "cfpo_types.h"
#include "safefile.h"

static const char magic[8] = {'C', 'F', 'P', 'O', 'D', 'E', 'N', 'S'};

static void put64(unsigned char *p, uint64_t v) { for (int i = 0; i < 8; i++) p[i] = (unsigned char)(v >> 8 * i); }
static void put32(unsigned char *p, uint32_t v) { for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> 8 * i); }
static uint64_t get64(const unsigned char *p) { uint64_t v = 0; for (int i = 7; i >= 0; i--) v = v << 8 | p[i]; return v; }
static uint32_t get32(const unsigned char *p) { uint32_t v = 0; for (int i = 3; i >= 0; i--) v = v << 8 | p[i]; return v; }

int dens_ckpt_is(const char *path)
{
    FILE *f = fopen(path, "rb");
    char b[8];
    int yes = f && fread(b, 1, 8, f) == 8 && memcmp(b, magic, 8) == 0;
    if (f) fclose(f);
    return yes;
}

static uint32_t checksum(const unsigned char *h, const unsigned char *pts, size_t len)
{
    unsigned char z[64];
    memcpy(z, h, 64);
    put32(z + 56, 0);
    uLong c = crc32(crc32(0L, Z_NULL, 0), z, 64);
    while (len > 0) {
        uInt k = len > (1u << 30) ? (1u << 30) : (uInt)len;
        c = crc32(c, pts, k);
        pts += k;
        len -= k;
    }
    return (uint32_t)c;
}

int dens_ckpt_write(const char *path, const dens_ckpt_info *info, const double *xy, char *err, size_t errlen)
{
    unsigned char h[64] = {0};
    memcpy(h, magic, 8);
    put32(h + 8, 1);
    put32(h + 12, (uint32_t)info->converged);
    put64(h + 16, (uint64_t)info->n);
    put64(h + 24, info->seed);
    put64(h + 32, info->hash);
    uint64_t t;
    memcpy(&t, &info->tol, 8);
    put64(h + 40, t);
    put64(h + 48, (uint64_t)info->iteration);
    const size_t len = (size_t)info->n * 16;
    unsigned char *pts = malloc(len ? len : 1);
    if (!pts) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    for (size_t i = 0; i < (size_t)info->n * 2; i++) {
        uint64_t u;
        memcpy(&u, &xy[i], 8);
        put64(pts + 8 * i, u);
    }
    put32(h + 56, checksum(h, pts, len));
    safefile a;
    int rc = safefile_open(&a, path, "wb", err, errlen);
    if (rc == 0) {
        if (fwrite(h, 1, 64, a.f) != 64 || fwrite(pts, 1, len, a.f) != len) {
            safefile_abort(&a);
            snprintf(err, errlen, "%s: write failed", path);
            rc = -1;
        } else rc = safefile_commit(&a, err, errlen);
    }
    free(pts);
    return rc;
}

int dens_ckpt_read(const char *path, dens_ckpt_info *info, double **xy, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) { snprintf(err, errlen, "--resume %s: cannot open the file", path); return -1; }
    unsigned char h[64];
    if (fread(h, 1, 64, f) != 64 || memcmp(h, magic, 8) != 0) {
        fclose(f);
        snprintf(err, errlen, "--resume %s: not a density checkpoint (bad magic or truncated header)", path);
        return -1;
    }
    info->converged = (int)get32(h + 12);
    info->n = (int64_t)get64(h + 16);
    info->seed = get64(h + 24);
    info->hash = get64(h + 32);
    uint64_t t = get64(h + 40);
    memcpy(&info->tol, &t, 8);
    const uint64_t it = get64(h + 48);
    const char *bad = get32(h + 8) != 1 ? "version" : info->converged > 1 ? "converged" : info->n < 2 || info->n > ((int64_t)1 << 40) ? "n"
                      : !(info->tol >= 0 && info->tol <= CFPO_TOL_MAX) ? "tol" : it > 1000000000u ? "iteration"
                      : get32(h + 60) != 0 ? "reserved field" : NULL;
    if (bad) {
        fclose(f);
        snprintf(err, errlen, "--resume %s: bad %s in the density checkpoint's header", path, bad);
        return -1;
    }
    info->iteration = (int)it;
    const size_t len = (size_t)info->n * 16;
    unsigned char *pts = malloc(len + 1);
    double *p = malloc((size_t)info->n * 2 * sizeof *p);
    int rc = -1;
    if (!pts || !p) snprintf(err, errlen, "--resume %s: out of memory", path);
    else if (fread(pts, 1, len + 1, f) != len) snprintf(err, errlen, "--resume %s: truncated or overlong (n=%lld)", path, (long long)info->n);
    else if (checksum(h, pts, len) != get32(h + 56)) snprintf(err, errlen, "--resume %s: checksum mismatch", path);
    else {
        rc = 0;
        for (size_t i = 0; i < (size_t)info->n * 2; i++) {
            uint64_t u = get64(pts + 8 * i);
            memcpy(&p[i], &u, 8);
            if (!(p[i] >= 0 && p[i] < 1)) {
                snprintf(err, errlen, "--resume %s: coordinate %zu is not in [0, 1)", path, i);
                rc = -1;
                break;
            }
        }
    }
    fclose(f);
    free(pts);
    if (rc != 0) free(p);
    else *xy = p;
    return rc;
}
