/* certwork.c - see certwork.h. */
#include "certwork.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"

typedef an_cert_ctx ctx;
typedef an_cert_work work;

int an_cert_reserve(work *w, size_t m)
{
    if (m <= w->cap) return 0;
    size_t cap = w->cap ? w->cap : 64;
    while (cap < m) cap *= 2;
    double *x = realloc(w->x, cap * sizeof *x);
    if (x) w->x = x;
    double *y = realloc(w->y, cap * sizeof *y);
    if (y) w->y = y;
    double *sx = realloc(w->sx, cap * sizeof *sx);
    if (sx) w->sx = sx;
    double *sy = realloc(w->sy, cap * sizeof *sy);
    if (sy) w->sy = sy;
    size_t *id = realloc(w->id, cap * sizeof *id);
    if (id) w->id = id;
    double *sc = realloc(w->scratch, cfpo_solver_scratch(cap) * sizeof *sc);
    if (sc) w->scratch = sc;
    double *pa = realloc(w->pa, 2 * (cap + 8) * sizeof *pa);
    if (pa) w->pa = pa;
    double *pb = realloc(w->pb, 2 * (cap + 8) * sizeof *pb);
    if (pb) w->pb = pb;
    double *sd = realloc(w->sd, 2 * (cap + 8) * sizeof *sd);
    if (sd) w->sd = sd;
    double *fr2 = realloc(w->fr2, (cap + 8) * sizeof *fr2);
    if (fr2) w->fr2 = fr2;
    if (!x || !y || !sx || !sy || !id || !sc || !pa || !pb || !sd || !fr2) return -1;
    w->cap = cap;
    return 0;
}

void an_cert_work_free(work *w)
{
    free(w->x); free(w->y); free(w->sx); free(w->sy); free(w->id); free(w->scratch);
    free(w->pa); free(w->pb); free(w->sd); free(w->fr2); free(w->mark); free(w->marked);
    free(w->cand); free(w->cand_id);
    an_far_free(&w->far);
    for (int k = 0; k < AN_PREP_SLOTS; k++) an_far_prep_free(&w->prep[k]);
    an_pwalk_free(&w->walk);
}

static long floordiv(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

/* All images of points within Chebyshev distance H of (cx, cy), in a fixed
 * order (cells by rows, points by index inside a cell). */
int an_cert_collect(const ctx *C, double cx, double cy, double H, work *w)
{
    const long g = (long)C->G.g;
    const long ix0 = (long)floor((cx - H) * g), ix1 = (long)floor((cx + H) * g);
    const long iy0 = (long)floor((cy - H) * g), iy1 = (long)floor((cy + H) * g);
    w->m = 0;
    for (long iy = iy0; iy <= iy1; iy++) {
        const long oy = floordiv(iy, g), wy = iy - oy * g;
        for (long ix = ix0; ix <= ix1; ix++) {
            const long ox = floordiv(ix, g), wx = ix - ox * g;
            const size_t cell = (size_t)(wy * g + wx);
            for (size_t q = C->G.start[cell]; q < C->G.start[cell + 1]; q++) {
                const size_t j = C->G.idx[q];
                const double X = C->xy[2 * j] + (double)ox, Y = C->xy[2 * j + 1] + (double)oy;
                if (fabs(X - cx) > H || fabs(Y - cy) > H) continue;
                if (an_cert_reserve(w, w->m + 1) != 0) return -1;
                w->x[w->m] = X;
                w->y[w->m] = Y;
                w->id[w->m] = j;
                w->m++;
            }
        }
    }
    return 0;
}
