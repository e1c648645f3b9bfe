/* sobol.c - see sobol.h. */
#include "sobol.h"

#include "rng.h"

static const uint64_t STREAM_X = 0x534f424f4c2d5800ULL, STREAM_Y = 0x534f424f4c2d5900ULL,
                      STREAM_TAIL = 0x534f424f4c2d5400ULL; /* "SOBOL-X", "-Y", "-T" */

void sobol_point(uint32_t i, uint32_t *x, uint32_t *y)
{
    /* Direction numbers of the second coordinate (polynomial x + 1, m1 = 1):
     * v_0 = 1/2, v_k = v_{k-1} xor (v_{k-1} >> 1), the columns of the
     * Pascal matrix mod 2. The first coordinate has v_k = 2^-(k+1). */
    uint32_t vx = 1u << 31, vy = 1u << 31, ax = 0, ay = 0;
    for (int k = 0; k < 32; k++) {
        if ((i >> k) & 1u) {
            ax ^= vx;
            ay ^= vy;
        }
        vx >>= 1;
        vy ^= vy >> 1;
    }
    *x = ax;
    *y = ay;
}

uint32_t sobol_owen(uint32_t v, uint64_t seed, int dim)
{
    const uint64_t stream = dim ? STREAM_Y : STREAM_X;
    uint32_t out = 0;
    for (int j = 0; j < 32; j++) {
        /* the node: level j and the j leading digits of v, as the heap
         * index 2^j + prefix (unique over all levels) */
        const uint64_t prefix = j ? (uint64_t)(v >> (32 - j)) : 0;
        const uint64_t node = ((uint64_t)1 << j) | prefix;
        const uint32_t flip = (uint32_t)(cfpo_rand64(seed, stream, node) >> 63);
        out |= ((((v >> (31 - j)) & 1u) ^ flip) << (31 - j));
    }
    return out;
}

void sobol_points(int64_t n, uint64_t seed, int scramble, double *xy)
{
    for (int64_t i = 0; i < n; i++) {
        uint32_t x, y;
        sobol_point((uint32_t)i, &x, &y);
        if (!scramble) {
            xy[2 * i] = (double)x * 0x1.0p-32;
            xy[2 * i + 1] = (double)y * 0x1.0p-32;
            continue;
        }
        x = sobol_owen(x, seed, 0);
        y = sobol_owen(y, seed, 1);
        /* the tail: 21 uniform digits below the 32 scrambled ones */
        const uint64_t tx = cfpo_rand64(seed, STREAM_TAIL, 2 * (uint64_t)i) >> 43;
        const uint64_t ty = cfpo_rand64(seed, STREAM_TAIL, 2 * (uint64_t)i + 1) >> 43;
        xy[2 * i] = (double)(((uint64_t)x << 21) | tx) * 0x1.0p-53;
        xy[2 * i + 1] = (double)(((uint64_t)y << 21) | ty) * 0x1.0p-53;
    }
}
