/* lloyd3.c - Lloyd's algorithm (Lloyd 1982) on the unit 3-torus, the
 * command cfpo3d-lloyd (bl3.h): every iteration moves each point to the
 * centroid of its Voronoi cell (measures3_vor.h: CGAL's periodic 3-D
 * Delaunay triangulation, rebuilt each iteration), all points at once.
 * Start: n uniform points (stream LLOYD3). Converged when no point moves
 * tol * L (L the cell side of cfpo3d's grid for this n); the stop rules of
 * the iterative baselines. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl3.h"
#include "grid3.h"
#include "measures3_vor.h"
#include "nn3.h"
#include "rng.h"

#define LLOYD3_STREAM 0x4c4c4f5944ULL /* "LLOYD" */

static int run_lloyd(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                     int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    const double tol = opt[0];
    cfpo3_grid G;
    if (cfpo3_grid_choose(n, &G, err, errlen) != 0) return -1;
    double *p = malloc(3 * (size_t)n * sizeof *p), *c = malloc(3 * (size_t)n * sizeof *c);
    if (!p || !c) {
        free(p), free(c);
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        return -1;
    }
    for (size_t i = 0; i < 3 * (size_t)n; i++) p[i] = cfpo_rand01(seed, LLOYD3_STREAM, i);
    cfpo_iter_stats s = {0};
    int why = CFPO_STOP_NONE, it = 0;
    for (;;) {
        s.iteration = it;
        if (cfpo3_nn_stats(p, (size_t)n, NULL, &s.delta_min, &s.delta_avg) != 0) {
            snprintf(err, errlen, "out of memory");
            goto fail;
        }
        if ((why = cb(user, &s)) != CFPO_STOP_NONE) break;
        if (cfpo3_voronoi(p, (size_t)n, NULL, NULL, c, err, errlen) != 0) goto fail;
        double md = 0;
        for (int64_t i = 0; i < n; i++) {
            const double dx = cfpo3_pdiff(c[3 * i], p[3 * i]), dy = cfpo3_pdiff(c[3 * i + 1], p[3 * i + 1]),
                         dz = cfpo3_pdiff(c[3 * i + 2], p[3 * i + 2]);
            md = fmax(md, dx * dx + dy * dy + dz * dz);
        }
        memcpy(p, c, 3 * (size_t)n * sizeof *p);
        s.moved = n;
        s.solved = n;
        s.max_disp = sqrt(md) / G.L;
        s.converged = cfpo_net_converged(s.moved, s.max_disp, tol);
        it++;
    }
    free(c);
    info->iterations = it;
    info->converged = s.converged;
    info->stop = cfpo_stop_name(why);
    *xyz = p;
    *n_out = n;
    return 0;
fail:
    free(p), free(c);
    return -1;
}

const bl3_method bl3_lloyd = {
    .name = "lloyd3d", .prog = "cfpo3d-lloyd", .min_n = 39, .run = run_lloyd, .iterative = 1, .noptions = 1,
    .options = {{"tol", CFPO_DEFAULT_TOL, 0, CFPO_TOL_MAX,
                 "      --tol T          converged when no point moves T * L, L = cfpo3d's cell side\n"
                 "                       (default %g)\n"}},
    .about = "Lloyd's algorithm (1982) on the unit 3-torus: each iteration moves every point to\n"
             "the centroid of its Voronoi cell (CGAL's periodic 3-D Delaunay triangulation).\n"
             "Iterative."};
