/* engine_ckpt.c - checkpoints: reading with validation (header fields,
 * checksum, points, the most points a cell can hold), writing (see
 * cells.h; the format is ckpt.h's). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ckpt.h"
#include "cli.h"

static int read_header(const char *path, ckpt_header *c, char *err, size_t errlen)
{
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER] = {0};
    int ok = size < CKPT_HEADER || comm_file_read_at(f, 0, h, CKPT_HEADER) == 0;
    comm_file_close(f);
    if (!ok) {
        snprintf(err, errlen, "%s: cannot read the checkpoint header", path);
        return -1;
    }
    return ckpt_decode(path, h, size, c, err, errlen);
}

int cfpo_checkpoint_peek(const char *path, cfpo_checkpoint_info *info, char *err, size_t errlen)
{
    ckpt_header c;
    if (read_header(path, &c, err, errlen) != 0) return -1;
    info->n = c.n;
    info->seed = c.seed;
    info->variant = c.variant;
    info->tol = c.tol;
    info->iteration = c.iteration;
    info->converged = c.converged;
    return 0;
}

/* The checksum of the byte range of every rank's share, joined in rank
 * order (shares are consecutive: rank r's follows rank r - 1's). */
static uint32_t join_shares(const cfpo_engine *E, uint32_t head, uint32_t mine, int *oom)
{
    int64_t *all = malloc((size_t)E->nranks * sizeof *all);
    if (!all) { *oom = 1; return 0; }
    comm_allgather_i64((int64_t)mine, all);
    uint32_t crc = head;
    for (int r = 0; r < E->nranks; r++) {
        const int64_t lo = E->n * r / E->nranks, hi = E->n * (r + 1) / E->nranks;
        crc = ckpt_crc_join(crc, (uint32_t)all[r], 16 * (uint64_t)(hi - lo));
    }
    free(all);
    return crc;
}

/* delta(X) never decreases (docs/method.md), so no state cfpo reaches
 * has two points closer than its start's minimum distance d0: the start
 * is a function of (n, seed, variant), made here as a fresh run makes it
 * and measured. A cell then holds at most ckpt_cell_bound(L, d0) points. */
static int start_cell_bound(cfpo_engine *E, int64_t *bound, double *d0, char *err, size_t errlen)
{
    const double shift = E->G.shift;
    E->G.shift = 0;
    int rc = eng_make_initial(E, err, errlen);
    if (!comm_all(rc == 0)) {
        E->G.shift = shift;
        if (rc == 0) snprintf(err, errlen, "another rank failed to make the start");
        return -1;
    }
    if (!comm_all(eng_refresh_halo(E) == 0)) {
        E->G.shift = shift;
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double dmin, davg;
    cfpo_engine_deltas(E, &dmin, &davg);
    E->G.shift = shift;
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby)); /* the cache held the start's blocks */
    E->dmin_now = 1;
    *d0 = dmin * E->G.delta * (1 - 1e-9); /* rounding can only lower it */
    *bound = ckpt_cell_bound(E->G.L, *d0);
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
    ckpt_header hd;
    if (!comm_all(read_header(path, &hd, err, errlen) == 0)) return -1;
    int64_t bound;
    double d0;
    if (start_cell_bound(E, &bound, &d0, err, errlen) != 0) return -1;
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER];
    int bad = comm_file_read_at(f, 0, h, CKPT_HEADER) != 0;
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
    bad |= !buf || !send || !sb || !scap || !recv || !rb;
    int64_t badpos = -1;
    size_t have = 0;
    uint32_t crc = 0;
    /* received points land in tx/ty/tid */
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = lo + r * CH, b = a + CH < hi ? a + CH : hi;
        if (a > b) a = b;
        for (int q = 0; q < P; q++) sb[q] = 0;
        if (!bad && b > a && comm_file_read_at(f, CKPT_HEADER + 16 * (uint64_t)a, buf, (size_t)(b - a) * 16) != 0)
            bad = 1;
        if (!bad) crc = ckpt_crc_more(crc, buf, (size_t)(b - a) * 16);
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
    if (hd.version >= 2) {
        int oom = 0;
        uint32_t all = join_shares(E, ckpt_crc_header(h), crc, &oom);
        if (!comm_all(!oom)) { snprintf(err, errlen, "out of memory"); return -1; }
        if (all != hd.crc) {
            snprintf(err, errlen, "%s: corrupt checkpoint: checksum 0x%08lx does not match the contents (0x%08lx)",
                     path, (unsigned long)hd.crc, (unsigned long)all);
            return -1;
        }
    }
    /* Counting sort into cells, then id order inside each cell. */
    memset(E->start, 0, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        int64_t c = own_cell_of(E, E->tx[i], E->ty[i]);
        E->start[c + 1]++;
    }
    int64_t worst[2] = {0, 0}; /* most points in a cell, its global index */
    for (int64_t c = 0; c < E->cells; c++) {
        if ((int64_t)E->start[c + 1] > worst[0]) {
            worst[0] = E->start[c + 1];
            worst[1] = (E->y0 + c / E->w) * E->G.g + E->x0 + c % E->w;
        }
        E->start[c + 1] += E->start[c];
    }
    int64_t most = worst[0];
    comm_max_i64(&most, 1);
    if (most > bound) {
        int64_t where = worst[0] == most ? worst[1] : -1;
        comm_max_i64(&where, 1);
        snprintf(err, errlen, "%s: checkpoint puts %lld points in cell (%lld, %lld); no run of cfpo puts more than "
                 "%lld in a cell (its start keeps points %.3g apart, and that distance never decreases)", path,
                 (long long)most, (long long)(where % E->G.g), (long long)(where / E->G.g), (long long)bound, d0);
        return -1;
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
    E->maxcell = (int)worst[0];
    int64_t tot = E->nloc;
    comm_sum_i64(&tot, 1);
    if (tot != E->n) {
        snprintf(err, errlen, "%s: corrupt checkpoint (point count)", path);
        return -1;
    }
    /* The invariant itself: the state's minimum distance is at least the
     * start's. */
    if (!comm_all(eng_refresh_halo(E) == 0)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double dmin, davg;
    cfpo_engine_deltas(E, &dmin, &davg);
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    if (dmin * E->G.delta < d0) {
        snprintf(err, errlen, "%s: checkpoint has points %.3g apart; no run of cfpo brings points closer than its "
                 "start's minimum distance %.3g", path, dmin * E->G.delta, d0);
        return -1;
    }
    return 0;
}

/* The checksum of what was written: every rank reads its share of the
 * temporary file back (so it also proves the points reached the file). */
static int written_crc(cfpo_engine *E, comm_file *f, const unsigned char *h, uint32_t *out)
{
    if (comm_file_sync(f) != 0) return -1;
    char e2[256];
    uint64_t size;
    comm_file *r = comm_file_open_read(comm_file_tmpname(f), &size, e2, sizeof e2);
    if (!r) return -1;
    const int64_t lo = E->n * E->rank / E->nranks, hi = E->n * (E->rank + 1) / E->nranks;
    const size_t CH = (size_t)1 << 24;
    unsigned char *buf = malloc(CH);
    uint32_t crc = 0;
    int ok = buf != NULL && size == CKPT_HEADER + 16 * (uint64_t)E->n;
    for (uint64_t off = 16 * (uint64_t)lo; ok && off < 16 * (uint64_t)hi; off += CH) {
        size_t b = 16 * (uint64_t)hi - off < CH ? (size_t)(16 * (uint64_t)hi - off) : CH;
        ok = comm_file_read_at(r, CKPT_HEADER + off, buf, b) == 0;
        if (ok) crc = ckpt_crc_more(crc, buf, b);
    }
    free(buf);
    comm_file_close(r);
    int oom = 0;
    if (!comm_all(ok)) return -1;
    *out = join_shares(E, ckpt_crc_header(h), crc, &oom);
    return comm_all(!oom) ? 0 : -1;
}

int eng_write_checkpoint(cfpo_engine *E, int iteration, int converged, char *err, size_t errlen)
{
    comm_file *f = comm_file_create(E->cfg.checkpoint, err, errlen);
    if (!f) return -1;
    /* The temporary is removed on SIGINT/SIGTERM like the output's. */
    char *tmp = E->rank == 0 && comm_file_tmpname(f) ? strdup(comm_file_tmpname(f)) : NULL;
    if (tmp) cli_guard_tmp(tmp);
    ckpt_header c = {.version = CKPT_VERSION, .n = E->n, .seed = E->o.seed, .variant = E->o.variant,
                     .tol = E->o.tol, .iteration = iteration, .converged = converged ? 1 : 0, .crc = 0};
    unsigned char h[CKPT_HEADER];
    ckpt_encode(&c, h);
    int ok = E->rank != 0 || comm_file_write_at(f, 0, h, sizeof h) == 0;
    char e2[256];
    if (cfpo_engine_write_points(E, f, CKPT_HEADER, e2, sizeof e2) != 0) ok = 0;
    if (comm_all(ok) && written_crc(E, f, h, &c.crc) == 0) {
        ckpt_encode(&c, h);
        ok = E->rank != 0 || comm_file_write_at(f, 0, h, sizeof h) == 0;
    } else {
        ok = 0;
    }
    int rc = comm_file_commit(f, ok, err, errlen);
    if (tmp) cli_unguard_tmp(tmp);
    free(tmp);
    return rc;
}
