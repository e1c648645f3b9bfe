/* fuzz_numbers.c - libFuzzer harness: the number parser of every command
 * (cli_parse_i64 / cli_parse_u64 / cli_parse_double). Properties checked
 * on every input: no accepted string holds a sign (except an exponent's),
 * a space, an 'x' or 'n' (hex, inf, nan); a whole number accepted by both
 * integer parsers has the same value; a plain run of digits reads as
 * strtoull reads it in base 10; accepted reals are finite and in range. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 256) return 0;
    char s[257];
    memcpy(s, data, size);
    s[size] = '\0';
    int64_t i;
    uint64_t u;
    double d;
    const int ri = cli_parse_i64(s, 0, INT64_MAX, &i);
    const int ru = cli_parse_u64(s, &u);
    const int rd = cli_parse_double(s, 0, 1e300, &d);
    const size_t len = strlen(s);
    if (ri == 0 || ru == 0 || rd == 0) {
        if (len == 0 || strpbrk(s, " \t\nxXnNiI") || s[0] == '-' || s[0] == '+') abort();
    }
    if (ri == 0 && (ru != 0 || (uint64_t)i != u)) abort();
    if (ri == 0 && i < 0) abort();
    if (ru == 0 && strspn(s, "0123456789") == len) {
        errno = 0;
        unsigned long long v = strtoull(s, NULL, 10);
        if (errno || v != u) abort();
    }
    if (rd == 0 && (!isfinite(d) || d < 0 || d > 1e300)) abort();
    return 0;
}
