/* stopflat.c - see stopflat.h. */
#include "stopflat.h"

#include <stdlib.h>

int cfpo_flat_init(cfpo_flat_rule *r, int window, double gain)
{
    r->window = window > 0 ? window : 0;
    r->gain = gain;
    r->count = 0;
    r->dmin = r->davg = NULL;
    if (r->window == 0) return 0;
    r->dmin = malloc(2 * (size_t)(r->window + 1) * sizeof *r->dmin);
    if (!r->dmin) return -1;
    r->davg = r->dmin + r->window + 1;
    return 0;
}

void cfpo_flat_free(cfpo_flat_rule *r)
{
    free(r->dmin);
    r->dmin = r->davg = NULL;
}

int cfpo_flat_push(cfpo_flat_rule *r, double dmin, double davg)
{
    if (r->window == 0) return 0;
    const int w1 = r->window + 1, at = r->count % w1;
    r->dmin[at] = dmin;
    r->davg[at] = davg;
    r->count++;
    return cfpo_flat_holds(r);
}

int cfpo_flat_holds(const cfpo_flat_rule *r)
{
    if (r->window == 0) return 0;
    const int w1 = r->window + 1;
    if (r->count < w1) return 0;
    const int last = (r->count - 1) % w1, old = r->count % w1; /* the entry W iterations back */
    return r->dmin[last] - r->dmin[old] < r->gain && r->davg[last] - r->davg[old] < r->gain;
}
