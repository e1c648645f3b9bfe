/* core_files3.c - the 3-D point files of cfpo._core (load3, save3,
 * format3_of) through the 3-D engine's own point-file module
 * (src/d3/points3.h): the bytes `cfpo --dim 3 -o FILE` writes, and the
 * formats `--init` reads. */
#include "core.h"


#include "points3.h"

/* load3(path) -> (n, 3) float64 array. */
PyObject *core_load3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *pathobj;
    if (!PyArg_ParseTuple(args, "O&", PyUnicode_FSConverter, &pathobj)) return NULL;
    const char *path = PyBytes_AS_STRING(pathobj);
    double *xyz = NULL;
    size_t n = 0;
    char err[1024];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = p3_read(path, &xyz, &n, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(pathobj);
    if (rc != 0) return core_read_error(err);
    const npy_intp dims[2] = {(npy_intp)n, 3};
    return core_adopt(xyz, 2, dims);
}

/* save3(path, points, box): atomically, format from the extension; the
 * points are a C-contiguous float64 (n, 3) array in [0, 1)^3 (checked by
 * the Python layer), box > 0 the side the XYZ, LAMMPS and .gro files
 * scale to. */
PyObject *core_save3(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *pathobj, *obj;
    double box;
    if (!PyArg_ParseTuple(args, "O&Od", PyUnicode_FSConverter, &pathobj, &obj, &box)) return NULL;
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!a || PyArray_DIM(a, 1) != 3) {
        Py_XDECREF(a);
        Py_DECREF(pathobj);
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "points must be an (n, 3) array");
        return NULL;
    }
    const char *path = PyBytes_AS_STRING(pathobj);
    char err[1024];
    const int known = p3_format_of(path) != P3F_UNKNOWN;
    int rc = -1, bad_box = 0;
    if (!known) snprintf(err, sizeof err, "%s: unknown output format (use %s)", path, P3_EXTENSIONS);
    else if (p3_check_box(path, box, err, sizeof err) != 0) bad_box = 1;
    else {
        const double *xyz = (const double *)PyArray_DATA(a);
        const size_t n = (size_t)PyArray_DIM(a, 0);
        Py_BEGIN_ALLOW_THREADS
        rc = p3_write(path, xyz, n, box, err, sizeof err);
        Py_END_ALLOW_THREADS
    }
    Py_DECREF(a);
    Py_DECREF(pathobj);
    if (rc != 0) return core_error(known && !bad_box ? PyExc_OSError : PyExc_ValueError, err);
    Py_RETURN_NONE;
}

/* format3_of(path) -> 1 when a 3-D file of that name can be written, 2
 * when it can also be read, 0 when the extension is unknown. */
PyObject *core_format3_of(PyObject *self, PyObject *args)
{
    (void)self;
    const char *path;
    if (!PyArg_ParseTuple(args, "s", &path)) return NULL;
    const p3_format f = p3_format_of(path);
    return PyLong_FromLong(f == P3F_UNKNOWN ? 0 : p3_format_readable(f) ? 2 : 1);
}
