/* ckpt.h - layer 3: the checkpoint file format: its 64-byte header, read and
 * written, every field validated, and its checksum.
 *
 * Version 4 (written now, by the uniform and the density engines alike),
 * little-endian:
 *    0  magic "CFPOCKPT"       8 bytes
 *    8  version = 4            u32
 *   12  header bytes = 80      u32
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
 *   64  density hash           u64   cfpo_density.hash of the run's density
 *                                    (density.h), 0 for a run without one
 *   72  davg_ref               f64   the density schedule's delta_avg one
 *                                    window back (policy.h), in [0, 2);
 *                                    0 without a density
 * then n points of 16 bytes (x, y as little-endian float64), in id order.
 * Version 3: the same up to byte 64, with a 64-byte header (no density).
 * Version 2: the same, with 0 at 56 (written before the near phase
 * existed: its runs solved exactly throughout, so it reads as near = 0).
 * Version 1 (magic "CFPOCKP1", no checksum): n, seed, variant, tol,
 * iteration, converged as u64 / f64 at 8, 16, ..., 48, then 8 zero bytes;
 * still read, its fields validated the same way. The density engine's own
 * format of 0.1.0 (magic "CFPODENS") is refused in one line.
 *
 * Owns: the layout, the validation of every field (one-line errors naming
 * the file and the field), the checksum's arithmetic.
 * Does not own: reading files, or where the points go (engine_ckpt.c). */
#ifndef CFPO_CKPT_H
#define CFPO_CKPT_H

#include <stddef.h>
#include <stdint.h>

#define CKPT_HEADER 80    /* version 4's header; the most bytes a header has */
#define CKPT_HEADER_V3 64 /* versions 1 to 3 */
#define CKPT_VERSION 4
#define CKPT_ITER_MAX 1000000000

typedef struct {
    int version; /* 1 to 4 */
    int bytes;   /* the header's size: 64, or 80 for version 4 */
    uint64_t hash; /* version 4: the density's hash, 0 without a density */
    double davg_ref; /* version 4: the density schedule's state, 0 without */
    int64_t n;
    uint64_t seed;
    int variant;
    double tol;
    int64_t iteration;
    int converged;
    int near;     /* version 3 only (else 0) */
    uint32_t crc; /* versions 2 and 3 */
} ckpt_header;

/* Validates the header h (the file's first min(size, CKPT_HEADER) bytes,
 * zero-padded to CKPT_HEADER) of a checkpoint file of `size` bytes. 0, or -1
 * with one line naming the file and the field in err. */
int ckpt_decode(const char *path, const unsigned char *h, uint64_t size, ckpt_header *out, char *err,
                size_t errlen);

/* A version-4 header of c (c->crc goes into its field), CKPT_HEADER bytes. */
void ckpt_encode(const ckpt_header *c, unsigned char *h);

/* The checksum of a version-2 or -3 file: ckpt_crc_header over the header's
 * bytes (its crc field taken as 0), continued by ckpt_crc_more over the
 * point bytes in order; pieces computed apart join with ckpt_crc_join
 * (zlib's crc32_combine). */
uint32_t ckpt_crc_header(const unsigned char *h, int bytes);
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
