/* fuzz_points.h - the body shared by the four point-file harnesses: the
 * reader must return 0 with n >= 1 points all in [0,1)^2, or -1 with one
 * line naming the file; anything else (a crash, a sanitizer report, a
 * message without the name, a point outside) aborts. */
#ifndef CFPO_FUZZ_POINTS_H
#define CFPO_FUZZ_POINTS_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "pointfile.h"

static int fuzz_points(pf_format fmt, const uint8_t *data, size_t size)
{
    double *xy = NULL;
    size_t n = 0;
    char err[512] = "";
    int rc = pf_read_buffer(fmt, "fuzz.input", data, size, &xy, &n, err, sizeof err);
    if (rc == 0) {
        if (n < 1) abort();
        for (size_t i = 0; i < 2 * n; i++)
            if (!(xy[i] >= 0 && xy[i] < 1)) abort();
        free(xy);
    } else {
        if (rc != -1 || strncmp(err, "fuzz.input: ", 12) != 0 || strchr(err, '\n')) abort();
    }
    return 0;
}

#endif
