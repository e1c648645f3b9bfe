/* bytes_le.h - layer 0 (includes nothing of the project): the
 * little-endian fields of the checkpoint formats (src/files/ckpt.h,
 * src/d3/engine3_ckpt.c, src/d3/sched3.c), written and read byte by byte,
 * so a file is the same bytes on any host. */
#ifndef CFPO_BYTES_LE_H
#define CFPO_BYTES_LE_H

#include <stdint.h>
#include <string.h>

static inline void le_put32(unsigned char *b, uint32_t v)
{
    for (int i = 0; i < 4; i++) b[i] = (unsigned char)(v >> (8 * i));
}
static inline void le_put64(unsigned char *b, uint64_t v)
{
    for (int i = 0; i < 8; i++) b[i] = (unsigned char)(v >> (8 * i));
}
static inline uint32_t le_get32(const unsigned char *b)
{
    uint32_t v = 0;
    for (int i = 3; i >= 0; i--) v = v << 8 | b[i];
    return v;
}
static inline uint64_t le_get64(const unsigned char *b)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--) v = v << 8 | b[i];
    return v;
}
/* A double as the 64 bits of its IEEE 754 form. */
static inline void le_putd(unsigned char *b, double v)
{
    uint64_t u;
    memcpy(&u, &v, 8);
    le_put64(b, u);
}
static inline double le_getd(const unsigned char *b)
{
    const uint64_t u = le_get64(b);
    double v;
    memcpy(&v, &u, 8);
    return v;
}

#endif
