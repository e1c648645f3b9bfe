/* rng.h - layer 0 (includes nothing of the project): counter-based random
 * numbers.
 *
 * Every random number is a pure function of (seed, stream, counter): no
 * shared generator state, so the numbers a cell gets do not depend on how
 * many threads or ranks run or in what order. The mixer is SplitMix64's
 * finaliser (a bijection with full avalanche), applied to a combination of
 * the three keys. Also a keyed permutation of [0, N) (a Feistel network with
 * cycle walking), used to choose random distinct cells without a shuffle. */
#ifndef CFPO_RNG_H
#define CFPO_RNG_H

#include <stdint.h>

static inline uint64_t cfpo_mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static inline uint64_t cfpo_rand64(uint64_t seed, uint64_t stream, uint64_t counter)
{
    return cfpo_mix64(cfpo_mix64(cfpo_mix64(seed) ^ stream) ^ counter);
}

/* Uniform double in [0, 1) with 53 random bits. */
static inline double cfpo_rand01(uint64_t seed, uint64_t stream, uint64_t counter)
{
    return (double)(cfpo_rand64(seed, stream, counter) >> 11) * 0x1.0p-53;
}

/* A bijection of [0, N) keyed by `key`, N >= 1. */
static inline uint64_t cfpo_permute(uint64_t v, uint64_t N, uint64_t key)
{
    if (N <= 1) return 0;
    int bits = 64 - __builtin_clzll(N - 1);
    if (bits & 1) bits++;
    const int half = bits / 2;
    const uint64_t mask = (1ULL << half) - 1;
    do { /* cycle walking: repeat until the image falls inside [0, N) */
        uint64_t l = v >> half, r = v & mask;
        for (uint64_t round = 0; round < 4; round++) {
            uint64_t f = cfpo_mix64(key ^ (round << 56) ^ r) & mask;
            uint64_t t = l ^ f;
            l = r;
            r = t;
        }
        v = (l << half) | r;
    } while (v >= N);
    return v;
}

#endif
