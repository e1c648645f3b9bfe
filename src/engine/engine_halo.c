/* engine_halo.c - the halo ring (see cells.h): which of this tile's cells
 * each neighbouring rank keeps, and the refresh after every phase. */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Builds, for this tile and its neighbours, which cells go where. The
 * cells of my ring that other ranks own, grouped by owner in my ring
 * order; and for each such owner, the cells of its ring that I own, in its
 * ring order (the order it will unpack them in). */
int eng_build_neighbours(cfpo_engine *E)
{
    const int64_t g = E->G.g;
    E->nring = cfpo_tile_ring(E->w, E->h);
    int *owner = malloc((size_t)E->nring * sizeof *owner);
    if (!owner) return -1;
    for (int64_t i = 0; i < E->nring; i++) {
        int64_t lx, ly;
        ring_coords(E, i, &lx, &ly);
        owner[i] = -1;
        if (locate(E, lx, ly) != -1 - i) continue; /* wraps onto an own cell or another ring cell */
        int64_t gx = (E->x0 + lx + g) % g, gy = (E->y0 + ly + g) % g;
        int r = cfpo_tiling_owner(&E->T, gx, gy);
        owner[i] = r;
        if (neighbour_of_rank(E, r) < 0) {
            neighbour *nb = realloc(E->nb, (size_t)(E->nnb + 1) * sizeof *nb);
            if (!nb) { free(owner); return -1; }
            E->nb = nb;
            memset(&E->nb[E->nnb], 0, sizeof *nb);
            E->nb[E->nnb].rank = r;
            E->nnb++;
        }
    }
    for (int k = 0; k < E->nnb; k++) {
        neighbour *nb = &E->nb[k];
        nb->recv_ring = malloc((size_t)E->nring * sizeof(int64_t));
        if (!nb->recv_ring) { free(owner); return -1; }
        for (int64_t i = 0; i < E->nring; i++)
            if (owner[i] == nb->rank) nb->recv_ring[nb->nrecv++] = i;
        /* The neighbour's tile and ring, walked in its order. */
        const int qx = nb->rank % E->T.px, qy = nb->rank / E->T.px;
        const int64_t qx0 = cfpo_tile_start(g, E->T.px, qx), qw = cfpo_tile_len(g, E->T.px, qx);
        const int64_t qy0 = cfpo_tile_start(g, E->T.py, qy), qh = cfpo_tile_len(g, E->T.py, qy);
        const int64_t qring = cfpo_tile_ring(qw, qh);
        nb->send_cells = malloc((size_t)qring * sizeof(int64_t));
        if (!nb->send_cells) { free(owner); return -1; }
        const int qwrapx = E->T.px == 1, qwrapy = E->T.py == 1;
        for (int64_t i = 0; i < qring; i++) {
            int64_t lx, ly, W = qw + 2;
            if (i < W) { lx = i - 1; ly = -1; }
            else if (i < 2 * W) { lx = i - W - 1; ly = qh; }
            else if (i < 2 * W + qh) { lx = -1; ly = i - 2 * W; }
            else { lx = qw; ly = i - 2 * W - qh; }
            /* Skip positions that wrap inside its own tile or onto another
             * ring position (as its locate() would). */
            int64_t wx = lx, wy = ly;
            if (qwrapx) wx = (lx + qw) % qw;
            if (qwrapy) wy = (ly + qh) % qh;
            if (wx != lx || wy != ly) continue;
            int64_t gx = (qx0 + lx + g) % g, gy = (qy0 + ly + g) % g;
            if (cfpo_tiling_owner(&E->T, gx, gy) != E->rank) continue;
            nb->send_cells[nb->nsend++] = (gy - E->y0) * E->w + (gx - E->x0);
        }
    }
    free(owner);
    E->msg = calloc((size_t)(E->nnb > 0 ? E->nnb : 1), sizeof(comm_msg));
    E->hstart = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    E->hstart2 = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    E->hcnt = calloc((size_t)E->nring + 1, sizeof(uint32_t));
    if (!E->msg || !E->hstart || !E->hstart2 || !E->hcnt) return -1;
    for (int k = 0; k < E->nnb; k++) E->msg[k].rank = E->nb[k].rank;
    return 0;
}

/* Packs the own cells neighbour k keeps in its halo: counts, then
 * coordinates. 0 or -1 (out of memory). */
static int pack_halo(cfpo_engine *E, int k)
{
    neighbour *nb = &E->nb[k];
    size_t pts = 0;
    for (int64_t i = 0; i < nb->nsend; i++) {
        const int64_t c = nb->send_cells[i];
        pts += E->start[c + 1] - E->start[c];
    }
    const size_t head = ((size_t)nb->nsend * 4 + 7) & ~(size_t)7;
    const size_t bytes = head + pts * 16;
    if (bytes > nb->hcap) {
        unsigned char *b = realloc(nb->hbuf, bytes + bytes / 2 + 64);
        if (!b) return -1;
        nb->hbuf = b;
        nb->hcap = bytes + bytes / 2 + 64;
    }
    uint32_t *cnt = (uint32_t *)nb->hbuf;
    double *xy = (double *)(nb->hbuf + head);
    size_t m = 0;
    for (int64_t i = 0; i < nb->nsend; i++) {
        const int64_t c = nb->send_cells[i];
        cnt[i] = E->start[c + 1] - E->start[c];
        for (uint32_t j = E->start[c]; j < E->start[c + 1]; j++, m++) {
            xy[2 * m] = E->px[j];
            xy[2 * m + 1] = E->py[j];
        }
    }
    E->msg[k].send = nb->hbuf;
    E->msg[k].sendbytes = bytes;
    E->b_halo += (double)bytes;
    return 0;
}

/* The received ring into the spare halo buffers: counts, offsets, then
 * coordinates. 0 or -1 (out of memory). */
static int unpack_halo(cfpo_engine *E)
{
    memset(E->hcnt, 0, ((size_t)E->nring + 1) * sizeof(uint32_t));
    for (int k = 0; k < E->nnb; k++) {
        const neighbour *nb = &E->nb[k];
        const uint32_t *cnt = E->msg[k].recv;
        for (int64_t i = 0; i < nb->nrecv; i++) E->hcnt[nb->recv_ring[i]] = cnt[i];
    }
    E->hstart2[0] = 0;
    for (int64_t i = 0; i < E->nring; i++) E->hstart2[i + 1] = E->hstart2[i] + E->hcnt[i];
    const size_t tot = E->hstart2[E->nring];
    if (tot > E->hcap2) {
        const size_t c = tot + tot / 2 + 64;
        double *a = realloc(E->hx2, c * sizeof(double)), *b;
        if (!a) return -1;
        E->hx2 = a;
        if (!(b = realloc(E->hy2, c * sizeof(double)))) return -1;
        E->hy2 = b;
        E->hcap2 = c;
    }
    for (int k = 0; k < E->nnb; k++) {
        const neighbour *nb = &E->nb[k];
        const unsigned char *b = E->msg[k].recv;
        const double *xy = (const double *)(b + (((size_t)nb->nrecv * 4 + 7) & ~(size_t)7));
        size_t m = 0;
        for (int64_t i = 0; i < nb->nrecv; i++) {
            const int64_t r = nb->recv_ring[i];
            for (uint32_t j = E->hstart2[r]; j < E->hstart2[r + 1]; j++, m++) {
                E->hx2[j] = xy[2 * m];
                E->hy2[j] = xy[2 * m + 1];
            }
        }
    }
    return 0;
}

/* Sends my border cells to the neighbours that keep them and receives my
 * halo; marks the blocks around every halo cell whose content changed. */
int eng_refresh_halo(cfpo_engine *E)
{
    if (E->nnb == 0) return 0;
    const double t0 = now();
    for (int k = 0; k < E->nnb; k++)
        if (pack_halo(E, k) != 0) return -1;
    if (comm_exchange(E->msg, E->nnb) != 0) return -1;
    if (unpack_halo(E) != 0) return -1;
    /* Blocks around changed halo cells must be solved again. */
    for (int64_t i = 0; i < E->nring; i++) {
        const uint32_t a = E->hstart[i], b = E->hstart[i + 1], a2 = E->hstart2[i], b2 = E->hstart2[i + 1];
        const int same = (b - a) == (b2 - a2) && (b == a || (memcmp(E->hx + a, E->hx2 + a2, (b - a) * 8) == 0 &&
                                                             memcmp(E->hy + a, E->hy2 + a2, (b - a) * 8) == 0));
        if (!same) {
            int64_t lx, ly;
            ring_coords(E, i, &lx, &ly);
            eng_mark_block(E, lx, ly);
        }
    }
    uint32_t *s = E->hstart; E->hstart = E->hstart2; E->hstart2 = s;
    double *t = E->hx; E->hx = E->hx2; E->hx2 = t;
    t = E->hy; E->hy = E->hy2; E->hy2 = t;
    const size_t c = E->hcap; E->hcap = E->hcap2; E->hcap2 = c;
    E->t_halo += now() - t0;
    return 0;
}
