/* power_brute.h - the BNOT tests' brute force: the power cell that holds a
 * sample point, by trying every site and its eight periodic copies. */
#ifndef CFPO_BASELINES_POWER_BRUTE_H
#define CFPO_BASELINES_POWER_BRUTE_H

#include <math.h>
#include <stdint.h>

/* The site i of n (positions p, weights w) whose copy is nearest to (x, y)
 * in the power distance |x - c|^2 - w_i; (x, y) moved by the copy's offset
 * into *bx, *by (the sample in the frame of the site itself). */
static inline int64_t power_cell_brute(const double *p, const double *w, int64_t n, double x, double y, double *bx,
                                       double *by)
{
    double best = HUGE_VAL;
    int64_t bi = -1;
    *bx = *by = 0;
    for (int64_t i = 0; i < n; i++)
        for (int oy = -1; oy <= 1; oy++)
            for (int ox = -1; ox <= 1; ox++) {
                const double cx = p[2 * i] + ox, cy = p[2 * i + 1] + oy;
                const double d = (x - cx) * (x - cx) + (y - cy) * (y - cy) - w[i];
                if (d < best) { best = d; bi = i; *bx = x - ox; *by = y - oy; }
            }
    return bi;
}

#endif
