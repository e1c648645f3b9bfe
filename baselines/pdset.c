/* pdset.c - see pdset.h. */
#include "pdset.h"

#include <stdlib.h>

#include "pd.h"

/* Neighbours within 2 rho: at most 24 by the packing bound (arcs.h). */
#define NEAR_CAP 64

int pdset_init(pdset *S, double r, int64_t hint, int track_arcs)
{
    S->rho = r * (1.0 + PD_RHO_EPS);
    S->n = 0;
    S->cap = hint > 16 ? hint + hint / 8 : 16;
    S->nactive = 0;
    S->npool = S->nfree = 0;
    S->poolcap = track_arcs ? 1024 : 0;
    S->track_arcs = track_arcs;
    S->xy = malloc(2 * (size_t)S->cap * sizeof *S->xy);
    S->active = malloc((size_t)S->cap * sizeof *S->active);
    S->pos = malloc((size_t)S->cap * sizeof *S->pos);
    S->slot = track_arcs ? malloc((size_t)S->cap * sizeof *S->slot) : NULL;
    S->pool = track_arcs ? malloc((size_t)S->poolcap * sizeof *S->pool) : NULL;
    S->free_slots = track_arcs ? malloc((size_t)S->poolcap * sizeof *S->free_slots) : NULL;
    int bad = pdgrid_init(&S->G, r) != 0;
    if (bad || !S->xy || !S->active || !S->pos ||
        (track_arcs && (!S->slot || !S->pool || !S->free_slots))) {
        if (!bad) pdgrid_free(&S->G);
        free(S->xy); free(S->active); free(S->pos); free(S->slot); free(S->pool);
        free(S->free_slots);
        S->xy = NULL;
        return -1;
    }
    return 0;
}

void pdset_free(pdset *S)
{
    pdgrid_free(&S->G);
    free(S->xy); free(S->active); free(S->pos); free(S->slot); free(S->pool); free(S->free_slots);
    S->xy = NULL;
}

double *pdset_take_points(pdset *S)
{
    double *xy = S->xy;
    S->xy = NULL;
    return xy;
}

static int grow(void **p, size_t elem, int64_t cap)
{
    void *q = realloc(*p, (size_t)cap * elem);
    if (!q) return -1;
    *p = q;
    return 0;
}

static int ensure_point_room(pdset *S)
{
    if (S->n < S->cap) return 0;
    int64_t cap = S->cap * 2;
    if (grow((void **)&S->xy, 2 * sizeof *S->xy, cap) || grow((void **)&S->active, sizeof *S->active, cap) ||
        grow((void **)&S->pos, sizeof *S->pos, cap) ||
        (S->track_arcs && grow((void **)&S->slot, sizeof *S->slot, cap)))
        return -1;
    S->cap = cap;
    return 0;
}

static int64_t take_slot(pdset *S)
{
    if (S->nfree > 0) return S->free_slots[--S->nfree];
    if (S->npool == S->poolcap) {
        int64_t cap = S->poolcap * 2;
        if (grow((void **)&S->pool, sizeof *S->pool, cap) ||
            grow((void **)&S->free_slots, sizeof *S->free_slots, cap))
            return -1;
        S->poolcap = cap;
    }
    return S->npool++;
}

static void deactivate(pdset *S, uint32_t id)
{
    int64_t k = S->pos[id];
    if (k < 0) return;
    pdset_retire(S, k);
}

void pdset_retire(pdset *S, int64_t k)
{
    uint32_t id = S->active[k], last = S->active[--S->nactive];
    S->active[k] = last;
    S->pos[last] = k;
    S->pos[id] = -1;
    if (S->track_arcs && S->slot[id] >= 0) {
        S->free_slots[S->nfree++] = S->slot[id];
        S->slot[id] = -1;
    }
}

void pdset_free_arcs(const pdset *S, uint32_t s, arcs *A)
{
    uint32_t near[NEAR_CAP];
    const double sx = S->xy[2 * s], sy = S->xy[2 * s + 1];
    int m = pdgrid_near(&S->G, sx, sy, 2.0 * S->rho, near, NEAR_CAP);
    arcs_full(A);
    for (int i = 0; i < m && A->m > 0; i++)
        if (near[i] != s) arcs_cover(A, sx, sy, S->xy[2 * near[i]], S->xy[2 * near[i] + 1], S->rho);
}

int64_t pdset_add(pdset *S, double x, double y)
{
    if (ensure_point_room(S) != 0) return -1;
    const uint32_t id = (uint32_t)S->n;
    uint32_t near[NEAR_CAP];
    int m = S->track_arcs ? pdgrid_near(&S->G, x, y, 2.0 * S->rho, near, NEAR_CAP) : 0;
    S->xy[2 * id] = x;
    S->xy[2 * id + 1] = y;
    S->n++;
    pdgrid_put(&S->G, x, y, id);
    S->pos[id] = -1;
    if (!S->track_arcs) {
        S->pos[id] = S->nactive;
        S->active[S->nactive++] = id;
        return id;
    }
    S->slot[id] = -1;
    arcs A;
    arcs_full(&A);
    for (int i = 0; i < m; i++) {
        const uint32_t t = near[i];
        const double tx = S->xy[2 * t], ty = S->xy[2 * t + 1];
        if (A.m > 0) arcs_cover(&A, x, y, tx, ty, S->rho);
        if (S->pos[t] >= 0) {
            arcs *B = &S->pool[S->slot[t]];
            arcs_cover(B, tx, ty, x, y, S->rho);
            if (B->m == 0) deactivate(S, t);
        }
    }
    if (A.m > 0) {
        int64_t sl = take_slot(S);
        if (sl < 0) return -1;
        S->pool[sl] = A;
        S->slot[id] = sl;
        S->pos[id] = S->nactive;
        S->active[S->nactive++] = id;
    }
    return id;
}
