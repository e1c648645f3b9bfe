/* bigmem.h - layer 0: large temporary arrays mapped from the system, not
 * taken from malloc.
 *
 * Owns: cfpo_map_bytes / cfpo_unmap_bytes, for work arrays of a few
 * megabytes that live only while the start is made. Freeing such a block
 * taken from glibc's malloc raises malloc's threshold for mapping later
 * large blocks (its dynamic mmap threshold), and the engine's arrays
 * taken after the start then came from the heap: at 1,048,576 points the
 * run's peak rose from 85.7 to 92.0 bytes a point
 * (docs/results/2026-11-29-imprint11.md). Mapped blocks leave malloc's
 * state as it was.
 * May include: the C library and POSIX only. */
#ifndef CFPO_BIGMEM_H
#define CFPO_BIGMEM_H

#include <stddef.h>
#include <sys/mman.h>

/* A zeroed block of `bytes` (at least one), or NULL. */
static inline void *cfpo_map_bytes(size_t bytes)
{
    void *p = mmap(NULL, bytes ? bytes : 1, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    return p == MAP_FAILED ? NULL : p;
}

/* Returns a block of cfpo_map_bytes(bytes); NULL is ignored. */
static inline void cfpo_unmap_bytes(void *p, size_t bytes)
{
    if (p) munmap(p, bytes ? bytes : 1);
}

#endif
