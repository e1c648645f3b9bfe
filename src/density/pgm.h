/* pgm.h - layer 1: the PGM reader (Netpbm greyscale, P5 binary and P2
 * plain, maxval 1..65535, '#' comments in the header), strict: the header
 * grammar of Netpbm's pgm(5), values above maxval refused, exactly one
 * image (no data after it), at most GREY_MAX_PIXELS pixels.
 * Owns: the PGM grammar. Does not own: what the grey values mean
 * (density.c). */
#ifndef CFPO_PGM_H
#define CFPO_PGM_H

#include <stddef.h>

#include "greyimg.h"

/* The image in buf (len bytes; name for messages). 0, or -1 with one line
 * in err; img->v is malloc'd on success. */
int pgm_parse(const unsigned char *buf, size_t len, const char *name, grey_image *img, char *err, size_t errlen);

#endif
