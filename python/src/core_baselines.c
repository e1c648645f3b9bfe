/* core_baselines.c - cfpo._core.poisson and iterative: the baselines
 * through their library entry points (baselines/pd.h, fpo.h, ccvt.h,
 * ccdt.h, bnot.h), with the checks and the run of their commands
 * (baselines/pd_main.c, iter_main.c): the same radius from n, the same
 * minimum n, the same start, the same stop rules (src/stoprule.h) tried
 * after the start and after every iteration, so the points are the
 * commands' bytes. The methods' own options are their commands'
 * (main_ccvt.c, main_ccdt.c, main_bnot.c), with the defaults of
 * ccvt_options_init and bnot_rule_init, which cfpo/baselines.py reads from
 * baseline_defaults. Ctrl-C and the caller's callback are seen after every
 * iteration (the Poisson-disk samplers, which are not iterative, at the
 * end of the call). */
#include "core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bnot.h"
#include "ccdt.h"
#include "ccvt.h"
#include "cfpo.h"
#include "cli.h"
#include "fpo.h"
#include "geom.h"
#include "pd.h"
#include "pd_main.h"
#include "pdgrid.h"
#include "stoprule.h"

/* poisson(kind, n, seed, radius, rel, max_fails, k, plain) -> (points,
 * trials); n or radius may be -1 (not given). */
PyObject *core_poisson(PyObject *self, PyObject *args)
{
    (void)self;
    int kind, k, plain;
    long long n, max_fails;
    unsigned long long seed;
    double radius, rel;
    if (!PyArg_ParseTuple(args, "iLKddLip", &kind, &n, &seed, &radius, &rel, &max_fails, &k, &plain)) return NULL;
    static const double REL[] = {[PD_DART] = PD_DART_REL, [PD_BS] = PD_BS_REL, [PD_BRIDSON] = PD_BRIDSON_REL};
    if (kind < PD_DART || kind > PD_BRIDSON) return PyErr_Format(PyExc_ValueError, "unknown sampler %d", kind);
    if (radius > 0 && rel > 0) return PyErr_Format(PyExc_ValueError, "give radius or rel_radius, not both");
    if (n < 0 && (kind == PD_DART || radius < 0))
        return PyErr_Format(PyExc_ValueError, kind == PD_DART ? "the number of points is required: n"
                                                              : "n or radius is required");
    if (n >= (long long)UINT32_MAX)
        return PyErr_Format(PyExc_ValueError, "n = %lld is too large for one process (at most %lld)", n,
                            (long long)UINT32_MAX - 1);
    if (radius < 0) radius = (rel > 0 ? rel : REL[kind]) * cfpo_delta_bound((double)n);
    const double rmax = kind == PD_DART ? 0.5 : 0.25 / (1.0 + PD_RHO_EPS);
    if (!(radius < rmax))
        return PyErr_Format(PyExc_ValueError, "radius %g is too large for the unit torus (must be below %g%s)",
                            radius, rmax, n > 0 ? "; use more points or a smaller rel_radius" : "");
    if (pdgrid_cells(radius) > 4294967295.0)
        return PyErr_Format(PyExc_ValueError, "radius %g is too small: the grid would need %.3g cells", radius,
                            pdgrid_cells(radius));
    pd_params p;
    memset(&p, 0, sizeof p);
    p.seed = seed;
    p.r = radius;
    p.k = k;
    p.plain = plain;
    p.max_fails = (uint64_t)max_fails;
    if (kind == PD_DART) p.target = n;
    else p.target = n > 0 ? n : (int64_t)(2.0 * REL[kind] * REL[kind] / (sqrt(3.0) * radius * radius)) + 1;
    p.report_step = p.target / 64 > 0 ? p.target / 64 : 1;
    pd_result res;
    char err[1024];
    int rc;
    Py_BEGIN_ALLOW_THREADS
    rc = kind == PD_DART ? dart_sample(&p, &res, err, sizeof err)
       : kind == PD_BS   ? bs_sample(&p, &res, err, sizeof err)
                         : bridson_sample(&p, &res, err, sizeof err);
    Py_END_ALLOW_THREADS
    if (rc != 0) return core_error(PyExc_RuntimeError, err);
    if (core_interrupted()) {
        free(res.xy);
        return NULL;
    }
    if (res.saturated) {
        PyErr_Format(PyExc_RuntimeError,
                     "saturated: placed %lld of %lld points at radius r = %.9g (%.4f Delta(n)); "
                     "%llu consecutive darts were rejected. Use a smaller rel_radius or radius, "
                     "or a larger max_fails", (long long)res.n, n, radius, radius / cfpo_delta_bound((double)n),
                     (unsigned long long)p.max_fails);
        free(res.xy);
        return NULL;
    }
    if (res.n < 2 && kind != PD_DART) {
        PyErr_Format(PyExc_RuntimeError, "radius %g leaves only %lld point(s)", radius, (long long)res.n);
        free(res.xy);
        return NULL;
    }
    return Py_BuildValue("(NK)", core_points_adopt(res.xy, (size_t)res.n), (unsigned long long)res.trials);
}

/* ------------------------------------------------ the iterative baselines */

/* The methods' own options, as their commands take them (main_fpo.c,
 * main_ccvt.c, main_ccdt.c, main_bnot.c); it_args_init gives the
 * commands' defaults (ccvt_options_init, bnot_rule_init). */
typedef struct {
    int local, grid;     /* FPO: the 2-ring only; cfpo's stratified start */
    ccvt_options ccvt;   /* m, points, update, assign (seed, tol: the call's) */
    int reference;       /* CCDT: the reference schedule's iterations (0: off) */
    bnot_rule rule;      /* BNOT: the authors' schedule (epsilon 0: the run to tol) */
} it_args;

static void it_args_init(it_args *a)
{
    memset(a, 0, sizeof *a);
    ccvt_options_init(&a->ccvt);
    bnot_rule_init(&a->rule);
}

typedef struct {
    void *(*create)(const it_args *a, int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
    void (*iterate)(void *E, cfpo_iter_stats *s);
    void (*deltas)(void *E, double *dmin, double *davg);
    const double *(*points)(void *E);
    void (*destroy)(void *E);
} it_ops;

static void *fpo_make(const it_args *a, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    fpo_options o;
    fpo_options_init(&o);
    o.seed = seed;
    o.tol = tol;
    o.local = a->local;
    o.start = a->grid ? FPO_START_GRID : FPO_START_RANDOM;
    return fpo_create(n, &o, err, errlen);
}
static void fpo_it(void *E, cfpo_iter_stats *s) { fpo_iterate(E, s); }
static void fpo_d(void *E, double *a, double *b) { fpo_deltas(E, a, b); }
static const double *fpo_p(void *E) { return fpo_points(E); }
static void fpo_f(void *E) { fpo_free(E); }

static void *ccvt_make(const it_args *a, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    ccvt_options o = a->ccvt;
    o.seed = seed;
    o.tol = tol;
    return ccvt_create(n, &o, err, errlen);
}
static void ccvt_it(void *E, cfpo_iter_stats *s) { ccvt_iterate(E, s); }
static void ccvt_d(void *E, double *a, double *b) { ccvt_deltas(E, a, b); }
static const double *ccvt_p(void *E) { return ccvt_sites(E); }
static void ccvt_f(void *E) { ccvt_free(E); }

/* as main_ccdt.c: the damped schedule, or the reference one for K
 * iterations */
static void *ccdt_make(const it_args *a, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    ccdt_engine *E = ccdt_create(n, seed, tol, err, errlen);
    if (E) ccdt_set_reference(E, a->reference);
    return E;
}
static void ccdt_it(void *E, cfpo_iter_stats *s) { ccdt_iterate(E, s); }
static void ccdt_d(void *E, double *a, double *b) { ccdt_deltas(E, a, b); }
static const double *ccdt_p(void *E) { return ccdt_points(E); }
static void ccdt_f(void *E) { ccdt_free(E); }

/* as main_bnot.c: the authors' schedule, or with epsilon 0 the run to tol */
static void *bnot_make(const it_args *a, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    if (a->rule.epsilon > 0) return bnot_create_rule(n, NULL, seed, 0, tol, &a->rule, err, errlen);
    return bnot_create(n, seed, tol, err, errlen);
}
static void bnot_it(void *E, cfpo_iter_stats *s) { bnot_iterate(E, s); }
static void bnot_d(void *E, double *a, double *b) { bnot_deltas(E, a, b); }
static const double *bnot_p(void *E) { return bnot_points(E); }
static void bnot_f(void *E) { bnot_free(E); }

static const it_ops *ops_of(const char *method)
{
    static const it_ops FPO = {fpo_make, fpo_it, fpo_d, fpo_p, fpo_f};
    static const it_ops CCVT = {ccvt_make, ccvt_it, ccvt_d, ccvt_p, ccvt_f};
    static const it_ops CCDT = {ccdt_make, ccdt_it, ccdt_d, ccdt_p, ccdt_f};
    static const it_ops BNOT = {bnot_make, bnot_it, bnot_d, bnot_p, bnot_f};
    if (strcmp(method, "fpo") == 0 || strcmp(method, "lfpo") == 0) return &FPO;
    if (strcmp(method, "ccvt") == 0) return &CCVT;
    if (strcmp(method, "ccdt") == 0) return &CCDT;
    if (strcmp(method, "bnot") == 0) return &BNOT;
    return NULL;
}

/* The command's check of n (iter_main.c): FPO's own, else cfpo's smallest
 * n for the grid that scales tol. 0, or -1 with the exception set. */
static int check_n(const char *method, int64_t n, double tol, int local)
{
    char err[1024];
    int vr;
    if (strcmp(method, "fpo") == 0 || strcmp(method, "lfpo") == 0) {
        fpo_options o;
        fpo_options_init(&o);
        o.tol = tol;
        o.local = local;
        vr = fpo_validate(n, &o, err, sizeof err);
    } else {
        cfpo_options co;
        cfpo_options_init(&co);
        co.tol = tol;
        co.threads = 1;
        vr = cfpo_validate(n, &co, err, sizeof err);
        if (vr == -2) vr = 0; /* cfpo's memory model is not this method's */
    }
    if (vr == 0) return 0;
    core_error(vr == -2 ? PyExc_MemoryError : PyExc_ValueError, err);
    return -1;
}

/* After each row: Ctrl-C and the callback, GIL taken. 1: stop (an
 * exception is set when *failed). */
static int checkpoint_row(PyObject *callback, const cfpo_iter_stats *s, double el, int *failed)
{
    if (core_interrupted()) {
        *failed = 1;
        return 1;
    }
    if (callback == Py_None) return 0;
    PyObject *d = Py_BuildValue("{s:i,s:d,s:d,s:L,s:L,s:d,s:d,s:d,s:O}", "iteration", s->iteration, "delta_min",
                                s->delta_min, "delta_avg", s->delta_avg, "moved", (long long)s->moved, "solved",
                                (long long)s->solved, "max_disp", s->max_disp, "seconds", s->seconds, "elapsed",
                                el, "converged", s->converged ? Py_True : Py_False);
    PyObject *r = d ? PyObject_CallOneArg(callback, d) : NULL;
    Py_XDECREF(d);
    int stop = r ? PyObject_IsTrue(r) : -1;
    Py_XDECREF(r);
    if (stop < 0) *failed = 1;
    return stop != 0;
}

/* The names of ccvt's choices (the commands' words), by enum value. */
static const char *const POINT_SET[] = {[CCVT_POINTS_LATTICE] = "lattice", [CCVT_POINTS_RANDOM] = "random"};
static const char *const UPDATE[] = {[CCVT_UPDATE_PAIR] = "pair", [CCVT_UPDATE_PASS] = "pass"};
static const char *const ASSIGN[] = {[CCVT_ASSIGN_NEAREST] = "nearest", [CCVT_ASSIGN_CURVE] = "curve"};

/* *v from a choice given as a string, one of name[0], name[1] (the
 * command's wording when it is neither); NULL or None: left as is (the
 * default). */
static int choice(const char *what, PyObject *o, const char *const name[2], int *v)
{
    if (!o || o == Py_None) return 0;
    const char *s = PyUnicode_Check(o) ? PyUnicode_AsUTF8(o) : NULL;
    if (!s) {
        if (!PyErr_Occurred()) PyErr_Format(PyExc_TypeError, "%s: expected a string, %s or %s", what, name[0], name[1]);
        return -1;
    }
    for (int i = 0; i < 2; i++)
        if (strcmp(s, name[i]) == 0) {
            *v = i;
            return 0;
        }
    PyErr_Format(PyExc_ValueError, "%s: '%s' is neither %s nor %s", what, s, name[0], name[1]);
    return -1;
}

int core_baselines_defaults(PyObject *module)
{
    it_args a;
    it_args_init(&a);
    PyObject *d = Py_BuildValue("{s:d,s:O,s:i,s:i,s:s,s:s,s:s}", "epsilon", a.rule.epsilon, "breaker",
                                a.rule.breaker ? Py_True : Py_False, "max_rounds", a.rule.max_rounds, "round_iters",
                                a.rule.round_iters, "point_set", POINT_SET[a.ccvt.points], "update",
                                UPDATE[a.ccvt.update], "assign", ASSIGN[a.ccvt.assign]);
    if (!d || PyModule_AddObject(module, "baseline_defaults", d) == 0) return d ? 0 : -1;
    Py_DECREF(d);
    return -1;
}

/* iterative(method, n, seed, tol, max_iter, tmin, tavg, tlimit, callback,
 * trace, *, local, grid, points_per_site, point_set, update, assign,
 * reference, epsilon, breaker, max_rounds, round_iters) -> (points,
 * iterations, seconds, delta_min, delta_avg, converged, stop, trace). The
 * method's options left out keep its command's defaults; the numbers are
 * checked by the caller (cfpo/baselines.py), the choices here. */
PyObject *core_iterative(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"method", "n", "seed", "tol", "max_iter", "tmin", "tavg", "tlimit", "callback",
                             "trace", "local", "grid", "points_per_site", "point_set", "update", "assign",
                             "reference", "epsilon", "breaker", "max_rounds", "round_iters", NULL};
    const char *method;
    long long n, m = 0;
    unsigned long long seed;
    double tol, tmin, tavg, tlimit;
    int max_iter, want_trace;
    PyObject *callback, *point_set = NULL, *update = NULL, *assign = NULL;
    it_args a;
    it_args_init(&a);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "sLKdidddOp|$ppLOOOidpii", kwlist, &method, &n, &seed, &tol,
                                     &max_iter, &tmin, &tavg, &tlimit, &callback, &want_trace, &a.local, &a.grid,
                                     &m, &point_set, &update, &assign, &a.reference, &a.rule.epsilon,
                                     &a.rule.breaker, &a.rule.max_rounds, &a.rule.round_iters))
        return NULL;
    a.ccvt.m = m;
    if (choice("point_set", point_set, POINT_SET, &a.ccvt.points) || choice("update", update, UPDATE, &a.ccvt.update) ||
        choice("assign", assign, ASSIGN, &a.ccvt.assign))
        return NULL;
    const it_ops *ops = ops_of(method);
    if (!ops) return PyErr_Format(PyExc_ValueError, "unknown method '%s'", method);
    if (check_n(method, n, tol, a.local) != 0) return NULL;
    cfpo_stop_rules rules = {.target_min = tmin, .target_avg = tavg, .time_limit = tlimit};
    char err[1024];
    core_trace trace = {0};
    int failed = 0, it = 0, why = 0;
    cfpo_iter_stats s;
    memset(&s, 0, sizeof s);
    const double t0 = cli_now();
    void *E;
    Py_BEGIN_ALLOW_THREADS
    E = ops->create(&a, n, seed, tol, err, sizeof err);
    Py_END_ALLOW_THREADS
    if (!E) return core_error(PyExc_ValueError, err);
    double el;
    for (;;) {
        if (it == 0) {
            Py_BEGIN_ALLOW_THREADS
            double t = cli_now();
            ops->deltas(E, &s.delta_min, &s.delta_avg);
            s.seconds = cli_now() - t;
            Py_END_ALLOW_THREADS
        }
        el = cli_now() - t0;
        if (want_trace) {
            const double row[TRACE_COLS] = {s.iteration, s.delta_min, s.delta_avg, (double)s.moved,
                                            (double)s.solved, s.max_disp, s.seconds, el, 0, 0};
            core_trace_add(&trace, row);
        }
        why = cfpo_stop_check(&rules, &s, el, max_iter);
        if (checkpoint_row(callback, &s, el, &failed) && !why) why = CFPO_STOP_CALLER;
        if (why || failed) break;
        Py_BEGIN_ALLOW_THREADS
        s.iteration = it + 1;
        ops->iterate(E, &s);
        s.iteration = ++it;
        Py_END_ALLOW_THREADS
    }
    const double seconds = cli_now() - t0;
    PyObject *points = NULL, *tr = NULL;
    if (!failed) {
        double *xy;
        if ((points = core_points_new((size_t)n, &xy))) memcpy(xy, ops->points(E), 2 * (size_t)n * sizeof *xy);
    }
    ops->destroy(E);
    if (!points) {
        free(trace.v);
        return NULL;
    }
    tr = want_trace ? core_trace_take(&trace, 8) : Py_NewRef(Py_None);
    if (!tr) {
        Py_DECREF(points);
        return NULL;
    }
    return Py_BuildValue("(NidddNsN)", points, it, seconds, s.delta_min, s.delta_avg, PyBool_FromLong(s.converged),
                         cfpo_stop_name(why), tr);
}
