/* greyimg.h - layer 0: a greyscale image as the image readers return it
 * (src/density/pgm.c, src/density/png_read.c) and src/density/density.c turns into a density.
 * Rows top first, as stored in the file; each value in [0, maxval]. */
#ifndef CFPO_GREYIMG_H
#define CFPO_GREYIMG_H

#include <stdint.h>

/* The largest image read: 2^26 pixels (a density of 8 bytes per pixel and
 * its sampling tables stay under about a gigabyte). */
#define GREY_MAX_PIXELS ((int64_t)1 << 26)

typedef struct {
    int64_t w, h;
    uint32_t maxval; /* white */
    uint16_t *v;     /* w h values, row 0 the top row */
} grey_image;

#endif
