/* main_density.c - layer 5: the `cfpo --density` run (main_density.h):
 * the density, the start (its own, --init or --resume), the run with
 * progress and trace, the files written whole or not at all, the SUMMARY
 * line. A checkpoint records the density's hash; a resume under another
 * density (or none) is refused. */
#include "main_density.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "comm.h"
#include "dens_ckpt.h"
#include "dens_dist.h"
#include "dens_engine.h"
#include "density.h"
#include "omp_compat.h"
#include "plan.h"
#include "pointfile.h"
#include "stoprule.h"
#include "tracecols.h"

static const char *prog = "cfpo";

/* The default tolerance of a move under a density, in local spacings. */
#define DENS_TOL 1e-4

typedef struct {
    const char *path;
    uint64_t seed, hash;
    double tol;
    int64_t n;
} save_ctx;

/* Under several ranks the set is gathered and rank 0 writes; every rank
 * returns its verdict. */
static int save(const cfpo_dens_engine *E, int iteration, int converged, void *user, char *err, size_t errlen)
{
    const save_ctx *s = user;
    dens_ckpt_info info = {.n = s->n, .seed = s->seed, .hash = s->hash, .tol = s->tol, .iteration = iteration,
                           .converged = converged};
    const double *xy = cfpo_dens_points(E);
    int rc = xy ? 0 : -1;
    if (!xy) snprintf(err, errlen, "out of memory gathering the points");
    else if (comm_rank() == 0) rc = dens_ckpt_write(s->path, &info, xy, err, errlen);
    comm_bcast(&rc, sizeof rc, 0);
    return rc;
}

typedef struct {
    cli_progress prog;
    FILE *trace;
    double t0;
    int64_t n;
    cfpo_progress_fn outer;
    void *outer_user;
} prog_ctx;

static int on_iteration(const cfpo_iter_stats *s, void *user)
{
    prog_ctx *c = user;
    const double el = cli_now() - c->t0;
    if (c->trace) {
        double row[CFPO_TRACE_COLUMNS];
        cfpo_trace_values(s, el, row);
        cfpo_trace_write_values(c->trace, cfpo_trace_columns, row, CFPO_TRACE_COLUMNS, 1);
        fputc('\n', c->trace);
    }
    cli_progress_line(&c->prog, 0, "iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  elapsed %.1fs", s->iteration,
                      s->delta_min, s->delta_avg, (long long)s->moved, el);
    return 0;
}

int cfpo_density_main(const cfpo_density_cmd *c)
{
    char err[600];
    if (!c->spec) cli_usage_error(prog, "--resume %s: the checkpoint was made with a density; give the same --density SPEC",
                                  c->resume);
    cfpo_density d;
    if (cfpo_density_load(c->spec, &d, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    cfpo_options o = c->o;
    if (!c->given_tol) o.tol = DENS_TOL;
    int64_t n = c->n;
    double *start = NULL;
    int iter0 = 0;
    if (c->resume) {
        dens_ckpt_info info;
        if (dens_ckpt_read(c->resume, &info, &start, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        if (info.hash != d.hash)
            cli_fail(prog, "--resume %s: the checkpoint was made with another density (hash %016llx, --density %s has %016llx)",
                     c->resume, (unsigned long long)info.hash, c->spec, (unsigned long long)d.hash);
        if ((n >= 0 && n != info.n) || (c->given_seed && o.seed != info.seed) || (c->given_tol && o.tol != info.tol))
            cli_usage_error(prog, "--resume %s: the checkpoint is for n=%lld seed=%llu tol=%g; leave those options out or give the same values",
                            c->resume, (long long)info.n, (unsigned long long)info.seed, info.tol);
        n = info.n;
        o.seed = info.seed;
        o.tol = info.tol;
        iter0 = info.iteration;
    } else if (c->init) {
        size_t m;
        if (pf_read(c->init, &start, &m, err, sizeof err) != 0) cli_fail(prog, "--init %s", err);
        if (n >= 0 && n != (int64_t)m)
            cli_usage_error(prog, "--init %s: the file holds %zu points, -n says %lld; leave -n out or give the same",
                            c->init, m, (long long)n);
        n = (int64_t)m;
    }
    if (n < 0) cli_usage_error(prog, "the number of points is required: -n N");
    if (cfpo_density_check_n(&d, n, err, sizeof err) != 0) cli_usage_error(prog, "--density %s: %s", c->spec, err);
    const int64_t g = cfpo_dens_grid(&d, n), most = cfpo_dens_dist_max_ranks(g);
    if (comm_size() > most) /* a rank needs cells of every colour (dens_dist.h) */
        cli_usage_error(prog, "--density %s at n=%lld: the grid has %lld x %lld cells, enough for at most %lld rank%s "
                        "(this run has %d); use fewer ranks or more points", c->spec, (long long)n, (long long)g,
                        (long long)g, (long long)most, most == 1 ? "" : "s", comm_size());
    if (c->checkpoint && c->out && strcmp(c->checkpoint, c->out) == 0)
        cli_usage_error(prog, "--checkpoint and --output name the same file");
    if (c->out && pf_format_of(c->out) == PF_UNKNOWN)
        cli_usage_error(prog, "--output %s: unknown extension (%s)", c->out, PF_EXTENSIONS);
    prog_ctx pc = {.n = n, .t0 = cli_now()};
    const int root = comm_rank() == 0;
    cli_progress_init(&pc.prog, c->quiet || !root);
    cli_atomic tr;
    if (c->trace && root) {
        if (cli_atomic_open(&tr, c->trace, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        pc.trace = tr.f;
        cfpo_trace_write_names(pc.trace, cfpo_trace_columns, CFPO_TRACE_COLUMNS, 1);
        fputc('\n', pc.trace);
    }
    o.progress = on_iteration;
    o.user = &pc;
    cfpo_dens_engine *E = cfpo_dens_create(&d, n, &o, start, iter0, err, sizeof err);
    free(start);
    save_ctx sc = {.path = c->checkpoint, .seed = o.seed, .hash = d.hash, .tol = o.tol, .n = n};
    cfpo_result res;
    int rc = E ? cfpo_dens_run(E, &res, c->checkpoint ? (c->every > 0 ? c->every : 100) : 0, save, &sc, err, sizeof err) : -1;
    cli_progress_end(&pc.prog);
    const double seconds = cli_now() - pc.t0;
    if (rc == 0 && c->out) { /* several ranks: gathered, written by rank 0 */
        const double *xy = cfpo_dens_points(E);
        if (!xy) { rc = -1; snprintf(err, sizeof err, "out of memory gathering the points"); }
        else if (root) rc = pf_write(c->out, xy, (size_t)n, err, sizeof err);
        comm_bcast(&rc, sizeof rc, 0);
    }
    if (c->trace && root) {
        if (rc == 0) rc = cli_atomic_commit(&tr, err, sizeof err);
        else cli_atomic_abort(&tr);
    }
    if (c->trace) comm_bcast(&rc, sizeof rc, 0);
    if (rc != 0) cli_fail(prog, "%s", err);
    const int P = comm_size();
    int64_t *own = calloc((size_t)P, sizeof *own);
    if (!comm_all(own != NULL)) cli_fail(prog, "out of memory");
    comm_allgather_i64(cfpo_dens_own_points(E), own);
    uint64_t peak, peak_max;
    cfpo_plan_peak_memory(&peak, &peak_max);
    cli_summary sm = {.method = "cfpo-density", .variant = "density", .n = n, .seed = o.seed,
                      .threads = o.threads > 0 ? o.threads : omp_get_num_procs(), .ranks = P,
                      .iterations = res.iterations, .seconds = seconds, .delta_min = res.delta_min,
                      .delta_avg = res.delta_avg, .converged = res.converged, .peak_bytes = peak,
                      .stop = cfpo_stop_name(res.stop)};
    if (!root) goto end;
    cli_print_summary(stdout, &sm);
    printf("DENSITY spec=%s hash=%016llx pixels=%lldx%lld contrast=%.4g support=%.4g cells=%lld\n", c->spec,
           (unsigned long long)d.hash, (long long)d.w, (long long)d.h, d.rho_max / d.rho_min, d.support,
           (long long)cfpo_dens_cells_per_side(E));
    if (P > 1) { /* the cut balances mass: each rank's points against n / P */
        int64_t lo = own[0], hi = own[0];
        printf("RANKS ranks=%d points=", P);
        for (int r = 0; r < P; r++) {
            printf("%s%lld", r ? "," : "", (long long)own[r]);
            lo = own[r] < lo ? own[r] : lo;
            hi = own[r] > hi ? own[r] : hi;
        }
        printf(" min_over_mean=%.3f max_over_mean=%.3f\n", (double)lo * P / (double)n, (double)hi * P / (double)n);
    }
    fflush(stdout);
end:
    free(own);
    cfpo_dens_free(E);
    cfpo_density_free(&d);
    return 0;
}
