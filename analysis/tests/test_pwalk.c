/* test_pwalk.c - the nearest-first walk over the images of the
 * certificate's point tree (ptree.c: an_pwalk_*) against brute force, on
 * the sets of ptree_sets.h (uniform from 1 to 3,000 points, clusters,
 * lines, the torus's edge, a lattice, copies of two positions).
 *
 * Must hold:
 *  - the walk (radius 0, below 0.5, 1, above 1, and exactly at an image's
 *    distance): with no leaf of one position, the multiset of (index,
 *    image) equals the brute force over every image with offsets well
 *    past the disk, whatever `skip`; each image (px, py) is its point
 *    moved by integers, with d2 = (px - qx)^2 + (py - qy)^2 exactly and
 *    within r, the distances non-decreasing, and the same query gives the
 *    same sequence again (the heap reused) and from a fresh walk. With 300
 *    copies of each of two positions, each position is reported exactly
 *    once for each of its images in the disk, and never as `skip` when
 *    `skip` is one of its copies (240 + 360: at least once, no point's
 *    image twice);
 *  - the walk's filter: fixed disks give the brute force's images in them
 *    (closed disks); disks shrunk during a walk, every image in the new
 *    ones beyond the distance reached and none outside them, whether the
 *    queue is pruned at once (an_pwalk_prune) or not; a new start drops
 *    the filter. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "ptree.h"
#include "ptree_sets.h"
#include "rng.h"
#include "testutil.h"

static int passed_, failed_;

/* ---- the walk ---- */

typedef struct { size_t id; double ox, oy, d2; int either; } image;

static int cmp_image(const void *a, const void *b)
{
    const image *p = a, *q = b;
    if (p->id != q->id) return p->id < q->id ? -1 : 1;
    if (p->ox != q->ox) return p->ox < q->ox ? -1 : 1;
    return p->oy < q->oy ? -1 : (p->oy > q->oy);
}

typedef struct { image *v; size_t len, cap; } list;

static void sort_list(list *L)
{
    if (L->len > 1) qsort(L->v, L->len, sizeof *L->v, cmp_image);
}

static void add(list *L, size_t id, double ox, double oy, double d2, int either)
{
    if (L->len == L->cap) {
        L->cap = L->cap ? 2 * L->cap : 1024;
        L->v = realloc(L->v, L->cap * sizeof *L->v);
    }
    L->v[L->len++] = (image){id, ox, oy, d2, either};
}

/* Every image of every point within r, in the walk's arithmetic, offsets
 * two periods past the disk on each side. An image whose coordinate
 * rounds out of its period (x + o rounded to o + 1: x within an ulp of 1)
 * is marked `either`: rounded, it may lie within r while the image itself
 * lies beyond (its period wholly beyond r), so the walk may give it or
 * not. */
static void brute_walk(const double *xy, size_t n, double qx, double qy, double r, list *L)
{
    const double r2 = r * r;
    L->len = 0;
    for (size_t j = 0; j < n; j++)
        for (double oy = floor(qy - r) - 2; oy <= floor(qy + r) + 2; oy++)
            for (double ox = floor(qx - r) - 2; ox <= floor(qx + r) + 2; ox++) {
                const double X = xy[2 * j] + ox, Y = xy[2 * j + 1] + oy;
                const double dx = X - qx, dy = Y - qy, d2 = dx * dx + dy * dy;
                if (d2 <= r2) add(L, j, ox, oy, d2, X >= ox + 1 || Y >= oy + 1);
            }
}

/* Whether the image (X, Y) lies in one of the fn closed disks (centres
 * fv, squared radii fr2), in the walk's arithmetic. */
static int in_disks(double X, double Y, const double *fv, const double *fr2, int fn)
{
    for (int v = 0; v < fn; v++) {
        const double dx = fabs(X - fv[2 * v]), dy = fabs(Y - fv[2 * v + 1]);
        if (dx * dx + dy * dy <= fr2[v]) return 1;
    }
    return 0;
}

/* The brute force's images in the disks (the pointers are L's). */
static void keep_in_disks(const double *xy, list *L, const double *fv, const double *fr2, int fn)
{
    size_t k = 0;
    for (size_t g = 0; g < L->len; g++) {
        const image *e = &L->v[g];
        if (in_disks(xy[2 * e->id] + e->ox, xy[2 * e->id + 1] + e->oy, fv, fr2, fn)) L->v[k++] = *e;
    }
    L->len = k;
}

/* Runs the walk; checks each image's form, distance and order; 0 on
 * failure. The images go to L with their offsets. */
static int walk_on(const char *what, an_pwalk *W, const double *xy, size_t n, double qx, double qy, double r,
                   list *L, size_t stop, double last);

static int run_walk(const char *what, an_pwalk *W, const an_ptree *T, const double *xy, size_t n, double qx,
                    double qy, double r, size_t skip, list *L)
{
    L->len = 0;
    if (an_pwalk_start(W, T, qx, qy, r, skip) != 0) { CHECK(0, "%s: walk start failed", what); return 0; }
    return walk_on(what, W, xy, n, qx, qy, r, L, SIZE_MAX, -INFINITY);
}

/* The walk from where it is, appending to L, until it ends or L holds
 * `stop` images; `last` the distance given before. */
static int walk_on(const char *what, an_pwalk *W, const double *xy, size_t n, double qx, double qy, double r,
                   list *L, size_t stop, double last)
{
    int ok_form = 1, ok_d2 = 1, ok_order = 1, got = 0;
    double px, py, d2;
    size_t id;
    while (L->len < stop && (got = an_pwalk_next(W, &px, &py, &id, &d2)) == 1) {
        if (id >= n) { ok_form = 0; break; }
        const double ox = round(px - xy[2 * id]), oy = round(py - xy[2 * id + 1]);
        if (xy[2 * id] + ox != px || xy[2 * id + 1] + oy != py) ok_form = 0;
        const double dx = px - qx, dy = py - qy;
        if (d2 != dx * dx + dy * dy || !(d2 <= r * r)) ok_d2 = 0;
        if (d2 < last) ok_order = 0;
        last = d2;
        add(L, id, ox, oy, d2, 0);
        if (L->len > 100000000) break;
    }
    if (L->len >= stop && got == 1) got = 0; /* stopped, not ended */
    CHECK(got == 0, "%s: walk ended with %d", what, got);
    CHECK(ok_form, "%s: r = %g: an image is not its point moved by whole periods", what, r);
    CHECK(ok_d2, "%s: r = %g: a distance is not the image's, or beyond r", what, r);
    CHECK(ok_order, "%s: r = %g: distances out of order", what, r);
    return ok_form && ok_d2 && ok_order && got == 0;
}

static int same_sequence(const list *A, const list *B)
{
    if (A->len != B->len) return 0;
    for (size_t k = 0; k < A->len; k++)
        if (A->v[k].id != B->v[k].id || A->v[k].ox != B->v[k].ox || A->v[k].oy != B->v[k].oy ||
            A->v[k].d2 != B->v[k].d2)
            return 0;
    return 1;
}

/* Sorts A and B; 1 when each of A is one of B's (at the same distance),
 * once, and each of B not `either` and beyond t is in A. */
static int covers(list *A, list *B, double t)
{
    sort_list(A);
    sort_list(B);
    size_t g = 0, w = 0;
    while (g < A->len || w < B->len) {
        const int c = g == A->len ? 1 : w == B->len ? -1 : cmp_image(&A->v[g], &B->v[w]);
        if (c == 0) {
            if (A->v[g].d2 != B->v[w].d2) return 0;
            g++; w++;
        } else if (c > 0 && (B->v[w].either || !(B->v[w].d2 > t))) w++;
        else return 0;
    }
    return 1;
}

/* The radii of one query: 0, a small one, below 0.5, about 1, above 1,
 * and one exactly at an image's distance (r * r == that d2 where a double
 * r gives it). */
static int radii(const double *xy, size_t n, double qx, double qy, double big, double *r)
{
    int k = 0;
    r[k++] = 0;
    r[k++] = n > 0 ? 2.5 / sqrt((double)n) : 0.1;
    r[k++] = 0.43;
    if (big > 0) { r[k++] = 1.0; r[k++] = big; }
    if (n > 0) {
        const size_t j = n / 3;
        const double dx = (xy[2 * j] + 1) - qx, dy = xy[2 * j + 1] - qy, e = dx * dx + dy * dy;
        double s = sqrt(e);
        for (int t = 0; t < 4 && s * s != e; t++) s = s * s < e ? nextafter(s, INFINITY) : nextafter(s, 0);
        if (s * s > e) s = nextafter(s, 0);
        r[k++] = s;
    }
    return k;
}

/* Sets with no leaf of one position: the walk is the brute force. */
static void walk_exact(const char *what, const an_ptree *T, const double *xy, size_t n, uint64_t seed, int nq,
                       double big)
{
    an_pwalk W = {0}, W2 = {0};
    list got = {0}, want = {0}, again = {0};
    int bad_multiset = 0, bad_skip = 0, bad_repeat = 0, runs = 0;
    for (int k = 0; k < nq; k++) {
        double qx, qy;
        const double u = cfpo_rand01(seed, 3, 2 * (uint64_t)k), v = cfpo_rand01(seed, 3, 2 * (uint64_t)k + 1);
        if (k % 3 == 0 && n > 0) { const size_t i = (size_t)(u * n); qx = xy[2 * i]; qy = xy[2 * i + 1]; }
        else if (k % 3 == 1) { qx = 3 * u - 1; qy = 3 * v - 1; }
        else { qx = u; qy = v; }
        double r[8];
        const int nr = radii(xy, n, qx, qy, big, r);
        for (int a = 0; a < nr; a++) {
            if (!run_walk(what, &W, T, xy, n, qx, qy, r[a], n, &got)) continue;
            runs++;
            brute_walk(xy, n, qx, qy, r[a], &want);
            list sorted = got; /* a copy: got keeps the walk's order */
            sorted.v = malloc((got.len + 1) * sizeof *got.v);
            if (got.len > 0) memcpy(sorted.v, got.v, got.len * sizeof *got.v);
            if (!covers(&sorted, &want, -INFINITY) && bad_multiset++ < 3)
                fprintf(stderr, "%s: walk at (%.17g, %.17g) r = %.17g: %zu images, brute force %zu\n", what, qx, qy,
                        r[a], sorted.len, want.len);
            free(sorted.v);
            /* The same query again on a used heap, and on a fresh walk:
             * the same sequence, ties included. */
            run_walk(what, &W, T, xy, n, qx, qy, r[a], n, &again);
            if (!same_sequence(&got, &again)) bad_repeat++;
            an_pwalk_free(&W2);
            run_walk(what, &W2, T, xy, n, qx, qy, r[a], n, &again);
            if (!same_sequence(&got, &again)) bad_repeat++;
            /* skip only chooses among copies: here nothing changes (for
             * n = 1 too: the last of a position is reported even when it
             * is `skip`). */
            run_walk(what, &W, T, xy, n, qx, qy, r[a], (size_t)(v * n), &again);
            if (!same_sequence(&got, &again)) bad_skip++;
        }
    }
    CHECK(bad_multiset == 0, "%s: %d of %d walks differ from brute force", what, bad_multiset, runs);
    CHECK(bad_repeat == 0, "%s: %d repeated walks differ from the first", what, bad_repeat);
    CHECK(bad_skip == 0, "%s: %d walks change with skip", what, bad_skip);
    an_pwalk_free(&W);
    an_pwalk_free(&W2);
    free(got.v); free(want.v); free(again.v);
}

/* The filter (an_pwalk_filter): with fixed disks, the images within r
 * in one of them (closed: disks through an image, and of radius 0 at
 * one); disks shrunk half-way, every image in the new disks beyond the
 * distance reached, and only those; a new start clears the filter. */
static void walk_filter(const char *what, const an_ptree *T, const double *xy, size_t n, uint64_t seed)
{
    an_pwalk W = {0};
    list got = {0}, want = {0}, tail = {0}, all = {0};
    int bad_fixed = 0, bad_shrink = 0, bad_clear = 0, runs = 0;
    for (int k = 0; k < 6 && n > 0; k++) {
        const double u = cfpo_rand01(seed, 5, 4 * (uint64_t)k), v = cfpo_rand01(seed, 5, 4 * (uint64_t)k + 1);
        const size_t i = (size_t)(u * n);
        const double qx = k % 2 ? xy[2 * i] : 2 * u - 0.5, qy = k % 2 ? xy[2 * i + 1] : 2 * v - 0.5;
        const double r = k < 3 ? 0.43 : 1.3;
        /* Four disks about the query: two random, one through an image
         * of point j (its radius that image's distance), one of radius 0
         * at another image of j. */
        double fv[8], fr2[4], gr2[4];
        for (int d = 0; d < 2; d++) {
            fv[2 * d] = qx + r * (cfpo_rand01(seed, 6 + (uint64_t)d, 3 * (uint64_t)k) - 0.5);
            fv[2 * d + 1] = qy + r * (cfpo_rand01(seed, 6 + (uint64_t)d, 3 * (uint64_t)k + 1) - 0.5);
            fr2[d] = pow(0.3 * r * cfpo_rand01(seed, 6 + (uint64_t)d, 3 * (uint64_t)k + 2), 2);
        }
        const size_t j = (size_t)(v * n);
        const double jx = xy[2 * j] + round(qx - xy[2 * j]), jy = xy[2 * j + 1] + round(qy - xy[2 * j + 1]);
        fv[4] = 0.5 * (qx + jx) + 1e-3;
        fv[5] = 0.5 * (qy + jy);
        fr2[2] = fabs(jx - fv[4]) * fabs(jx - fv[4]) + fabs(jy - fv[5]) * fabs(jy - fv[5]);
        fv[6] = jx + 1;
        fv[7] = jy - 1;
        fr2[3] = 0;
        for (int d = 0; d < 4; d++) gr2[d] = fr2[d] * 0.5;
        /* Fixed. */
        an_pwalk_start(&W, T, qx, qy, r, n);
        an_pwalk_filter(&W, fv, fr2, 4);
        got.len = 0;
        if (!walk_on(what, &W, xy, n, qx, qy, r, &got, SIZE_MAX, -INFINITY)) continue;
        runs++;
        brute_walk(xy, n, qx, qy, r, &want);
        keep_in_disks(xy, &want, fv, fr2, 4);
        if (!covers(&got, &want, -INFINITY)) bad_fixed++;
        /* Shrunk after half of them: the first three disks at half their
         * squared radius (the pointers change too). */
        const size_t half = got.len / 2;
        an_pwalk_start(&W, T, qx, qy, r, n);
        an_pwalk_filter(&W, fv, fr2, 4);
        all.len = 0;
        walk_on(what, &W, xy, n, qx, qy, r, &all, half, -INFINITY);
        const double t = half > 0 ? all.v[half - 1].d2 : -INFINITY;
        an_pwalk_filter(&W, fv, gr2, 3);
        if (k % 2) an_pwalk_prune(&W); /* the queue pruned at once, or image by image */
        tail.len = 0;
        walk_on(what, &W, xy, n, qx, qy, r, &tail, SIZE_MAX, t);
        int ok = 1;
        for (size_t g = 0; g < tail.len; g++) {
            const image *e = &tail.v[g];
            if (!in_disks(xy[2 * e->id] + e->ox, xy[2 * e->id + 1] + e->oy, fv, gr2, 3) || e->d2 < t) ok = 0;
        }
        brute_walk(xy, n, qx, qy, r, &want);
        keep_in_disks(xy, &want, fv, gr2, 3);
        /* Every image in the new disks beyond t is in the tail, and the
         * tail holds no other (images queued before the change are
         * dropped when they come out). */
        list extra = {0};
        for (size_t g = 0; g < tail.len; g++) {
            const image *e = &tail.v[g];
            if (in_disks(xy[2 * e->id] + e->ox, xy[2 * e->id + 1] + e->oy, fv, gr2, 3))
                add(&extra, e->id, e->ox, e->oy, e->d2, 0);
        }
        list beyond = {0};
        for (size_t g = 0; g < want.len; g++)
            if (want.v[g].d2 >= t) {
                const image *e = &want.v[g];
                add(&beyond, e->id, e->ox, e->oy, e->d2, e->either);
            }
        if (!ok || !covers(&extra, &beyond, t)) bad_shrink++;
        free(extra.v);
        free(beyond.v);
        /* A new start: no filter. */
        run_walk(what, &W, T, xy, n, qx, qy, r, n, &got);
        brute_walk(xy, n, qx, qy, r, &want);
        if (!covers(&got, &want, -INFINITY)) bad_clear++;
    }
    CHECK(bad_fixed == 0, "%s: %d of %d filtered walks differ from brute force", what, bad_fixed, runs);
    CHECK(bad_shrink == 0, "%s: %d walks wrong after the disks shrank", what, bad_shrink);
    CHECK(bad_clear == 0, "%s: %d walks keep a filter after a new start", what, bad_clear);
    an_pwalk_free(&W);
    free(got.v); free(want.v); free(tail.v); free(all.v);
}

/* Sets of repeated positions: the distinct positions of xy (np of them,
 * pos[2k], pos[2k + 1]); each image of each position within r once
 * (`once`), or at least once and no point's image twice (not `once`:
 * copies spread over several leaves), every reported index a copy there,
 * and never `skip` where skip's position has a leaf of its own. */
static void walk_copies(const char *what, const an_ptree *T, const double *xy, size_t n, const double *pos,
                        size_t np, int once, uint64_t seed)
{
    an_pwalk W = {0};
    list got = {0}, want = {0};
    int bad_pos = 0, bad_count = 0, bad_skip = 0, bad_dup = 0, runs = 0;
    const double rs[] = {0, 0.2, 0.49, 1.0, 1.7};
    for (int k = 0; k < 8; k++) {
        double qx = cfpo_rand01(seed, 4, 2 * (uint64_t)k) * 3 - 1;
        double qy = cfpo_rand01(seed, 4, 2 * (uint64_t)k + 1) * 3 - 1;
        if (k < 2) { qx = pos[2 * k % (2 * np)]; qy = pos[2 * k % (2 * np) + 1]; } /* at a position */
        for (size_t a = 0; a < sizeof rs / sizeof rs[0]; a++)
            for (int s = 0; s < 3; s++) {
                /* skip: none, the copy reported first for position 0 with
                 * none skipped, and index 1. */
                size_t skip = n;
                if (s == 1) {
                    run_walk(what, &W, T, xy, n, pos[0], pos[1], 0, n, &got);
                    skip = got.len > 0 ? got.v[0].id : 0;
                } else if (s == 2) skip = 1;
                if (!run_walk(what, &W, T, xy, n, qx, qy, rs[a], skip, &got)) continue;
                runs++;
                /* Brute force over positions: index = position number. */
                brute_walk(pos, np, qx, qy, rs[a], &want);
                size_t *count = calloc(want.len + 1, sizeof *count);
                for (size_t g = 0; g < got.len; g++) {
                    const image *e = &got.v[g];
                    if (once && e->id == skip) bad_skip++;
                    const double x = xy[2 * e->id] + e->ox, y = xy[2 * e->id + 1] + e->oy;
                    size_t w = 0;
                    while (w < want.len && (pos[2 * want.v[w].id] + want.v[w].ox != x ||
                                            pos[2 * want.v[w].id + 1] + want.v[w].oy != y))
                        w++;
                    if (w == want.len) bad_pos++;
                    else count[w]++;
                    for (size_t h = 0; h < g; h++)
                        if (got.v[h].id == e->id && got.v[h].ox == e->ox && got.v[h].oy == e->oy) bad_dup++;
                }
                for (size_t w = 0; w < want.len; w++)
                    if (once ? count[w] != 1 : count[w] < 1) {
                        if (bad_count++ < 3)
                            fprintf(stderr, "%s: r = %g skip %zu: position %zu image (%g, %g) reported %zu times\n",
                                    what, rs[a], skip, want.v[w].id, want.v[w].ox, want.v[w].oy, count[w]);
                    }
                free(count);
            }
    }
    CHECK(bad_pos == 0, "%s: %d images at no position's image within r", what, bad_pos);
    CHECK(bad_count == 0, "%s: %d position images not reported %s (of %d walks)", what, bad_count,
          once ? "exactly once" : "at least once", runs);
    CHECK(bad_dup == 0, "%s: %d point images reported twice", what, bad_dup);
    CHECK(bad_skip == 0, "%s: skip reported %d times where another copy was there", what, bad_skip);
    an_pwalk_free(&W);
    free(got.v); free(want.v);
}

static void one_set(const char *what, const double *xy, size_t n, int kind)
{
    an_ptree T;
    CHECK(an_ptree_build(&T, xy, n) == 0, "%s: build failed", what);
    if (kind == COPIES || kind == UNEVEN) {
        size_t b = 1;
        while (xy[2 * b] == xy[0] && xy[2 * b + 1] == xy[1]) b++;
        const double pos[4] = {xy[0], xy[1], xy[2 * b], xy[2 * b + 1]};
        walk_copies(what, &T, xy, n, pos, 2, kind == COPIES, 41);
    } else {
        const int nq = n >= 3000 ? 4 : n >= 500 ? 8 : 16;
        walk_exact(what, &T, xy, n, 51 + (uint64_t)kind, nq, n >= 3000 ? 1.3 : n >= 500 ? 1.6 : 2.7);
        walk_filter(what, &T, xy, n, 61 + (uint64_t)kind);
    }
    an_ptree_free(&T);
}

int main(void)
{
    double *xy = malloc(2 * 3000 * sizeof *xy);
    ptree_sets_each(xy, one_set);
    /* No point: an empty walk. */
    an_ptree T;
    an_pwalk W = {0};
    double px, py, d2;
    size_t id;
    CHECK(an_ptree_build(&T, xy, 0) == 0 && an_pwalk_start(&W, &T, 0.5, 0.5, 3, 0) == 0 &&
              an_pwalk_next(&W, &px, &py, &id, &d2) == 0,
          "no points: walk");
    an_ptree_free(&T);
    an_pwalk_free(&W);
    free(xy);
    return test_report(passed_, failed_);
}
