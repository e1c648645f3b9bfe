/* core_baselines.c - cfpo._core.methods, poisson and iterative: the
 * baselines as the library describes them (baselines/bl_method.h, the list
 * bl_list.c), run through the library's own pieces that their commands use:
 * the Poisson-disk radius check (pd_check.h) and the run loop with the stop
 * rules (bl_loop.h), so the points are the commands' bytes. methods()
 * gives cfpo/baselines.py every method's options (ranges, defaults,
 * wording) and trace columns; the options' values come back checked, as a
 * tuple in the table's order. Ctrl-C and the caller's callback are seen
 * after every iteration (the Poisson-disk samplers, which are not
 * iterative, at the end of the call). */
#include "core.h"

#include <stdlib.h>
#include <string.h>

#include "bl_loop.h"
#include "bl_method.h"
#include "cli.h"
#include "pd_check.h"
#include "stoprule.h"

static const char *const TYPE_NAME[] = {[BL_INT] = "int", [BL_REAL] = "real", [BL_FLAG] = "flag",
                                        [BL_CHOICE] = "choice"};

/* An option as a dict: py, cli, type, min, max, open_min, default,
 * choices, bad. */
static PyObject *option_dict(const bl_option *o)
{
    PyObject *choices = PyTuple_New(0);
    for (int c = 0; choices && c < BL_MAX_CHOICES && o->choices[c]; c++) {
        PyObject *w = PyUnicode_FromString(o->choices[c]);
        if (!w || _PyTuple_Resize(&choices, c + 1) != 0) {
            Py_XDECREF(w);
            Py_CLEAR(choices);
            break;
        }
        PyTuple_SET_ITEM(choices, c, w);
    }
    if (!choices) return NULL;
    PyObject *lo, *hi, *def;
    if (o->type == BL_REAL) {
        lo = PyFloat_FromDouble(o->min);
        hi = PyFloat_FromDouble(o->max);
        def = PyFloat_FromDouble(o->def);
    } else {
        lo = o->type == BL_INT ? PyLong_FromLongLong(o->lo) : Py_NewRef(Py_None);
        hi = o->type == BL_INT ? PyLong_FromLongLong(o->hi) : Py_NewRef(Py_None);
        def = PyLong_FromLongLong((long long)o->def);
    }
    return Py_BuildValue("{s:s,s:s,s:s,s:N,s:N,s:O,s:N,s:N,s:s}", "py", o->py, "cli", o->cli, "type",
                         TYPE_NAME[o->type], "min", lo, "max", hi, "open_min", o->open_min ? Py_True : Py_False,
                         "default", def, "choices", choices, "bad", o->bad ? o->bad : "");
}

/* A method as a dict: prog, kind, options (a tuple of option dicts, the
 * table's order), columns (the trace's, common ones first), rel_radius. */
static PyObject *method_dict(const bl_method *m)
{
    PyObject *opts = PyTuple_New(m->noptions);
    for (int i = 0; opts && i < m->noptions; i++) {
        PyObject *d = option_dict(&m->options[i]);
        if (!d) Py_CLEAR(opts);
        else PyTuple_SET_ITEM(opts, i, d);
    }
    const int common = m->kind == BL_ITERATIVE ? CFPO_TRACE_COMMON : 0;
    PyObject *cols = PyTuple_New(m->kind == BL_ITERATIVE ? common + m->ncolumns : 0);
    for (int c = 0; cols && c < PyTuple_GET_SIZE(cols); c++) {
        PyObject *w = PyUnicode_FromString(c < common ? cfpo_trace_columns[c].name : m->columns[c - common].name);
        if (!w) Py_CLEAR(cols);
        else PyTuple_SET_ITEM(cols, c, w);
    }
    if (!opts || !cols) {
        Py_XDECREF(opts);
        Py_XDECREF(cols);
        return NULL;
    }
    /* density: whether the method takes density= (--density) */
    const int dens = m->kind == BL_ITERATIVE ? m->create_density != NULL : m->pd_kind == PD_DART;
    return Py_BuildValue("{s:s,s:s,s:N,s:N,s:d,s:N}", "prog", m->prog, "kind",
                         m->kind == BL_ITERATIVE ? "iterative" : "poisson", "options", opts, "columns", cols,
                         "rel_radius", m->pd_rel, "density", PyBool_FromLong(dens));
}

/* methods() -> {name: method dict}, in the list's order. */
PyObject *core_methods(PyObject *self, PyObject *args)
{
    (void)self;
    (void)args;
    PyObject *all = PyDict_New();
    for (int i = 0; all && bl_methods[i]; i++) {
        PyObject *d = method_dict(bl_methods[i]);
        if (!d || PyDict_SetItemString(all, bl_methods[i]->name, d) != 0) Py_CLEAR(all);
        Py_XDECREF(d);
    }
    return all;
}

/* The method named by the call and its options' values from a tuple in
 * the table's order (already checked by cfpo/baselines.py). */
static const bl_method *method_values(const char *name, bl_kind kind, PyObject *values, bl_value *v)
{
    const bl_method *m = bl_method_find(name);
    if (!m || m->kind != kind) return PyErr_Format(PyExc_ValueError, "unknown method '%s'", name), NULL;
    if (!PyTuple_Check(values) || PyTuple_GET_SIZE(values) != m->noptions)
        return PyErr_Format(PyExc_TypeError, "%s: expected %d option values", name, m->noptions), NULL;
    for (int i = 0; i < m->noptions; i++) {
        PyObject *o = PyTuple_GET_ITEM(values, i);
        if (m->options[i].type == BL_REAL) v[i].d = PyFloat_AsDouble(o);
        else v[i].i = PyLong_AsLongLong(o);
        if (PyErr_Occurred()) return NULL;
    }
    return m;
}

/* poisson(method, n, seed, values, density) -> (points, trials); n -1: not
 * given; radius and rel_radius -1: not given; density None, a SPEC or a
 * 2-D array (dart throwing only, as cfpo-dart --density). */
PyObject *core_poisson(PyObject *self, PyObject *args)
{
    (void)self;
    const char *name;
    long long n;
    unsigned long long seed;
    PyObject *values, *dens = Py_None;
    if (!PyArg_ParseTuple(args, "sLKO|O", &name, &n, &seed, &values, &dens)) return NULL;
    bl_value v[BL_MAX_OPTIONS];
    const bl_method *m = method_values(name, BL_POISSON, values, v);
    if (!m) return NULL;
    const int kind = m->pd_kind;
    if (dens != Py_None && kind != PD_DART) return core_error(PyExc_ValueError, "density applies to dart only");
    char err[1024];
    pd_params p;
    double radius, rel;
    pd_params_of(m, v, seed, &p, &radius, &rel);
    if (pd_check_args(kind, n, radius, rel, &pd_py_names, err, sizeof err) != 0)
        return core_error(PyExc_ValueError, err);
    cfpo_density d;
    const int has = core_density_in(dens, &d);
    if (has < 0) return NULL;
    if (has) {
        if (cfpo_density_check_n(&d, n, err, sizeof err) != 0) {
            cfpo_density_free(&d);
            return core_error(PyExc_ValueError, err);
        }
        p.density = &d;
    }
    PyObject *ret = NULL;
    if (pd_setup(kind, n, radius, rel, m->pd_rel, &pd_py_names, &p, err, sizeof err) != 0) {
        core_error(PyExc_ValueError, err);
        goto done;
    }
    pd_result res;
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = pd_sample(kind, &p, &res, err, sizeof err);
    Py_END_ALLOW_THREADS
    if (rc != 0) {
        core_error(PyExc_RuntimeError, err);
        goto done;
    }
    if (core_interrupted()) {
        free(res.xy);
        goto done;
    }
    if (pd_verdict(kind, &res, n, &p, &pd_py_names, err, sizeof err) != 0) {
        free(res.xy);
        core_error(PyExc_RuntimeError, err);
        goto done;
    }
    ret = Py_BuildValue("(NK)", core_points_adopt(res.xy, (size_t)res.n), (unsigned long long)res.trials);
done:
    if (has) cfpo_density_free(&d);
    return ret;
}

/* ------------------------------------------------ the iterative baselines */

typedef struct {
    const bl_method *m;
    PyThreadState *ts;  /* this thread's state while the GIL is released */
    PyObject *callback; /* None or a callable(dict) -> truthy to stop */
    int want_trace;
    core_trace trace;
} row_ctx;

/* After each row, GIL released: the trace row, then with the GIL Ctrl-C
 * and the callback. */
static int on_row(void *user, void *E, const cfpo_iter_stats *s, double el)
{
    row_ctx *c = user;
    if (c->want_trace) {
        double row[CFPO_TRACE_COMMON + BL_MAX_COLUMNS];
        bl_trace_values(c->m, E, s, el, row);
        core_trace_add(&c->trace, row);
    }
    PyEval_RestoreThread(c->ts);
    int stop = 0;
    if (core_interrupted()) stop = -1;
    else if (c->callback != Py_None) {
        PyObject *d = core_stats_dict(s, el, CFPO_TRACE_COMMON);
        PyObject *r = d ? PyObject_CallOneArg(c->callback, d) : NULL;
        Py_XDECREF(d);
        stop = r ? PyObject_IsTrue(r) : -1;
        Py_XDECREF(r);
        if (stop > 0) stop = 1;
    }
    c->ts = PyEval_SaveThread();
    return stop;
}

/* iterative(method, n, seed, tol, max_iter, tmin, tavg, tlimit, callback,
 * trace, values, density) -> (points, iterations, seconds, delta_min,
 * delta_avg, converged, stop, trace); density None, a SPEC or a 2-D array
 * (the methods with create_density, as their --density). */
PyObject *core_iterative(PyObject *self, PyObject *args)
{
    (void)self;
    const char *name;
    long long n;
    unsigned long long seed;
    double tol, tmin, tavg, tlimit;
    int max_iter, want_trace;
    PyObject *callback, *values, *dens = Py_None;
    if (!PyArg_ParseTuple(args, "sLKdidddOpO|O", &name, &n, &seed, &tol, &max_iter, &tmin, &tavg, &tlimit, &callback,
                          &want_trace, &values, &dens))
        return NULL;
    bl_value v[BL_MAX_OPTIONS];
    const bl_method *m = method_values(name, BL_ITERATIVE, values, v);
    if (!m) return NULL;
    char err[1024];
    if (dens != Py_None && !m->create_density)
        return PyErr_Format(PyExc_ValueError, "density is not offered by %s", name);
    cfpo_density d;
    const int has = core_density_in(dens, &d);
    if (has < 0) return NULL;
    const char *why = has && m->density_refuses ? m->density_refuses(v) : NULL;
    if (has && (why || cfpo_density_check_n(&d, n, err, sizeof err) != 0)) {
        cfpo_density_free(&d);
        return core_error(PyExc_ValueError, why ? why : err);
    }
    const int vr = m->check_n(v, n, tol, err, sizeof err);
    if (vr != 0) {
        if (has) cfpo_density_free(&d);
        return core_error(vr == -2 ? PyExc_MemoryError : PyExc_ValueError, err);
    }
    bl_loop_args a = {.n = n, .seed = seed, .tol = tol, .max_iter = max_iter,
                      .rules = {.target_min = tmin, .target_avg = tavg, .time_limit = tlimit},
                      .density = has ? &d : NULL};
    row_ctx c = {.m = m, .callback = callback, .want_trace = want_trace,
                 .trace = {.cols = CFPO_TRACE_COMMON + m->ncolumns}};
    bl_outcome o;
    const double t0 = cli_now();
    c.ts = PyEval_SaveThread();
    void *E = bl_loop(m, v, &a, t0, on_row, &c, &o, err, sizeof err);
    const double seconds = cli_now() - t0;
    PyEval_RestoreThread(c.ts);
    if (!E) {
        free(c.trace.v);
        if (has) cfpo_density_free(&d);
        return core_error(PyExc_ValueError, err);
    }
    PyObject *points = NULL, *tr = NULL;
    if (!o.failed) {
        double *xy;
        if ((points = core_points_new((size_t)n, &xy))) memcpy(xy, m->points(E), 2 * (size_t)n * sizeof *xy);
    }
    m->destroy(E);
    if (has) cfpo_density_free(&d);
    if (!points) {
        free(c.trace.v);
        return NULL;
    }
    tr = want_trace ? core_trace_take(&c.trace, cfpo_trace_columns, CFPO_TRACE_COMMON, m->columns)
                    : Py_NewRef(Py_None);
    if (!tr) {
        Py_DECREF(points);
        return NULL;
    }
    return Py_BuildValue("(NidddNsN)", points, o.iterations, seconds, o.last.delta_min, o.last.delta_avg,
                         PyBool_FromLong(o.last.converged), cfpo_stop_name(o.why), tr);
}
