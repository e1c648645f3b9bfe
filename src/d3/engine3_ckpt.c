/* engine3_ckpt.c - the 3-D engine's checkpoint file (engine3.h).
 *
 * Version 2 (no caller's block) or 3 (with one), little-endian, 64-byte
 * header (version 1, before the near phase, is refused):
 *    0  magic "CFPO3DCK"   8 bytes
 *    8  version = 2 or 3   u32
 *   12  header bytes = 64  u32
 *   16  n                  u64   points (id order after the header)
 *   24  seed               u64
 *   32  iteration          u64   iterations done, in [0, 1e9]
 *   40  tol                f64   in (0, CFPO_TOL_MAX]
 *   48  flags              u32   bit 0 relax, bit 1 shift, bit 2 skip, bit 3 in the
 *                                near phase; no other bit
 *   52  tail bytes         u64   version 2: 0; version 3: the caller's block
 *                                after the points, 1 .. 2^40 bytes
 *   60  crc32              u32   zlib's crc32 of the header (this field as
 *                                0) followed by the points and the block
 * then n points of 24 bytes (x, y, z as float64, each in [0,1)), then the
 * block (the command's schedule, sched3.c; opaque here).
 * The rest of the state is a function of these: the grid's shift (of the
 * seed and the iteration), delta(X) (of the points); the skip stamps start
 * empty, which solves every cell once and changes nothing (a skipped cell
 * is one whose answer is "stay"). So a resumed run gives the bytes of an
 * uninterrupted one, on any rank count: under several ranks the set is
 * gathered in id order and rank 0 writes the file, so its bytes do not
 * depend on the rank count either. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "bytes_le.h"
#include "engine3_dist.h"
#include "state3.h"
#include "readall.h"
#include "cli.h"

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the 3-D checkpoint code assumes a little-endian machine"
#endif

#define MAGIC "CFPO3DCK"
#define HDR 64
#define ITER_MAX 1000000000ULL
#define N_MAX (1LL << 40)
#define TAIL_MAX (1ULL << 40)

static uLong crc_more(uLong c, const unsigned char *p, size_t left)
{
    while (left > 0) { /* crc32 takes a uInt length */
        const uInt part = left > (1u << 30) ? (1u << 30) : (uInt)left;
        c = crc32(c, p, part);
        p += part;
        left -= part;
    }
    return c;
}

static uint32_t crc_of(const unsigned char *h, const double *pos, int64_t n, const unsigned char *tail,
                       size_t tail_len)
{
    unsigned char hz[HDR];
    memcpy(hz, h, HDR);
    le_put32(hz + 60, 0);
    uLong c = crc32(0L, Z_NULL, 0);
    c = crc32(c, hz, HDR);
    c = crc_more(c, (const unsigned char *)pos, sizeof(double) * 3 * (size_t)n);
    return (uint32_t)crc_more(c, tail, tail_len);
}

uint32_t cfpo3_checkpoint_crc(const unsigned char *buf, size_t len)
{
    if (len < HDR) return 0;
    unsigned char hz[HDR];
    memcpy(hz, buf, HDR);
    le_put32(hz + 60, 0);
    uLong c = crc32(0L, Z_NULL, 0);
    c = crc32(c, hz, HDR);
    return (uint32_t)crc_more(c, buf + HDR, len - HDR);
}

void cfpo3_set_checkpoint_tail(cfpo3_engine *e, cfpo3_tail_fn fn, void *user)
{
    e->tail_fn = fn;
    e->tail_user = user;
}

const unsigned char *cfpo3_checkpoint_tail(const cfpo3_engine *e, size_t *len)
{
    *len = e->tail_in_len;
    return e->tail_in;
}

/* Writes the file from pos (3n doubles by id) and the caller's block:
 * one process. */
static int write_file(const cfpo3_engine *e, const double *pos, const unsigned char *tail, size_t tail_len,
                      const char *path, char *err, size_t errlen)
{
    unsigned char h[HDR];
    memset(h, 0, sizeof h);
    memcpy(h, MAGIC, 8);
    le_put32(h + 8, tail_len > 0 ? 3 : 2);
    le_put32(h + 12, HDR);
    le_put64(h + 16, (uint64_t)e->n);
    le_put64(h + 24, e->o.seed);
    le_put64(h + 32, (uint64_t)e->iter);
    memcpy(h + 40, &e->o.tol, 8);
    le_put32(h + 48, (uint32_t)((e->o.relax ? 1 : 0) | (e->o.shift ? 2 : 0) | (e->o.skip ? 4 : 0) |
                          (e->near ? 8 : 0)));
    le_put64(h + 52, (uint64_t)tail_len);
    le_put32(h + 60, crc_of(h, pos, e->n, tail, tail_len));
    cli_atomic f;
    if (cli_atomic_open(&f, path, err, errlen) != 0) return -1;
    if (fwrite(h, 1, HDR, f.f) != HDR || fwrite(pos, sizeof(double), 3 * (size_t)e->n, f.f) != 3 * (size_t)e->n ||
        (tail_len > 0 && fwrite(tail, 1, tail_len, f.f) != tail_len)) {
        snprintf(err, errlen, "%s: write failed", path);
        cli_atomic_abort(&f);
        return -1;
    }
    return cli_atomic_commit(&f, err, errlen);
}

int cfpo3_checkpoint_write(const cfpo3_engine *e, const char *path, char *err, size_t errlen)
{
    unsigned char *tail = NULL;
    size_t tail_len = 0;
    if (e->tail_fn && comm_all(e->tail_fn(e->tail_user, &tail, &tail_len) == 0) == 0) {
        free(tail);
        snprintf(err, errlen, "%s: out of memory for the checkpoint", path);
        return -1;
    }
    if (!e->dist) {
        const int rc = write_file(e, e->pos, tail, tail_len, path, err, errlen);
        free(tail);
        return rc;
    }
    /* several ranks: the set gathered, rank 0 writes, every rank learns how it went */
    double *all = malloc(sizeof(double) * 3 * (size_t)e->n);
    if (comm_all(all != NULL) == 0 || cfpo3_dist_gather(e, all) != 0) {
        free(all);
        free(tail);
        snprintf(err, errlen, "%s: out of memory gathering the points", path);
        return -1;
    }
    int64_t rc = 0;
    if (comm_rank() == 0) rc = write_file(e, all, tail, tail_len, path, err, errlen);
    free(all);
    free(tail);
    comm_bcast(&rc, sizeof rc, 0);
    if (rc != 0) comm_bcast(err, errlen, 0);
    return rc == 0 ? 0 : -1;
}

cfpo3_engine *cfpo3_checkpoint_parse(const unsigned char *buf, size_t len, const char *name, int threads,
                                     char *err, size_t errlen)
{
    if (len < HDR || memcmp(buf, MAGIC, 8) != 0) {
        snprintf(err, errlen, "%s: not a 3-D checkpoint (bad magic or too short)", name);
        return NULL;
    }
    const uint32_t version = le_get32(buf + 8);
    if ((version != 2 && version != 3) || le_get32(buf + 12) != HDR) {
        snprintf(err, errlen, "%s: unsupported 3-D checkpoint version %u", name, le_get32(buf + 8));
        return NULL;
    }
    const uint64_t n = le_get64(buf + 16), it = le_get64(buf + 32);
    const uint32_t flags = le_get32(buf + 48);
    double tol;
    memcpy(&tol, buf + 40, 8);
    const uint64_t tail_len = le_get64(buf + 52);
    if (version == 2 ? tail_len != 0 : (tail_len == 0 || tail_len > TAIL_MAX)) {
        snprintf(err, errlen, "%s: bad block length for version %u", name, version);
        return NULL;
    }
    if (n > (uint64_t)N_MAX || (uint64_t)(len - HDR) < tail_len || (uint64_t)(len - HDR) - tail_len != 24 * n) {
        snprintf(err, errlen, "%s: size does not match its point count", name);
        return NULL;
    }
    if (it > ITER_MAX) {
        snprintf(err, errlen, "%s: iteration out of range", name);
        return NULL;
    }
    if (!(tol > 0.0 && tol <= CFPO_TOL_MAX)) {
        snprintf(err, errlen, "%s: tolerance out of range", name);
        return NULL;
    }
    if ((flags & ~15u) != 0) {
        snprintf(err, errlen, "%s: bad flags or reserved fields", name);
        return NULL;
    }
    double *pos = malloc(sizeof(double) * 3 * (size_t)(n ? n : 1));
    if (!pos) {
        snprintf(err, errlen, "%s: out of memory", name);
        return NULL;
    }
    memcpy(pos, buf + HDR, sizeof(double) * 3 * (size_t)n);
    const unsigned char *tail = buf + HDR + 24 * n;
    if (crc_of(buf, pos, (int64_t)n, tail, (size_t)tail_len) != le_get32(buf + 60)) {
        snprintf(err, errlen, "%s: checksum mismatch (the file is corrupt)", name);
        free(pos);
        return NULL;
    }
    cfpo3_options o;
    cfpo3_options_default(&o);
    o.seed = le_get64(buf + 24);
    o.tol = tol;
    o.relax = (flags & 1) != 0;
    o.shift = (flags & 2) != 0;
    o.skip = (flags & 4) != 0;
    o.near = (flags & 8) != 0;
    o.threads = threads;
    char e2[200];
    cfpo3_engine *e = NULL;
    if (n < 2) {
        snprintf(e2, sizeof e2, "too few points");
    } else {
        e = cfpo3_alloc((int64_t)n, &o, e2, sizeof e2);
    }
    if (!e) {
        snprintf(err, errlen, "%s: %s", name, e2);
        free(pos);
        return NULL;
    }
    for (uint64_t i = 0; i < 3 * n; i++)
        if (!(pos[i] >= 0.0 && pos[i] < 1.0)) {
            snprintf(err, errlen, "%s: point %llu has a coordinate outside [0,1)", name,
                     (unsigned long long)(i / 3));
            free(pos);
            cfpo3_free(e);
            return NULL;
        }
    memcpy(e->pos, pos, sizeof(double) * 3 * (size_t)n);
    free(pos);
    if (tail_len > 0) {
        e->tail_in = malloc((size_t)tail_len);
        if (!e->tail_in) {
            snprintf(err, errlen, "%s: out of memory", name);
            cfpo3_free(e);
            return NULL;
        }
        memcpy(e->tail_in, tail, (size_t)tail_len);
        e->tail_in_len = (size_t)tail_len;
    }
    e->iter = (int)it;
    cfpo3_shift_for(e, e->iter, e->shift);
    cfpo3_assign(e);
    if (cfpo3_remeasure(e) != 0) {
        snprintf(err, errlen, "%s: out of memory", name);
        cfpo3_free(e);
        return NULL;
    }
    return e;
}

cfpo3_engine *cfpo3_checkpoint_read(const char *path, int threads, char *err, size_t errlen)
{
    unsigned char *buf;
    size_t len;
    switch (readall(path, 0, &buf, &len)) {
    case READALL_OK: break;
    case READALL_OPEN: snprintf(err, errlen, "%s: cannot open checkpoint", path); return NULL;
    case READALL_MEMORY:
    case READALL_LARGE: snprintf(err, errlen, "%s: out of memory", path); return NULL;
    case READALL_READ: snprintf(err, errlen, "%s: read error", path); return NULL;
    }
    cfpo3_engine *e = cfpo3_checkpoint_parse(buf, len, path, threads, err, errlen);
    free(buf);
    return e;
}
