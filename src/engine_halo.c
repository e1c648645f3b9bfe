/* engine_halo.c - the halo ring and the --check verifications (see
 * engine_impl.h). */
#include "engine_impl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the halo ---- */

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

/* Sends my border cells to the neighbours that keep them and receives my
 * halo; marks the blocks around every halo cell whose content changed. */
int eng_refresh_halo(cfpo_engine *E)
{
    if (E->nnb == 0) return 0;
    double t0 = now();
    for (int k = 0; k < E->nnb; k++) {
        neighbour *nb = &E->nb[k];
        size_t pts = 0;
        for (int64_t i = 0; i < nb->nsend; i++) {
            int64_t c = nb->send_cells[i];
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
            int64_t c = nb->send_cells[i];
            cnt[i] = E->start[c + 1] - E->start[c];
            for (uint32_t j = E->start[c]; j < E->start[c + 1]; j++) {
                xy[2 * m] = E->px[j];
                xy[2 * m + 1] = E->py[j];
                m++;
            }
        }
        E->msg[k].send = nb->hbuf;
        E->msg[k].sendbytes = bytes;
        E->b_halo += (double)bytes;
    }
    if (comm_exchange(E->msg, E->nnb) != 0) return -1;
    /* New ring contents: counts, offsets, then coordinates. */
    memset(E->hcnt, 0, ((size_t)E->nring + 1) * sizeof(uint32_t));
    for (int k = 0; k < E->nnb; k++) {
        const neighbour *nb = &E->nb[k];
        const uint32_t *cnt = E->msg[k].recv;
        for (int64_t i = 0; i < nb->nrecv; i++) E->hcnt[nb->recv_ring[i]] = cnt[i];
    }
    E->hstart2[0] = 0;
    for (int64_t i = 0; i < E->nring; i++) E->hstart2[i + 1] = E->hstart2[i] + E->hcnt[i];
    size_t tot = E->hstart2[E->nring];
    if (tot > E->hcap2) {
        size_t c = tot + tot / 2 + 64;
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
            int64_t r = nb->recv_ring[i];
            for (uint32_t j = E->hstart2[r]; j < E->hstart2[r + 1]; j++, m++) {
                E->hx2[j] = xy[2 * m];
                E->hy2[j] = xy[2 * m + 1];
            }
        }
    }
    /* Blocks around changed halo cells must be solved again. */
    for (int64_t i = 0; i < E->nring; i++) {
        uint32_t a = E->hstart[i], b = E->hstart[i + 1], a2 = E->hstart2[i], b2 = E->hstart2[i + 1];
        int same = (b - a) == (b2 - a2) && (b == a || (memcmp(E->hx + a, E->hx2 + a2, (b - a) * 8) == 0 &&
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
    size_t c = E->hcap; E->hcap = E->hcap2; E->hcap2 = c;
    E->t_halo += now() - t0;
    return 0;
}

/* ---- checks (config.check) ---- */

void eng_check_fail(const cfpo_engine *E, const char *what)
{
    fprintf(stderr, "cfpo: rank %d: check failed: %s\n", E->rank, what);
    comm_abort(3);
}

void eng_check_migration(cfpo_engine *E)
{
    int64_t v[2] = {E->nloc, 0};
    uint64_t sum = 0;
    for (int64_t c = 0; c < E->cells; c++)
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
            sum += cfpo_mix64(E->pid[k]);
            if (!in_cell(E, E->px[k], E->py[k], c % E->w, c / E->w)) eng_check_fail(E, "a point lies outside its cell");
            if (k > E->start[c] && E->pid[k - 1] >= E->pid[k]) eng_check_fail(E, "ids out of order in a cell");
        }
    comm_sum_i64(v, 1);
    int64_t s = (int64_t)sum;
    comm_sum_i64(&s, 1);
    if (v[0] != E->n) eng_check_fail(E, "the global point count changed");
    if ((uint64_t)s != E->id_sum) eng_check_fail(E, "the checksum of point ids changed");
    E->chk_mig++;
}

typedef struct {
    double x, y;
    uint64_t id;
} pt_rec;

static int cmp_cell_id(const void *a, const void *b, const cfpo_grid *G)
{
    const pt_rec *p = a, *q = b;
    int64_t cp = cfpo_grid_coord(G, p->y) * G->g + cfpo_grid_coord(G, p->x);
    int64_t cq = cfpo_grid_coord(G, q->y) * G->g + cfpo_grid_coord(G, q->x);
    if (cp != cq) return cp < cq ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}
static const cfpo_grid *sort_grid;
static int cmp_cell_id_q(const void *a, const void *b) { return cmp_cell_id(a, b, sort_grid); }

/* Every halo cell equals its owner's cell: gathers the whole (small) set. */
void eng_check_halo(cfpo_engine *E)
{
    if (E->n > 200000) return;
    pt_rec *mine = malloc(((size_t)E->nloc + 1) * sizeof *mine);
    if (!mine) eng_check_fail(E, "out of memory");
    for (int64_t k = 0; k < E->nloc; k++) mine[k] = (pt_rec){E->px[k], E->py[k], E->pid[k]};
    void *all;
    size_t total;
    if (comm_allgatherv(mine, (size_t)E->nloc * sizeof *mine, &all, &total) != 0) eng_check_fail(E, "out of memory");
    free(mine);
    pt_rec *A = all;
    size_t na = total / sizeof *A;
    if ((int64_t)na != E->n) eng_check_fail(E, "gathered set has the wrong size");
    sort_grid = &E->G;
    qsort(A, na, sizeof *A, cmp_cell_id_q);
    const int64_t g = E->G.g;
    int64_t *first = malloc(((size_t)(g * g) + 1) * sizeof *first);
    if (!first) eng_check_fail(E, "out of memory");
    size_t j = 0;
    for (int64_t c = 0; c <= g * g; c++) {
        while (j < na && cfpo_grid_coord(&E->G, A[j].y) * g + cfpo_grid_coord(&E->G, A[j].x) < c) j++;
        first[c] = (int64_t)j;
    }
    for (int64_t i = 0; i < E->nring; i++) {
        int64_t lx, ly;
        ring_coords(E, i, &lx, &ly);
        if (locate(E, lx, ly) != -1 - i) continue;
        int64_t gx = (E->x0 + lx + g) % g, gy = (E->y0 + ly + g) % g, c = gy * g + gx;
        uint32_t a = E->hstart[i], b = E->hstart[i + 1];
        if ((int64_t)(b - a) != first[c + 1] - first[c]) eng_check_fail(E, "a halo cell has the wrong point count");
        for (uint32_t k = a; k < b; k++) {
            const pt_rec *p = &A[first[c] + (k - a)];
            if (p->x != E->hx[k] || p->y != E->hy[k]) eng_check_fail(E, "a halo cell differs from its owner's cell");
        }
    }
    free(first);
    free(A);
    E->chk_halo++;
}
