/* core_util.c - the helpers of core.h that the module's files share:
 * error mapping, point arrays in and out, the interruption check and the
 * trace grown row by row. Calls nothing of the module's other files. */
#define CFPO_PY_IMPORT_ARRAY /* NumPy's C API table lives here */
#include "core.h"

#include <stdlib.h>
#include <string.h>

int core_import_numpy(void)
{
    import_array1(-1);
    return 0;
}

PyObject *core_error(PyObject *type, const char *msg)
{
    if (strstr(msg, "out of memory") || strstr(msg, "too large for memory")) type = PyExc_MemoryError;
    PyErr_SetString(type, msg);
    return NULL;
}

PyObject *core_read_error(const char *msg)
{
    const int io = strstr(msg, "cannot open") || strstr(msg, "not a regular file") || strstr(msg, "read error");
    return core_error(io ? PyExc_OSError : PyExc_ValueError, msg);
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

PyObject *core_stats_dict(const cfpo_iter_stats *s, double elapsed, int ncols)
{
    double row[CFPO_TRACE_COLUMNS];
    cfpo_trace_values(s, elapsed, row);
    PyObject *d = PyDict_New();
    for (int c = 0; d && c <= ncols; c++) {
        PyObject *v = c == ncols ? PyBool_FromLong(s->converged)
                    : cfpo_trace_is_whole(&cfpo_trace_columns[c]) ? PyLong_FromLongLong((long long)row[c])
                                                                   : PyFloat_FromDouble(row[c]);
        if (!v || PyDict_SetItemString(d, c == ncols ? "converged" : cfpo_trace_columns[c].name, v) != 0) Py_CLEAR(d);
        Py_XDECREF(v);
    }
    return d;
}

void core_trace_add(core_trace *t, const double *row)
{
    if (t->oom) return;
    if (t->rows == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        double *v = realloc(t->v, cap * (size_t)t->cols * sizeof *v);
        if (!v) {
            t->oom = 1;
            return;
        }
        t->v = v;
        t->cap = cap;
    }
    memcpy(t->v + t->rows * (size_t)t->cols, row, (size_t)t->cols * sizeof *row);
    t->rows++;
}

PyObject *core_trace_take(core_trace *t, const cfpo_trace_column *a, int na, const cfpo_trace_column *b)
{
    if (t->oom) {
        free(t->v);
        t->v = NULL;
        return PyErr_NoMemory();
    }
    PyObject *tup = PyTuple_New(t->cols);
    for (int c = 0; tup && c < t->cols; c++) {
        const int whole = cfpo_trace_is_whole(c < na ? &a[c] : &b[c - na]);
        npy_intp dim = (npy_intp)t->rows;
        PyObject *arr = PyArray_SimpleNew(1, &dim, whole ? NPY_INT64 : NPY_DOUBLE);
        if (!arr) {
            Py_CLEAR(tup);
            break;
        }
        void *d = PyArray_DATA((PyArrayObject *)arr);
        for (size_t r = 0; r < t->rows; r++) {
            const double v = t->v[r * (size_t)t->cols + (size_t)c];
            if (whole) ((int64_t *)d)[r] = (int64_t)v;
            else ((double *)d)[r] = v;
        }
        PyTuple_SET_ITEM(tup, c, arr);
    }
    free(t->v);
    t->v = NULL;
    return tup;
}
