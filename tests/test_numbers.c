/* test_numbers.c - the one number grammar of every command (src/common/cli.c):
 * decimal only, no sign, no spaces, no hexadecimal or octal, exact power
 * forms, exact range limits, subnormal reals accepted. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "cli.h"
#include "testutil.h"

static int passed_, failed_;

static void whole(const char *s, int ok, int64_t want)
{
    int64_t v = -7;
    int rc = cli_parse_i64(s, 0, INT64_MAX, &v);
    if (ok) CHECK(rc == 0 && v == want, "i64 '%s': rc %d value %lld, want %lld", s, rc, (long long)v, (long long)want);
    else CHECK(rc != 0, "i64 '%s' accepted as %lld", s, (long long)v);
}

static void seed(const char *s, int ok, uint64_t want)
{
    uint64_t v = 7;
    int rc = cli_parse_u64(s, &v);
    if (ok) CHECK(rc == 0 && v == want, "u64 '%s': rc %d value %llu", s, rc, (unsigned long long)v);
    else CHECK(rc != 0, "u64 '%s' accepted as %llu", s, (unsigned long long)v);
}

static void real(const char *s, int ok, double want)
{
    double v = -7;
    int rc = cli_parse_double(s, 0, 1e300, &v);
    if (ok) CHECK(rc == 0 && v == want, "double '%s': rc %d value %g", s, rc, v);
    else CHECK(rc != 0, "double '%s' accepted as %g", s, v);
}

int main(void)
{
    /* whole numbers */
    whole("0", 1, 0);
    whole("65536", 1, 65536);
    whole("010", 1, 10); /* leading zeros are decimal, never octal */
    whole("08", 1, 8);
    whole("2^20", 1, 1048576);
    whole("2^0", 1, 1);
    whole("1e6", 1, 1000000);
    whole("1E6", 1, 1000000);
    whole("2.5e3", 1, 2500);
    whole("1.000e2", 1, 100);
    whole("9223372036854775807", 1, INT64_MAX);
    whole("2^62", 1, (int64_t)1 << 62);
    whole("9223372036854775808", 0, 0); /* 2^63 */
    whole("2^63", 0, 0);
    whole("2^65", 0, 0);
    whole("1e19", 0, 0);
    whole("1e400", 0, 0);
    whole("2^99999999999", 0, 0);
    whole("1^99999999999", 1, 1); /* no long loop either */
    whole("2.5e0", 0, 0);
    whole("1e6.5", 0, 0);
    whole("1.5", 0, 0);
    whole("", 0, 0);
    whole(NULL, 0, 0);
    whole("-2^4", 0, 0);
    whole("-5", 0, 0);
    whole("+100", 0, 0);
    whole(" 100", 0, 0);
    whole("100 ", 0, 0);
    whole("\t100", 0, 0);
    whole("0x100", 0, 0);
    whole("0X10", 0, 0);
    whole("1e-3", 0, 0);
    whole("1e+3", 0, 0);
    whole("2^-1", 0, 0);
    whole("2^", 0, 0);
    whole("^2", 0, 0);
    whole("2^2^2", 0, 0);
    whole("e6", 0, 0);
    whole("1e", 0, 0);
    whole(".5e1", 0, 0);
    whole("5.e1", 0, 0);
    whole("12abc", 0, 0);
    whole("inf", 0, 0);
    /* ranges */
    int64_t v;
    CHECK(cli_parse_i64("5", 6, 10, &v) != 0, "below lo accepted");
    CHECK(cli_parse_i64("11", 6, 10, &v) != 0, "above hi accepted");
    CHECK(cli_parse_i64("10", 6, 10, &v) == 0 && v == 10, "hi refused");
    /* seeds: the same grammar over [0, 2^64) */
    seed("010", 1, 10);
    seed("08", 1, 8);
    seed("18446744073709551615", 1, UINT64_MAX);
    seed("18446744073709551616", 0, 0);
    seed("1e19", 1, 10000000000000000000ull);
    seed("1e20", 0, 0);
    seed("2^63", 1, (uint64_t)1 << 63);
    seed("2^64", 0, 0);
    seed("0x10", 0, 0);
    seed("-1", 0, 0);
    seed("+1", 0, 0);
    seed(" 1", 0, 0);
    /* reals */
    real("0.25", 1, 0.25);
    real("3e-5", 1, 3e-5);
    real("1E-4", 1, 1e-4);
    real("1e+2", 1, 100);
    real(".5", 1, 0.5);
    real("5.", 1, 5.0);
    real("0", 1, 0);
    real("1e-320", 1, 1e-320); /* subnormal: representable */
    real("4.9e-324", 1, 4.9e-324);
    real("1e-400", 0, 0); /* underflows to zero */
    real("1e400", 0, 0);
    real("-0.1", 0, 0);
    real("+0.1", 0, 0);
    real(" 0.1", 0, 0);
    real("0.1 ", 0, 0);
    real("0x1p-3", 0, 0);
    real("inf", 0, 0);
    real("nan", 0, 0);
    real("infinity", 0, 0);
    real(".", 0, 0);
    real("e5", 0, 0);
    real("1e", 0, 0);
    real("1e+", 0, 0);
    real("", 0, 0);
    real(NULL, 0, 0);
    double d;
    CHECK(cli_parse_double("0.5", 0, 0.49, &d) != 0, "above hi accepted");
    return test_report(passed_, failed_);
}
