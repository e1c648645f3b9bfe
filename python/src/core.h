/* core.h - the pieces the extension module cfpo._core shares between its
 * files (CPython + NumPy C API): error mapping, point arrays in and out,
 * the interruption check, the statistics and the trace of an iteration
 * (core_util.c). The Python layer (python/cfpo/) checks and
 * converts the arguments; these functions take them already checked and
 * check again only what would otherwise crash.
 *
 * Rules every function here keeps: the GIL is released around every long
 * call into the C library; Ctrl-C (a pending signal, seen through
 * PyErr_CheckSignals) stops an iterative run at the next iteration; no
 * path calls exit() or installs a signal handler. */
#ifndef CFPO_PY_CORE_H
#define CFPO_PY_CORE_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#ifndef CFPO_PY_IMPORT_ARRAY
#define NO_IMPORT_ARRAY
#endif
#define PY_ARRAY_UNIQUE_SYMBOL cfpo_core_ARRAY_API
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

#include <stddef.h>
#include <stdint.h>

#include "density.h"
#include "tracecols.h"

/* Loads NumPy's C API (whose table core_util.c holds); 0, or -1 with
 * an exception. */
int core_import_numpy(void);

/* Raises the exception that fits a library message: MemoryError for "out
 * of memory" / "too large for memory", else `type`. Returns NULL. */
PyObject *core_error(PyObject *type, const char *msg);
/* A point-file reader's one line raised as OSError (the file cannot be
 * opened or read) or ValueError (its contents are refused); NULL. */
PyObject *core_read_error(const char *msg);

/* A C-contiguous float64 (n, 2) view of obj (a new reference), or NULL
 * with TypeError/ValueError. The Python layer has already converted. */
PyArrayObject *core_points_in(PyObject *obj, size_t *n);

/* A new (n, 2) float64 array; *data its buffer. */
PyObject *core_points_new(size_t n, double **data);

/* A float64 array of shape dims over v (malloc'ed), which the array then
 * owns (freed with it): no copy. On failure v is freed. */
PyObject *core_adopt(double *v, int nd, const npy_intp *dims);
/* The same for n points (xy: 2n doubles), shape (n, 2). */
PyObject *core_points_adopt(double *xy, size_t n);

/* 1 when a signal handler raised (KeyboardInterrupt): the exception is set.
 * Call with the GIL held. */
int core_interrupted(void);

/* The statistics of an iteration for a progress callable: the first ncols
 * of src/common/tracecols.h's columns by name, and converged. */
PyObject *core_stats_dict(const cfpo_iter_stats *s, double elapsed, int ncols);

/* The trace: one row per iteration, grown as the run goes; cols values a
 * row (src/common/tracecols.h's columns, then a baseline's own). */
typedef struct {
    double *v;
    size_t rows, cap;
    int cols;
    int oom;
} core_trace;
void core_trace_add(core_trace *t, const double *row);
/* The columns as a tuple of arrays (int64 for whole-number columns,
 * float64 otherwise): a[0..na-1], then b[...]. Frees t->v. */
PyObject *core_trace_take(core_trace *t, const cfpo_trace_column *a, int na, const cfpo_trace_column *b);

/* A run's per-iteration state (core_sample.c): the callback, the trace,
 * Ctrl-C; core_on_iteration is the engine's progress function over it. */
typedef struct {
    PyThreadState *ts;  /* this thread's state while the GIL is released */
    PyObject *callback; /* None or a callable(dict) -> truthy to stop */
    int want_trace;
    core_trace trace;
    double t0;
    int failed;         /* an exception is set (Ctrl-C, the callback's) */
} core_run_ctx;
int core_on_iteration(const cfpo_iter_stats *s, void *user);
/* The options of a run from the arguments (core_sample.c). */
int core_options_of(cfpo_options *o, unsigned long long seed, const char *variant, int threads, double tol,
                    int max_iter, double tmin, double tavg, double tlimit);

/* The module's functions, one file each. */
PyObject *core_run_result(core_run_ctx *c, int rc, int created, const char *err, PyObject *points,
                          const cfpo_result *res, double seconds);
PyObject *core_run(PyObject *self, PyObject *args);
/* The 3-D engine's run (core_sample3.c): the tuple of core_run_result, points (n, 3). */
PyObject *core_run3(PyObject *self, PyObject *args);
PyObject *core_progressive(PyObject *self, PyObject *args);
PyObject *core_deltas(PyObject *self, PyObject *args);
PyObject *core_spectrum(PyObject *self, PyObject *args);
PyObject *core_certify(PyObject *self, PyObject *args);
PyObject *core_discrepancy(PyObject *self, PyObject *args);
PyObject *core_lowfreq(PyObject *self, PyObject *args);
PyObject *core_pcf(PyObject *self, PyObject *args);
PyObject *core_delaunay(PyObject *self, PyObject *args);
PyObject *core_density_measures(PyObject *self, PyObject *args);
PyObject *core_integration(PyObject *self, PyObject *args);
PyObject *core_prefixes(PyObject *self, PyObject *args);
PyObject *core_poisson(PyObject *self, PyObject *args);
/* core_density.c: density= (None, a SPEC string or a 2-D array) into *d;
 * 1 when loaded, 0 for None, -1 with a Python error (ValueError: the
 * density's one line). */
int core_density_in(PyObject *dens, cfpo_density *d);
PyObject *core_iterative(PyObject *self, PyObject *args);
PyObject *core_methods(PyObject *self, PyObject *args);
/* The 3-D measures of cfpo3d-analyze (core_measures3.c). */
PyObject *core_deltas3(PyObject *self, PyObject *args);
PyObject *core_bond_order3(PyObject *self, PyObject *args);
PyObject *core_spectrum3(PyObject *self, PyObject *args);
PyObject *core_pcf3(PyObject *self, PyObject *args);
PyObject *core_voronoi3(PyObject *self, PyObject *args);
PyObject *core_certify3(PyObject *self, PyObject *args);
/* The 3-D point files (core_files3.c). */
PyObject *core_load3(PyObject *self, PyObject *args);
PyObject *core_save3(PyObject *self, PyObject *args);
PyObject *core_format3_of(PyObject *self, PyObject *args);

#endif
