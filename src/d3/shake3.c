/* shake3.c - see shake3.h. */
#include "shake3.h"

#include <math.h>

#include "rng.h"
#include "solve3.h"

/* the random stream of the shakes: "SHAKE3" with the round in the low bits */
#define SHAKE3_STREAM 0x534841b4b4533000ULL

void cfpo3_shake(double *xyz, int64_t n, uint64_t seed, int round, double amp)
{
    const double a = amp * cfpo3_delta_bound((double)n);
    const uint64_t stream = SHAKE3_STREAM ^ (uint64_t)round;
    for (int64_t i = 0; i < 3 * n; i++) {
        double x = xyz[i] + a * (2.0 * cfpo_rand01(seed, stream, (uint64_t)i) - 1.0);
        x -= floor(x);
        xyz[i] = x < 1.0 ? x : 0.0; /* (a tiny negative x rounds to 1) */
    }
}
