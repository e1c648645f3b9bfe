/* testutil.h - the closing line every test prints, "N passed, N failed",
 * and the exit code that goes with it; the brute-force tests' distance on
 * the unit torus. */
#ifndef CFPO_TESTUTIL_H
#define CFPO_TESTUTIL_H
#include <math.h>
#include <stdio.h>
/* The distance of the points a and b (x, y) on the unit torus. */
static inline double tu_torus_dist(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    if (dx > 0.5) dx = 1 - dx;
    if (dy > 0.5) dy = 1 - dy;
    return sqrt(dx * dx + dy * dy);
}
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
