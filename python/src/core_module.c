/* core_module.c - the extension module cfpo._core: its table of functions,
 * the shared helpers of core.h, and the point files (load, save) through
 * the suite's one point-file module (src/pointfile.h). */
#define CFPO_PY_IMPORT_ARRAY
#include "core.h"

#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "pointfile.h"

PyObject *core_error(PyObject *type, const char *msg)
{
    if (strstr(msg, "out of memory") || strstr(msg, "too large for memory")) type = PyExc_MemoryError;
    PyErr_SetString(type, msg);
    return NULL;
}

PyArrayObject *core_points_in(PyObject *obj, size_t *n)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!a) return NULL;
    if (PyArray_DIM(a, 1) != 2) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "points must be an (n, 2) array");
        return NULL;
    }
    *n = (size_t)PyArray_DIM(a, 0);
    return a;
}

PyObject *core_points_new(size_t n, double **data)
{
    npy_intp dims[2] = {(npy_intp)n, 2};
    PyObject *a = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (a) *data = (double *)PyArray_DATA((PyArrayObject *)a);
    return a;
}

static void free_capsule(PyObject *cap) { free(PyCapsule_GetPointer(cap, NULL)); }

PyObject *core_adopt(double *v, int nd, const npy_intp *dims)
{
    PyObject *cap = PyCapsule_New(v, NULL, free_capsule);
    if (!cap) {
        free(v);
        return NULL;
    }
    PyObject *a = PyArray_SimpleNewFromData(nd, (npy_intp *)dims, NPY_DOUBLE, v);
    if (!a || PyArray_SetBaseObject((PyArrayObject *)a, cap) != 0) {
        Py_XDECREF(a);
        Py_DECREF(cap);
        return NULL;
    }
    return a;
}

PyObject *core_points_adopt(double *xy, size_t n)
{
    const npy_intp dims[2] = {(npy_intp)n, 2};
    return core_adopt(xy, 2, dims);
}

int core_interrupted(void) { return PyErr_CheckSignals() != 0; }

void core_trace_add(core_trace *t, const double *row)
{
    if (t->oom) return;
    if (t->rows == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        double *v = realloc(t->v, cap * TRACE_COLS * sizeof *v);
        if (!v) {
            t->oom = 1;
            return;
        }
        t->v = v;
        t->cap = cap;
    }
    memcpy(t->v + t->rows * TRACE_COLS, row, TRACE_COLS * sizeof *row);
    t->rows++;
}

PyObject *core_trace_take(core_trace *t, int cols)
{
    if (t->oom) {
        free(t->v);
        t->v = NULL;
        return PyErr_NoMemory();
    }
    PyObject *tup = PyTuple_New(cols);
    for (int c = 0; tup && c < cols; c++) {
        const int whole = c == 0 || c == 3 || c == 4 || c == 9; /* iteration, moved, solved, near */
        npy_intp dim = (npy_intp)t->rows;
        PyObject *a = PyArray_SimpleNew(1, &dim, whole ? NPY_INT64 : NPY_DOUBLE);
        if (!a) {
            Py_CLEAR(tup);
            break;
        }
        void *d = PyArray_DATA((PyArrayObject *)a);
        for (size_t r = 0; r < t->rows; r++) {
            const double v = t->v[r * TRACE_COLS + c];
            if (whole) ((int64_t *)d)[r] = (int64_t)v;
            else ((double *)d)[r] = v;
        }
        PyTuple_SET_ITEM(tup, c, a);
    }
    free(t->v);
    t->v = NULL;
    return tup;
}

/* load(path) -> (n, 2) float64 array. */
static PyObject *core_load(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *pathobj;
    if (!PyArg_ParseTuple(args, "O&", PyUnicode_FSConverter, &pathobj)) return NULL;
    const char *path = PyBytes_AS_STRING(pathobj);
    double *xy = NULL;
    size_t n = 0;
    char err[1024];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = pf_read(path, &xy, &n, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(pathobj);
    if (rc != 0) {
        if (strstr(err, "cannot open") || strstr(err, "not a regular file") || strstr(err, "read error"))
            return core_error(PyExc_OSError, err);
        return core_error(PyExc_ValueError, err);
    }
    return core_points_adopt(xy, n);
}

/* save(path, points): atomically, format from the extension. */
static PyObject *core_save(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *pathobj, *obj;
    if (!PyArg_ParseTuple(args, "O&O", PyUnicode_FSConverter, &pathobj, &obj)) return NULL;
    size_t n;
    PyArrayObject *a = core_points_in(obj, &n);
    if (!a) {
        Py_DECREF(pathobj);
        return NULL;
    }
    const char *path = PyBytes_AS_STRING(pathobj);
    char err[1024];
    int rc;
    const int known = pf_format_of(path) != PF_UNKNOWN;
    Py_BEGIN_ALLOW_THREADS
    rc = known ? pf_write(path, (const double *)PyArray_DATA(a), n, err, sizeof err) : -1;
    Py_END_ALLOW_THREADS
    Py_DECREF(a);
    if (!known) snprintf(err, sizeof err, "%s: unknown output format (use %s)", path, PF_EXTENSIONS);
    Py_DECREF(pathobj);
    if (rc != 0) return core_error(known ? PyExc_OSError : PyExc_ValueError, err);
    Py_RETURN_NONE;
}

/* format_of(path) -> "text", "csv", "npy", "raw" or "unknown". */
static PyObject *core_format_of(PyObject *self, PyObject *args)
{
    (void)self;
    const char *path;
    if (!PyArg_ParseTuple(args, "s", &path)) return NULL;
    return PyUnicode_FromString(pf_format_name(pf_format_of(path)));
}

static PyMethodDef methods[] = {
    {"run", core_run, METH_VARARGS, "CFPO run (see cfpo.run)."},
    {"deltas", core_deltas, METH_VARARGS, "Nearest-neighbour statistics (see cfpo.analysis.deltas)."},
    {"spectrum", core_spectrum, METH_VARARGS, "Power spectrum and its measures (see cfpo.analysis.spectrum)."},
    {"certify", core_certify, METH_VARARGS, "FPD certificate (see cfpo.analysis.certify)."},
    {"discrepancy", core_discrepancy, METH_VARARGS, "L2 discrepancies (see cfpo.analysis.discrepancy)."},
    {"lowfreq", core_lowfreq, METH_VARARGS, "Low-frequency measures and shift variances of a periodogram."},
    {"poisson", core_poisson, METH_VARARGS, "Poisson-disk baselines (see cfpo.baselines)."},
    {"iterative", (PyCFunction)(void (*)(void))core_iterative, METH_VARARGS | METH_KEYWORDS,
     "Iterative baselines (see cfpo.baselines)."},
    {"load", core_load, METH_VARARGS, "Reads a point file (see cfpo.load)."},
    {"save", core_save, METH_VARARGS, "Writes a point file (see cfpo.save)."},
    {"format_of", core_format_of, METH_VARARGS, "The point-file format of a file name."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_core",
                                    "The C library of cfpo (sampler, analysis, baselines, point files).",
                                    -1, methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__core(void)
{
    import_array();
    PyObject *m = PyModule_Create(&module);
    if (!m) return NULL;
    if (PyModule_AddStringConstant(m, "version", CFPO_VERSION) != 0 ||
        PyModule_AddStringConstant(m, "extensions", PF_EXTENSIONS) != 0 ||
        PyModule_AddIntConstant(m, "default_max_iter", CFPO_DEFAULT_MAX_ITER) != 0 ||
        PyModule_AddObject(m, "tol_max", PyFloat_FromDouble(CFPO_TOL_MAX)) != 0 ||
        core_baselines_defaults(m) != 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
