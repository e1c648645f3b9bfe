/* ptree_sets.h - the point sets that test_ptree and test_pwalk check the
 * point tree on (ptree.c): uniform, clusters of 1e-3 and 1e-9 (against
 * the edge y = 0), horizontal, vertical and diagonal lines, points on the
 * torus's edge, a 20 x 20 lattice (ties), 300 copies of each of two
 * positions, and 240 + 360. */
#ifndef AN_TEST_PTREE_SETS_H
#define AN_TEST_PTREE_SETS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "rng.h"

enum { UNIFORM, CLUSTER3, CLUSTER9, HLINE, VLINE, DIAG, EDGE, LATTICE, COPIES, UNEVEN, KINDS };

static const char *const ptree_set_names[KINDS] = {"uniform",         "1e-3 cluster",  "1e-9 cluster",
                                                   "horizontal line", "vertical line", "diagonal line",
                                                   "torus edge",      "20x20 lattice", "300 + 300 copies",
                                                   "240 + 360 copies"};

/* The sizes tried: every one for the uniform set, 500 for the others (a
 * few at 3,000 too; some sets have their own size). */
static const size_t ptree_set_sizes[] = {1, 2, 9, 500, 3000};
#define PTREE_SET_SIZES (sizeof ptree_set_sizes / sizeof ptree_set_sizes[0])

static inline int ptree_set_tried(int kind, size_t size)
{
    return kind == UNIFORM || size == 500 || (size == 3000 && (kind == CLUSTER9 || kind == DIAG));
}

/* Set `kind` of about n points into xy; returns its n. */
static inline size_t ptree_set_make(int kind, size_t n, double *xy, uint64_t seed)
{
    static const double ev[] = {0, 0x1p-1074, 1e-300, 1e-17, 0.5, 1 - 1e-12, 1 - 0x1p-53};
    const size_t ne = sizeof ev / sizeof ev[0];
    if (kind == EDGE) n = ne * ne;
    if (kind == LATTICE) n = 400;
    if (kind == COPIES || kind == UNEVEN) n = 600;
    for (size_t i = 0; i < n; i++) {
        const double u = cfpo_rand01(seed, (uint64_t)kind, 2 * i), v = cfpo_rand01(seed, (uint64_t)kind, 2 * i + 1);
        double x = u, y = v;
        switch (kind) {
        case CLUSTER3: x = 0.3 + 1e-3 * u; y = 0.6 + 1e-3 * v; break;
        case CLUSTER9: x = 0.5 + 1e-9 * u; y = 1e-9 * v; break; /* against the edge y = 0 */
        case HLINE: y = 0.25; break;
        case VLINE: x = 0.75; break;
        case DIAG: y = u; break;
        case EDGE: x = ev[i % ne]; y = ev[i / ne]; break;
        case LATTICE: x = (double)(i % 20) / 20; y = (double)(i / 20) / 20; break;
        case COPIES: x = i % 2 ? 0.75 : 0.125; y = i % 2 ? 0.5 : 1 - 0x1p-53; break;
        case UNEVEN: x = i % 5 < 2 ? 0.375 : 0.9; y = i % 5 < 2 ? 0.0 : 0.4; break;
        default: break;
        }
        xy[2 * i] = x;
        xy[2 * i + 1] = y;
    }
    return n;
}

/* Calls fn on every set tried, named in `what` (xy: room for 3,000). */
static inline void ptree_sets_each(double *xy, void (*fn)(const char *what, const double *xy, size_t n, int kind))
{
    char what[96];
    for (int kind = 0; kind < KINDS; kind++)
        for (size_t s = 0; s < PTREE_SET_SIZES; s++) {
            if (!ptree_set_tried(kind, ptree_set_sizes[s])) continue;
            const size_t n = ptree_set_make(kind, ptree_set_sizes[s], xy, 21 + s);
            snprintf(what, sizeof what, "%s, n = %zu", ptree_set_names[kind], n);
            fn(what, xy, n, kind);
        }
}

#endif
