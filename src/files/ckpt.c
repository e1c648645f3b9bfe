/* ckpt.c - see ckpt.h. */
#include "ckpt.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <zlib.h>

#include "bytes_le.h"
#include "cfpo_types.h"
#include "grid.h"
#include "policy.h"

#define MAGIC_V2 "CFPOCKPT"
#define MAGIC_V1 "CFPOCKP1"


static int known_variant(uint64_t v)
{
    return v == CFPO_VARIANT_PAPER || v == CFPO_VARIANT_SIMPLIFIED || v == CFPO_VARIANT_ADAPTIVE ||
           v == CFPO_VARIANT_HYPERUNIFORM;
}

int ckpt_decode(const char *path, const unsigned char *h, uint64_t size, ckpt_header *c, char *err,
                size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->bytes = CKPT_HEADER_V3;
    if (size < CKPT_HEADER_V3) {
        snprintf(err, errlen, "%s: not a cfpo checkpoint (%llu bytes, shorter than its 64-byte header)", path,
                 (unsigned long long)size);
        return -1;
    }
    if (memcmp(h, "CFPODENS", 8) == 0) {
        snprintf(err, errlen, "%s: a density checkpoint of cfpo 0.1.0 before its one checkpoint format; this "
                 "cfpo does not read it (run again from --init with its points, or with the older cfpo)", path);
        return -1;
    }
    uint64_t variant, converged, n;
    if (memcmp(h, MAGIC_V2, 8) == 0) {
        c->version = (int)le_get32(h + 8);
        if (le_get32(h + 8) != 2 && le_get32(h + 8) != 3 && le_get32(h + 8) != CKPT_VERSION) {
            snprintf(err, errlen, "%s: checkpoint version %lu is not one this cfpo reads (1 to 4)", path,
                     (unsigned long)le_get32(h + 8));
            return -1;
        }
        c->bytes = c->version == CKPT_VERSION ? CKPT_HEADER : CKPT_HEADER_V3;
        if (le_get32(h + 12) != (uint32_t)c->bytes) {
            snprintf(err, errlen, "%s: corrupt checkpoint: header size field %lu, expected %d", path,
                     (unsigned long)le_get32(h + 12), c->bytes);
            return -1;
        }
        if (size < (uint64_t)c->bytes) {
            snprintf(err, errlen, "%s: not a cfpo checkpoint (%llu bytes, shorter than its %d-byte header)", path,
                     (unsigned long long)size, c->bytes);
            return -1;
        }
        if (c->version == CKPT_VERSION) {
            c->hash = le_get64(h + 64);
            const uint64_t rb = le_get64(h + 72);
            memcpy(&c->davg_ref, &rb, 8);
            if (!(c->davg_ref >= 0 && c->davg_ref < 2) || (c->hash == 0 && c->davg_ref != 0)) {
                snprintf(err, errlen, "%s: corrupt checkpoint: field davg_ref = %g is not in [0, 2)%s", path,
                         c->davg_ref, c->hash == 0 ? " and 0 without a density" : "");
                return -1;
            }
        }
        n = le_get64(h + 16);
        c->seed = le_get64(h + 24);
        variant = le_get32(h + 32);
        converged = le_get32(h + 36);
        uint64_t tb = le_get64(h + 40);
        memcpy(&c->tol, &tb, 8);
        c->iteration = (int64_t)(le_get64(h + 48) > CKPT_ITER_MAX ? -1 : (int64_t)le_get64(h + 48));
        const uint32_t near = le_get32(h + 56);
        if (c->version == 2 && near != 0) {
            snprintf(err, errlen, "%s: corrupt version-2 checkpoint: reserved field is not zero", path);
            return -1;
        }
        if (near > 1) {
            snprintf(err, errlen, "%s: corrupt checkpoint: field near = %lu is not 0 or 1", path,
                     (unsigned long)near);
            return -1;
        }
        c->near = (int)near;
        c->crc = le_get32(h + 60);
    } else if (memcmp(h, MAGIC_V1, 8) == 0) {
        c->version = 1;
        n = le_get64(h + 8);
        c->seed = le_get64(h + 16);
        variant = le_get64(h + 24);
        uint64_t tb = le_get64(h + 32);
        memcpy(&c->tol, &tb, 8);
        c->iteration = (int64_t)(le_get64(h + 40) > CKPT_ITER_MAX ? -1 : (int64_t)le_get64(h + 40));
        converged = le_get64(h + 48);
        if (le_get64(h + 56) != 0) {
            snprintf(err, errlen, "%s: corrupt version-1 checkpoint: reserved field is not zero", path);
            return -1;
        }
    } else {
        snprintf(err, errlen, "%s: not a cfpo checkpoint (bad magic)", path);
        return -1;
    }
    if (!known_variant(variant)) {
        snprintf(err, errlen, "%s: corrupt checkpoint: field variant = %llu is not 0, 1 or 2", path,
                 (unsigned long long)variant);
        return -1;
    }
    c->variant = (int)variant;
    if (converged > 1) {
        snprintf(err, errlen, "%s: corrupt checkpoint: field converged = %llu is not 0 or 1", path,
                 (unsigned long long)converged);
        return -1;
    }
    c->converged = (int)converged;
    if (c->near && (c->converged || !cfpo_policy_starts_near(c->variant))) {
        snprintf(err, errlen, "%s: corrupt checkpoint: field near = 1 with %s", path,
                 c->converged ? "converged = 1" : "a variant that has no near phase");
        return -1;
    }
    if (!(c->tol >= 0 && c->tol <= CFPO_TOL_MAX)) {
        snprintf(err, errlen, "%s: corrupt checkpoint: field tol = %g is outside [0, %g]", path, c->tol,
                 CFPO_TOL_MAX);
        return -1;
    }
    if (c->iteration < 0) {
        snprintf(err, errlen, "%s: corrupt checkpoint: field iteration is outside [0, 1e9]", path);
        return -1;
    }
    const int64_t nmin = cfpo_grid_min_n(c->variant);
    const uint64_t hb = (uint64_t)c->bytes;
    if (n < (uint64_t)nmin || n > (size - hb) / 16) {
        if (n < (uint64_t)nmin)
            snprintf(err, errlen, "%s: corrupt checkpoint: field n = %llu is below the smallest n of variant %s (%lld)",
                     path, (unsigned long long)n, c->variant == CFPO_VARIANT_SIMPLIFIED ? "simplified" : c->variant == CFPO_VARIANT_PAPER ? "paper" : c->variant == CFPO_VARIANT_HYPERUNIFORM ? "hyperuniform" : "adaptive", (long long)nmin);
        else
            snprintf(err, errlen, "%s: checkpoint field n = %llu needs %llu bytes or more, file has %llu (truncated?)",
                     path, (unsigned long long)n, (unsigned long long)n < UINT64_MAX / 16 - 4 ?
                     (unsigned long long)(hb + 16 * n) : (unsigned long long)UINT64_MAX,
                     (unsigned long long)size);
        return -1;
    }
    c->n = (int64_t)n;
    if (size != hb + 16 * n) {
        snprintf(err, errlen, "%s: checkpoint of %llu points should be %llu bytes, file has %llu (trailing data)",
                 path, (unsigned long long)n, (unsigned long long)(hb + 16 * n), (unsigned long long)size);
        return -1;
    }
    return 0;
}

void ckpt_encode(const ckpt_header *c, unsigned char *h)
{
    memset(h, 0, CKPT_HEADER);
    memcpy(h, MAGIC_V2, 8);
    le_put32(h + 8, CKPT_VERSION);
    le_put32(h + 12, CKPT_HEADER);
    le_put64(h + 16, (uint64_t)c->n);
    le_put64(h + 24, c->seed);
    le_put32(h + 32, (uint32_t)c->variant);
    le_put32(h + 36, (uint32_t)c->converged);
    uint64_t tb;
    memcpy(&tb, &c->tol, 8);
    le_put64(h + 40, tb);
    le_put64(h + 48, (uint64_t)c->iteration);
    le_put32(h + 56, (uint32_t)c->near);
    le_put32(h + 60, c->crc);
    le_put64(h + 64, c->hash);
    uint64_t rb;
    memcpy(&rb, &c->davg_ref, 8);
    le_put64(h + 72, rb);
}

uint32_t ckpt_crc_header(const unsigned char *h, int bytes)
{
    unsigned char z[CKPT_HEADER];
    memcpy(z, h, (size_t)bytes);
    le_put32(z + 60, 0);
    return (uint32_t)crc32(crc32(0L, Z_NULL, 0), z, (uInt)bytes);
}

uint32_t ckpt_crc_more(uint32_t crc, const void *buf, size_t bytes)
{
    const unsigned char *p = buf;
    while (bytes) { /* zlib takes at most UINT_MAX bytes at once */
        uInt k = bytes > (1u << 30) ? (1u << 30) : (uInt)bytes;
        crc = (uint32_t)crc32(crc, p, k);
        p += k;
        bytes -= k;
    }
    return crc;
}

uint32_t ckpt_crc_join(uint32_t a, uint32_t b, uint64_t bbytes)
{
    return (uint32_t)crc32_combine(a, b, (z_off_t)bbytes);
}

int ckpt_check_buffer(const char *path, const unsigned char *buf, size_t len, ckpt_header *c, char *err,
                      size_t errlen)
{
    if (len < CKPT_HEADER_V3) return ckpt_decode(path, buf, len, c, err, errlen);
    if (ckpt_decode(path, buf, len, c, err, errlen) != 0) return -1;
    const size_t hb = (size_t)c->bytes;
    if (c->version >= 2) {
        uint32_t crc = ckpt_crc_more(ckpt_crc_header(buf, c->bytes), buf + hb, len - hb);
        if (crc != c->crc) {
            snprintf(err, errlen, "%s: corrupt checkpoint: checksum 0x%08lx does not match the contents (0x%08lx)",
                     path, (unsigned long)c->crc, (unsigned long)crc);
            return -1;
        }
    }
    for (int64_t i = 0; i < c->n; i++) {
        double v[2];
        for (int k = 0; k < 2; k++) {
            uint64_t u = le_get64(buf + hb + 16 * i + 8 * k);
            memcpy(&v[k], &u, 8);
        }
        if (!(v[0] >= 0 && v[0] < 1 && v[1] >= 0 && v[1] < 1)) {
            snprintf(err, errlen, "%s: corrupt checkpoint: point %lld at offset %llu is not in [0,1)^2", path,
                     (long long)i, (unsigned long long)(hb + 16 * (uint64_t)i));
            return -1;
        }
    }
    return 0;
}

int64_t ckpt_cell_bound(double L, double d)
{
    if (!(d > 0)) return INT64_MAX;
    double k = ceil(L * sqrt(2.0) / d) + 1;
    if (!(k < 3e9)) return INT64_MAX;
    return (int64_t)(k * k);
}
