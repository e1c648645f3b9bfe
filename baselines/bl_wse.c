/* bl_wse.c - weighted sample elimination (wse.h) as a baseline method
 * (bl_method.h): a direct sampler (its create makes the set; no
 * iterations), with the paper's defaults and its progressive order. */
#include <math.h>
#include <stdio.h>

#include "bl_method.h"
#include "bl_set.h"
#include "wse.h"

enum { PROGRESSIVE, RATIO, ALPHA, WEIGHT_LIMIT };

static const bl_option OPTS[] = {
    {.cli = "progressive", .py = "progressive", .type = BL_FLAG, .def = 0,
     .help = "      --progressive    the progressive order: eliminate again to n/2, n/4, ...,\n"
             "                       1, each eliminated part behind the survivors (the\n"
             "                       later-eliminated first): every prefix n/2^k is the set\n"
             "                       left at that stage (SUMMARY method=wse-progressive)\n"},
    {.cli = "ratio", .py = "ratio", .type = BL_REAL, .min = 1, .max = 100, .def = WSE_RATIO,
     .bad = "is not a number in [1, 100]",
     .help = "      --ratio R        candidates per output point (default %g, the paper's)\n"},
    {.cli = "alpha", .py = "alpha", .type = BL_REAL, .min = 0, .max = 64, .open_min = 1, .def = WSE_ALPHA,
     .bad = "is not a number in (0, 64]",
     .help = "      --alpha A        the weight's exponent (default %g, the paper's)\n"},
    {.cli = "", .py = "weight_limit", .type = BL_FLAG, .def = 1, .cli_off = "no-weight-limit",
     .help = "      --no-weight-limit  no weight limiting (the paper's default has it:\n"
             "                       beta 0.65, gamma 1.5)\n"},
};

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    /* candidates (16 bytes), their grid, weights, heap and flags (about 50 bytes), the output */
    return bl_check_n_memory("wse", n, tol, ceil(v[RATIO].d * (double)n) * 72 + (double)n * 40, err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    (void)tol;
    const wse_params p = {.alpha = v[ALPHA].d, .weight_limit = (int)v[WEIGHT_LIMIT].i,
                          .progressive = (int)v[PROGRESSIVE].i};
    bl_set *S = bl_set_new(n, err, errlen);
    if (S && wse_points(n, seed, v[RATIO].d, &p, S->xy, err, errlen) != 0) {
        bl_set_destroy(S);
        return NULL;
    }
    return S;
}

static const char *wse_name(const bl_value *v) { return v[PROGRESSIVE].i ? "wse-progressive" : "wse"; }

const bl_method bl_wse = {
    .name = "wse", .prog = "cfpo-wse", .kind = BL_ITERATIVE,
    .about = "Weighted sample elimination (Yuksel, Eurographics 2015) on the periodic unit\n"
             "square: ratio * n white-noise candidates, pair weights (1 - d/d_max)^alpha within\n"
             "d_max = 2 r_max, r_max = sqrt(1 / (2 sqrt(3) n)), weight limiting, the heaviest\n"
             "sample eliminated until n remain. Direct: no iterations. Prints one SUMMARY line\n"
             "on stdout.",
    BL_OPTIONS(OPTS), .method_name = wse_name, .check_n = check_n, .create = create, BL_SET_ENGINE,
};
