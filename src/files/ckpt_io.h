/* ckpt_io.h - layer 3: checkpoint files written and read across ranks,
 * for every engine (the format is ckpt.h's).
 *
 * Owns: writing a checkpoint whole or not at all (a temporary beside the
 * name, guarded against SIGINT/SIGTERM, the header, the points put by the
 * engine at their ids' places, the checksum of what reached the file, the
 * rename), the checksum of every rank's share joined in rank order, and
 * reading a whole checkpoint on every rank (the density engine's way; the
 * uniform engine reads its share, engine_ckpt.c).
 * Does not own: the layout (ckpt.c), where the points live (the engines).
 * May include: ckpt.h, comm.h, tmpguard.h. */
#ifndef CFPO_CKPT_IO_H
#define CFPO_CKPT_IO_H

#include <stddef.h>
#include <stdint.h>

#include "ckpt.h"
#include "comm.h"

/* Collective: every rank writes its points into f, point of id k at byte
 * base + 16 k (x then y, little-endian float64). 0, or -1 with a message. */
typedef int (*ckpt_put_points)(void *engine, comm_file *f, uint64_t base, char *err, size_t errlen);

/* Collective: writes the checkpoint of c (c->n points; version, header
 * size and crc are filled here) to path. 0, or -1 with a message on every
 * rank (nothing replaced, no temporary left). */
int ckpt_write(const char *path, ckpt_header *c, ckpt_put_points put, void *engine, char *err, size_t errlen);

/* Collective: the checksum of rank r's share (points [n r / P, n (r+1) / P)
 * of the file), each rank giving its own as mine, joined in rank order
 * after head. *oom set when out of memory. */
uint32_t ckpt_join_shares(int64_t n, uint32_t head, uint32_t mine, int *oom);

/* Reads the header of a checkpoint (every rank reads it). 0, or -1 with
 * one line. */
int ckpt_read_header(const char *path, ckpt_header *c, char *err, size_t errlen);

/* Every rank: reads and validates the whole checkpoint (header, checksum,
 * points in [0,1)^2); *xy gets its 2 n doubles (malloc'd). 0, or -1 with
 * one line (the same on every rank). */
int ckpt_read_all(const char *path, ckpt_header *c, double **xy, char *err, size_t errlen);

#endif
