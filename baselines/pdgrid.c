/* pdgrid.c - see pdgrid.h. */
#include "pdgrid.h"

#include <math.h>
#include <stdlib.h>

#include "geom.h"

double pdgrid_cells(double r)
{
    double g = ceil(sqrt(2.0) / r);
    return g * g;
}

int pdgrid_init(pdgrid *G, double r)
{
    G->cx = NULL;
    G->id = NULL;
    G->order = NULL;
    int64_t g = (int64_t)ceil(sqrt(2.0) / r);
    if (g < 1) g = 1;
    while (sqrt(2.0) / (double)g > r) g++; /* cell diagonal <= r */
    if ((double)g * (double)g > 4294967295.0) return -1;
    G->g = g;
    G->c = 1.0 / (double)g;
    G->r = r;
    G->r2 = r * r;
    G->reach = (int)ceil(r * (double)g);
    size_t cells = (size_t)(g * g);
    G->cx = malloc(2 * cells * sizeof *G->cx);
    G->id = malloc(cells * sizeof *G->id);
    const int w = G->reach < 100 ? G->reach : 100, side = 2 * w + 1;
    G->order = malloc((size_t)(side * side) * sizeof *G->order);
    if (!G->cx || !G->id || !G->order) {
        pdgrid_free(G);
        return -1;
    }
    for (size_t i = 0; i < cells; i++) G->cx[2 * i] = -1.0;
    /* The conflict test looks at the dart's own cell first (occupied means
     * a conflict, since a cell's diagonal is at most r), then ring by ring:
     * the same answer as any order, found sooner. */
    G->norder = 0;
    for (int ring = 0; ring <= w; ring++)
        for (int dy = -ring; dy <= ring; dy++)
            for (int dx = -ring; dx <= ring; dx++)
                if (abs(dx) == ring || abs(dy) == ring) {
                    G->order[G->norder][0] = (int8_t)dx;
                    G->order[G->norder][1] = (int8_t)dy;
                    G->norder++;
                }
    return 0;
}

void pdgrid_free(pdgrid *G)
{
    free(G->cx);
    free(G->id);
    free(G->order);
    G->cx = NULL;
    G->id = NULL;
    G->order = NULL;
}

/* The cell window of half-width w around cell k: first cell and count,
 * each cell once even when the window would wrap onto itself. */
static void window(const pdgrid *G, int64_t k, int w, int64_t *first, int64_t *count)
{
    if (2 * (int64_t)w + 1 >= G->g) {
        *first = 0;
        *count = G->g;
    } else {
        *first = k - w;
        *count = 2 * (int64_t)w + 1;
    }
}

static inline int64_t wrap_cell(int64_t k, int64_t g) { return k < 0 ? k + g : (k >= g ? k - g : k); }

int pdgrid_conflict(const pdgrid *G, double x, double y)
{
    const int64_t g = G->g, kx = pdgrid_coord(G, x), ky = pdgrid_coord(G, y);
    if (2 * (int64_t)G->reach + 1 < g && G->reach <= 100) {
        for (int k = 0; k < G->norder; k++) {
            const int64_t cx = wrap_cell(kx + G->order[k][0], g), cy = wrap_cell(ky + G->order[k][1], g);
            const double *p = G->cx + 2 * (size_t)(cy * g + cx);
            if (p[0] >= 0 && cfpo_torus_dist2(x, y, p[0], p[1]) < G->r2) return 1;
        }
        return 0;
    }
    int64_t fx, nx, fy, ny; /* a window as wide as the torus: each cell once */
    window(G, kx, G->reach, &fx, &nx);
    window(G, ky, G->reach, &fy, &ny);
    for (int64_t j = 0; j < ny; j++) {
        const double *row = G->cx + 2 * (size_t)(wrap_cell(fy + j, g) * g);
        for (int64_t i = 0; i < nx; i++) {
            const double *p = row + 2 * wrap_cell(fx + i, g);
            if (p[0] >= 0 && cfpo_torus_dist2(x, y, p[0], p[1]) < G->r2) return 1;
        }
    }
    return 0;
}

void pdgrid_put(pdgrid *G, double x, double y, uint32_t id)
{
    size_t c = (size_t)(pdgrid_coord(G, y) * G->g + pdgrid_coord(G, x));
    G->cx[2 * c] = x;
    G->cx[2 * c + 1] = y;
    G->id[c] = id;
}

int pdgrid_near(const pdgrid *G, double x, double y, double R, uint32_t *ids, int cap)
{
    const int64_t g = G->g, kx = pdgrid_coord(G, x), ky = pdgrid_coord(G, y);
    const int w = (int)ceil(R * (double)g);
    const double R2 = R * R;
    int64_t fx, nx, fy, ny;
    window(G, kx, w, &fx, &nx);
    window(G, ky, w, &fy, &ny);
    int m = 0;
    for (int64_t j = 0; j < ny; j++) {
        const size_t rowc = (size_t)(wrap_cell(fy + j, g) * g);
        for (int64_t i = 0; i < nx; i++) {
            const size_t c = rowc + (size_t)wrap_cell(fx + i, g);
            const double *p = G->cx + 2 * c;
            if (p[0] >= 0 && cfpo_torus_dist2(x, y, p[0], p[1]) < R2 && m < cap) ids[m++] = G->id[c];
        }
    }
    return m;
}
