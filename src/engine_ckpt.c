/* engine_ckpt.c - checkpoints: the header, reading with validation,
 * writing (see cells.h). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- checkpoints ---- */

static void put64(unsigned char *b, uint64_t v) { for (int i = 0; i < 8; i++) b[i] = (unsigned char)(v >> (8 * i)); }
static uint64_t get64(const unsigned char *b)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--) v = v << 8 | b[i];
    return v;
}

int cfpo_checkpoint_peek(const char *path, cfpo_checkpoint_info *info, char *err, size_t errlen)
{
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER];
    int ok = size >= CKPT_HEADER && comm_file_read_at(f, 0, h, CKPT_HEADER) == 0;
    comm_file_close(f);
    if (!ok || memcmp(h, CKPT_MAGIC, 8) != 0) {
        snprintf(err, errlen, "%s: not a cfpo checkpoint (bad magic)", path);
        return -1;
    }
    info->n = (int64_t)get64(h + 8);
    info->seed = get64(h + 16);
    info->variant = (int)get64(h + 24);
    uint64_t tb = get64(h + 32);
    memcpy(&info->tol, &tb, 8);
    info->iteration = (int64_t)get64(h + 40);
    info->converged = (int)get64(h + 48);
    if (info->n < 1 || (info->variant != CFPO_VARIANT_PAPER && info->variant != CFPO_VARIANT_SIMPLIFIED &&
                        info->variant != CFPO_VARIANT_ADAPTIVE) ||
        !(info->tol >= 0 && info->tol <= CFPO_TOL_MAX) || info->iteration < 0 || info->iteration > 1000000000) {
        snprintf(err, errlen, "%s: corrupt checkpoint header", path);
        return -1;
    }
    if (size != CKPT_HEADER + 16 * (uint64_t)info->n) {
        snprintf(err, errlen, "%s: checkpoint of %lld points should be %llu bytes, file has %llu (truncated?)",
                 path, (long long)info->n, (unsigned long long)(CKPT_HEADER + 16 * (uint64_t)info->n),
                 (unsigned long long)size);
        return -1;
    }
    return 0;
}

typedef struct {
    double x, y;
    uint64_t id;
} ck_rec;


/* Every rank reads a contiguous share of ids, sends each point to the rank
 * owning its cell, then builds its buckets. */
int eng_load_checkpoint(cfpo_engine *E, char *err, size_t errlen)
{
    const char *path = E->cfg.resume;
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    const int P = E->nranks;
    const int64_t lo = E->n * E->rank / P, hi = E->n * (E->rank + 1) / P;
    const int64_t CH = (int64_t)1 << 20;
    int64_t rounds = (hi - lo + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    double *buf = malloc((size_t)CH * 16);
    void **send = calloc((size_t)P, sizeof *send);
    size_t *sb = calloc((size_t)P, sizeof *sb), *scap = calloc((size_t)P, sizeof *scap);
    void **recv = calloc((size_t)P, sizeof *recv);
    size_t *rb = calloc((size_t)P, sizeof *rb);
    int bad = !buf || !send || !sb || !scap || !recv || !rb;
    int64_t badpos = -1;
    size_t have = 0;
    /* received points land in tx/ty/tid */
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = lo + r * CH, b = a + CH < hi ? a + CH : hi;
        if (a > b) a = b;
        for (int q = 0; q < P; q++) sb[q] = 0;
        if (!bad && b > a && comm_file_read_at(f, CKPT_HEADER + 16 * (uint64_t)a, buf, (size_t)(b - a) * 16) != 0)
            bad = 1;
        for (int64_t i = a; !bad && i < b; i++) {
            double x = buf[2 * (i - a)], y = buf[2 * (i - a) + 1];
            if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) {
                badpos = i;
                bad = 1;
                break;
            }
            int q = cfpo_tiling_owner(&E->T, cfpo_grid_coord(&E->G, x), cfpo_grid_coord(&E->G, y));
            if (sb[q] + sizeof(ck_rec) > scap[q]) {
                size_t c = (sb[q] + sizeof(ck_rec)) * 2;
                void *p = realloc(send[q], c);
                if (!p) { bad = 1; break; }
                send[q] = p;
                scap[q] = c;
            }
            ck_rec rec = {x, y, (uint64_t)i};
            memcpy((char *)send[q] + sb[q], &rec, sizeof rec);
            sb[q] += sizeof rec;
        }
        if (!comm_all(!bad)) break;
        if (comm_alltoallv(send, sb, recv, rb) != 0) { bad = 1; break; }
        size_t add = 0;
        for (int q = 0; q < P; q++) add += rb[q] / sizeof(ck_rec);
        if (eng_ensure_cap(E, have + add) != 0) bad = 1;
        for (int q = 0; q < P; q++) {
            const ck_rec *rr = recv[q];
            for (size_t i = 0; !bad && i < rb[q] / sizeof(ck_rec); i++, have++) {
                E->tx[have] = rr[i].x;
                E->ty[have] = rr[i].y;
                E->tid[have] = rr[i].id;
            }
            free(recv[q]);
            recv[q] = NULL;
        }
        if (!comm_all(!bad)) break;
    }
    comm_file_close(f);
    for (int q = 0; send && q < P; q++) free(send[q]);
    free(send); free(sb); free(scap); free(recv); free(rb); free(buf);
    int64_t bp = badpos;
    comm_max_i64(&bp, 1);
    if (!comm_all(!bad)) {
        if (bp >= 0)
            snprintf(err, errlen, "%s: corrupt checkpoint: point %lld at offset %llu is not in [0,1)^2",
                     path, (long long)bp, (unsigned long long)(CKPT_HEADER + 16 * (uint64_t)bp));
        else snprintf(err, errlen, "%s: cannot read the checkpoint (or out of memory)", path);
        return -1;
    }
    /* Counting sort into cells, then id order inside each cell. */
    memset(E->start, 0, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        int64_t c = own_cell_of(E, E->tx[i], E->ty[i]);
        E->start[c + 1]++;
    }
    int maxcell = 0;
    for (int64_t c = 0; c < E->cells; c++) {
        if ((int)E->start[c + 1] > maxcell) maxcell = (int)E->start[c + 1];
        E->start[c + 1] += E->start[c];
    }
    memcpy(E->start2, E->start, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        int64_t c = own_cell_of(E, E->tx[i], E->ty[i]);
        uint32_t k = E->start2[c]++;
        E->px[k] = E->tx[i];
        E->py[k] = E->ty[i];
        E->pid[k] = E->tid[i];
    }
    for (int64_t c = 0; c < E->cells; c++) eng_sort3(E->pid, E->px, E->py, E->start[c], E->start[c + 1]);
    E->nloc = (int64_t)have;
    E->maxcell = maxcell;
    int64_t tot = E->nloc;
    comm_sum_i64(&tot, 1);
    if (tot != E->n) {
        snprintf(err, errlen, "%s: corrupt checkpoint (point count)", path);
        return -1;
    }
    return 0;
}

int eng_write_checkpoint(cfpo_engine *E, int iteration, int converged, char *err, size_t errlen)
{
    comm_file *f = comm_file_create(E->cfg.checkpoint, err, errlen);
    if (!f) return -1;
    int ok = 1;
    if (E->rank == 0) {
        unsigned char h[CKPT_HEADER] = {0};
        memcpy(h, CKPT_MAGIC, 8);
        put64(h + 8, (uint64_t)E->n);
        put64(h + 16, E->o.seed);
        put64(h + 24, (uint64_t)E->o.variant);
        uint64_t tb;
        memcpy(&tb, &E->o.tol, 8);
        put64(h + 32, tb);
        put64(h + 40, (uint64_t)iteration);
        put64(h + 48, (uint64_t)converged);
        ok = comm_file_write_at(f, 0, h, sizeof h) == 0;
    }
    char e2[256];
    if (cfpo_engine_write_points(E, f, CKPT_HEADER, e2, sizeof e2) != 0) ok = 0;
    return comm_file_commit(f, ok, err, errlen);
}
