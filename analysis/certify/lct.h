/* lct.h - the Local Characterization Theorem's two properties for one
 * point (lct.c; certify.h says what they are). */
#ifndef AN_LCT_H
#define AN_LCT_H

#include <stddef.h>

#include "certwork.h"

/* Both properties of the Local Characterization Theorem for point i, with
 * D(x) of half-side h (lct.c): their violations, absolute. 0, -1 out of
 * memory, -2 the solver found no vertex. */
int an_lct(const an_cert_ctx *C, size_t i, an_cert_work *w, double h, double *p1, double *p2);

#endif
