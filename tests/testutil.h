/* testutil.h - the closing line every test prints, "N passed, N failed",
 * and the exit code that goes with it. */
#ifndef CFPO_TESTUTIL_H
#define CFPO_TESTUTIL_H
#include <stdio.h>
static inline int test_report(int passed, int failed)
{
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
#define CHECK(cond, ...)                                                          \
    do {                                                                          \
        if (cond) passed_++;                                                      \
        else { failed_++; fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);    \
               fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); }               \
    } while (0)
#endif
