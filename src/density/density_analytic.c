/* density_analytic.c - layer 2: the named test densities of density.h
 * (cos, ramp, balzer), their parameters parsed strictly, sampled at the
 * centres of an R x R raster and handed to cfpo_density_from_values. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "density.h"

typedef struct {
    const char *key;
    double lo, hi, value;
    int whole;
} param;

/* key=value,key=value into ps (np of them); unknown keys and bad values
 * are errors. */
static int parse_params(const char *name, const char *text, param *ps, int np, char *err, size_t errlen)
{
    if (!text) return 0;
    char buf[256];
    if (strlen(text) >= sizeof buf) { snprintf(err, errlen, "--density %s: parameters too long", name); return -1; }
    strcpy(buf, text);
    for (char *tok = buf, *next; tok; tok = next) {
        next = strchr(tok, ',');
        if (next) *next++ = '\0';
        char *eq = strchr(tok, '=');
        int k = -1;
        if (eq) {
            *eq = '\0';
            for (int i = 0; i < np; i++)
                if (strcmp(tok, ps[i].key) == 0) k = i;
        }
        if (k < 0) {
            snprintf(err, errlen, "--density %s: '%s' is not a parameter of the form key=value (keys:%s%s%s%s%s%s%s%s)", name, tok,
                     np > 0 ? " " : "", np > 0 ? ps[0].key : "", np > 1 ? " " : "", np > 1 ? ps[1].key : "",
                     np > 2 ? " " : "", np > 2 ? ps[2].key : "", np > 3 ? " " : "", np > 3 ? ps[3].key : "");
            return -1;
        }
        double v;
        int bad;
        if (ps[k].whole) {
            int64_t iv;
            bad = cli_parse_i64(eq + 1, (int64_t)ps[k].lo, (int64_t)ps[k].hi, &iv) != 0;
            v = (double)iv;
        } else bad = cli_parse_double(eq + 1, ps[k].lo, ps[k].hi, &v) != 0;
        if (bad) {
            snprintf(err, errlen, "--density %s: %s='%s' is not a %s in [%g, %g]", name, ps[k].key, eq + 1,
                     ps[k].whole ? "whole number" : "number", ps[k].lo, ps[k].hi);
            return -1;
        }
        ps[k].value = v;
    }
    return 0;
}

static const double two_pi = 6.283185307179586;

int cfpo_density_named(const char *name, const char *params, cfpo_density *d, char *err, size_t errlen)
{
    enum { COS, RAMP, BALZER } kind;
    param ps[4];
    int np;
    if (strcmp(name, "cos") == 0) {
        kind = COS;
        np = 4;
        ps[0] = (param){"a", 0, 1, 0.9, 0};
        ps[1] = (param){"kx", -64, 64, 1, 1};
        ps[2] = (param){"ky", -64, 64, 0, 1};
    } else if (strcmp(name, "ramp") == 0) {
        kind = RAMP;
        np = 2;
        ps[0] = (param){"contrast", 1, 1e6, 16, 0};
    } else if (strcmp(name, "balzer") == 0) {
        kind = BALZER;
        np = 1;
    } else {
        snprintf(err, errlen, "--density: '%s' is not an image (.png, .pgm), a .npy array or one of cos, ramp, balzer", name);
        return -1;
    }
    ps[np - 1] = (param){"res", 16, 4096, 1024, 1};
    if (parse_params(name, params, ps, np, err, errlen) != 0) return -1;
    const int64_t R = (int64_t)ps[np - 1].value;
    double *v = malloc((size_t)(R * R) * sizeof *v);
    if (!v) { snprintf(err, errlen, "--density %s: out of memory", name); return -1; }
    double vmax = 0;
    for (int64_t j = 0; j < R; j++)
        for (int64_t i = 0; i < R; i++) {
            const double x = ((double)i + 0.5) / (double)R, y = ((double)j + 0.5) / (double)R;
            double r;
            /* cos along x alone (ky = 0): ky y is +0 on every row, so row
             * 0's value is every row's, the same bits */
            if (kind == COS && ps[2].value == 0 && j > 0) r = v[i];
            else if (kind == COS) r = 1 + ps[0].value * cos(two_pi * (ps[1].value * x + ps[2].value * y));
            else if (kind == RAMP) r = 1 + (ps[0].value - 1) * (1 - fabs(2 * (double)i / (double)R - 1));
            else {
                const double u = 2 * x - 1, w = 2 * y - 1, su = sin(M_PI * u), sw = sin(M_PI * w);
                r = exp(-20 * (u * u + w * w)) + 0.2 * su * su * sw * sw;
            }
            if (r < 0) r = 0; /* a = 1: rounding below the zero troughs */
            v[j * R + i] = r;
            if (r > vmax) vmax = r;
        }
    if (kind == BALZER)
        for (int64_t p = 0; p < R * R; p++)
            if (v[p] < vmax / 256) v[p] = vmax / 256;
    char what[64];
    snprintf(what, sizeof what, "--density %s", name);
    int rc = cfpo_density_from_values(v, R, R, what, d, err, errlen);
    free(v);
    return rc;
}
