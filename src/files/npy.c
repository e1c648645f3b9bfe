/* npy.c - see npy.h. A small recursive-descent reader of the one dict
 * literal numpy writes; every byte of the header is accounted for. */
#include "npy.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define NPY_HEADER_MAX 10000 /* numpy's own limit (np.load max_header_size) */

typedef struct {
    const char *s;
    size_t i, len;
    const char *path;
    char *err;
    size_t errlen;
} lexer;

static int fail(lexer *L, const char *fmt, ...)
{
    char what[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(L->err, L->errlen, "%s: bad .npy header: %s (at header byte %zu)", L->path, what, L->i);
    return -1;
}

static void skip_ws(lexer *L)
{
    while (L->i < L->len && (L->s[L->i] == ' ' || L->s[L->i] == '\t' || L->s[L->i] == '\n' || L->s[L->i] == '\r'))
        L->i++;
}

static int peek(lexer *L) { return L->i < L->len ? (unsigned char)L->s[L->i] : -1; }

static int expect(lexer *L, char c)
{
    skip_ws(L);
    if (peek(L) != (unsigned char)c) return fail(L, "expected '%c'", c);
    L->i++;
    return 0;
}

/* A quoted string without escapes, into buf (NUL-terminated). */
static int string(lexer *L, char *buf, size_t cap)
{
    skip_ws(L);
    int q = peek(L);
    if (q != '\'' && q != '"') return fail(L, "expected a quoted string");
    size_t start = ++L->i, k = 0;
    while (L->i < L->len && L->s[L->i] != q) {
        unsigned char c = (unsigned char)L->s[L->i];
        if (c == '\\' || c < 0x20 || c > 0x7e) return fail(L, "unsupported character in a string");
        if (k + 1 < cap) buf[k++] = (char)c;
        else return fail(L, "string too long");
        L->i++;
    }
    if (L->i >= L->len) { L->i = start; return fail(L, "unterminated string"); }
    L->i++;
    buf[k] = '\0';
    /* 'a' 'b' is one string in Python: refused rather than misread. */
    skip_ws(L);
    if (peek(L) == '\'' || peek(L) == '"') return fail(L, "concatenated strings");
    return 0;
}

/* A name (True, False) ending at a delimiter. */
static int boolean(lexer *L, int *out)
{
    skip_ws(L);
    size_t k = L->i;
    while (k < L->len && ((L->s[k] >= 'a' && L->s[k] <= 'z') || (L->s[k] >= 'A' && L->s[k] <= 'Z') ||
                          (L->s[k] >= '0' && L->s[k] <= '9') || L->s[k] == '_'))
        k++;
    size_t w = k - L->i;
    if (w == 4 && memcmp(L->s + L->i, "True", 4) == 0) *out = 1;
    else if (w == 5 && memcmp(L->s + L->i, "False", 5) == 0) *out = 0;
    else return fail(L, "fortran_order is not True or False");
    L->i = k;
    return 0;
}

/* A non-negative decimal int as Python writes it: no sign, no leading
 * zero (except 0 itself), no underscore, no suffix. */
static int integer(lexer *L, uint64_t *out)
{
    skip_ws(L);
    size_t k = L->i;
    uint64_t v = 0;
    while (k < L->len && L->s[k] >= '0' && L->s[k] <= '9') {
        if (__builtin_mul_overflow(v, 10u, &v) || __builtin_add_overflow(v, (uint64_t)(L->s[k] - '0'), &v))
            return fail(L, "shape dimension too large");
        k++;
    }
    if (k == L->i) return fail(L, "shape dimension is not a non-negative integer");
    if (L->s[L->i] == '0' && k - L->i > 1) return fail(L, "shape dimension with a leading zero");
    if (k < L->len && ((L->s[k] >= 'a' && L->s[k] <= 'z') || (L->s[k] >= 'A' && L->s[k] <= 'Z') ||
                       L->s[k] == '_' || L->s[k] == '.'))
        return fail(L, "shape dimension is not a plain integer");
    L->i = k;
    *out = v;
    return 0;
}

static int shape(lexer *L, uint64_t dims[2], int *nd)
{
    skip_ws(L);
    if (peek(L) != '(') return fail(L, "shape is not a tuple");
    L->i++;
    *nd = 0;
    skip_ws(L);
    while (peek(L) != ')') {
        if (*nd == 2) return fail(L, "shape has more than two dimensions");
        if (integer(L, &dims[*nd]) != 0) return -1;
        (*nd)++;
        skip_ws(L);
        if (peek(L) == ',') { L->i++; skip_ws(L); }
        else if (peek(L) != ')') return fail(L, "expected ',' or ')' in shape");
    }
    L->i++;
    return 0;
}

static int descr(lexer *L, npy_info *info)
{
    char d[16];
    if (string(L, d, sizeof d) != 0) return -1;
    const char *p = d;
    const uint16_t one = 1;
    unsigned char host_le;
    memcpy(&host_le, &one, 1);
    int big = !host_le;
    if (*p == '<') { big = 0; p++; }
    else if (*p == '>') { big = 1; p++; }
    else if (*p == '=') p++;
    if (strcmp(p, "f8") == 0 || strcmp(p, "d") == 0) info->itemsize = 8;
    else if (strcmp(p, "f4") == 0 || strcmp(p, "f") == 0) info->itemsize = 4;
    else return fail(L, "descr '%s' is not float64 or float32", d);
    info->big_endian = big;
    return 0;
}

static int dict(lexer *L, npy_info *info, int any_cols)
{
    enum { DESCR = 1, FORTRAN = 2, SHAPE = 4 };
    int seen = 0;
    uint64_t dims[2] = {0, 0};
    int nd = 0;
    if (expect(L, '{') != 0) return -1;
    skip_ws(L);
    while (peek(L) != '}') {
        char key[32];
        if (string(L, key, sizeof key) != 0) return -1;
        int k = strcmp(key, "descr") == 0 ? DESCR : strcmp(key, "fortran_order") == 0 ? FORTRAN
              : strcmp(key, "shape") == 0 ? SHAPE : 0;
        if (!k) return fail(L, "unexpected key '%s'", key);
        if (seen & k) return fail(L, "key '%s' given twice", key);
        seen |= k;
        if (expect(L, ':') != 0) return -1;
        int rc = k == DESCR ? descr(L, info) : k == FORTRAN ? boolean(L, &info->fortran) : shape(L, dims, &nd);
        if (rc != 0) return -1;
        skip_ws(L);
        if (peek(L) == ',') { L->i++; skip_ws(L); }
        else if (peek(L) != '}') return fail(L, "expected ',' or '}'");
    }
    L->i++;
    if (seen != (DESCR | FORTRAN | SHAPE))
        return fail(L, "missing key '%s'", !(seen & DESCR) ? "descr" : !(seen & FORTRAN) ? "fortran_order" : "shape");
    skip_ws(L);
    if (L->i != L->len) return fail(L, "data after the closing brace");
    if (any_cols && nd == 2) {
        if (dims[0] > SIZE_MAX / 8 || dims[1] > SIZE_MAX / 8 || (dims[1] > 0 && dims[0] > SIZE_MAX / 8 / dims[1]))
            return fail(L, "shape too large");
        info->n = (size_t)dims[0];
        info->cols = (size_t)dims[1];
        return 0;
    }
    if (any_cols) {
        snprintf(L->err, L->errlen, "%s: .npy array has %d dimensions, not 2", L->path, nd);
        return -1;
    }
    if (nd != 2 || dims[1] != 2) {
        if (nd == 2) snprintf(L->err, L->errlen, "%s: .npy shape (%llu, %llu) is not (n, 2)", L->path,
                              (unsigned long long)dims[0], (unsigned long long)dims[1]);
        else if (nd == 1) snprintf(L->err, L->errlen, "%s: .npy shape (%llu) is not (n, 2)", L->path,
                                   (unsigned long long)dims[0]);
        else snprintf(L->err, L->errlen, "%s: .npy shape () is not (n, 2)", L->path);
        return -1;
    }
    if (dims[0] > SIZE_MAX / 16) return fail(L, "shape too large");
    info->n = (size_t)dims[0];
    info->cols = 2;
    return 0;
}

static int parse_header(const char *path, const unsigned char *buf, size_t len, npy_info *info, char *err,
                        size_t errlen, int any_cols)
{
    static const unsigned char magic[6] = {0x93, 'N', 'U', 'M', 'P', 'Y'};
    memset(info, 0, sizeof *info);
    if (len < 10 || memcmp(buf, magic, 6) != 0) {
        snprintf(err, errlen, "%s: not a NumPy .npy file (bad magic)", path);
        return -1;
    }
    const unsigned major = buf[6], minor = buf[7];
    if (major < 1 || major > 3 || minor != 0) {
        snprintf(err, errlen, "%s: unsupported .npy version %u.%u (1.0, 2.0 and 3.0 are read)", path, major, minor);
        return -1;
    }
    size_t hlen, hstart;
    if (major == 1) {
        hlen = (size_t)buf[8] | (size_t)buf[9] << 8;
        hstart = 10;
    } else {
        if (len < 12) { snprintf(err, errlen, "%s: truncated .npy header", path); return -1; }
        hlen = (size_t)buf[8] | (size_t)buf[9] << 8 | (size_t)buf[10] << 16 | (size_t)buf[11] << 24;
        hstart = 12;
    }
    if (hlen > NPY_HEADER_MAX) {
        snprintf(err, errlen, "%s: .npy header of %zu bytes is over numpy's limit of %d", path, hlen, NPY_HEADER_MAX);
        return -1;
    }
    if (hlen > len - hstart) {
        snprintf(err, errlen, "%s: truncated .npy header (%zu bytes announced, file has %zu)", path, hlen, len);
        return -1;
    }
    lexer L = {(const char *)buf + hstart, 0, hlen, path, err, errlen};
    /* ast.literal_eval strips leading spaces and tabs only. */
    while (L.i < L.len && (L.s[L.i] == ' ' || L.s[L.i] == '\t')) L.i++;
    if (peek(&L) != '{') return fail(&L, "not a dict");
    if (dict(&L, info, any_cols) != 0) return -1;
    info->data = hstart + hlen;
    return 0;
}

int npy_parse_header(const char *path, const unsigned char *buf, size_t len, npy_info *info, char *err,
                     size_t errlen)
{
    return parse_header(path, buf, len, info, err, errlen, 0);
}

int npy_parse_header_2d(const char *path, const unsigned char *buf, size_t len, npy_info *info, char *err,
                        size_t errlen)
{
    return parse_header(path, buf, len, info, err, errlen, 1);
}
