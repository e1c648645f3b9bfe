/* pmj.h - progressive multi-jittered (0,2) sample sequences, pmj02 and its
 * blue-noise variant pmj02bn (Christensen, Kensler and Kilpatrick,
 * "Progressive Multi-Jittered Sample Sequences", EGSR 2018), on the unit
 * square, which is the unit torus here (the blue-noise variant measures
 * distances periodically).
 *
 * Owns: the sequence's construction as the paper describes it. Point 0 is
 * uniform. With N = 4^m points placed (a (0,2m,2)-net, one point in each
 * cell of the 2^m x 2^m grid), the even step places point N + i in the
 * subquadrant of point i's cell diagonally opposite point i's own, for
 * i = 0..N-1; the odd step places points 2N + i and 3N + i in the two
 * subquadrants of that cell still empty (which one first: random). Each
 * new point of the step towards M = 2^k points lies in an elementary
 * interval of area 2^-k of every shape 2^-a x 2^-(k-a), a = 0..k, that no
 * earlier point occupies, so every prefix of 2^k points is a (0,k,2)-net.
 * Inside a subquadrant (an aligned box whose top f digits of x and y are
 * fixed, k <= 2f) the valid positions are a product: the shapes a >= k - f
 * depend on x alone, the shapes a <= f on y alone; both sets of valid
 * k-digit strata are found by descending the digit tree, pruning an
 * occupied interval at its first digit. A point is uniform in a valid fine
 * cell of side 2^-k (53 random bits a coordinate). pmj02 draws one such
 * candidate; pmj02bn draws `candidates` of them and keeps the one farthest
 * (periodic distance) from every earlier point (Mitchell's best candidate),
 * in the odd step over both free subquadrants.
 * A derived fact that bounds what the best candidate can do: the first
 * 2^(k-1) points hold one point in every elementary interval of area
 * 2^-(k-1), and two sibling intervals of area 2^-k (halves of one such
 * interval) hold one old point between them; so inside a subquadrant the
 * digit tree leaves at most one valid x stratum and one valid y stratum of
 * width 2^-k, and the candidates differ only inside one cell of side 2^-k
 * (and, in the odd step, in the subquadrant). `global` instead draws the
 * candidates from every subquadrant with a valid position (a list of the
 * subquadrants whose fixed shapes are free, kept as points fill them): not
 * the paper's order, tried as the widest choice the strata allow.
 * A step that meets a subquadrant with no valid position (a dead end of
 * the random choices) is redone with other random numbers (at most
 * PMJ_RETRIES times; the count is reported).
 * Does not own: the run loop, files (bl_pmj.c, bl_cli.c). */
#ifndef CFPO_BASELINES_PMJ_H
#define CFPO_BASELINES_PMJ_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PMJ_CANDIDATES 100 /* pmj02bn's default candidates a point */
#define PMJ_RETRIES 64     /* attempts of one step before giving up */
#define PMJ_MAX_CANDIDATES 100000
#define PMJ_MAX_N ((int64_t)1 << 26) /* its strata take (k + 1) 2^k bytes */

/* The first n points (x0 y0 x1 y1 ...) into xy, candidates = 1 for pmj02,
 * more for pmj02bn. *redone (may be NULL) receives the number of steps
 * redone after a dead end. 0, or -1 with a message (out of memory, n out
 * of 1..PMJ_MAX_N, a step stuck PMJ_RETRIES times). */
typedef struct {
    int candidates; /* 1: pmj02; more: the best of that many (pmj02bn) */
    int global;     /* candidates from every valid subquadrant, not only the
                     * one the progressive order names */
} pmj_params;

int pmj_points(int64_t n, uint64_t seed, const pmj_params *p, double *xy, int *redone, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
