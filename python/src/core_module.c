/* core_module.c - the extension module cfpo._core: its table of functions,
 * its constants, and the point files (load, save) through the suite's one
 * point-file module (src/files/pointfile.h). The shared helpers of core.h are
 * core_util.c. */
#include "core.h"

#include <stdlib.h>

#include "cfpo.h"
#include "pointfile.h"
#include "stoprule.h"
#include "tracecols.h"

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
    if (rc != 0) return core_read_error(err);
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
    {"run3", core_run3, METH_VARARGS, "CFPO run on the unit 3-torus (see cfpo.run, dim=3)."},
    {"progressive", core_progressive, METH_VARARGS, "Progressive CFPO run (see cfpo.sample)."},
    {"deltas", core_deltas, METH_VARARGS, "Nearest-neighbour statistics (see cfpo.analysis.deltas)."},
    {"spectrum", core_spectrum, METH_VARARGS, "Power spectrum and its measures (see cfpo.analysis.spectrum)."},
    {"certify", core_certify, METH_VARARGS, "FPD certificate (see cfpo.analysis.certify)."},
    {"discrepancy", core_discrepancy, METH_VARARGS, "L2 discrepancies (see cfpo.analysis.discrepancy)."},
    {"lowfreq", core_lowfreq, METH_VARARGS, "Low-frequency measures and shift variances of a periodogram."},
    {"pcf", core_pcf, METH_VARARGS, "Pair correlation g(r) (see cfpo.analysis.pcf)."},
    {"delaunay", core_delaunay, METH_VARARGS, "psi6, Voronoi area variance, mesh ratio (see cfpo.analysis.structure)."},
    {"density_measures", core_density_measures, METH_VARARGS,
     "The measures under a density (see cfpo.analysis.density)."},
    {"integration", core_integration, METH_VARARGS, "UTK's integration test (see cfpo.analysis.integration)."},
    {"prefixes", core_prefixes, METH_VARARGS, "Measures of the prefixes in file order (see cfpo.analysis.prefixes)."},
    {"poisson", core_poisson, METH_VARARGS, "Poisson-disk baselines (see cfpo.baselines)."},
    {"iterative", core_iterative, METH_VARARGS, "Iterative baselines (see cfpo.baselines)."},
    {"methods", core_methods, METH_NOARGS, "The baselines' descriptions: options, defaults, trace columns."},
    {"deltas3", core_deltas3, METH_VARARGS, "3-D nearest-neighbour statistics (see cfpo.analysis.deltas)."},
    {"bond_order3", core_bond_order3, METH_VARARGS, "Q6, W6 and crystal-like points (see cfpo.analysis.bond_order)."},
    {"spectrum3", core_spectrum3, METH_VARARGS, "3-D power spectrum, shells and P0 (see cfpo.analysis.spectrum)."},
    {"pcf3", core_pcf3, METH_VARARGS, "3-D pair correlation g(r) (see cfpo.analysis.pcf)."},
    {"voronoi3", core_voronoi3, METH_VARARGS, "3-D Voronoi statistics (see cfpo.analysis.structure)."},
    {"certify3", core_certify3, METH_VARARGS, "3-D FPD certificate (see cfpo.analysis.certify)."},
    {"load", core_load, METH_VARARGS, "Reads a point file (see cfpo.load)."},
    {"save", core_save, METH_VARARGS, "Writes a point file (see cfpo.save)."},
    {"format_of", core_format_of, METH_VARARGS, "The point-file format of a file name."},
    {"load3", core_load3, METH_VARARGS, "Reads a 3-D point file (see cfpo.load, dim=3)."},
    {"save3", core_save3, METH_VARARGS, "Writes a 3-D point file (see cfpo.save)."},
    {"format3_of", core_format3_of, METH_VARARGS, "0, 1 (written) or 2 (also read): a 3-D file name's format."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_core",
                                    "The C library of cfpo (sampler, analysis, baselines, point files).",
                                    -1, methods, NULL, NULL, NULL, NULL};

/* trace_columns: cfpo's trace columns (src/common/tracecols.h); stop_options:
 * {name: (lo, hi)} of the stop rules (src/common/stoprule.h), names as Python's
 * keywords. */
static int add_tables(PyObject *m)
{
    PyObject *cols = PyTuple_New(CFPO_TRACE_COLUMNS);
    for (int c = 0; cols && c < CFPO_TRACE_COLUMNS; c++) {
        PyObject *w = PyUnicode_FromString(cfpo_trace_columns[c].name);
        if (!w) Py_CLEAR(cols);
        else PyTuple_SET_ITEM(cols, c, w);
    }
    if (!cols || PyModule_AddObject(m, "trace_columns", cols) != 0) {
        Py_XDECREF(cols);
        return -1;
    }
    PyObject *stops = PyDict_New();
    for (int i = 0; stops && i < 3; i++) {
        char key[32];
        snprintf(key, sizeof key, "%s", cfpo_stop_options[i].name);
        for (char *p = key; *p; p++)
            if (*p == '-') *p = '_';
        PyObject *r = Py_BuildValue("(dd)", cfpo_stop_options[i].lo, cfpo_stop_options[i].hi);
        if (!r || PyDict_SetItemString(stops, key, r) != 0) Py_CLEAR(stops);
        Py_XDECREF(r);
    }
    if (!stops || PyModule_AddObject(m, "stop_options", stops) != 0) {
        Py_XDECREF(stops);
        return -1;
    }
    return 0;
}

PyMODINIT_FUNC PyInit__core(void)
{
    if (core_import_numpy() != 0) return NULL;
    PyObject *m = PyModule_Create(&module);
    if (!m) return NULL;
    if (PyModule_AddStringConstant(m, "version", CFPO_VERSION) != 0 ||
        PyModule_AddStringConstant(m, "extensions", PF_EXTENSIONS) != 0 ||
        PyModule_AddIntConstant(m, "default_max_iter", CFPO_DEFAULT_MAX_ITER) != 0 ||
        PyModule_AddIntConstant(m, "max_iter_max", CFPO_MAX_ITER_MAX) != 0 ||
        PyModule_AddObject(m, "tol_max", PyFloat_FromDouble(CFPO_TOL_MAX)) != 0 ||
        PyModule_AddObject(m, "default_tol", PyFloat_FromDouble(CFPO_DEFAULT_TOL)) != 0 || add_tables(m) != 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
