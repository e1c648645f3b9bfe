/* ckpt_io.c - see ckpt_io.h. */
#include "ckpt_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tmpguard.h"

uint32_t ckpt_join_shares(int64_t n, uint32_t head, uint32_t mine, int *oom)
{
    const int P = comm_size();
    int64_t *all = malloc((size_t)P * sizeof *all);
    if (!all) { *oom = 1; return 0; }
    comm_allgather_i64((int64_t)mine, all);
    uint32_t crc = head;
    for (int r = 0; r < P; r++) {
        const int64_t lo = n * r / P, hi = n * (r + 1) / P;
        crc = ckpt_crc_join(crc, (uint32_t)all[r], 16 * (uint64_t)(hi - lo));
    }
    free(all);
    return crc;
}

/* The checksum of what was written: every rank reads its share of the
 * temporary file back (so it also proves the points reached the file). */
static int written_crc(int64_t n, comm_file *f, const unsigned char *h, uint32_t *out)
{
    if (comm_file_sync(f) != 0) return -1;
    char e2[256];
    uint64_t size;
    comm_file *r = comm_file_open_read(comm_file_tmpname(f), &size, e2, sizeof e2);
    if (!r) return -1;
    const int P = comm_size(), me = comm_rank();
    const int64_t lo = n * me / P, hi = n * (me + 1) / P;
    const size_t CH = (size_t)1 << 24;
    unsigned char *buf = malloc(CH);
    uint32_t crc = 0;
    int ok = buf != NULL && size == CKPT_HEADER + 16 * (uint64_t)n;
    for (uint64_t off = 16 * (uint64_t)lo; ok && off < 16 * (uint64_t)hi; off += CH) {
        size_t b = 16 * (uint64_t)hi - off < CH ? (size_t)(16 * (uint64_t)hi - off) : CH;
        ok = comm_file_read_at(r, CKPT_HEADER + off, buf, b) == 0;
        if (ok) crc = ckpt_crc_more(crc, buf, b);
    }
    free(buf);
    comm_file_close(r);
    int oom = 0;
    if (!comm_all(ok)) return -1;
    *out = ckpt_join_shares(n, ckpt_crc_header(h, CKPT_HEADER), crc, &oom);
    return comm_all(!oom) ? 0 : -1;
}

int ckpt_write(const char *path, ckpt_header *c, ckpt_put_points put, void *engine, char *err, size_t errlen)
{
    comm_file *f = comm_file_create(path, err, errlen);
    if (!f) return -1;
    /* The temporary is removed on SIGINT/SIGTERM like the output's. */
    char *tmp = comm_rank() == 0 && comm_file_tmpname(f) ? strdup(comm_file_tmpname(f)) : NULL;
    if (tmp) tmpguard_file(tmp);
    c->version = CKPT_VERSION;
    c->bytes = CKPT_HEADER;
    c->crc = 0;
    unsigned char h[CKPT_HEADER];
    ckpt_encode(c, h);
    int ok = comm_rank() != 0 || comm_file_write_at(f, 0, h, sizeof h) == 0;
    char e2[256];
    if (put(engine, f, CKPT_HEADER, e2, sizeof e2) != 0) ok = 0;
    if (comm_all(ok) && written_crc(c->n, f, h, &c->crc) == 0) {
        ckpt_encode(c, h);
        ok = comm_rank() != 0 || comm_file_write_at(f, 0, h, sizeof h) == 0;
    } else {
        ok = 0;
    }
    int rc = comm_file_commit(f, ok, err, errlen);
    if (tmp) tmpguard_forget(tmp);
    free(tmp);
    return rc;
}

int ckpt_read_header(const char *path, ckpt_header *c, char *err, size_t errlen)
{
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char h[CKPT_HEADER] = {0};
    const size_t want = size < CKPT_HEADER ? (size_t)size : CKPT_HEADER;
    int ok = size < CKPT_HEADER_V3 || comm_file_read_at(f, 0, h, want) == 0;
    comm_file_close(f);
    if (!ok) {
        snprintf(err, errlen, "%s: cannot read the checkpoint header", path);
        return -1;
    }
    return ckpt_decode(path, h, size, c, err, errlen);
}

int ckpt_read_all(const char *path, ckpt_header *c, double **xy, char *err, size_t errlen)
{
    *xy = NULL;
    if (ckpt_read_header(path, c, err, errlen) != 0) return -1;
    uint64_t size;
    comm_file *f = comm_file_open_read(path, &size, err, errlen);
    if (!f) return -1;
    unsigned char *buf = malloc((size_t)size);
    double *pts = malloc((size_t)c->n * 2 * sizeof *pts + 1);
    int ok = buf && pts && comm_file_read_at(f, 0, buf, (size_t)size) == 0;
    comm_file_close(f);
    if (!ok) {
        free(buf); free(pts);
        snprintf(err, errlen, "%s: cannot read the checkpoint (or out of memory)", path);
        return -1;
    }
    if (ckpt_check_buffer(path, buf, (size_t)size, c, err, errlen) != 0) {
        free(buf); free(pts);
        return -1;
    }
    for (int64_t i = 0; i < 2 * c->n; i++) { /* little-endian float64 */
        uint64_t u = 0;
        for (int k = 7; k >= 0; k--) u = u << 8 | buf[(size_t)c->bytes + 8 * (size_t)i + (size_t)k];
        memcpy(&pts[i], &u, 8);
    }
    free(buf);
    *xy = pts;
    return 0;
}
