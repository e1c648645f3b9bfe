/* main_prog.c - see main_prog.h. */
#include "main_prog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "comm.h"
#include "omp_compat.h"
#include "plan.h"
#include "runfiles.h"
#include "runsignal.h"
#include "stoprule.h"
#include "tracecols.h"

int prog_cli_option(prog_cli *pc, const char *prog, int ch, const char *arg)
{
    int64_t v;
    switch (ch) {
    case PROG_OPT_PROGRESSIVE: pc->on = 1; return 1;
    case PROG_OPT_BASE:
        if (cli_parse_i64(arg, 1, INT64_MAX / 4, &v) != 0)
            cli_usage_error(prog, "--base: '%s' is not a whole number >= 1", arg);
        pc->p.base = v;
        pc->base_given = 1;
        return 1;
    case PROG_OPT_CLASSES:
        if (cli_parse_i64(arg, 1, CFPO_PROG_MAX_LEVELS, &v) != 0)
            cli_usage_error(prog, "--classes: '%s' is not a whole number in 1..%d", arg, CFPO_PROG_MAX_LEVELS);
        pc->p.classes = (int)v;
        pc->on = 1;
        return 1;
    case PROG_OPT_LEVEL_MIN:
        if (cli_parse_double(arg, 0, 1, &pc->p.level_min) != 0)
            cli_usage_error(prog, "--level-min: '%s' is not a number in [0, 1]", arg);
        pc->level_min_given = 1;
        return 1;
    case PROG_OPT_RELAX:
        if (cli_parse_i64(arg, 0, 1000000, &v) != 0) cli_usage_error(prog, "--relax: '%s' is not a whole number in 0..1e6", arg);
        pc->p.relax = (int)v;
        pc->relax_given = 1;
        return 1;
    case PROG_OPT_JOINT:
        if (cli_parse_i64(arg, 0, 1000000, &v) != 0) cli_usage_error(prog, "--joint: '%s' is not a whole number in 0..1e6", arg);
        pc->p.joint.sweeps = (int)v;
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_LAST:
        if (cli_parse_i64(arg, 1, 1000000, &v) != 0)
            cli_usage_error(prog, "--joint-last: '%s' is not a whole number in 1..1e6", arg);
        pc->p.joint_last = (int)v;
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_CANDIDATES:
        if (cli_parse_i64(arg, 1, 1000, &v) != 0)
            cli_usage_error(prog, "--joint-candidates: '%s' is not a whole number in 1..1000", arg);
        pc->p.joint.candidates = (int)v;
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_SOLVE:
        if (cli_parse_i64(arg, 0, 1000, &v) != 0)
            cli_usage_error(prog, "--joint-solve: '%s' is not a whole number in 0..1000", arg);
        pc->p.joint.solve = v > 0 ? (int)v : -1; /* (0: off, not the classes' default) */
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_AVG:
        if (cli_parse_double(arg, 0, 10, &pc->p.joint.avg) != 0)
            cli_usage_error(prog, "--joint-avg: '%s' is not a number in [0, 10]", arg);
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_SOFT:
        if (cli_parse_double(arg, 0, 1, &pc->p.joint.soft) != 0)
            cli_usage_error(prog, "--joint-soft: '%s' is not a number in [0, 1]", arg);
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_CIRCUM:
        if (cli_parse_i64(arg, 0, 24, &v) != 0)
            cli_usage_error(prog, "--joint-circum: '%s' is not a whole number in 0..24", arg);
        pc->p.joint.circum = v > 0 ? (int)v : -1; /* (0: off, not the classes' default) */
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_PAIRS:
        if (cli_parse_i64(arg, 0, 1000, &v) != 0)
            cli_usage_error(prog, "--joint-pairs: '%s' is not a whole number in 0..1000", arg);
        pc->p.joint.pairs = (int)v;
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_JOINT_HOLD:
        if (cli_parse_double(arg, 0, 1.2, &pc->p.joint.hold) != 0)
            cli_usage_error(prog, "--joint-hold: '%s' is not a number in [0, 1.2]", arg);
        pc->joint_given = 1;
        return 1;
    case PROG_OPT_POLISH:
        if (cli_parse_i64(arg, 0, 1000000, &v) != 0)
            cli_usage_error(prog, "--polish: '%s' is not a whole number in 0..1e6", arg);
        pc->p.polish = (int)v;
        pc->polish_given = 1;
        return 1;
    case PROG_OPT_LEVEL_ITER:
        if (cli_parse_i64(arg, 0, 1000000000, &v) != 0)
            cli_usage_error(prog, "--level-iter: '%s' is not a whole number in 0..1e9", arg);
        pc->p.level_iter = v > 0 ? (int)v : -1; /* (0: no cap) */
        pc->level_iter_given = 1;
        return 1;
    case PROG_OPT_LEVEL_BALANCE:
        if (cli_parse_i64(arg, 0, 1000000, &v) != 0)
            cli_usage_error(prog, "--level-balance: '%s' is not a whole number in 0..1e6", arg);
        pc->p.balance = v > 0 ? (int)v : -1; /* (0: off, not the default) */
        pc->balance_given = 1;
        return 1;
    case PROG_OPT_LEVEL_BALANCE_ORDER:
        pc->p.balance_order = 1;
        return 1;
    case PROG_OPT_CLASSES_LEVELS:
        pc->p.classes_levels = 1;
        pc->colour_given |= 2;
        return 1;
    case PROG_OPT_CLASS_UNION_FLOOR:
        if (cli_parse_double(arg, 0.05, 1.5, &pc->p.union_floor) != 0)
            cli_usage_error(prog, "--class-union-floor: '%s' is not a number in [0.05, 1.5]", arg);
        pc->colour_given |= 1;
        return 1;
    case PROG_OPT_CLASS_REACH:
        if (cli_parse_double(arg, 0.5, 1.5, &pc->p.colour_reach) != 0)
            cli_usage_error(prog, "--class-reach: '%s' is not a number in [0.5, 1.5]", arg);
        pc->colour_given |= 1;
        return 1;
    case PROG_OPT_CLASS_SWAPS:
        if (cli_parse_i64(arg, 0, 64, &v) != 0) cli_usage_error(prog, "--class-swaps: '%s' is not a whole number in 0..64", arg);
        pc->p.joint.swaps = v > 0 ? (int)v : -1; /* (0: off, not the default) */
        pc->colour_given |= 1;
        return 1;
    case PROG_OPT_POLISH_FLOOR:
        if (cli_parse_double(arg, 0.05, 1.2, &pc->p.polish_floor) != 0)
            cli_usage_error(prog, "--polish-floor: '%s' is not a number in [0.05, 1.2]", arg);
        pc->polish_given = 1;
        return 1;
    case PROG_OPT_JOINT_PREFIX:
    case PROG_OPT_JOINT_FULL: {
        double t;
        const char *name = ch == PROG_OPT_JOINT_PREFIX ? "--joint-prefix" : "--joint-full";
        if (cli_parse_double(arg, 0.05, 1.2, &t) != 0) cli_usage_error(prog, "%s: '%s' is not a number in [0.05, 1.2]", name, arg);
        if (ch == PROG_OPT_JOINT_PREFIX) pc->p.joint.target_prefix = t;
        else pc->p.joint.target_full = t;
        pc->joint_given = 1;
        return 1;
    }
    default: return 0;
    }
}

void prog_cli_settle(prog_cli *pc, const char *prog, int64_t n, int variant)
{
    if (!pc->on && pc->polish_given) cli_usage_error(prog, "--polish needs --progressive");
    if (!pc->on && (pc->base_given || pc->level_min_given || pc->relax_given || pc->joint_given || pc->polish_given ||
                    pc->level_iter_given))
        cli_usage_error(prog, "%s needs --progressive or --classes K",
                        pc->base_given ? "--base" : pc->relax_given ? "--relax" : pc->joint_given ? "--joint"
                        : pc->polish_given ? "--polish" : pc->level_iter_given ? "--level-iter" : "--level-min");
    if (pc->colour_given && pc->p.classes <= 0)
        cli_usage_error(prog, "%s needs --classes K", pc->colour_given & 2 ? "--classes-levels" : "--class-union-floor, --class-reach or --class-swaps");
    if (pc->colour_given == 3) cli_usage_error(prog, "--class-union-floor, --class-reach and --class-swaps do not go with --classes-levels");
    if (pc->p.balance_order && pc->p.balance < 0)
        cli_usage_error(prog, "--level-balance-order does not go with --level-balance 0");
    if ((pc->balance_given || pc->p.balance_order) && (!pc->on || pc->p.classes > 0))
        cli_usage_error(prog, "%s needs --progressive (without --classes)",
                        pc->balance_given ? "--level-balance" : "--level-balance-order");
    if (!pc->on) return;
    if (pc->polish_given && pc->p.classes > 0) cli_usage_error(prog, "--polish does not go with --classes");
    const double tp = pc->p.joint.target_prefix > 0 ? pc->p.joint.target_prefix : 0.78;
    const double tf = pc->p.joint.target_full > 0 ? pc->p.joint.target_full : 0.90;
    if (tf >= sqrt(2.0) * tp) /* the pair weights must fall with the level (prog_joint.h) */
        cli_usage_error(prog, "--joint-full %g must be below sqrt(2) times --joint-prefix %g", tf, tp);
    if (pc->base_given && pc->p.classes > 0) cli_usage_error(prog, "--base does not go with --classes");
    if (pc->p.classes > 0 && !pc->p.classes_levels && (pc->relax_given || pc->level_min_given || pc->level_iter_given))
        cli_usage_error(prog, "%s does not go with --classes (by colouring; --classes-levels takes it)",
                        pc->relax_given ? "--relax" : pc->level_min_given ? "--level-min" : "--level-iter");
    if (variant == CFPO_VARIANT_HYPERUNIFORM)
        cli_usage_error(prog, "--variant hyperuniform does not go with %s", pc->p.classes ? "--classes" : "--progressive");
    int64_t sizes[CFPO_PROG_MAX_LEVELS];
    char err[256];
    if (cfpo_prog_sizes(n, variant, &pc->p, sizes, err, sizeof err) < 0) cli_usage_error(prog, "%s", err);
}

typedef struct {
    cli_progress prog;
    FILE *trace;
    double t0;
    int level;
    int64_t m;
    const cfpo_prog_level *done; /* the finished levels */
    int ndone;
    FILE *joint;          /* the JOINT (and POLISH) lines, printed after the LEVEL lines */
    const char *tag;      /* "JOINT", or "POLISH" during the polish */
    int classes;          /* --classes: the JOINT lines' groups are the classes and their union */
    double worst_min;     /* over the finished levels */
    int64_t worst_m;
} prog_ctx;

static void level_begin(int k, int64_t m, void *user)
{
    prog_ctx *c = user;
    c->level = k;
    c->m = m;
    c->ndone = k;
    for (int j = 0; j < k; j++) /* (a resumed run starts past level 0) */
        if (c->done[j].delta_min < c->worst_min) {
            c->worst_min = c->done[j].delta_min;
            c->worst_m = c->done[j].m;
        }
}

static int on_iteration(const cfpo_iter_stats *s, void *user)
{
    prog_ctx *c = user;
    const double el = cli_now() - c->t0;
    const int now_worse = s->delta_min < c->worst_min;
    if (c->trace) {
        double row[CFPO_TRACE_COLUMNS];
        cfpo_trace_values(s, el, row);
        fprintf(c->trace, "%d\t%lld\t", c->level, (long long)c->m);
        cfpo_trace_write_values(c->trace, cfpo_trace_columns, row, CFPO_TRACE_COLUMNS, 1);
        fprintf(c->trace, "\t%lld\t%.9f\n", (long long)(now_worse ? c->m : c->worst_m),
                now_worse ? s->delta_min : c->worst_min);
    }
    cli_progress_line(&c->prog, 0, "level %d (prefix %lld)  iter %d  delta_min %.4f  delta_avg %.4f  moved %lld  "
                      "elapsed %.1fs", c->level, (long long)c->m, s->iteration, s->delta_min, s->delta_avg,
                      (long long)s->moved, el);
    return 0;
}

/* One sweep of the joint move: a JOINT line (kept until the LEVEL lines
 * are out) and a trace row (level = the level count, prefix = n). */
static void on_sweep(int sweep, int64_t moved, const double *dmin, const double *davg, int NG, void *user)
{
    prog_ctx *c = user;
    const int K = c->classes ? NG - 1 : NG; /* the levels so far (classes: NG - 1 classes, then the union) */
    int w = 0;
    for (int k = 1; k < K; k++)
        if (dmin[k] < dmin[w]) w = k;
    const int64_t wm = c->classes ? w : c->done[w].m;
    if (c->joint) {
        fprintf(c->joint, "%s level=%d prefix=%lld sweep=%d moved=%lld %s=%lld worst_delta_min=%.9f delta_min=",
                c->tag, K - 1, (long long)c->done[K - 1].m, sweep, (long long)moved,
                c->classes ? "worst_class" : "worst_prefix_min", (long long)wm, dmin[w]);
        for (int k = 0; k < NG; k++) fprintf(c->joint, "%s%.9f", k ? "," : "", dmin[k]);
        fprintf(c->joint, " delta_avg=");
        for (int k = 0; k < NG; k++) fprintf(c->joint, "%s%.9f", k ? "," : "", davg[k]);
        fprintf(c->joint, "\n");
    }
    const double el = cli_now() - c->t0;
    if (c->trace) {
        const cfpo_iter_stats s = {.iteration = sweep, .delta_min = dmin[NG - 1], .delta_avg = davg[NG - 1],
                                   .moved = moved, .solved = 0, .max_disp = NAN, .seconds = NAN, .max_move = NAN};
        double row[CFPO_TRACE_COLUMNS];
        cfpo_trace_values(&s, el, row);
        fprintf(c->trace, "%d\t%lld\t", K - 1, (long long)c->done[K - 1].m);
        cfpo_trace_write_values(c->trace, cfpo_trace_columns, row, CFPO_TRACE_COLUMNS, 1);
        if (c->classes) /* (the classes' sweeps measure classes, not prefixes: the worst finished prefix) */
            fprintf(c->trace, "\t%lld\t%.9f\n", (long long)c->worst_m, c->worst_min);
        else
            fprintf(c->trace, "\t%lld\t%.9f\n", (long long)wm, dmin[w]);
    }
    cli_progress_line(&c->prog, 0, "%s of levels 0-%d  sweep %d  worst group %lld: %.4f  full set %.4f / %.4f  moved %lld  "
                      "elapsed %.1fs", c->tag[0] == 'P' ? "polish" : "joint move", K - 1, sweep, (long long)wm,
                      dmin[w], dmin[NG - 1], davg[NG - 1], (long long)moved, el);
}

/* One sweep of the polish: a POLISH line (as on_sweep's). */
static void on_polish(int sweep, int64_t moved, const double *dmin, const double *davg, int NG, void *user)
{
    prog_ctx *c = user;
    c->tag = "POLISH";
    on_sweep(sweep, moved, dmin, davg, NG, user);
}

/* The trace's rows into a memory stream, its file written whole at the end. */
static int commit_trace(const char *path, const char *buf, size_t len, char *err, size_t errlen)
{
    cli_atomic a;
    if (cli_atomic_open(&a, path, err, errlen) != 0) return -1;
    if (fwrite(buf, 1, len, a.f) != len) {
        cli_atomic_abort(&a);
        snprintf(err, errlen, "%s: write failed", path);
        return -1;
    }
    return cli_atomic_commit(&a, err, errlen);
}

int prog_cli_main(prog_cli *pc, const char *prog, int64_t n, cfpo_options *o, const char *out, const char *trace,
                  int quiet, const char *checkpoint, int every, const char *resume)
{
    char err[600];
    if (pc->p.classes > 0 && !pc->p.classes_levels && (checkpoint || resume))
        cli_usage_error(prog, "%s does not go with --classes (by colouring; --classes-levels takes it)",
                        checkpoint ? "--checkpoint" : "--resume");
    cfpo_runfiles *files = cfpo_runfiles_open(out, NULL, checkpoint, n, err, sizeof err);
    if (!files) cli_fail(prog, "%s", err);
    cfpo_prog_level levels[CFPO_PROG_MAX_LEVELS];
    prog_ctx ctx = {.done = levels, .worst_min = INFINITY, .worst_m = -1, .tag = "JOINT"};
    char *tbuf = NULL;
    size_t tlen = 0;
    const int root = comm_rank() == 0; /* several ranks: rank 0 reports, every rank writes its part of the output */
    if (trace && root) {
        ctx.trace = open_memstream(&tbuf, &tlen);
        if (!ctx.trace) cli_fail(prog, "out of memory for the trace");
        fprintf(ctx.trace, "level\tprefix\t");
        cfpo_trace_write_names(ctx.trace, cfpo_trace_columns, CFPO_TRACE_COLUMNS, 1);
        fprintf(ctx.trace, "\tworst_prefix\tworst_delta_min\n");
    }
    cli_progress_init(&ctx.prog, quiet || !root);
    o->progress = on_iteration;
    o->user = &ctx;
    char *jbuf = NULL;
    size_t jlen = 0;
    if (pc->p.joint.sweeps > 0 || pc->p.joint_last > 0 || pc->p.polish > 0 || (pc->p.classes > 0 && !pc->p.classes_levels)) {
        ctx.joint = open_memstream(&jbuf, &jlen);
        if (!ctx.joint) cli_fail(prog, "out of memory for the JOINT lines");
        pc->p.joint.sweep_done = on_sweep;
        pc->p.polish_sweep = on_polish;
        ctx.classes = pc->p.classes > 0;
        pc->p.joint.user = &ctx;
    }
    cfpo_prog_colour_options colour = {.passes_run = -1};
    pc->p.colour_out = &colour;
    pc->p.level_begin = level_begin;
    pc->p.user = &ctx;
    pc->p.checkpoint = checkpoint;
    pc->p.checkpoint_every = every;
    pc->p.resume = resume;
    ctx.t0 = cli_now();
    if (checkpoint) runsignal_install(); /* SIGTERM, SIGUSR1: a checkpoint, then stop */
    cfpo_run_engine R;
    cfpo_result res;
    int K = 0;
    int rc = cfpo_prog_run(n, o, &pc->p, &R, &res, levels, &K, err, sizeof err);
    runsignal_restore();
    cli_progress_end(&ctx.prog);
    const double seconds = cli_now() - ctx.t0;
    if (ctx.trace) fclose(ctx.trace);
    if (ctx.joint) fclose(ctx.joint);
    if (rc != 0) free(jbuf);
    if (rc == 1) { /* stopped by a signal after the checkpoint */
        free(tbuf);
        cfpo_runfiles_abort(files);
        if (root)
            fprintf(stderr, "%s: stopped by a signal at level %d (prefix %lld); checkpoint %s written, no output; "
                "continue with --resume %s\n", prog, K - 1, (long long)levels[K - 1].m, checkpoint, checkpoint);
        return 3;
    }
    if (rc != 0) {
        free(tbuf);
        cfpo_runfiles_abort(files);
        cli_fail(prog, "%s", err);
    }
    if (cfpo_runfiles_commit(files, &R, err, sizeof err) != 0) {
        free(tbuf);
        R.ops->free(R.E);
        cli_fail(prog, "%s", err);
    }
    if (trace && root && commit_trace(trace, tbuf, tlen, err, sizeof err) != 0) {
        free(tbuf);
        R.ops->free(R.E);
        cli_fail(prog, "%s", err);
    }
    free(tbuf);
    uint64_t peak, peak_max; /* (collective) */
    cfpo_plan_peak_memory(&peak, &peak_max);
    if (!root) {
        free(jbuf);
        R.ops->free(R.E);
        return 0;
    }
    int64_t iters = 0;
    for (int k = 0; k < K; k++) {
        const cfpo_prog_level *L = &levels[k];
        if (L->iterations > 0) iters += L->iterations;
        char its[32] = "-", d0[32] = "-";
        if (L->iterations >= 0) snprintf(its, sizeof its, "%d", L->iterations);
        if (!isnan(L->delta_min0)) snprintf(d0, sizeof d0, "%.6f", L->delta_min0);
        printf("LEVEL level=%d prefix=%lld iterations=%s seconds=%.6f start_delta_min=%s delta_min=%.6f "
               "delta_avg=%.6f\n", k, (long long)L->m, its, L->seconds, d0, L->delta_min, L->delta_avg);
    }
    if (colour.passes_run >= 0)
        printf("COLOUR passes=%d restores=%lld close_start=%lld close_end=%lld cpu_seconds=%.6f\n",
               colour.passes_run, (long long)colour.restores, (long long)colour.close_start,
               (long long)colour.close_end, colour.cpu_seconds);
    if (jbuf) fwrite(jbuf, 1, jlen, stdout);
    free(jbuf);
    int wm, wa;
    cfpo_prog_worst(levels, K, &wm, &wa);
    char extra[256];
    snprintf(extra, sizeof extra, " levels=%d worst_prefix_min=%lld worst_delta_min=%.6f worst_prefix_avg=%lld "
             "worst_delta_avg=%.6f", K, (long long)levels[wm].m, levels[wm].delta_min, (long long)levels[wa].m,
             levels[wa].delta_avg);
    cli_summary sm = {.method = pc->p.classes ? "cfpo-classes" : "cfpo-progressive",
                      .variant = cfpo_variant_name(o->variant), .n = n, .seed = o->seed,
                      .threads = o->threads > 0 ? o->threads : omp_get_num_procs(), .ranks = comm_size(),
                      .iterations = iters, .seconds = seconds, .delta_min = res.delta_min,
                      .delta_avg = res.delta_avg, .converged = res.converged, .peak_bytes = peak,
                      .stop = cfpo_stop_name(res.stop)};
    cli_print_summary_ex(stdout, &sm, extra);
    R.ops->free(R.E);
    return 0;
}
