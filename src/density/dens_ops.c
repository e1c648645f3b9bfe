/* dens_ops.c - layer 3: the density engine's table of the one interface
 * (engine_iface.h): its iteration, measure, points out and checkpoints in
 * the one format (ckpt.h, with the density's hash). */
#include "dens_ops.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ckpt_io.h"

typedef struct {
    cfpo_dens_engine *E;
    const cfpo_density *d;
    cfpo_options o;
    int64_t n;
    int converged0; /* as the checkpoint resumed from said */
} dens_run;

static int step(void *p, cfpo_iter_stats *s, char *err, size_t errlen)
{
    dens_run *r = p;
    if (cfpo_dens_iterate(r->E, s) != 0) {
        snprintf(err, errlen, "out of memory mid-run");
        return -1;
    }
    return 0;
}

static int now_stats(void *p, cfpo_iter_stats *s, char *err, size_t errlen)
{
    dens_run *r = p;
    *s = (cfpo_iter_stats){.iteration = cfpo_dens_iteration(r->E), .converged = r->converged0};
    if (cfpo_dens_measure(r->E, &s->delta_min, &s->delta_avg) == 0) return 0;
    snprintf(err, errlen, "out of memory");
    return -1;
}

static int put_points(void *p, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    return cfpo_dens_write_points(((dens_run *)p)->E, f, base, err, errlen);
}

static int put_text(void *p, pf_writer *w, char *err, size_t errlen)
{
    dens_run *r = p;
    const double *xy = cfpo_dens_points(r->E); /* one rank: the store itself */
    if (!xy) {
        snprintf(err, errlen, "out of memory gathering the points");
        return -1;
    }
    return pf_writer_put(w, xy, (size_t)r->n, err, errlen);
}

static int checkpoint(void *p, const char *path, int iteration, int converged, char *err, size_t errlen)
{
    dens_run *r = p;
    ckpt_header c = {.n = r->n, .seed = r->o.seed, .variant = CFPO_VARIANT_ADAPTIVE, .tol = r->o.tol,
                     .iteration = iteration, .converged = converged ? 1 : 0, .hash = r->d->hash,
                     .davg_ref = cfpo_dens_davg_ref(r->E)};
    return ckpt_write(path, &c, put_points, p, err, errlen);
}

static void copy(void *p, double *xy)
{
    dens_run *r = p;
    memcpy(xy, cfpo_dens_points(r->E), (size_t)r->n * 2 * sizeof *xy);
}

static void timing(void *p, cfpo_engine_timing *t) { cfpo_dens_timing(((dens_run *)p)->E, t); }
static int64_t cells_per_side(const void *p) { return cfpo_dens_cells_per_side(((const dens_run *)p)->E); }

static void release(void *p)
{
    dens_run *r = p;
    if (!r) return;
    cfpo_dens_free(r->E);
    free(r);
}

static const cfpo_engine_ops ops = {"density", step, now_stats, put_points, put_text, copy, checkpoint, timing,
                                    cells_per_side, release};

int cfpo_dens_open(const cfpo_density *d, int64_t n, const cfpo_options *o, const double *start, int iter0,
                   int converged0, double davg_ref, cfpo_run_engine *R, char *err, size_t errlen)
{
    dens_run *r = calloc(1, sizeof *r);
    if (!comm_all(r != NULL)) {
        free(r);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    *r = (dens_run){.d = d, .o = *o, .n = n, .converged0 = converged0};
    r->E = cfpo_dens_create(d, n, o, start, iter0, err, errlen);
    if (!r->E) {
        free(r);
        return -1;
    }
    cfpo_dens_set_davg_ref(r->E, davg_ref);
    R->ops = &ops;
    R->E = r;
    R->n = n;
    R->o = *o;
    return 0;
}

int64_t cfpo_dens_run_own_points(const cfpo_run_engine *R)
{
    return cfpo_dens_own_points(((const dens_run *)R->E)->E);
}

int cfpo_dens_run_levels(const cfpo_run_engine *R) { return cfpo_dens_levels_count(((const dens_run *)R->E)->E); }
