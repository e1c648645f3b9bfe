/* png_read.c - layer 1: the PNG reader (png_read.h). */
#include "png_read.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int png_parse(const unsigned char *buf, size_t len, const char *name, grey_image *img, char *err, size_t errlen)
{
    img->v = NULL;
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (len < 8 || memcmp(buf, sig, 8) != 0) {
        snprintf(err, errlen, "%s: not a PNG image (bad signature)", name);
        return -1;
    }
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&im, buf, len)) {
        snprintf(err, errlen, "%s: unreadable PNG: %s", name, im.message);
        png_image_free(&im);
        return -1;
    }
    if ((int64_t)im.width * im.height > GREY_MAX_PIXELS) {
        snprintf(err, errlen, "%s: image of %u x %u pixels is too large (at most %lld pixels)", name, im.width,
                 im.height, (long long)GREY_MAX_PIXELS);
        png_image_free(&im);
        return -1;
    }
    im.format = PNG_FORMAT_GRAY;
    const size_t np = (size_t)im.width * im.height;
    unsigned char *g = malloc(np ? np : 1);
    uint16_t *v = malloc((np ? np : 1) * sizeof *v);
    if (!g || !v) {
        snprintf(err, errlen, "%s: out of memory for %zu pixels", name, np);
        free(g); free(v);
        png_image_free(&im);
        return -1;
    }
    if (!png_image_finish_read(&im, NULL, g, (png_int_32)im.width, NULL)) {
        snprintf(err, errlen, "%s: unreadable PNG: %s", name, im.message);
        free(g); free(v);
        png_image_free(&im);
        return -1;
    }
    for (size_t p = 0; p < np; p++) v[p] = g[p];
    free(g);
    img->w = im.width;
    img->h = im.height;
    img->maxval = 255;
    img->v = v;
    png_image_free(&im);
    return 0;
}
