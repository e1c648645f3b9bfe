/* bl_method.c - see bl_method.h: the options' defaults, lookup and the
 * command's parse of a value with its wording; the common check of n. */
#include "bl_method.h"

#include <stdio.h>
#include <string.h>

#include "cfpo.h"
#include "cli.h"

void bl_defaults(const bl_method *m, bl_value *v)
{
    for (int i = 0; i < m->noptions; i++) {
        if (m->options[i].type == BL_REAL) v[i].d = m->options[i].def;
        else v[i].i = (int64_t)m->options[i].def;
    }
}

int bl_option_index(const bl_method *m, const char *cli)
{
    for (int i = 0; i < m->noptions; i++) {
        const bl_option *o = &m->options[i];
        if ((o->cli[0] && strcmp(o->cli, cli) == 0) || (o->cli_off && strcmp(o->cli_off, cli) == 0)) return i;
    }
    return -1;
}

int bl_option_parse(const bl_method *m, int i, const char *arg, int off, bl_value *v, char *err, size_t errlen)
{
    const bl_option *o = &m->options[i];
    int ok = 1;
    switch (o->type) {
    case BL_FLAG: v[i].i = !off; return 0;
    case BL_INT: ok = cli_parse_i64(arg, o->lo, o->hi, &v[i].i) == 0; break;
    case BL_REAL:
        ok = cli_parse_double(arg, o->min, o->max, &v[i].d) == 0 && (!o->open_min || v[i].d > o->min);
        break;
    case BL_CHOICE:
        ok = 0;
        for (int c = 0; c < BL_MAX_CHOICES && o->choices[c]; c++)
            if (strcmp(arg, o->choices[c]) == 0) {
                v[i].i = c;
                ok = 1;
            }
        break;
    }
    if (ok) return 0;
    snprintf(err, errlen, "--%s: '%s' %s", o->cli, arg, o->bad);
    return -1;
}

int bl_check_n_memory(const char *method, int64_t n, double tol, double bytes, char *err, size_t errlen)
{
    cfpo_options co;
    cfpo_options_init(&co);
    co.tol = tol;
    co.threads = 1;
    if (cfpo_validate(n, &co, err, errlen) == -1) return -1; /* cfpo's memory model is not this method's */
    const double have = cli_physical_memory();
    if (bytes > 0.9 * have) {
        snprintf(err, errlen, "n = %lld is too large for memory: %s needs about %.1f GB, this machine has %.1f GB",
                 (long long)n, method, bytes / 1e9, have / 1e9);
        return -2;
    }
    return 0;
}
