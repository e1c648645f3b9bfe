/* nngrow.c - nearest neighbour among a growing subset (nngrow.h). */
#include "nngrow.h"

#include <math.h>
#include <stdlib.h>

double bl_torus_d2(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    if (dx > 0.5) dx = 1 - dx;
    if (dy > 0.5) dy = 1 - dy;
    return dx * dx + dy * dy;
}

static long cell_of(double x, long G)
{
    long c = (long)floor(x * (double)G);
    return c < 0 ? 0 : (c >= G ? G - 1 : c);
}

static long cell_index(const bl_nngrow *g, const double *p)
{
    return cell_of(p[1], g->G) * g->G + cell_of(p[0], g->G);
}

/* a grid of side G over the inserted points */
static int build(bl_nngrow *g, long G)
{
    long *head = malloc((size_t)G * (size_t)G * sizeof *head);
    if (!head) return -1;
    free(g->head);
    g->head = head;
    g->G = G;
    for (long c = 0; c < G * G; c++) head[c] = -1;
    for (size_t k = 0; k < g->count; k++) {
        const size_t i = g->ids[k];
        const long c = cell_index(g, g->xy + 2 * i);
        g->next[i] = head[c];
        head[c] = (long)i;
    }
    return 0;
}

int bl_nngrow_init(bl_nngrow *g, const double *xy, size_t n)
{
    g->xy = xy;
    g->n = n;
    g->count = 0;
    g->head = NULL;
    g->ids = malloc((n ? n : 1) * sizeof *g->ids);
    g->next = malloc((n ? n : 1) * sizeof *g->next);
    if (!g->ids || !g->next || build(g, 1) != 0) {
        bl_nngrow_free(g);
        return -1;
    }
    return 0;
}

int bl_nngrow_insert(bl_nngrow *g, size_t i)
{
    g->ids[g->count++] = i;
    if ((double)g->count >= 8.0 * (double)g->G * (double)g->G) { /* about 2 a cell after doubling the side */
        long G = (long)floor(sqrt((double)g->count / 2.0));
        if (G > 4096) G = 4096;
        if (G > g->G) return build(g, G);
    }
    const long c = cell_index(g, g->xy + 2 * i);
    g->next[i] = g->head[c];
    g->head[c] = (long)i;
    return 0;
}

double bl_nngrow_nearest2(const bl_nngrow *g, const double *p, size_t *id)
{
    double best = INFINITY;
    size_t who = 0;
    const long G = g->G, cx = cell_of(p[0], G), cy = cell_of(p[1], G);
    const double h = 1.0 / (double)G;
    for (long r = 0; g->count > 0; r++) {
        if (2 * r + 1 > G || (double)(2 * r + 1) * (double)(2 * r + 1) > (double)g->count) {
            for (size_t k = 0; k < g->count; k++) { /* every inserted point */
                const double q = bl_torus_d2(p, g->xy + 2 * g->ids[k]);
                if (q < best || (q == best && g->ids[k] < who)) best = q, who = g->ids[k];
            }
            break;
        }
        for (long oy = -r; oy <= r; oy++) {
            const long step = (r == 0 || oy == -r || oy == r) ? 1 : 2 * r; /* the ring's border */
            for (long ox = -r; ox <= r; ox += step) {
                const long c = ((cy + oy + G) % G) * G + (cx + ox + G) % G;
                for (long i = g->head[c]; i >= 0; i = g->next[i]) {
                    const double q = bl_torus_d2(p, g->xy + 2 * i);
                    if (q < best || (q == best && (size_t)i < who)) best = q, who = (size_t)i;
                }
            }
        }
        /* an unseen point is more than r cell sides away along one axis */
        if (best <= ((double)r * h) * ((double)r * h)) break;
    }
    if (id) *id = who;
    return best;
}

void bl_nngrow_free(bl_nngrow *g)
{
    free(g->ids);
    free(g->next);
    free(g->head);
    g->ids = NULL;
    g->next = g->head = NULL;
}
