/* core_measures.c - cfpo._core.discrepancy and lowfreq: the measures of
 * analysis/measures/ for one set, the calls cfpo-analyze makes
 * (analysis/main.c), so the numbers are the command's. */
#include "core.h"

#include "discrepancy.h"
#include "lowfreq.h"
#include "power.h"
#include "rings.h"
#include "shiftvar.h"

/* discrepancy(points) -> (wrap_l2, diaphony, l2_star, generalized_l2,
 * centred_l2), square roots. */
PyObject *core_discrepancy(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    an_discrepancy d;
    char err[512];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = an_discrepancy_compute((const double *)PyArray_DATA(a), n, &d, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) return core_error(PyExc_ValueError, err);
    return Py_BuildValue("(ddddd)", d.wrap_l2, d.diaphony, d.l2_star, d.generalized_l2, d.centred_l2);
}

/* lowfreq(P, n) for a (2K+1, 2K+1) float64 periodogram -> ((range, P0,
 * P0 count, H, intercept, peak, peak ring, alpha, rings), {integrand:
 * (variance, tail)}). */
PyObject *core_lowfreq(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    Py_ssize_t n;
    if (!PyArg_ParseTuple(args, "On", &obj, &n)) return NULL;
    PyArrayObject *P = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!P) return NULL;
    const npy_intp side = PyArray_DIM(P, 0);
    if (n < 1 || side < 3 || side % 2 == 0 || PyArray_DIM(P, 1) != side) {
        Py_DECREF(P);
        return PyErr_Format(PyExc_ValueError, "power: not a (2K+1, 2K+1) periodogram, or n < 1");
    }
    const int K = (int)((side - 1) / 2);
    const double *p = PyArray_DATA(P);
    an_rings rings;
    an_lowfreq lf;
    an_shiftvar sv;
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = an_rings_compute(p, K, &rings);
    if (rc == 0) {
        rc = an_lowfreq_compute(p, K, (size_t)n, &rings, &lf);
        an_rings_free(&rings);
    }
    if (rc == 0) an_shiftvar_compute(p, K, (size_t)n, &sv);
    Py_END_ALLOW_THREADS
    Py_DECREF(P);
    if (rc != 0) return PyErr_NoMemory();
    PyObject *vars = PyDict_New();
    for (int t = 0; vars && t < AN_SHIFTVAR_COUNT; t++) {
        PyObject *v = Py_BuildValue("(dd)", sv.var[t], sv.tail[t]);
        if (!v || PyDict_SetItemString(vars, an_integrands[t].name, v) != 0) Py_CLEAR(vars);
        Py_XDECREF(v);
    }
    if (!vars) return NULL;
    return Py_BuildValue("((ddLdddidi)N)", lf.range, lf.p0, (long long)lf.p0_count, lf.h, lf.s0, lf.peak,
                         lf.peak_ring, lf.alpha, lf.rings, vars);
}
