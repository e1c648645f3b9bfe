/* test_dens_qbound.c - the bound of q = sqrt(rho) over a box
 * (src/density/dens_qbound.c), on random boxes of random densities (odd
 * sizes, so the pyramid's levels have ragged edges), boxes that wrap
 * around the torus, tiny boxes and boxes wider than the torus:
 *  - it bounds q at every point of the box, read as the solve reads it
 *    (the torus point wrapped, then its pixel);
 *  - it is local: at most the largest q over the box widened by twice its
 *    span and eight pixels each side (brute force over the pixels, to the
 *    float rounding of the upper levels, 1e-6 relative; a
 *    level of the pyramid is chosen where the span covers at most two
 *    texels, each under twice the span plus three pixels), so it is
 *    not the global maximum in disguise;
 *  - the pyramid of minima (over the non-zero pixels) bounds q from
 *    below at every point of the box whose pixel is not zero, and is
 *    local in the same sense (at least the smallest non-zero q over the
 *    widened box, less the float rounding);
 *  - read two levels finer (cfpo_dens_qbound_box_finer), it is still a
 *    bound, never looser than the coarse one, and local within half the
 *    span and eight pixels each side;
 *  - a density whose q is flat within CFPO_QBOUND_FLAT answers every box
 *    with its global maximum (minimum), still a bound and within that
 *    ratio of the local one; one just past the ratio is answered locally. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "dens_qbound.h"
#include "dens_solve.h"
#include "density.h"
#include "testutil.h"

static int passed_, failed_;

static double urand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* The largest (lowest: the smallest non-zero) q over the pixels whose
 * centres lie within [x0, x1] x [y0, y1] widened by `grow` each side (the
 * torus: taken modulo 1). */
static double brute(const cfpo_density *d, double x0, double y0, double x1, double y1, double grow, int lowest)
{
    double m = lowest ? INFINITY : 0;
    for (int64_t j = 0; j < d->h; j++)
        for (int64_t i = 0; i < d->w; i++) {
            const double cx = (i + 0.5) / (double)d->w, cy = (j + 0.5) / (double)d->h;
            const double ux = cx - (x0 - grow) - floor(cx - (x0 - grow)), uy = cy - (y0 - grow) - floor(cy - (y0 - grow));
            const double q = sqrt(d->rho[j * d->w + i]);
            if (ux <= x1 - x0 + 2 * grow && uy <= y1 - y0 + 2 * grow && (lowest ? q > 0 && q < m : q > m)) m = q;
        }
    return m;
}

static void boxes(const cfpo_density *d, const char *what, unsigned long long seed, int count, int lowest, int flat)
{
    cfpo_dens_qbound b;
    if ((lowest ? cfpo_dens_qbound_build_min(&b, d) : cfpo_dens_qbound_build(&b, d)) != 0) {
        CHECK(0, "%s: out of memory", what);
        return;
    }
    int below = 0, loose = 0, global = 0, fbelow = 0, floose = 0, fwide = 0;
    const double px = 1.0 / (double)d->w, py = 1.0 / (double)d->h;
    for (int t = 0; t < count; t++) {
        const int kind = t % 4; /* 0 small, 1 tiny, 2 wide, 3 around an edge of the torus */
        const double sx = kind == 1 ? 1e-6 * urand(&seed) : kind == 2 ? 0.5 + urand(&seed) : 0.2 * urand(&seed);
        const double sy = kind == 1 ? 1e-6 * urand(&seed) : kind == 2 ? 0.3 * urand(&seed) : 0.2 * urand(&seed);
        double x0 = kind == 3 ? 1 - 0.5 * sx : 3 * urand(&seed) - 1, y0 = kind == 3 ? -0.5 * sy : 3 * urand(&seed) - 1;
        const double x1 = x0 + sx, y1 = y0 + sy;
        const double q = cfpo_dens_qbound_box(&b, x0, y0, x1, y1);
        const double qf = cfpo_dens_qbound_box_finer(&b, x0, y0, x1, y1, 2);
        for (int s = 0; s < 50; s++) {
            const double cx = x0 + (s == 0 ? 0 : s == 1 ? sx : urand(&seed) * sx);
            const double cy = y0 + (s == 0 ? 0 : s == 1 ? sy : urand(&seed) * sy);
            const double qc = cfpo_dens_local_q(d, 0, 0, cx, cy);
            if (lowest ? qc > 0 && qc < q : qc > q) below++;
            if (lowest ? qc > 0 && qc < qf : qc > qf) fbelow++;
        }
        /* two levels finer: a bound as well, never looser, and local
         * within half the span (texels under a quarter of the coarse
         * ones) */
        fwide += lowest ? qf < q : qf > q;
        const double growf = 0.5 * (sx > sy ? sx : sy) + 8 * (px > py ? px : py);
        const double nearf = brute(d, x0, y0, x1, y1, growf, lowest);
        if (!flat && (lowest ? qf < nearf / (1 + 1e-6) : qf > nearf * (1 + 1e-6))) floose++;
        const double grow = 2 * (sx > sy ? sx : sy) + 8 * (px > py ? px : py);
        const double near = brute(d, x0, y0, x1, y1, grow, lowest); /* levels above 0: floats rounded outward */
        const double tol = flat ? CFPO_QBOUND_FLAT : 1 + 1e-6;
        if (lowest ? q < near / tol : q > near * tol) loose++;
        global += lowest ? q <= sqrt(d->rho_min) : q >= sqrt(d->rho_max);
    }
    const char *side = lowest ? "below" : "above", *ext = lowest ? "minimum" : "maximum";
    CHECK(below == 0, "%s: %d points of a box on the wrong side of its %s bound", what, below, side);
    CHECK(loose == 0, "%s: %d %s bounds past the extreme q near the box", what, loose, side);
    CHECK(fbelow == 0, "%s: %d points of a box on the wrong side of its finer %s bound", what, fbelow, side);
    CHECK(fwide == 0, "%s: %d finer bounds looser than the coarse ones", what, fwide);
    CHECK(floose == 0, "%s: %d finer %s bounds past the extreme q within half the span", what, floose, side);
    if (flat)
        CHECK(global == count, "%s: flat, but %d of %d %s bounds not the global %s", what, count - global, count, side, ext);
    else
        CHECK(global < count, "%s: every %s bound is the global %s", what, side, ext);
    printf("%s: %d boxes, %d of them bounded by the global %s\n", what, count, global, ext);
    cfpo_dens_qbound_free(&b);
}

int main(void)
{
    unsigned long long seed = 99;
    const int64_t sizes[3][2] = {{37, 23}, {1, 5}, {64, 64}};
    for (int z = 0; z < 3; z++) {
        const int64_t w = sizes[z][0], h = sizes[z][1];
        double *v = malloc((size_t)(w * h) * sizeof *v);
        for (int64_t k = 0; k < w * h; k++) v[k] = urand(&seed) < 0.2 ? 0 : 0.05 + urand(&seed);
        v[0] = 1;
        cfpo_density d;
        char err[256], what[64];
        snprintf(what, sizeof what, "random %lld x %lld", (long long)w, (long long)h);
        if (cfpo_density_from_values(v, w, h, what, &d, err, sizeof err) != 0) {
            CHECK(0, "%s: %s", what, err);
        } else {
            boxes(&d, what, seed + (unsigned long long)z, 400, 0, 0);
            boxes(&d, what, seed + (unsigned long long)z, 400, 1, 0);
            cfpo_density_free(&d);
        }
        free(v);
    }
    cfpo_density d;
    char err[256];
    if (cfpo_density_load("cos:a=0.9,res=128", &d, err, sizeof err) == 0) {
        boxes(&d, "cos a=0.9", seed, 400, 0, 0);
        boxes(&d, "cos a=0.9", seed, 400, 1, 0);
        cfpo_density_free(&d);
    } else {
        CHECK(0, "cos: %s", err);
    }
    /* q spread sqrt(1.005 / 0.995) = 1.005 (flat) and sqrt(1.03 / 0.97) = 1.030 (not) */
    const char *spec[2] = {"cos:a=0.005,res=128", "cos:a=0.03,res=128"};
    for (int f = 0; f < 2; f++) {
        if (cfpo_density_load(spec[f], &d, err, sizeof err) != 0) {
            CHECK(0, "%s: %s", spec[f], err);
            continue;
        }
        CHECK((sqrt(d.rho_max) <= sqrt(d.rho_min) * CFPO_QBOUND_FLAT) == (f == 0), "%s: spread %.4f", spec[f],
              sqrt(d.rho_max / d.rho_min));
        boxes(&d, spec[f], seed, 400, 0, f == 0);
        boxes(&d, spec[f], seed, 400, 1, f == 0);
        cfpo_density_free(&d);
    }
    return test_report(passed_, failed_);
}
