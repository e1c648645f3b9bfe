/* ckpt.h - layer 3: the checkpoint file format: its 64-byte header, read and
 * written, every field validated, and its checksum.
 *
 * Version 3 (written now), little-endian:
 *    0  magic "CFPOCKPT"       8 bytes
 *    8  version = 3            u32
 *   12  header bytes = 64      u32
 *   16  n                      u64   points (id order after the header)
 *   24  seed                   u64
 *   32  variant                u32   CFPO_VARIANT_*
 *   36  converged              u32   0 or 1
 *   40  tol                    f64   in [0, CFPO_TOL_MAX]
 *   48  iteration              u64   in [0, 1e9]
 *   56  near                   u32   1 while the adaptive variant's near
 *                                    phase runs (never with converged),
 *                                    else 0
 *   60  crc32                  u32   zlib's crc32 of the header (this
 *                                    field as 0) followed by the points
 * then n points of 16 bytes (x, y as little-endian float64).
 * Version 2: the same, with 0 at 56 (written before the near phase
 * existed: its runs solved exactly throughout, so it reads as near = 0).
 * Version 1 (magic "CFPOCKP1", no checksum): n, seed, variant, tol,
 * iteration, converged as u64 / f64 at 8, 16, ..., 48, then 8 zero bytes;
 * still read, its fields validated the same way.
 *
 * Owns: the layout, the validation of every field (one-line errors naming
 * the file and the field), the checksum's arithmetic.
 * Does not own: reading files, or where the points go (engine_ckpt.c). */
#ifndef CFPO_CKPT_H
#define CFPO_CKPT_H

#include <stddef.h>
#include <stdint.h>

#define CKPT_HEADER 64
#define CKPT_VERSION 3
#define CKPT_ITER_MAX 1000000000

typedef struct {
    int version; /* 1, 2 or 3 */
    int64_t n;
    uint64_t seed;
    int variant;
    double tol;
    int64_t iteration;
    int converged;
    int near;     /* version 3 only (else 0) */
    uint32_t crc; /* versions 2 and 3 */
} ckpt_header;

/* Validates the header h of a checkpoint file of `size` bytes. 0, or -1
 * with one line naming the file and the field in err. */
int ckpt_decode(const char *path, const unsigned char *h, uint64_t size, ckpt_header *out, char *err,
                size_t errlen);

/* A version-3 header of c (c->crc goes into its field). */
void ckpt_encode(const ckpt_header *c, unsigned char *h);

/* The checksum of a version-2 or -3 file: ckpt_crc_header over the header's
 * bytes (its crc field taken as 0), continued by ckpt_crc_more over the
 * point bytes in order; pieces computed apart join with ckpt_crc_join
 * (zlib's crc32_combine). */
uint32_t ckpt_crc_header(const unsigned char *h);
uint32_t ckpt_crc_more(uint32_t crc, const void *buf, size_t bytes);
uint32_t ckpt_crc_join(uint32_t a, uint32_t b, uint64_t bbytes);

/* Whether a whole checkpoint held in memory is valid: header, checksum,
 * every point in [0,1)^2. For tests and the fuzzing harness; the engine
 * reads in pieces (engine_ckpt.c). */
int ckpt_check_buffer(const char *path, const unsigned char *buf, size_t len, ckpt_header *out, char *err,
                      size_t errlen);

/* Most points one cell of side L can hold when no two are closer than d
 * (every state cfpo reaches keeps its start's minimum distance): the cell
 * cut into k x k squares of diagonal at most d holds at most one point in
 * each, k = ceil(L sqrt(2) / d), plus one row and column for rounding at
 * the cell's edges. INT64_MAX when d is 0. */
int64_t ckpt_cell_bound(double L, double d);

#endif
