/* core_sample3.c - cfpo._core.run3: one run of the 3-D engine (src/d3/)
 * the way `cfpo --dim 3` runs it (src/d3/cli3.c: the same defaults, start,
 * schedule, checks and points in id order), behind the one engine
 * interface (engine3_ops.h) and through the command's schedule of rounds
 * (sched3.h), with the per-iteration callback in Python's hands
 * (core_on_iteration, core_sample.c; called once before the run and after
 * every iteration of every round). */
#include "core.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "engine3.h"
#include "engine3_ops.h"
#include "sched3.h"
#include "stoprule.h"

/* The (n, 3) start of init= (already checked by the Python layer), or
 * NULL with an exception. */
static PyArrayObject *start_of(PyObject *init, long long *n)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(init, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!a) return NULL;
    const long long m = (long long)PyArray_DIM(a, 0);
    if (PyArray_DIM(a, 1) != 3) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "init: expected an (n, 3) array of points");
        return NULL;
    }
    if (*n >= 0 && *n != m) {
        Py_DECREF(a);
        PyErr_Format(PyExc_ValueError, "init: the array holds %lld points, n says %lld; leave n out or give the same",
                     m, *n);
        return NULL;
    }
    *n = m;
    return a;
}

/* The schedule's callback: Python's, but for the set before a later
 * round's first iteration (a round starts from the shaken set). */
static int on_iter(const cfpo_iter_stats *st, int round, int first, void *user)
{
    if (first && round > 0) return 0;
    return core_on_iteration(st, user);
}

PyObject *core_run3(PyObject *self, PyObject *args)
{
    (void)self;
    long long n;
    unsigned long long seed;
    int threads, max_iter, want_trace;
    double tol, tmin, tavg, tlimit;
    PyObject *init, *callback;
    if (!PyArg_ParseTuple(args, "LKididddOOp", &n, &seed, &threads, &tol, &max_iter, &tmin, &tavg, &tlimit, &init,
                          &callback, &want_trace))
        return NULL;
    PyArrayObject *start = NULL;
    if (init != Py_None && !(start = start_of(init, &n))) return NULL;
    if (n < 0) {
        PyErr_SetString(PyExc_ValueError, "the number of points is required: n");
        return NULL;
    }
    if (n < cfpo3_grid_min_n()) { /* the command's wording (cli3.c) */
        Py_XDECREF(start);
        PyErr_Format(PyExc_ValueError, "n = %lld is too small: at least %lld points are needed in 3-D", n,
                     (long long)cfpo3_grid_min_n());
        return NULL;
    }
    cfpo3_options o3;
    cfpo3_options_default(&o3);
    o3.seed = seed;
    o3.threads = threads > 0 ? threads : 0;
    if (tol >= 0) o3.tol = tol;
    cfpo3_sched_args sa;
    memset(&sa, 0, sizeof sa);
    cfpo3_sched_default(&sa.so);
    sa.max_iter = max_iter >= 0 ? max_iter : CFPO_DEFAULT_MAX_ITER;
    cfpo_stop_rules_init(&sa.stop);
    sa.stop.target_min = tmin;
    sa.stop.target_avg = tavg;
    sa.stop.time_limit = tlimit;
    core_run_ctx c = {.callback = callback, .want_trace = want_trace, .trace = {.cols = CFPO_TRACE_COLUMNS}};
    sa.on_iter = on_iter;
    sa.user = &c;
    char err[1024] = "";
    cfpo_result res = {0};
    int rc = -1;
    double *xyz = NULL;
    c.t0 = cli_now();
    sa.t0 = c.t0;
    c.ts = PyEval_SaveThread();
    cfpo3_engine *e = start ? cfpo3_create_given((const double *)PyArray_DATA(start), n, &o3, err, sizeof err)
                            : cfpo3_create(n, &o3, err, sizeof err);
    const int created = e != NULL;
    if (e) {
        cfpo3_sched_result sr;
        rc = cfpo3_sched_run(e, &sa, &sr, err, sizeof err);
        if (rc == 0 && !c.failed && (xyz = malloc(sizeof(double) * 3 * (size_t)n)))
            memcpy(xyz, sr.best ? sr.best : cfpo3_points(sr.e), sizeof(double) * 3 * (size_t)n);
        res = (cfpo_result){.iterations = sr.iterations, .converged = sr.converged, .stop = sr.stop,
                            .delta_min = sr.dmin, .delta_avg = sr.davg};
        if (rc == 0) free(sr.best);
        cfpo3_free(sr.e);
    }
    const double seconds = cli_now() - c.t0;
    PyEval_RestoreThread(c.ts);
    Py_XDECREF(start);
    PyObject *points = NULL;
    if (rc == 0 && !c.failed) {
        if (!xyz) return PyErr_NoMemory();
        const npy_intp dims[2] = {(npy_intp)n, 3};
        points = core_adopt(xyz, 2, dims);
    }
    return core_run_result(&c, rc, created, err, points, &res, seconds);
}
