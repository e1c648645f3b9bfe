/* png_read.h - layer 1: the PNG reader, through libpng's simplified API:
 * any PNG libpng reads (grey, palette, colour, with or without alpha) as
 * 8-bit grey (libpng's conversion of colour to grey; alpha composited by
 * it), at most GREY_MAX_PIXELS pixels.
 * Owns: the call into libpng. Does not own: what grey means (density.c). */
#ifndef CFPO_PNG_READ_H
#define CFPO_PNG_READ_H

#include <stddef.h>

#include "greyimg.h"

/* The image in buf (len bytes; name for messages). 0, or -1 with one line
 * in err; img->v is malloc'd on success. */
int png_parse(const unsigned char *buf, size_t len, const char *name, grey_image *img, char *err, size_t errlen);

#endif
