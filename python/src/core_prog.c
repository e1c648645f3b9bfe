/* core_prog.c - cfpo._core.progressive: the run of `cfpo --progressive`
 * and `cfpo --classes K` (src/main_prog.c) through progressive.h, with the
 * same options, defaults and checks, the points in prefix order and the
 * per-level results; the per-iteration callback in Python's hands. */
#include "core.h"

#include <string.h>

#include "cfpo.h"
#include "cli.h"
#include "plan.h"
#include "progressive.h"
#include "stoprule.h"

/* progressive(n, seed, variant, threads, tol, max_iter, target_min,
 * target_avg, base, classes, level_min, relax, joint, joint_last,
 * balance, callback) -> (points,
 * iterations, seconds, delta_min, delta_avg, converged, stop, levels):
 * levels a list of (prefix, iterations, delta_min, delta_avg). balance as
 * cfpo_prog_options.balance: 0 the default leaf size, < 0 off. */
PyObject *core_progressive(PyObject *self, PyObject *args)
{
    (void)self;
    long long n, base;
    unsigned long long seed;
    const char *variant;
    int threads, max_iter, classes, relax, joint, joint_last, balance;
    double tol, tmin, tavg, level_min;
    PyObject *callback;
    if (!PyArg_ParseTuple(args, "LKsididdLidiiiiO", &n, &seed, &variant, &threads, &tol, &max_iter, &tmin, &tavg,
                          &base, &classes, &level_min, &relax, &joint, &joint_last, &balance, &callback))
        return NULL;
    cfpo_options o;
    if (core_options_of(&o, seed, variant, threads, tol, max_iter, tmin, tavg, 0) != 0) return NULL;
    if (o.variant == CFPO_VARIANT_HYPERUNIFORM) {
        PyErr_Format(PyExc_ValueError, "variant hyperuniform does not go with %s", classes ? "classes" : "progressive");
        return NULL;
    }
    cfpo_prog_options p = {.base = base, .classes = classes, .level_min = level_min, .relax = relax,
                           .joint = {.sweeps = joint}, .joint_last = joint_last, .balance = balance};
    char err[1024];
    int64_t sizes[CFPO_PROG_MAX_LEVELS];
    if (cfpo_prog_sizes(n, o.variant, &p, sizes, err, sizeof err) < 0) return core_error(PyExc_ValueError, err);
    const int vr = cfpo_plan_check(n, &o, 0, 0, err, sizeof err);
    if (vr != 0) return core_error(vr == -2 ? PyExc_MemoryError : PyExc_ValueError, err);
    core_run_ctx c = {.callback = callback, .want_trace = 0, .trace = {.cols = CFPO_TRACE_COLUMNS}};
    o.progress = core_on_iteration;
    o.user = &c;
    cfpo_prog_level levels[CFPO_PROG_MAX_LEVELS];
    int K = 0;
    cfpo_run_engine R;
    cfpo_result res;
    c.t0 = cli_now();
    c.ts = PyEval_SaveThread();
    const int rc = cfpo_prog_run(n, &o, &p, &R, &res, levels, &K, err, sizeof err);
    const double seconds = cli_now() - c.t0;
    PyEval_RestoreThread(c.ts);
    PyObject *points = NULL;
    if (rc == 0) {
        if (!c.failed) {
            double *xy;
            points = core_points_new((size_t)n, &xy);
            if (points) R.ops->copy(R.E, xy);
        }
        R.ops->free(R.E);
    }
    if (c.failed || rc != 0 || !points) {
        Py_XDECREF(points);
        if (!c.failed && rc != 0) core_error(PyExc_RuntimeError, err);
        return NULL;
    }
    int64_t iters = 0;
    PyObject *lv = PyList_New(K);
    if (!lv) {
        Py_DECREF(points);
        return NULL;
    }
    for (int k = 0; k < K; k++) {
        iters += levels[k].iterations;
        PyList_SET_ITEM(lv, k, Py_BuildValue("(Lidd)", (long long)levels[k].m, levels[k].iterations,
                                             levels[k].delta_min, levels[k].delta_avg));
    }
    return Py_BuildValue("(NLdddNsN)", points, (long long)iters, seconds, res.delta_min, res.delta_avg,
                         PyBool_FromLong(res.converged), cfpo_stop_name(res.stop), lv);
}
