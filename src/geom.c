/* geom.c - see geom.h. The solver's source is solver_impl.h, shared with
 * the device build. */
#include "geom.h"

#include "solver_impl.h"

double cfpo_min_dist2(double cx, double cy, const double *yx, const double *yy, int m, int skip)
{
    return cfpo_min_dist2_hd(cx, cy, yx, yy, m, skip);
}

double cfpo_local_solve(const double *yx, const double *yy, int m, int skip, cfpo_square S,
                        double hx, double hy, double floor2, double *cx, double *cy,
                        double *scratch)
{
    return cfpo_local_solve_hd(yx, yy, m, skip, S, hx, hy, floor2, cx, cy, scratch);
}
