/* dens_ckpt.h - layer 3: the checkpoint of a run under a density.
 *
 * Little-endian, 64-byte header, then n points (x, y as float64):
 *    0  magic "CFPODENS"  8 bytes
 *    8  version = 1       u32
 *   12  converged         u32   0 or 1
 *   16  n                 u64
 *   24  seed              u64
 *   32  density hash      u64   cfpo_density.hash of the run's density
 *   40  tol               f64
 *   48  iteration         u64   in [0, 1e9]
 *   56  crc32             u32   zlib's crc32 of the header (this field 0)
 *                               and the points
 *   60  zero              u32
 * Owns: the layout, its validation, writing it whole or not at all. */
#ifndef CFPO_DENS_CKPT_H
#define CFPO_DENS_CKPT_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    int64_t n;
    uint64_t seed, hash;
    double tol;
    int iteration, converged;
} dens_ckpt_info;

/* 1 when the file begins with the density checkpoint's magic. */
int dens_ckpt_is(const char *path);

/* Reads and validates the whole file; *xy (2 n doubles, malloc'd). 0, or
 * -1 with one line in err. */
int dens_ckpt_read(const char *path, dens_ckpt_info *info, double **xy, char *err, size_t errlen);

int dens_ckpt_write(const char *path, const dens_ckpt_info *info, const double *xy, char *err, size_t errlen);

#endif
