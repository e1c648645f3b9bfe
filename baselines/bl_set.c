/* bl_set.c - the engine of a direct sampler (bl_set.h). */
#include "bl_set.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stats.h"

bl_set *bl_set_new(int64_t n, char *err, size_t errlen)
{
    bl_set *S = malloc(sizeof *S);
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!S || !xy) {
        free(S);
        free(xy);
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        return NULL;
    }
    S->n = n;
    S->xy = xy;
    return S;
}

void bl_set_deltas(void *E, double *dmin, double *davg)
{
    const bl_set *S = E;
    if (cfpo_nn_stats(S->xy, (size_t)S->n, NULL, dmin, davg) != 0) *dmin = *davg = NAN;
}

const double *bl_set_points(void *E) { return ((bl_set *)E)->xy; }

void bl_set_destroy(void *E)
{
    bl_set *S = E;
    if (!S) return;
    free(S->xy);
    free(S);
}
