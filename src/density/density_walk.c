/* density_walk.c - see density_walk.h. */
#include "density_walk.h"

#include <math.h>

/* The first grid line m / s strictly ahead of v0 going the way of dv, as
 * the parameter t; the line's index in *m. */
static double first_cross(double v0, double dv, double s, int64_t *m)
{
    if (dv == 0) return INFINITY;
    *m = dv > 0 ? (int64_t)floor(v0 * s) + 1 : (int64_t)ceil(v0 * s) - 1;
    return ((double)*m / s - v0) / dv;
}

void cfpo_density_walk(const cfpo_density *d, double x0, double y0, double dx, double dy, cfpo_pixel_piece_fn fn,
                       void *ctx)
{
    const double sw = (double)d->w, sh = (double)d->h;
    int64_t mx = 0, my = 0;
    double tx = first_cross(x0, dx, sw, &mx), ty = first_cross(y0, dy, sh, &my), tc = 0;
    const int64_t sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
    while (tc < 1) {
        double tn = tx < ty ? tx : ty;
        if (tn > 1) tn = 1;
        if (tn > tc) {
            const double tm = 0.5 * (tc + tn);
            fn(ctx, tc, tn, (int64_t)floor((x0 + tm * dx) * sw), (int64_t)floor((y0 + tm * dy) * sh));
        }
        if (tx <= tn) {
            mx += sx;
            tx = ((double)mx / sw - x0) / dx;
        }
        if (ty <= tn) {
            my += sy;
            ty = ((double)my / sh - y0) / dy;
        }
        tc = tn;
    }
}
