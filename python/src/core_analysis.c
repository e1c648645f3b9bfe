/* core_analysis.c - cfpo._core.deltas, spectrum and certify: the modules
 * of analysis/ that cfpo-analyze uses for one set (analysis/main.c), the
 * same calls in the same order, so the numbers are the command's. */
#include "core.h"

#include <stdlib.h>
#include <string.h>

#include "certify.h"
#include "hsd.h"
#include "nnhist.h"
#include "power.h"
#include "rings.h"

/* deltas(points) -> (delta_min, delta_avg, nn distances, histogram). */
PyObject *core_deltas(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    if (n < 2) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "points: distances need at least 2 points");
        return NULL;
    }
    npy_intp bins = AN_NN_BINS;
    PyObject *hist = PyArray_ZEROS(1, &bins, NPY_UINT64, 0);
    if (!hist) {
        Py_DECREF(a);
        return NULL;
    }
    an_nn nn;
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = an_nn_compute((const double *)PyArray_DATA(a), n, &nn,
                       (uint64_t *)PyArray_DATA((PyArrayObject *)hist));
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) {
        Py_DECREF(hist);
        return PyErr_NoMemory();
    }
    const npy_intp dim = (npy_intp)n;
    PyObject *dist = core_adopt(nn.nn, 1, &dim);
    if (!dist) {
        Py_DECREF(hist);
        return NULL;
    }
    return Py_BuildValue("(ddNN)", nn.delta_min, nn.delta_avg, dist, hist);
}

static PyObject *int64_array(const int64_t *v, npy_intp len)
{
    PyObject *a = PyArray_SimpleNew(1, &len, NPY_INT64);
    if (a) memcpy(PyArray_DATA((PyArrayObject *)a), v, (size_t)len * sizeof *v);
    return a;
}

static PyObject *double_array(const double *v, npy_intp len)
{
    PyObject *a = PyArray_SimpleNew(1, &len, NPY_DOUBLE);
    if (a) memcpy(PyArray_DATA((PyArrayObject *)a), v, (size_t)len * sizeof *v);
    return a;
}

/* spectrum(points, K, exact, width, grid) -> (P, ring counts, RAPS,
 * anisotropy, spike (ratio, kx, ky, ring, P, ring mean), peak (ring, mean),
 * hsd (eff_nyquist, r_half, r_01, oscillation, from, to, clipped), nufft
 * (width, grid, beta) or None, lattice (ratio, kx, ky, g, period,
 * frequencies, P, ring mean)); grid -1: cfpo's grid for n. */
PyObject *core_spectrum(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    int K, exact, width, grid;
    if (!PyArg_ParseTuple(args, "Oipii", &obj, &K, &exact, &width, &grid)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    if (n < 1 || K < 1 || K > AN_KMAX) {
        Py_DECREF(a);
        return PyErr_Format(PyExc_ValueError, "K: %d is not an integer in [1, %d]", K, AN_KMAX);
    }
    const npy_intp side = (npy_intp)an_side(K), dims[2] = {side, side};
    PyObject *P = PyArray_SimpleNew(2, (npy_intp *)dims, NPY_DOUBLE);
    if (!P) {
        Py_DECREF(a);
        return NULL;
    }
    double *p = PyArray_DATA((PyArrayObject *)P);
    an_nufft_info info = {0};
    an_rings rings = {0};
    an_hsd hsd = {0};
    an_lattice lat = {0};
    char err[1024];
    int rc, ring_rc = -1;
    Py_BEGIN_ALLOW_THREADS
    rc = exact ? an_power_exact((const double *)PyArray_DATA(a), n, K, p, NULL, NULL, err, sizeof err)
               : an_power_nufft((const double *)PyArray_DATA(a), n, K, width, p, &info, err, sizeof err);
    if (rc == 0 && an_rings_compute(p, K, &rings) == 0) ring_rc = an_hsd_compute(p, K, n, &rings, &hsd);
    if (ring_rc == 0) {
        const int g = an_lattice_grid(grid, n);
        an_lattice_compute(p, &rings, g, an_lattice_period(g), &lat);
    }
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) {
        Py_DECREF(P);
        return core_error(PyExc_ValueError, err);
    }
    if (ring_rc != 0) {
        an_rings_free(&rings);
        Py_DECREF(P);
        return PyErr_NoMemory();
    }
    if (core_interrupted()) {
        an_rings_free(&rings);
        Py_DECREF(P);
        return NULL;
    }
    PyObject *nufft = exact ? Py_NewRef(Py_None) : Py_BuildValue("(iid)", info.width, info.grid, info.beta);
    PyObject *r = Py_BuildValue("(NNNN(ddiiid)(id)(ddddiii)N(diiiiidd))", P, int64_array(rings.count, K + 1),
                                double_array(rings.mean, K + 1), double_array(rings.aniso_db, K + 1),
                                rings.spike_ratio, rings.spike_P, rings.spike_kx, rings.spike_ky,
                                rings.spike_ring, rings.spike_mean, rings.peak_ring, rings.peak_mean,
                                hsd.eff_nyquist, hsd.r_half, hsd.r_01, hsd.oscillation, hsd.osc_from,
                                hsd.osc_to, hsd.osc_clipped, nufft, lat.ratio, lat.kx, lat.ky, lat.g, lat.period,
                                lat.count, lat.P, lat.mean);
    an_rings_free(&rings);
    return r;
}

/* certify(points, tol) -> (pass bytes (n,), violation (n,), target (n, 2),
 * summary dict). */
PyObject *core_certify(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    double tol;
    if (!PyArg_ParseTuple(args, "Od", &obj, &tol)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    if (n < 2) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "points: the certificate needs at least 2 points");
        return NULL;
    }
    const npy_intp len = (npy_intp)n;
    PyObject *pass = PyArray_SimpleNew(1, (npy_intp *)&len, NPY_UINT8);
    double *viol = malloc(n * sizeof *viol), *target = malloc(2 * n * sizeof *target);
    if (!pass || !viol || !target) {
        Py_DECREF(a);
        Py_XDECREF(pass);
        free(viol);
        free(target);
        return pass ? PyErr_NoMemory() : NULL;
    }
    an_certificate c;
    char err[1024];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = an_certify_points((const double *)PyArray_DATA(a), n, tol, &c, viol, target,
                           (unsigned char *)PyArray_DATA((PyArrayObject *)pass), err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0 || core_interrupted()) {
        Py_DECREF(pass);
        free(viol);
        free(target);
        return rc != 0 ? core_error(PyExc_RuntimeError, err) : NULL;
    }
    PyObject *summary = Py_BuildValue(
        "{s:O,s:n,s:d,s:d,s:d,s:n,s:d,s:n,s:n,s:n,s:n,s:d,s:d}", "fpd", c.fpd ? Py_True : Py_False,
        "points", (Py_ssize_t)c.n, "tolerance", c.tol_rel, "delta", c.delta, "covering_radius", c.covering,
        "fp_pass", (Py_ssize_t)c.fp_pass, "fp_max_violation", c.fp_max_violation, "fp_worst",
        (Py_ssize_t)c.fp_worst, "p1_pass", (Py_ssize_t)c.p1_pass, "p2_pass", (Py_ssize_t)c.p2_pass,
        "lct_pass", (Py_ssize_t)c.lct_pass, "p1_max_violation", c.p1_max_violation, "p2_max_violation",
        c.p2_max_violation);
    const npy_intp d1[1] = {len}, d2[2] = {len, 2};
    return Py_BuildValue("(NNNN)", pass, core_adopt(viol, 1, d1), core_adopt(target, 2, d2), summary);
}
