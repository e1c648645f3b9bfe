/* bl_loop.c - see bl_loop.h. */
#include "bl_loop.h"

#include <string.h>

#include "cli.h"
#include "stoprule.h"

static int after_row(const bl_loop_args *a, int hook, const cfpo_iter_stats *s, double el, bl_outcome *o)
{
    if (hook < 0) {
        o->failed = 1;
        return 1;
    }
    o->why = cfpo_stop_check(&a->rules, s, el, a->max_iter);
    if (!o->why && hook > 0) o->why = CFPO_STOP_CALLER;
    return o->why != CFPO_STOP_NONE;
}

void *bl_loop(const bl_method *m, const bl_value *v, const bl_loop_args *a, double t0, bl_row_fn row, void *user,
              bl_outcome *o, char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    void *E = a->density ? m->create_density(v, a->n, a->seed, a->tol, a->density, err, errlen)
                         : m->create(v, a->n, a->seed, a->tol, err, errlen);
    if (!E) return NULL;
    cfpo_iter_stats *s = &o->last;
    const double t = cli_now();
    m->deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t;
    s->converged = m->iterate == NULL; /* a direct sampler: the start is the set */
    double el = cli_now() - t0;
    int it = 0;
    int stop = after_row(a, row(user, E, s, el), s, el, o);
    while (!stop) {
        s->iteration = it + 1;
        m->iterate(E, s);
        s->iteration = ++it;
        el = cli_now() - t0;
        stop = after_row(a, row(user, E, s, el), s, el, o);
    }
    o->iterations = it;
    return E;
}

int bl_trace_values(const bl_method *m, void *E, const cfpo_iter_stats *s, double elapsed, double *row)
{
    double all[CFPO_TRACE_COLUMNS];
    cfpo_trace_values(s, elapsed, all);
    memcpy(row, all, CFPO_TRACE_COMMON * sizeof *row);
    if (m->column_values) m->column_values(E, row + CFPO_TRACE_COMMON);
    return CFPO_TRACE_COMMON + m->ncolumns;
}
