/* core_measures.c - cfpo._core.discrepancy, lowfreq, pcf, delaunay,
 * integration and prefixes: the measures of
 * analysis/measures/ for one set, the calls cfpo-analyze makes
 * (analysis/main.c), so the numbers are the command's. */
#include "core.h"

#include "delaunay.h"
#include "discrepancy.h"
#include "integration.h"
#include "lowfreq.h"
#include "pcf.h"
#include "power.h"
#include "prefixes.h"
#include "rings.h"
#include "shiftvar.h"

/* The measures of one point set that give five numbers: the set from the
 * single argument, the measure run with the GIL released, its five numbers
 * as a tuple (ValueError with the measure's message on failure). */
typedef int (*five_fn)(const double *xy, size_t n, double out[5], char *err, size_t errlen);

static PyObject *five_of_points(PyObject *args, five_fn fn)
{
    PyObject *obj;
    if (!PyArg_ParseTuple(args, "O", &obj)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    double v[5];
    char err[512];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = fn((const double *)PyArray_DATA(a), n, v, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) return core_error(PyExc_ValueError, err);
    return Py_BuildValue("(ddddd)", v[0], v[1], v[2], v[3], v[4]);
}

static int discrepancy5(const double *xy, size_t n, double out[5], char *err, size_t errlen)
{
    an_discrepancy d;
    if (an_discrepancy_compute(xy, n, &d, err, errlen) != 0) return -1;
    out[0] = d.wrap_l2, out[1] = d.diaphony, out[2] = d.l2_star, out[3] = d.generalized_l2, out[4] = d.centred_l2;
    return 0;
}

static int delaunay5(const double *xy, size_t n, double out[5], char *err, size_t errlen)
{
    an_delaunay d;
    if (an_delaunay_compute(xy, n, &d, err, errlen) != 0) return -1;
    out[0] = d.psi6, out[1] = d.area_var, out[2] = d.covering, out[3] = d.delta_min, out[4] = d.mesh_ratio;
    return 0;
}

/* discrepancy(points) -> (wrap_l2, diaphony, l2_star, generalized_l2,
 * centred_l2), square roots. */
PyObject *core_discrepancy(PyObject *self, PyObject *args)
{
    (void)self;
    return five_of_points(args, discrepancy5);
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

/* pcf(points, sigma, rmax) -> g at r_b = b sigma / 5, b = 1..B (float64
 * array; empty when no bin fits). */
PyObject *core_pcf(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    double sigma, rmax;
    if (!PyArg_ParseTuple(args, "Odd", &obj, &sigma, &rmax)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    const int B = an_pcf_bins(n, sigma, rmax);
    double *g = malloc(((size_t)B + 1) * sizeof *g);
    if (!g) {
        Py_DECREF(a);
        return PyErr_NoMemory();
    }
    int rc = 0;
    Py_BEGIN_ALLOW_THREADS
    if (B > 0) rc = an_pcf_compute((const double *)PyArray_DATA(a), n, sigma, rmax, B, g);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) {
        free(g);
        return PyErr_NoMemory();
    }
    const npy_intp dims[1] = {B};
    return core_adopt(g, 1, dims);
}

/* delaunay(points) -> (psi6, area_var, covering, delta_min, mesh_ratio),
 * covering and delta_min absolute. */
PyObject *core_delaunay(PyObject *self, PyObject *args)
{
    (void)self;
    return five_of_points(args, delaunay5);
}

/* integration(points, M, seed) -> (gauss MSE, its se, Heaviside MSE, its se). */
PyObject *core_integration(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    int M;
    unsigned long long seed;
    if (!PyArg_ParseTuple(args, "OiK", &obj, &M, &seed)) return NULL;
    if (M < 1) return core_error(PyExc_ValueError, "integrands: M must be at least 1");
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) return NULL;
    an_integration r;
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = an_integration_compute((const double *)PyArray_DATA(a), n, M, (uint64_t)seed, &r);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (rc != 0) return PyErr_NoMemory();
    return Py_BuildValue("(dddd)", r.gauss_mse, r.gauss_se, r.heaviside_mse, r.heaviside_se);
}

/* prefixes(points, base, sizes) -> ([(m, kind, delta_min, delta_avg, p0,
 * {integrand: variance}), ...], worst_any, worst_any_m); sizes: a sequence
 * of whole numbers or None (the default plan). cfpo-analyze --prefixes. */
PyObject *core_prefixes(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj, *sizes_obj;
    Py_ssize_t base;
    if (!PyArg_ParseTuple(args, "OnO", &obj, &base, &sizes_obj)) return NULL;
    if (base < 2) return core_error(PyExc_ValueError, "prefixes: base must be at least 2");
    size_t *sizes = NULL;
    Py_ssize_t ns = 0;
    if (sizes_obj != Py_None) {
        PyObject *seq = PySequence_Fast(sizes_obj, "prefixes: sizes must be a sequence of whole numbers or None");
        if (!seq) return NULL;
        ns = PySequence_Fast_GET_SIZE(seq);
        sizes = malloc(((size_t)ns + 1) * sizeof *sizes);
        if (!sizes) {
            Py_DECREF(seq);
            return PyErr_NoMemory();
        }
        for (Py_ssize_t i = 0; i < ns; i++) {
            const long long v = PyLong_AsLongLong(PySequence_Fast_GET_ITEM(seq, i));
            if (v == -1 && PyErr_Occurred()) {
                free(sizes);
                Py_DECREF(seq);
                return NULL;
            }
            if (v < 2) {
                free(sizes);
                Py_DECREF(seq);
                return core_error(PyExc_ValueError, "prefixes: every size must be at least 2");
            }
            sizes[i] = (size_t)v;
        }
        Py_DECREF(seq);
        if (ns == 0) {
            free(sizes);
            return core_error(PyExc_ValueError, "prefixes: no size");
        }
    }
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) {
        free(sizes);
        return NULL;
    }
    an_prefixes p;
    char err[512];
    int rc;
    if (n < 2) {
        Py_DECREF(a);
        free(sizes);
        return core_error(PyExc_ValueError, "prefixes: at least 2 points");
    }
    Py_BEGIN_ALLOW_THREADS
    rc = an_prefixes_compute((const double *)PyArray_DATA(a), n, (size_t)base, sizes, (int)ns, 0, &p, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    free(sizes);
    if (rc != 0) return core_error(PyExc_ValueError, err);
    static const char *kinds[] = {"dyadic", "sample", "given", "full"};
    PyObject *rows = PyList_New(p.count);
    for (int i = 0; rows && i < p.count; i++) {
        const an_prefix_row *r = &p.rows[i];
        PyObject *vars = PyDict_New();
        for (int t = 0; vars && t < AN_SHIFTVAR_COUNT; t++) {
            PyObject *v = PyFloat_FromDouble(r->var[t]);
            if (!v || PyDict_SetItemString(vars, an_integrands[t].name, v) != 0) Py_CLEAR(vars);
            Py_XDECREF(v);
        }
        PyObject *row = vars ? Py_BuildValue("(nsdddN)", (Py_ssize_t)r->m, kinds[r->kind], r->dmin, r->davg, r->p0, vars)
                             : NULL;
        if (!row) Py_CLEAR(rows);
        else PyList_SET_ITEM(rows, i, row);
    }
    const double worst = p.worst_any;
    const Py_ssize_t at = (Py_ssize_t)p.worst_any_m;
    an_prefixes_free(&p);
    if (!rows) return NULL;
    return Py_BuildValue("(Ndn)", rows, worst, at);
}
