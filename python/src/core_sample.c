/* core_sample.c - cfpo._core.run: one CFPO run, with or without a
 * density, through the one engine interface and run loop, the way the
 * `cfpo` command runs it (src/main.c: the same options, defaults, checks,
 * start and points in id order), with the per-iteration callback in
 * Python's hands: Ctrl-C, the caller's callback and the trace. */
#include "core.h"

#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "engine.h"
#include "engines.h"
#include "run_loop.h"
#include "plan.h"
#include "stoprule.h"

/* Called by the engine after every iteration, on the calling thread with
 * the GIL released: takes the GIL for the checks only. */
int core_on_iteration(const cfpo_iter_stats *s, void *user)
{
    core_run_ctx *c = user;
    const double el = cli_now() - c->t0;
    if (c->want_trace) {
        double row[CFPO_TRACE_COLUMNS];
        cfpo_trace_values(s, el, row);
        core_trace_add(&c->trace, row);
    }
    PyEval_RestoreThread(c->ts);
    int stop = 0;
    if (!c->failed && core_interrupted()) c->failed = 1;
    if (!c->failed && c->callback != Py_None) {
        PyObject *d = core_stats_dict(s, el, CFPO_TRACE_COLUMNS);
        PyObject *r = d ? PyObject_CallOneArg(c->callback, d) : NULL;
        Py_XDECREF(d);
        if (!r) c->failed = 1;
        else {
            stop = PyObject_IsTrue(r);
            Py_DECREF(r);
            if (stop < 0) c->failed = 1;
        }
    }
    c->ts = PyEval_SaveThread();
    return c->failed || stop > 0;
}

/* The options of a run from the arguments (already checked by the Python
 * layer); ValueError with the command's wording for what the library
 * refuses. */
int core_options_of(cfpo_options *o, unsigned long long seed, const char *variant, int threads,
                      double tol, int max_iter, double tmin, double tavg, double tlimit)
{
    cfpo_options_init(o);
    o->seed = seed;
    if (cfpo_variant_parse(variant, &o->variant) != 0) {
        PyErr_Format(PyExc_ValueError, "variant: '%s' is not one of adaptive, paper, simplified, hyperuniform", variant);
        return -1;
    }
    o->tol = tol >= 0 ? tol : cfpo_default_tol(o->variant);
    o->threads = threads > 0 ? threads : 0;
    if (max_iter >= 0) o->max_iter = max_iter;
    o->stop.target_min = tmin;
    o->stop.target_avg = tavg;
    o->stop.time_limit = tlimit;
    return 0;
}

/* The start of --init (or None) into *start and n; -1 with an exception. */
static int take_init(PyObject *init, long long *n, PyArrayObject **start)
{
    *start = NULL;
    if (init == Py_None) return 0;
    size_t m;
    if (!(*start = core_points_in(init, &m))) return -1;
    if (*n >= 0 && (size_t)*n != m) {
        Py_CLEAR(*start);
        PyErr_Format(PyExc_ValueError, "init: the array holds %zu points, n says %lld; leave n out or give the same",
                     m, *n);
        return -1;
    }
    *n = (long long)m;
    return 0;
}

/* What the command checks before a run (src/main.c): n for the density,
 * or the plan's memory without one. 0, or -1 with an exception. */
static int check_run(long long n, const cfpo_options *o, const cfpo_density *d)
{
    char err[1024];
    if (n < 0) {
        PyErr_Format(PyExc_ValueError, "the number of points is required: n");
        return -1;
    }
    if (d && !cfpo_density_is_flat(d)) {
        if (cfpo_density_check_n(d, n, err, sizeof err) == 0) return 0;
        core_error(PyExc_ValueError, err);
        return -1;
    }
    const int vr = cfpo_plan_check(n, o, 0, 0, err, sizeof err);
    if (vr == 0) return 0;
    core_error(vr == -2 ? PyExc_MemoryError : PyExc_ValueError, err);
    return -1;
}

PyObject *core_run(PyObject *self, PyObject *args)
{
    (void)self;
    long long n;
    unsigned long long seed;
    const char *variant;
    int threads, max_iter, want_trace;
    double tol, tmin, tavg, tlimit;
    PyObject *init, *callback, *dens;
    if (!PyArg_ParseTuple(args, "LKsididddOOpO", &n, &seed, &variant, &threads, &tol, &max_iter, &tmin, &tavg,
                          &tlimit, &init, &callback, &want_trace, &dens))
        return NULL;
    cfpo_options o;
    if (core_options_of(&o, seed, variant, threads, tol, max_iter, tmin, tavg, tlimit) != 0) return NULL;
    cfpo_density d;
    const int got = core_density_in(dens, &d);
    if (got < 0) return NULL;
    const cfpo_density *dp = got ? &d : NULL;
    if (tol < 0) o.tol = cfpo_engines_default_tol(o.variant, dp);
    cfpo_engine_config cfg;
    memset(&cfg, 0, sizeof cfg);
    PyArrayObject *start;
    if (take_init(init, &n, &start) != 0 || check_run(n, &o, dp) != 0) {
        Py_XDECREF(start);
        if (dp) cfpo_density_free(&d);
        return NULL;
    }
    if (start) cfg.start_xy = (const double *)PyArray_DATA(start);
    char err[1024];
    core_run_ctx c = {.callback = callback, .want_trace = want_trace, .trace = {.cols = CFPO_TRACE_COLUMNS}};
    o.progress = core_on_iteration;
    o.user = &c;
    o.lazy_measure = !want_trace && callback == Py_None; /* as the command: nothing shows each iteration's deltas */
    cfpo_result res;
    int rc = -1;
    c.t0 = cli_now();
    c.ts = PyEval_SaveThread();
    cfpo_run_engine R;
    const int created = cfpo_engines_open(n, &o, &cfg, dp, c.t0, &R, err, sizeof err) == 0;
    if (created) rc = cfpo_run_loop(&R, NULL, 0, &res, err, sizeof err);
    const double seconds = cli_now() - c.t0;
    PyEval_RestoreThread(c.ts);
    Py_XDECREF(start);
    PyObject *points = NULL;
    if (!c.failed && rc == 0) {
        double *xy;
        points = core_points_new((size_t)n, &xy);
        if (points) {
            Py_BEGIN_ALLOW_THREADS
            R.ops->copy(R.E, xy);
            Py_END_ALLOW_THREADS
        }
    }
    if (created) R.ops->free(R.E);
    if (dp) cfpo_density_free(&d);
    return core_run_result(&c, rc, created, err, points, &res, seconds);
}

/* The end of a run (core_run): the failure as an exception
 * (RuntimeError once the engine was created, ValueError before; none when the
 * callback or an interrupt already raised one), else the tuple (points,
 * iterations, seconds, delta_min, delta_avg, converged, stop, trace or
 * None). Takes the reference to points. */
PyObject *core_run_result(core_run_ctx *c, int rc, int created, const char *err, PyObject *points,
                          const cfpo_result *res, double seconds)
{
    PyObject *trace;
    if (c->failed || rc != 0 || !points) {
        free(c->trace.v);
        Py_XDECREF(points);
        if (!c->failed && rc != 0) core_error(created ? PyExc_RuntimeError : PyExc_ValueError, err);
        return NULL;
    }
    if (c->want_trace) {
        if (!(trace = core_trace_take(&c->trace, cfpo_trace_columns, CFPO_TRACE_COLUMNS, NULL))) {
            Py_DECREF(points);
            return NULL;
        }
    } else {
        trace = Py_NewRef(Py_None);
    }
    return Py_BuildValue("(NidddNsN)", points, res->iterations, seconds, res->delta_min, res->delta_avg,
                         PyBool_FromLong(res->converged), cfpo_stop_name(res->stop), trace);
}
