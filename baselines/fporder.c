/* fporder.c - the greedy farthest-point order of a set (fporder.h). */
#include "fporder.h"

#include <math.h>
#include <stdlib.h>

#include "nngrow.h"

typedef struct {
    double key; /* an upper bound of the squared distance to the taken points */
    size_t id;
} item;

static int before(const item *a, const item *b) { return a->key > b->key || (a->key == b->key && a->id < b->id); }

static void down(item *h, size_t len, size_t i)
{
    for (;;) {
        size_t l = 2 * i + 1, b = i;
        if (l < len && before(&h[l], &h[b])) b = l;
        if (l + 1 < len && before(&h[l + 1], &h[b])) b = l + 1;
        if (b == i) return;
        const item t = h[i];
        h[i] = h[b], h[b] = t;
        i = b;
    }
}

static void up(item *h, size_t i)
{
    while (i > 0 && before(&h[i], &h[(i - 1) / 2])) {
        const item t = h[i];
        h[i] = h[(i - 1) / 2], h[(i - 1) / 2] = t;
        i = (i - 1) / 2;
    }
}

int fp_order(const double *xy, size_t n, size_t first, size_t *order)
{
    if (n == 0) return 0;
    bl_nngrow g;
    item *h = malloc(n * sizeof *h);
    if (!h || bl_nngrow_init(&g, xy, n) != 0) {
        free(h);
        return -1;
    }
    int rc = -1;
    size_t len = 0, k = 0;
    for (size_t i = 0; i < n; i++)
        if (i != first) h[len++] = (item){INFINITY, i};
    /* every key is the same: already a heap */
    order[k++] = first;
    if (bl_nngrow_insert(&g, first) != 0) goto done;
    while (len > 0) {
        item top = h[0];
        top.key = bl_nngrow_nearest2(&g, xy + 2 * top.id, NULL);
        h[0] = h[--len]; /* out of the heap ... */
        down(h, len, 0);
        if (len == 0 || !before(&h[0], &top)) { /* ... taken: it beats every other bound */
            order[k++] = top.id;
            if (bl_nngrow_insert(&g, top.id) != 0) goto done;
        } else { /* ... or back with its true distance */
            h[len] = top;
            up(h, len++);
        }
    }
    rc = 0;
done:
    free(h);
    bl_nngrow_free(&g);
    return rc;
}
