/* pgm.c - layer 1: the PGM reader (pgm.h). */
#include "pgm.h"

#include <stdio.h>
#include <stdlib.h>

static int is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/* Skips white space and comments (a '#' to the end of its line). */
static size_t skip_blank(const unsigned char *b, size_t len, size_t i)
{
    for (;;) {
        while (i < len && is_space(b[i])) i++;
        if (i < len && b[i] == '#') {
            while (i < len && b[i] != '\n' && b[i] != '\r') i++;
            continue;
        }
        return i;
    }
}

/* A decimal number in [lo, hi] at b[*i]. */
static int number(const unsigned char *b, size_t len, size_t *i, long lo, long hi, long *out)
{
    size_t k = *i;
    long v = 0;
    if (k >= len || b[k] < '0' || b[k] > '9') return -1;
    while (k < len && b[k] >= '0' && b[k] <= '9') {
        v = v * 10 + (b[k] - '0');
        if (v > hi) return -1;
        k++;
    }
    if (v < lo) return -1;
    *i = k;
    *out = v;
    return 0;
}

int pgm_parse(const unsigned char *buf, size_t len, const char *name, grey_image *img, char *err, size_t errlen)
{
    img->v = NULL;
    if (len < 2 || buf[0] != 'P' || (buf[1] != '5' && buf[1] != '2')) {
        snprintf(err, errlen, "%s: not a PGM image (magic P5 or P2 expected)", name);
        return -1;
    }
    const int plain = buf[1] == '2';
    size_t i = 2;
    long f[3];
    static const char *what[3] = {"width", "height", "maxval"};
    for (int k = 0; k < 3; k++) {
        size_t j = skip_blank(buf, len, i);
        if (j == i || number(buf, len, &j, 1, k == 2 ? 65535 : 1L << 30, &f[k]) != 0) {
            snprintf(err, errlen, "%s: PGM header: bad or missing %s", name, what[k]);
            return -1;
        }
        i = j;
    }
    if ((int64_t)f[0] * f[1] > GREY_MAX_PIXELS) {
        snprintf(err, errlen, "%s: image of %ld x %ld pixels is too large (at most %lld pixels)", name, f[0], f[1],
                 (long long)GREY_MAX_PIXELS);
        return -1;
    }
    if (i >= len || !is_space(buf[i])) {
        snprintf(err, errlen, "%s: truncated PGM header", name);
        return -1;
    }
    i++;
    const size_t np = (size_t)f[0] * (size_t)f[1];
    const int wide = f[2] > 255;
    if (!plain && len - i < np * (wide ? 2u : 1u)) {
        snprintf(err, errlen, "%s: truncated PGM data (%zu pixels announced)", name, np);
        return -1;
    }
    uint16_t *v = malloc(np * sizeof *v);
    if (!v) { snprintf(err, errlen, "%s: out of memory for %zu pixels", name, np); return -1; }
    for (size_t p = 0; p < np; p++) {
        long x;
        if (plain) {
            size_t j = skip_blank(buf, len, i);
            if ((j == i && p > 0) || number(buf, len, &j, 0, 65535, &x) != 0) {
                snprintf(err, errlen, "%s: truncated or bad PGM data at pixel %zu", name, p);
                free(v);
                return -1;
            }
            i = j;
        } else if (wide) { x = (long)buf[i] << 8 | buf[i + 1]; i += 2; }
        else x = buf[i++];
        if (x > f[2]) {
            snprintf(err, errlen, "%s: PGM value %ld above maxval %ld at pixel %zu", name, x, f[2], p);
            free(v);
            return -1;
        }
        v[p] = (uint16_t)x;
    }
    if (plain) i = skip_blank(buf, len, i);
    if (i != len) {
        snprintf(err, errlen, "%s: data after the PGM image (%zu bytes)", name, len - i);
        free(v);
        return -1;
    }
    img->w = f[0];
    img->h = f[1];
    img->maxval = (uint32_t)f[2];
    img->v = v;
    return 0;
}
