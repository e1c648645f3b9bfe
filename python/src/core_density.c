/* core_density.c - cfpo._core.run_density: one CFPO run under a density,
 * the way `cfpo --density` runs it (src/main_density.c: the density from
 * a SPEC string or a 2-D array, the same default tolerance, start, checks
 * and points in id order), with the per-iteration callback of
 * core_sample.c; and the density of a SPEC string or an array
 * (core_density_in), which the density measures share. */
#include "core.h"

#include <string.h>

#include "cli.h"
#include "dens_engine.h"
#include "density.h"
#include "stoprule.h"

#define DENS_TOL 1e-4 /* src/main_density.c's default */

int core_density_in(PyObject *dens, cfpo_density *d)
{
    if (dens == Py_None) return 0;
    char err[1024];
    int rc;
    if (PyUnicode_Check(dens)) {
        const char *spec = PyUnicode_AsUTF8(dens);
        if (!spec) return -1;
        Py_BEGIN_ALLOW_THREADS
        rc = cfpo_density_load(spec, d, err, sizeof err);
        Py_END_ALLOW_THREADS
    } else {
        PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(dens, NPY_FLOAT64, 2, 2, NPY_ARRAY_IN_ARRAY);
        if (!a) return -1;
        rc = cfpo_density_from_values((const double *)PyArray_DATA(a), (int64_t)PyArray_DIM(a, 1),
                                      (int64_t)PyArray_DIM(a, 0), "density", d, err, sizeof err);
        Py_DECREF(a);
    }
    if (rc != 0) {
        core_error(PyExc_ValueError, err);
        return -1;
    }
    return 1;
}

PyObject *core_run_density(PyObject *self, PyObject *args)
{
    (void)self;
    long long n;
    unsigned long long seed;
    int threads, max_iter, want_trace;
    double tol, tmin, tavg, tlimit;
    PyObject *init, *callback, *dens;
    if (!PyArg_ParseTuple(args, "LKididddOOpO", &n, &seed, &threads, &tol, &max_iter, &tmin, &tavg, &tlimit, &init,
                          &callback, &want_trace, &dens))
        return NULL;
    cfpo_options o;
    if (core_options_of(&o, seed, "adaptive", threads, tol >= 0 ? tol : DENS_TOL, max_iter, tmin, tavg, tlimit) != 0)
        return NULL;
    char err[1024];
    cfpo_density d;
    int rc;
    const int got = core_density_in(dens, &d);
    if (got <= 0) return got == 0 ? core_error(PyExc_TypeError, "density: expected a SPEC or an array, got None") : NULL;
    PyArrayObject *start = NULL;
    if (init != Py_None) {
        size_t m;
        if (!(start = core_points_in(init, &m))) { cfpo_density_free(&d); return NULL; }
        if (n >= 0 && (size_t)n != m) {
            Py_DECREF(start);
            cfpo_density_free(&d);
            return PyErr_Format(PyExc_ValueError, "init: the array holds %zu points, n says %lld; "
                                "leave n out or give the same", m, n);
        }
        n = (long long)m;
    }
    if (n < 0 || cfpo_density_check_n(&d, n, err, sizeof err) != 0) {
        Py_XDECREF(start);
        cfpo_density_free(&d);
        return n < 0 ? PyErr_Format(PyExc_ValueError, "the number of points is required: n")
                     : core_error(PyExc_ValueError, err);
    }
    core_run_ctx c = {.callback = callback, .want_trace = want_trace, .trace = {.cols = CFPO_TRACE_COLUMNS}};
    o.progress = core_on_iteration;
    o.user = &c;
    cfpo_result res;
    rc = -1;
    c.t0 = cli_now();
    c.ts = PyEval_SaveThread();
    cfpo_dens_engine *E = cfpo_dens_create(&d, n, &o, start ? (const double *)PyArray_DATA(start) : NULL, 0, err,
                                           sizeof err);
    const int created = E != NULL;
    if (E) rc = cfpo_dens_run(E, &res, 0, NULL, NULL, err, sizeof err);
    const double seconds = cli_now() - c.t0;
    PyEval_RestoreThread(c.ts);
    Py_XDECREF(start);
    PyObject *points = NULL;
    if (!c.failed && rc == 0) {
        double *xy;
        points = core_points_new((size_t)n, &xy);
        if (points) memcpy(xy, cfpo_dens_points(E), (size_t)n * 2 * sizeof *xy);
    }
    cfpo_dens_free(E);
    cfpo_density_free(&d);
    return core_run_result(&c, rc, created, err, points, &res, seconds);
}
