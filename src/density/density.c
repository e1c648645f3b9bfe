/* density.c - layer 2: a density on the torus (density.h): the SPEC
 * grammar, the files read whole, grey values and arrays handed to
 * density_values.c (normalisation, validation, hash). */
#include "density.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "geom.h"
#include "npy.h"
#include "pgm.h"
#include "png_read.h"
#include "readall.h"

/* The largest file read: an image or array of GREY_MAX_PIXELS float64
 * values and its header. */
#define FILE_MAX ((size_t)GREY_MAX_PIXELS * 8 + 65536)

static int read_whole(const char *path, unsigned char **buf, size_t *len, char *err, size_t errlen)
{
    switch (readall(path, FILE_MAX, buf, len)) {
    case READALL_OK: return 0;
    case READALL_OPEN: snprintf(err, errlen, "--density %s: cannot open the file", path); break;
    case READALL_LARGE: snprintf(err, errlen, "--density %s: file too large (over %zu bytes)", path, FILE_MAX); break;
    case READALL_MEMORY: snprintf(err, errlen, "--density %s: out of memory reading the file", path); break;
    case READALL_READ: snprintf(err, errlen, "--density %s: read error", path); break;
    }
    return -1;
}

static int from_grey(const grey_image *g, int invert, const char *what, cfpo_density *d, char *err, size_t errlen)
{
    double *v = malloc((size_t)(g->w * g->h) * sizeof *v + 1);
    if (!v) { snprintf(err, errlen, "%s: out of memory", what); return -1; }
    for (int64_t j = 0; j < g->h; j++) /* file row 0 is the top: y near 1 */
        for (int64_t i = 0; i < g->w; i++) {
            const double t = (double)g->v[(g->h - 1 - j) * g->w + i] / (double)g->maxval;
            v[j * g->w + i] = invert ? t : 1 - t;
        }
    int rc = cfpo_density_from_values(v, g->w, g->h, what, d, err, errlen);
    free(v);
    return rc;
}

static int from_npy(const unsigned char *buf, size_t len, const char *path, cfpo_density *d, char *err,
                    size_t errlen)
{
    npy_info h;
    if (npy_parse_header_2d(path, buf, len, &h, err, errlen) != 0) return -1;
    const size_t H = h.n, W = h.cols, cnt = H * W;
    if (H == 0 || W == 0) { snprintf(err, errlen, "%s: empty array (%zu x %zu)", path, H, W); return -1; }
    if (cnt > (size_t)GREY_MAX_PIXELS) {
        snprintf(err, errlen, "%s: array of %zu x %zu is too large (at most %lld values)", path, H, W,
                 (long long)GREY_MAX_PIXELS);
        return -1;
    }
    if (len - h.data != cnt * (size_t)h.itemsize) {
        snprintf(err, errlen, "%s: %s .npy data: %zu bytes for %zu values of %d bytes", path,
                 len - h.data < cnt * (size_t)h.itemsize ? "truncated" : "extra bytes after the", len - h.data, cnt,
                 h.itemsize);
        return -1;
    }
    double *v = malloc(cnt * sizeof *v);
    if (!v) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    for (size_t k = 0; k < cnt; k++) {
        const unsigned char *p = buf + h.data + k * (size_t)h.itemsize;
        unsigned char b[8];
        for (int t = 0; t < h.itemsize; t++) b[t] = h.big_endian ? p[h.itemsize - 1 - t] : p[t];
        uint64_t u = 0;
        for (int t = h.itemsize - 1; t >= 0; t--) u = u << 8 | b[t];
        double x;
        if (h.itemsize == 8) memcpy(&x, &u, 8);
        else { uint32_t u32 = (uint32_t)u; float f; memcpy(&f, &u32, 4); x = f; }
        const size_t row = h.fortran ? k % H : k / W, col = h.fortran ? k / H : k % W;
        v[row * W + col] = x;
    }
    int rc = cfpo_density_from_values(v, (int64_t)W, (int64_t)H, path, d, err, errlen);
    free(v);
    return rc;
}

static int ends_with(const char *s, size_t n, const char *ext)
{
    size_t m = strlen(ext);
    return n >= m && strncasecmp(s + n - m, ext, m) == 0;
}

int cfpo_density_load(const char *spec, cfpo_density *d, char *err, size_t errlen)
{
    memset(d, 0, sizeof *d);
    size_t n = strlen(spec);
    int invert = 0;
    if (ends_with(spec, n, ":invert")) { invert = 1; n -= 7; }
    enum { NONE, PNG, PGM, NPY } kind = ends_with(spec, n, ".png") ? PNG : ends_with(spec, n, ".pgm") ? PGM
                                        : ends_with(spec, n, ".npy") ? NPY : NONE;
    if (kind == NONE || (invert && kind == NPY)) {
        if (invert) {
            snprintf(err, errlen, "--density %s: ':invert' is for images (.png, .pgm)", spec);
            return -1;
        }
        char name[32];
        const char *colon = strchr(spec, ':');
        size_t k = colon ? (size_t)(colon - spec) : n;
        if (k >= sizeof name) k = sizeof name - 1;
        memcpy(name, spec, k);
        name[k] = '\0';
        return cfpo_density_named(name, colon ? colon + 1 : NULL, d, err, errlen);
    }
    char *path = malloc(n + 1);
    if (!path) { snprintf(err, errlen, "--density: out of memory"); return -1; }
    memcpy(path, spec, n);
    path[n] = '\0';
    unsigned char *buf;
    size_t len;
    int rc = read_whole(path, &buf, &len, err, errlen);
    if (rc == 0) {
        if (kind == NPY) rc = from_npy(buf, len, path, d, err, errlen);
        else {
            grey_image g;
            char what[300];
            snprintf(what, sizeof what, "--density %s", path);
            rc = kind == PNG ? png_parse(buf, len, what, &g, err, errlen) : pgm_parse(buf, len, what, &g, err, errlen);
            if (rc == 0) rc = from_grey(&g, invert, what, d, err, errlen);
            free(g.v);
        }
        free(buf);
    }
    free(path);
    return rc;
}
