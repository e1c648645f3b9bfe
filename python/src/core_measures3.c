/* core_measures3.c - cfpo._core's 3-D measures: the calls of
 * cfpo3d-analyze (src/d3/analyze3d.c) for one (n, 3) set, with the same
 * arguments and the same small summaries (the highest shell, the g(r)
 * range, the Voronoi means), so the numbers are the command's: delta_min
 * and delta_avg (nn3.h), Q6 with the crystal-like count (q6.h) and W6
 * (measures3_w6.h), the shell-averaged spectrum with P0
 * (measures3_spec.h), g(r) (measures3_pcf.h), and on CGAL (which the
 * package always has) the Voronoi cells (measures3_vor.h) and the FPD
 * certificate (measures3_fpd.h). */
#include "core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "measures3_fpd.h"
#include "measures3_pcf.h"
#include "measures3_spec.h"
#include "measures3_vor.h"
#include "measures3_w6.h"
#include "nn3.h"
#include "q6.h"
#include "solve3.h"

/* A C-contiguous float64 (n, 3) view of obj (checked by the Python layer),
 * at least min_n points; NULL with ValueError. */
static PyArrayObject *points3_in(PyObject *obj, size_t min_n, size_t *n)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!a) return NULL;
    if (PyArray_DIM(a, 1) != 3) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "points must be an (n, 3) array");
        return NULL;
    }
    *n = (size_t)PyArray_DIM(a, 0);
    if (*n < min_n) {
        Py_DECREF(a);
        PyErr_Format(PyExc_ValueError, "points: %zu points; at least %zu needed", *n, min_n);
        return NULL;
    }
    return a;
}

/* deltas3(points) -> (delta_min, delta_avg, nn distances (n,)). */
PyObject *core_deltas3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = points3_in(obj, 2, &n);
    if (!a) return NULL;
    double *nn = malloc(n * sizeof *nn), dmin = 0, davg = 0;
    int rc = -1;
    if (nn) {
        Py_BEGIN_ALLOW_THREADS
        rc = cfpo3_nn_stats((const double *)PyArray_DATA(a), n, nn, &dmin, &davg);
        Py_END_ALLOW_THREADS
    }
    Py_DECREF(a);
    if (rc != 0) {
        free(nn);
        return PyErr_NoMemory();
    }
    const npy_intp d = (npy_intp)n;
    return Py_BuildValue("(ddN)", dmin, davg, core_adopt(nn, 1, &d));
}

/* bond_order3(points, k, bond, bonds) -> (q6_global, q6_local, crystal,
 * crystal_fraction, w6, w6_local). */
PyObject *core_bond_order3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    int k, bonds;
    double bond;
    if (!PyArg_ParseTuple(args, "Oidi", &obj, &k, &bond, &bonds)) return NULL;
    if (k < 1 || k > 64 || bonds < 0 || bonds > 64 || !(bond >= 0 && bond <= 1))
        return PyErr_Format(PyExc_ValueError, "bond order: neighbours 1..64, bond in [0, 1], bonds 0..64");
    size_t n;
    PyArrayObject *a = points3_in(obj, (size_t)k + 1, &n);
    if (!a) return NULL;
    cfpo3_q6_result q;
    cfpo3_w6_result w;
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = cfpo3_q6((const double *)PyArray_DATA(a), n, k, bond, bonds, &q) != 0 ||
         cfpo3_w6((const double *)PyArray_DATA(a), n, k, &w) != 0;
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc) return PyErr_NoMemory();
    return Py_BuildValue("(ddLddd)", q.q6_global, q.q6_local, (long long)q.crystal, q.crystal_frac, w.w6,
                         w.w6_local);
}

/* spectrum3(points, K, exact) -> (P (S, S, S), shell means (K+1,), shell
 * counts (K+1,), p0, p0 count, peak, peak shell, K); K 0: the command's
 * default for n. */
PyObject *core_spectrum3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    int K, exact;
    if (!PyArg_ParseTuple(args, "Oip", &obj, &K, &exact)) return NULL;
    size_t n;
    PyArrayObject *a = points3_in(obj, 1, &n);
    if (!a) return NULL;
    if (K == 0) K = cfpo3_spec_default_K(n);
    if (K < 1 || K > CFPO3_SPEC_KMAX) {
        Py_DECREF(a);
        return PyErr_Format(PyExc_ValueError, "K: %d is not a whole number in 1..%d", K, CFPO3_SPEC_KMAX);
    }
    const npy_intp S = 2 * (npy_intp)K + 1, dims[3] = {S, S, S}, sl = (npy_intp)K + 1;
    PyObject *P = PyArray_SimpleNew(3, (npy_intp *)dims, NPY_DOUBLE);
    PyObject *sh = PyArray_SimpleNew(1, (npy_intp *)&sl, NPY_DOUBLE);
    long *cnt = malloc((size_t)sl * sizeof *cnt);
    if (!P || !sh || !cnt) {
        Py_DECREF(a);
        Py_XDECREF(P);
        Py_XDECREF(sh);
        free(cnt);
        return PyErr_NoMemory();
    }
    double *p = PyArray_DATA((PyArrayObject *)P), *s = PyArray_DATA((PyArrayObject *)sh), p0 = NAN;
    long c0 = 0;
    char err[512] = "out of memory for the spectrum";
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = exact ? cfpo3_power_exact((const double *)PyArray_DATA(a), n, K, p)
               : cfpo3_power_nufft((const double *)PyArray_DATA(a), n, K, p, err, sizeof err);
    if (rc == 0) {
        cfpo3_power_shells(p, K, s, cnt);
        p0 = cfpo3_power_p0(p, K, n, &c0);
    }
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    PyObject *count = rc == 0 ? PyArray_SimpleNew(1, (npy_intp *)&sl, NPY_INT64) : NULL;
    if (rc != 0 || !count || core_interrupted()) {
        Py_DECREF(P);
        Py_DECREF(sh);
        Py_XDECREF(count);
        free(cnt);
        return rc != 0 ? core_error(PyExc_ValueError, err) : NULL;
    }
    for (npy_intp i = 0; i < sl; i++) ((int64_t *)PyArray_DATA((PyArrayObject *)count))[i] = cnt[i];
    free(cnt);
    const int peak = cfpo3_power_peak(s, K); /* the command's */
    return Py_BuildValue("(NNNdldii)", P, sh, count, p0, c0, s[peak], peak, K);
}

/* pcf3(points, rmax, dr) -> g (bins,): r / Delta3(n) in bins of dr from 0,
 * rmax lowered by dr until rmax Delta3(n) < 1/2, as the command does. */
PyObject *core_pcf3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    double rmax, dr;
    if (!PyArg_ParseTuple(args, "Odd", &obj, &rmax, &dr)) return NULL;
    size_t n;
    PyArrayObject *a = points3_in(obj, 2, &n);
    if (!a) return NULL;
    const double D = cfpo3_delta_bound((double)n);
    const int bins = cfpo3_pcf_bins(n, rmax, dr); /* the command's range */
    if (bins < 1) {
        Py_DECREF(a);
        return PyErr_Format(PyExc_ValueError, "g(r): no bin of width dr = %g fits below rmax = %g and half the box "
                            "(Delta3(n) = %.3g)", dr, rmax, D);
    }
    double *g = malloc((size_t)bins * sizeof *g);
    int rc = -1;
    if (g) {
        Py_BEGIN_ALLOW_THREADS
        rc = cfpo3_pcf((const double *)PyArray_DATA(a), n, bins * dr, dr, g, bins);
        Py_END_ALLOW_THREADS
    }
    Py_DECREF(a);
    if (rc != 0) {
        free(g);
        return PyErr_NoMemory();
    }
    const npy_intp d = bins;
    return core_adopt(g, 1, &d);
}

/* voronoi3(points) -> (faces (n,) int64, volumes (n,), mean faces, their
 * standard deviation, the variance of n V). */
PyObject *core_voronoi3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = points3_in(obj, 1, &n);
    if (!a) return NULL;
    int *f = malloc(n * sizeof *f);
    double *v = malloc(n * sizeof *v);
    const npy_intp len = (npy_intp)n;
    PyObject *faces = PyArray_SimpleNew(1, (npy_intp *)&len, NPY_INT64);
    char err[512] = "out of memory for the Voronoi cells";
    int rc = -1;
    if (f && v && faces) {
        Py_BEGIN_ALLOW_THREADS
        rc = cfpo3_voronoi((const double *)PyArray_DATA(a), n, f, v, NULL, err, sizeof err);
        Py_END_ALLOW_THREADS
    }
    Py_DECREF(a);
    if (rc != 0) {
        free(f), free(v);
        Py_XDECREF(faces);
        return core_error(PyExc_ValueError, err);
    }
    double sf = 0, sf2 = 0, sv = 0, sv2 = 0; /* the command's sums, in its order */
    int64_t *fo = PyArray_DATA((PyArrayObject *)faces);
    for (size_t i = 0; i < n; i++) {
        const double nv = v[i] * (double)n;
        sf += f[i], sf2 += (double)f[i] * f[i], sv += nv, sv2 += nv * nv;
        fo[i] = f[i];
    }
    free(f);
    const double mf = sf / (double)n, mv = sv / (double)n;
    return Py_BuildValue("(NNddd)", faces, core_adopt(v, 1, &len), mf, sqrt(fmax(0, sf2 / (double)n - mf * mf)),
                         fmax(0, sv2 / (double)n - mv * mv));
}

/* certify3(points) -> (points that pass, max violation over Delta3(n),
 * each point's violation (n,)). */
PyObject *core_certify3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = points3_in(obj, 2, &n);
    if (!a) return NULL;
    cfpo3_fpd_result r;
    char err[512];
    int rc;
    double *each = malloc(n * sizeof *each);
    if (!each) {
        Py_DECREF(a);
        return PyErr_NoMemory();
    }
    Py_BEGIN_ALLOW_THREADS
    rc = cfpo3_fpd_certify((const double *)PyArray_DATA(a), n, &r, each, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) {
        free(each);
        return core_error(PyExc_ValueError, err);
    }
    const npy_intp dims[1] = {(npy_intp)n};
    PyObject *v = core_adopt(each, 1, dims);
    if (!v) return NULL;
    return Py_BuildValue("(ndN)", (Py_ssize_t)r.passed, r.max_violation, v);
}
