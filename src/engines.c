/* engines.c - see engines.h. */
#include "engines.h"

#include <stdio.h>
#include <stdlib.h>

#include "ckpt_io.h"
#include "dens_ops.h"
#include "policy.h"

int cfpo_density_is_flat(const cfpo_density *d)
{
    return d && d->rho_min == d->rho_max && d->support >= 1;
}

double cfpo_engines_default_tol(int variant, const cfpo_density *d)
{
    return cfpo_policy_default_tol(variant, d && !cfpo_density_is_flat(d));
}

/* The density engine from a checkpoint: the whole file on every rank, its
 * density's hash against d's. */
static int open_resumed(int64_t n, const cfpo_options *o, const char *path, const cfpo_density *d,
                        cfpo_run_engine *R, char *err, size_t errlen)
{
    ckpt_header c;
    double *xy = NULL;
    if (!comm_all(ckpt_read_all(path, &c, &xy, err, errlen) == 0)) {
        free(xy);
        return -1;
    }
    int rc = -1;
    if (c.hash != d->hash)
        snprintf(err, errlen, "%s: the checkpoint was made %s (hash %016llx, this density's %016llx)", path,
                 c.hash ? "with another density" : "without a density", (unsigned long long)c.hash,
                 (unsigned long long)d->hash);
    else if (c.n != n || c.seed != o->seed || c.tol != o->tol)
        snprintf(err, errlen, "%s: checkpoint is for another run (n, seed or tol differ)", path);
    else
        rc = cfpo_dens_open(d, n, o, xy, (int)c.iteration, c.converged, c.davg_ref, R, err, errlen);
    free(xy);
    return rc;
}

int cfpo_engines_open(int64_t n, const cfpo_options *o, const cfpo_engine_config *cfg, const cfpo_density *d,
                      double t_born, cfpo_run_engine *R, char *err, size_t errlen)
{
    int rc;
    if (!d || cfpo_density_is_flat(d)) {
        cfpo_engine_config c = *cfg;
        c.density_hash = d ? d->hash : 0;
        cfpo_engine *E = cfpo_engine_create_ex(n, o, &c, err, errlen);
        if (!E) return -1;
        cfpo_engine_as_run(E, R);
        R->t_born = t_born;
        return 0;
    }
    if (cfg->resume) rc = open_resumed(n, o, cfg->resume, d, R, err, errlen);
    else rc = cfpo_dens_open(d, n, o, cfg->start_xy, 0, 0, 0, R, err, errlen);
    if (!comm_all(rc == 0)) {
        if (rc == 0) {
            R->ops->free(R->E);
            snprintf(err, errlen, "another rank failed to make its points");
        }
        return -1;
    }
    R->t_born = t_born;
    return 0;
}
