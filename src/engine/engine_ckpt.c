/* engine_ckpt.c - checkpoints: reading with validation (header fields,
 * checksum, points, the most points a cell can hold), writing (see
 * cells.h; the format is ckpt.h's). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ckpt.h"
#include "ckpt_io.h"

int cfpo_checkpoint_peek(const char *path, cfpo_checkpoint_info *info, char *err, size_t errlen)
{
    ckpt_header c;
    if (ckpt_read_header(path, &c, err, errlen) != 0) return -1;
    info->n = c.n;
    info->seed = c.seed;
    info->variant = c.variant;
    info->tol = c.tol;
    info->iteration = c.iteration;
    info->converged = c.converged;
    info->near = c.near;
    info->hash = c.hash;
    return 0;
}

/* delta(X) never decreases (docs/method.md), so no state cfpo reaches
 * has two points closer than its start's minimum distance d0: the start
 * is a function of (n, seed, variant), made here as a fresh run makes it
 * and measured. A cell then holds at most ckpt_cell_bound(L, d0) points.
 * The adaptive start is measured without its relaxation (start_relax.h):
 * the relaxed start's d0 (about 0.7 Delta(n)) would refuse the states of
 * runs from given points (the progressive levels, --init), which start
 * closer; the raw start's d0 (about 1e-3 Delta(n)) is the bound it was
 * before the relaxation, and the relaxed start is far above it. */
static int start_cell_bound(cfpo_engine *E, int64_t *bound, double *d0, char *err, size_t errlen)
{
    const double shx = E->G.shift_x, shy = E->G.shift_y;
    E->G.shift_x = E->G.shift_y = 0;
    E->start_raw = 1;
    int rc = eng_make_initial(E, err, errlen);
    E->start_raw = 0;
    if (!comm_all(rc == 0)) {
        E->G.shift_x = shx, E->G.shift_y = shy;
        if (rc == 0) snprintf(err, errlen, "another rank failed to make the start");
        return -1;
    }
    if (!comm_all(eng_refresh_halo(E) == 0)) {
        E->G.shift_x = shx, E->G.shift_y = shy;
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double dmin, davg;
    cfpo_engine_deltas(E, &dmin, &davg);
    E->G.shift_x = shx, E->G.shift_y = shy;
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
/* Buffers of the scatter: this rank's share of the file, read in pieces,
 * each point sent to the rank that owns its cell. */
typedef struct {
    int P;
    double *buf;
    void **send, **recv;
    size_t *sb, *scap, *rb;
} scatter;

static int scatter_init(scatter *s, int P, size_t piece)
{
    memset(s, 0, sizeof *s);
    s->P = P;
    s->buf = malloc(piece * 16);
    s->send = calloc((size_t)P, sizeof *s->send);
    s->recv = calloc((size_t)P, sizeof *s->recv);
    s->sb = calloc((size_t)P, sizeof *s->sb);
    s->scap = calloc((size_t)P, sizeof *s->scap);
    s->rb = calloc((size_t)P, sizeof *s->rb);
    return s->buf && s->send && s->recv && s->sb && s->scap && s->rb ? 0 : -1;
}

static void scatter_free(scatter *s)
{
    for (int q = 0; s->send && q < s->P; q++) free(s->send[q]);
    free(s->send); free(s->recv); free(s->sb); free(s->scap); free(s->rb); free(s->buf);
}

/* Adds point i at (x, y) to the message for rank q. */
static int scatter_add(scatter *s, int q, double x, double y, int64_t i)
{
    if (s->sb[q] + sizeof(ck_rec) > s->scap[q]) {
        const size_t c = (s->sb[q] + sizeof(ck_rec)) * 2;
        void *p = realloc(s->send[q], c);
        if (!p) return -1;
        s->send[q] = p;
        s->scap[q] = c;
    }
    const ck_rec rec = {x, y, (uint64_t)i};
    memcpy((char *)s->send[q] + s->sb[q], &rec, sizeof rec);
    s->sb[q] += sizeof rec;
    return 0;
}

/* Points [a, b) of the file into the messages; the checksum grows over
 * them. 0; -1 (read failure or out of memory); *badpos gets the first
 * point outside [0,1)^2. */
static int read_piece(cfpo_engine *E, comm_file *f, uint64_t hb, scatter *s, int64_t a, int64_t b, uint32_t *crc,
                      int64_t *badpos)
{
    for (int q = 0; q < s->P; q++) s->sb[q] = 0;
    if (b > a && comm_file_read_at(f, hb + 16 * (uint64_t)a, s->buf, (size_t)(b - a) * 16) != 0) return -1;
    *crc = ckpt_crc_more(*crc, s->buf, (size_t)(b - a) * 16);
    for (int64_t i = a; i < b; i++) {
        const double x = s->buf[2 * (i - a)], y = s->buf[2 * (i - a) + 1];
        if (!(x >= 0 && x < 1 && y >= 0 && y < 1)) {
            *badpos = i;
            return -1;
        }
        const int q = cfpo_tiling_owner(&E->T, cfpo_grid_cx(&E->G, x), cfpo_grid_cy(&E->G, y));
        if (scatter_add(s, q, x, y, i) != 0) return -1;
    }
    return 0;
}

/* The received points of one piece into tx/ty/tid from slot *have on. */
static int take_piece(cfpo_engine *E, scatter *s, size_t *have)
{
    size_t add = 0;
    for (int q = 0; q < s->P; q++) add += s->rb[q] / sizeof(ck_rec);
    const int bad = eng_ensure_cap(E, *have + add) != 0;
    for (int q = 0; q < s->P; q++) {
        const ck_rec *rr = s->recv[q];
        for (size_t i = 0; !bad && i < s->rb[q] / sizeof(ck_rec); i++, (*have)++) {
            E->tx[*have] = rr[i].x;
            E->ty[*have] = rr[i].y;
            E->tid[*have] = rr[i].id;
        }
        free(s->recv[q]);
        s->recv[q] = NULL;
    }
    return bad ? -1 : 0;
}

/* Collective: every rank reads its share of the points (n P-th parts, in
 * pieces of 2^20) and sends each to its cell's owner; this rank's points
 * land in tx/ty/tid (*have of them), *crc is the checksum of its share.
 * 0, or -1 with a message. */
static int read_points(cfpo_engine *E, comm_file *f, uint64_t hb, const char *path, size_t *have, uint32_t *crc,
                       char *err, size_t errlen)
{
    const int64_t lo = E->n * E->rank / E->nranks, hi = E->n * (E->rank + 1) / E->nranks;
    const int64_t CH = (int64_t)1 << 20;
    int64_t rounds = (hi - lo + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    scatter s;
    int bad = scatter_init(&s, E->nranks, (size_t)CH) != 0;
    int64_t badpos = -1;
    *have = 0;
    *crc = 0;
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = lo + r * CH, b = a + CH < hi ? a + CH : hi;
        if (a > b) a = b;
        if (!bad && read_piece(E, f, hb, &s, a, b, crc, &badpos) != 0) bad = 1;
        if (!comm_all(!bad)) break;
        if (comm_alltoallv(s.send, s.sb, s.recv, s.rb) != 0 || take_piece(E, &s, have) != 0) bad = 1;
        if (!comm_all(!bad)) break;
    }
    scatter_free(&s);
    comm_max_i64(&badpos, 1);
    if (comm_all(!bad)) return 0;
    if (badpos >= 0)
        snprintf(err, errlen, "%s: corrupt checkpoint: point %lld at offset %llu is not in [0,1)^2", path,
                 (long long)badpos, (unsigned long long)(hb + 16 * (uint64_t)badpos));
    else snprintf(err, errlen, "%s: cannot read the checkpoint (or out of memory)", path);
    return -1;
}

/* Version 2: the checksum of the header and every rank's share, joined in
 * rank order, against the header's. */
static int check_crc(cfpo_engine *E, const char *path, const ckpt_header *hd, const unsigned char *h, uint32_t crc,
                     char *err, size_t errlen)
{
    if (hd->version < 2) return 0;
    int oom = 0;
    const uint32_t all = ckpt_join_shares(E->n, ckpt_crc_header(h, hd->bytes), crc, &oom);
    if (!comm_all(!oom)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    if (all == hd->crc) return 0;
    snprintf(err, errlen, "%s: corrupt checkpoint: checksum 0x%08lx does not match the contents (0x%08lx)", path,
             (unsigned long)hd->crc, (unsigned long)all);
    return -1;
}

/* The have points of tx/ty/tid into their cells, id order inside each;
 * refuses a cell fuller than bound (the message says d0) or than
 * CFPO_CELL_MAX. */
static int bucket_points(cfpo_engine *E, const char *path, size_t have, int64_t bound, double d0, char *err,
                         size_t errlen)
{
    memset(E->start, 0, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) E->start[own_cell_of(E, E->tx[i], E->ty[i]) + 1]++;
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
    if (most > bound || most > CFPO_CELL_MAX) {
        int64_t where = worst[0] == most ? worst[1] : -1;
        comm_max_i64(&where, 1);
        const long long cx = (long long)(where % E->G.g), cy = (long long)(where / E->G.g);
        if (most > bound)
            snprintf(err, errlen, "%s: checkpoint puts %lld points in cell (%lld, %lld); no run of cfpo puts more "
                     "than %lld in a cell (its start keeps points %.3g apart, and that distance never decreases)",
                     path, (long long)most, cx, cy, (long long)bound, d0);
        else
            snprintf(err, errlen, "%s: checkpoint puts %lld points in cell (%lld, %lld); more than %d is refused "
                     "(a cell's work grows with the cube of its count; cfpo's runs hold about 10 at most)",
                     path, (long long)most, cx, cy, CFPO_CELL_MAX);
        return -1;
    }
    memcpy(E->start2, E->start, ((size_t)E->cells + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < have; i++) {
        const uint32_t k = E->start2[own_cell_of(E, E->tx[i], E->ty[i])]++;
        E->px[k] = E->tx[i];
        E->py[k] = E->ty[i];
        E->pid[k] = E->tid[i];
    }
    for (int64_t c = 0; c < E->cells; c++) eng_sort3(E->pid, E->px, E->py, E->start[c], E->start[c + 1]);
    E->nloc = (int64_t)have;
    E->maxcell = (int)worst[0];
    return 0;
}

/* The invariant itself: the state's minimum distance is at least the
 * start's d0. */
static int check_distance(cfpo_engine *E, const char *path, double d0, char *err, size_t errlen)
{
    if (!comm_all(eng_refresh_halo(E) == 0)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double dmin, davg;
    cfpo_engine_deltas(E, &dmin, &davg);
    memset(E->bdirty, 1, (size_t)(E->nbx * E->nby));
    if (dmin * E->G.delta >= d0) return 0;
    snprintf(err, errlen, "%s: checkpoint has points %.3g apart; no run of cfpo brings points closer than its "
             "start's minimum distance %.3g", path, dmin * E->G.delta, d0);
    return -1;
}

int eng_load_checkpoint(cfpo_engine *E, char *err, size_t errlen)
{
    const char *path = E->cfg.resume;
    ckpt_header hd;
    if (!comm_all(ckpt_read_header(path, &hd, err, errlen) == 0)) return -1;
    int64_t bound;
    double d0;
    if (start_cell_bound(E, &bound, &d0, err, errlen) != 0) return -1;
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER] = {0};
    if (!comm_all(comm_file_read_at(f, 0, h, (size_t)hd.bytes) == 0)) {
        comm_file_close(f);
        snprintf(err, errlen, "%s: cannot read the checkpoint (or out of memory)", path);
        return -1;
    }
    size_t have;
    uint32_t crc;
    const int rc = read_points(E, f, (uint64_t)hd.bytes, path, &have, &crc, err, errlen);
    comm_file_close(f);
    if (rc != 0 || check_crc(E, path, &hd, h, crc, err, errlen) != 0) return -1;
    if (bucket_points(E, path, have, bound, d0, err, errlen) != 0) return -1;
    int64_t tot = E->nloc;
    comm_sum_i64(&tot, 1);
    if (tot != E->n) {
        snprintf(err, errlen, "%s: corrupt checkpoint (point count)", path);
        return -1;
    }
    return check_distance(E, path, d0, err, errlen);
}

static int put_points(void *engine, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    return cfpo_engine_write_points(engine, f, base, err, errlen);
}

int eng_write_checkpoint(cfpo_engine *E, int iteration, int converged, char *err, size_t errlen)
{
    ckpt_header c = {.n = E->n, .seed = E->o.seed, .variant = E->o.variant, .tol = E->o.tol,
                     .iteration = iteration, .converged = converged ? 1 : 0, .near = E->near, .hash = E->cfg.density_hash};
    return ckpt_write(E->cfg.checkpoint, &c, put_points, E, err, errlen);
}
