/* lct.c - the two properties of the Local Characterization Theorem for
 * one point x (certify.h says what they are): the farthest point of S(x)
 * from the points of D(x), and from those without x.
 *
 * Where D(x) holds few points (a well-spread set) each is one call of the
 * solver. Where it holds many, they are usually the same many for many
 * points (each point of a cluster has the whole cluster for D(x)): a
 * thread keeps the last few such sets, prepares one when it is seen again
 * (farprep.c), and from then on recognises it through the points' tree,
 * without collecting D(x) at all. */
#include <math.h>

#include "certify_int.h"
#include "farthest.h"
#include "farthest_int.h"
#include "geom.h"
#include "ptree.h"

/* Copies into sx/sy the collected images within Chebyshev H of (cx, cy),
 * leaving out the images of point `skip` (pass n to keep all). */
static int subset(const an_cert_work *w, double cx, double cy, double H, size_t skip, double *sx, double *sy)
{
    int m = 0;
    for (size_t t = 0; t < w->m; t++) {
        if (w->id[t] == skip || fabs(w->x[t] - cx) > H || fabs(w->y[t] - cy) > H) continue;
        sx[m] = w->x[t];
        sy[m] = w->y[t];
        m++;
    }
    return m;
}

/* The prepared set that is exactly D(x)'s, found without collecting: its
 * box lies in D(x) and D(x) holds as many images (2h < 1: one of x). */
static an_far_prep *covering_slot(const an_cert_ctx *C, an_cert_work *w, double x, double y, double h)
{
    if (!(h < 0.5)) return NULL;
    size_t count = 0;
    int counted = 0;
    for (int k = 0; k < AN_PREP_SLOTS; k++) {
        an_far_prep *P = &w->prep[k];
        if (!P->ready || fabs(P->x0 - x) > h || fabs(P->x1 - x) > h || fabs(P->y0 - y) > h || fabs(P->y1 - y) > h)
            continue;
        if (!counted) { count = an_ptree_count_box(C->tree, x, y, h); counted = 1; }
        if (count != P->m) continue;
        w->used[k] = ++w->clock;
        return P;
    }
    return NULL;
}

/* The slot holding the collected set sx/sy (m points) once it has been
 * seen AN_PREP_AFTER times, or NULL (after keeping it in the least
 * recently used slot if it is new); -1 in *err out of memory. */
static an_far_prep *remembered(an_cert_work *w, int m, int *err)
{
    int lru = 0;
    for (int k = 0; k < AN_PREP_SLOTS; k++) {
        if (an_far_prep_same(&w->prep[k], w->sx, w->sy, (size_t)m)) {
            w->used[k] = ++w->clock;
            if (w->seen[k] < AN_PREP_AFTER) w->seen[k]++;
            return w->seen[k] >= AN_PREP_AFTER ? &w->prep[k] : NULL;
        }
        if (w->used[k] < w->used[lru]) lru = k;
    }
    if (an_far_prep_set(&w->prep[lru], w->sx, w->sy, (size_t)m) != 0) *err = -1;
    w->used[lru] = ++w->clock;
    w->seen[lru] = 1;
    return NULL;
}

int an_lct(const an_cert_ctx *C, size_t i, an_cert_work *w, double h, double *p1, double *p2)
{
    const double x = C->xy[2 * i], y = C->xy[2 * i + 1];
    const double e = h - C->delta;
    const cfpo_square S = {x - e, y - e, x + e, y + e};
    double px, py, r2;
    an_far_prep *P = covering_slot(C, w, x, y, h);
    if (P) {
        r2 = an_far_prep_solve(P, S, 0, 0, 0, NULL, &px, &py, &w->far);
        if (r2 < 0) return -2;
        *p1 = sqrt(r2) - C->delta;
        const double dY2 = an_far_prep_nearest(P, x, y, 1, x, y), p1_at[2] = {px, py};
        r2 = an_far_prep_solve(P, S, 1, x, y, p1_at, &px, &py, &w->far);
        if (r2 == -3) { /* not for the prepared form: the set without x, collected */
            if (an_cert_collect(C, x, y, h, w) != 0) return -1;
            const int m = subset(w, x, y, h, i, w->sx, w->sy);
            r2 = an_farthest(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
        }
        if (r2 < 0) return -2;
        *p2 = sqrt(r2) - sqrt(dY2);
        return 0;
    }
    if (an_cert_collect(C, x, y, h, w) != 0) return -1;
    int m = subset(w, x, y, h, C->n, w->sx, w->sy);
    /* The set is kept, and prepared when seen AN_PREP_AFTER times (each
     * point of a cluster has the whole cluster for D(x)); until then a few
     * points may decide it (farsub.c: a segment's or an arc's D(x), which
     * differs from point to point or recurs a few times only). */
    r2 = -3;
    if (m > AN_FAR_SMALL) {
        int err = 0;
        P = remembered(w, m, &err);
        if (err) return -1;
        if (!P) r2 = an_farthest_sub(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, w->scratch);
        else if (!P->ready && an_far_prep_build(P) != 0) return -1;
    }
    if (r2 == -3)
        r2 = P ? an_far_prep_solve(P, S, 0, 0, 0, NULL, &px, &py, &w->far)
               : an_farthest_whole(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
    if (r2 < 0) return -2;
    *p1 = sqrt(r2) - C->delta;
    const int m1 = m;
    const double p1_at[2] = {px, py};
    m = subset(w, x, y, h, i, w->sx, w->sy);
    const double dY2 = cfpo_min_dist2(x, y, w->sx, w->sy, m, -1);
    r2 = m > AN_FAR_SMALL ? an_farthest_sub(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, w->scratch) : -3;
    if (r2 == -3 && P && m == m1 - 1 && m > AN_FAR_SMALL) r2 = an_far_prep_solve(P, S, 1, x, y, p1_at, &px, &py, &w->far);
    if (r2 == -3) r2 = an_farthest_whole(w->sx, w->sy, (size_t)m, S, x, y, &px, &py, &w->far);
    if (r2 < 0) return -2;
    *p2 = sqrt(r2) - sqrt(dY2);
    return 0;
}
