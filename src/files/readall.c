/* readall.c - see readall.h. */
#include "readall.h"

#include <stdio.h>
#include <stdlib.h>

readall_status readall(const char *path, size_t max, unsigned char **buf, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return READALL_OPEN;
    size_t cap = (size_t)1 << 16, n = 0;
    unsigned char *b = malloc(cap);
    readall_status st = b ? READALL_OK : READALL_MEMORY;
    while (st == READALL_OK) {
        if (n == cap) {
            unsigned char *nb = cap <= ((size_t)-1) / 2 ? realloc(b, cap * 2) : NULL;
            if (!nb) { st = READALL_MEMORY; break; }
            b = nb;
            cap *= 2;
        }
        const size_t got = fread(b + n, 1, cap - n, f);
        n += got;
        if (max > 0 && n > max) st = READALL_LARGE;
        else if (got == 0) break;
    }
    if (st == READALL_OK && ferror(f)) st = READALL_READ;
    fclose(f);
    if (st != READALL_OK) {
        free(b);
        return st;
    }
    *buf = b;
    *len = n;
    return READALL_OK;
}
