/* tiles.c - see tiles.h. */
#include "tiles.h"

#include <stdio.h>

int64_t cfpo_tiling_max_ranks(int64_t g)
{
    int64_t per = g / CFPO_TILE_MIN;
    return per * per;
}

int cfpo_tiling_init(cfpo_tiling *T, int64_t g, int P, int force_px, int force_py, char *err,
                     size_t errlen)
{
    T->g = g;
    if (P < 1) {
        snprintf(err, errlen, "rank count %d must be at least 1", P);
        return -1;
    }
    int px = force_px, py = force_py;
    if (px > 0 || py > 0) {
        if (px <= 0 || py <= 0 || (int64_t)px * py != P) {
            snprintf(err, errlen, "--tiles %dx%d does not give one tile to each of %d ranks", px, py, P);
            return -1;
        }
    } else {
        /* The factor pair closest to square (the shortest tile boundary)
         * among those that keep tiles large enough; px <= py. */
        int64_t per = g / CFPO_TILE_MIN;
        px = 0;
        for (int a = 1; (int64_t)a * a <= P; a++)
            if (P % a == 0 && a <= per && P / a <= per) px = a;
        if (px == 0) {
            snprintf(err, errlen, "tiles too small: %d ranks on a %lldx%lld grid leave tiles under "
                     "%dx%d cells; use at most %lld ranks for this n (a count whose factors are "
                     "both at most %lld)", P, (long long)g, (long long)g, CFPO_TILE_MIN,
                     CFPO_TILE_MIN, (long long)cfpo_tiling_max_ranks(g), (long long)per);
            return -1;
        }
        py = P / px;
    }
    int64_t per = g / CFPO_TILE_MIN;
    if (px > per || py > per) {
        int64_t maxr = cfpo_tiling_max_ranks(g);
        snprintf(err, errlen, "tiles too small: a %lldx%lld grid cut %dx%d leaves tiles under "
                 "%dx%d cells; use at most %lld tiles per side (%lld ranks) for this n",
                 (long long)g, (long long)g, px, py, CFPO_TILE_MIN, CFPO_TILE_MIN, (long long)per,
                 (long long)maxr);
        return -1;
    }
    T->px = px;
    T->py = py;
    return 0;
}
