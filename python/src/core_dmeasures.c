/* core_dmeasures.c - cfpo._core.density_measures: the measures of one set
 * under a density, the calls `cfpo-analyze --density SPEC` makes for a set
 * (analysis/main.c: the Voronoi cells of the periodic Delaunay
 * triangulation, an_density_add, an_density_finish), so the numbers are
 * the command's; and each point's capacity. */
#include "core.h"

#include <math.h>
#include <string.h>

#include "capacity.h"
#include "cli.h"
#include "delaunay.h"
#include "density_measures.h"
#include "power.h"
#include "rings.h"

static PyObject *array_of(const void *v, npy_intp len, int type, size_t size)
{
    PyObject *a = PyArray_SimpleNew(1, &len, type);
    if (a) memcpy(PyArray_DATA((PyArrayObject *)a), v, (size_t)len * size);
    return a;
}

typedef struct {
    an_density a;
    an_vcells cells;
    an_rings rings;
    double *cap;
    int have_cells, have_rings;
} work;

static void work_free(work *w)
{
    an_density_free(&w->a);
    an_vcells_free(&w->cells);
    if (w->have_rings) an_rings_free(&w->rings);
    free(w->cap);
}

/* Everything with the GIL released: 0, or -1 with err. */
static int compute(work *w, const double *xy, size_t n, int K, char *err, size_t errlen)
{
    an_delaunay dt;
    w->have_cells = an_delaunay_compute_cells(xy, n, &dt, &w->cells, err, errlen) == 0;
    if (w->have_cells) {
        if (!(w->cap = malloc(n * sizeof *w->cap)) || an_capacity_compute(&w->a.d, &w->cells, w->cap) != 0) {
            snprintf(err, errlen, "out of memory for the capacities");
            return -1;
        }
    }
    if (an_density_add(&w->a, xy, n, w->have_cells ? &w->cells : NULL, K, err, errlen) != 0) return -1;
    if (an_density_finish(&w->a, n) != 0 || an_rings_compute(w->a.dda, K, &w->rings) != 0) {
        snprintf(err, errlen, "out of memory for the differential-domain spectrum");
        return -1;
    }
    w->have_rings = 1;
    return 0;
}

/* density_measures(points, density, K) -> dict: delta_min, delta_avg,
 * hist (int64, AN_DENS_BINS), count_fidelity_rms/max, count_fidelity16_rms
 * /max, blocks, off_support, capacity_deviation, capacities (float64 or
 * None), capacity_sum_error, and the spectrum: K, radius, pairs, power
 * ((2K+1, 2K+1)), ring_count, raps, anisotropy_db (rings 0..K), peak,
 * peak_ring, peak_freq, low, anisotropy_mean_db. */
PyObject *core_density_measures(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj, *dens;
    int K;
    if (!PyArg_ParseTuple(args, "OOi", &obj, &dens, &K)) return NULL;
    if (K < 1 || K > AN_KMAX) return PyErr_Format(PyExc_ValueError, "K: %d is not in [1, %d]", K, AN_KMAX);
    size_t n;
    PyArrayObject *pts = core_points_in(obj, &n);
    if (!pts) return NULL;
    work w;
    memset(&w, 0, sizeof w);
    w.a.radius = AN_DDA_RADIUS;
    const int got = core_density_in(dens, &w.a.d);
    if (got <= 0) {
        Py_DECREF(pts);
        return got == 0 ? PyErr_Format(PyExc_TypeError, "density: expected a SPEC or an array, got None") : NULL;
    }
    char err[1024];
    int rc;
    if (an_dda_check_memory(n, K, AN_DDA_RADIUS, cli_physical_memory(), err, sizeof err) != 0) {
        Py_DECREF(pts);
        work_free(&w);
        return PyErr_Format(PyExc_MemoryError, "%s", err);
    }
    Py_BEGIN_ALLOW_THREADS
    rc = compute(&w, (const double *)PyArray_DATA(pts), n, K, err, sizeof err);
    Py_END_ALLOW_THREADS
    Py_DECREF(pts);
    if (rc != 0) {
        work_free(&w);
        return core_error(PyExc_ValueError, err);
    }
    const an_density *a = &w.a;
    npy_intp dims[2] = {(npy_intp)an_side(K), (npy_intp)an_side(K)};
    PyObject *power = core_adopt(w.a.dda, 2, dims);
    w.a.dda = NULL; /* the array owns it now */
    PyObject *caps = w.have_cells ? core_adopt(w.cap, 1, (npy_intp[]){(npy_intp)n}) : (Py_INCREF(Py_None), Py_None);
    w.cap = NULL;
    PyObject *hist = array_of(a->hist, AN_DENS_BINS, NPY_UINT64, sizeof a->hist[0]);
    PyObject *cnt = array_of(w.rings.count, K + 1, NPY_INT64, sizeof(int64_t));
    PyObject *raps = array_of(w.rings.mean, K + 1, NPY_DOUBLE, sizeof(double));
    PyObject *aniso = array_of(w.rings.aniso_db, K + 1, NPY_DOUBLE, sizeof(double));
    PyObject *r = NULL;
    if (power && caps && hist && cnt && raps && aniso)
        r = Py_BuildValue("{s:d,s:d,s:O,s:d,s:d,s:d,s:d,s:L,s:d,s:d,s:O,s:d,s:i,s:d,s:d,s:O,s:O,s:O,s:O,s:d,s:i,"
                          "s:d,s:d,s:d}",
                          "delta_min", a->dmin, "delta_avg", a->davg, "hist", hist, "count_fidelity_rms", a->fid_rms,
                          "count_fidelity_max", a->fid_max, "count_fidelity16_rms", a->fid_rms16,
                          "count_fidelity16_max", a->fid_max16, "blocks", (long long)a->blocks, "off_support", a->off,
                          "capacity_deviation", a->cap_sets ? a->cap_dev : NAN, "capacities", caps,
                          "capacity_sum_error", a->cap_sum_err, "K", K, "radius", a->radius, "pairs", a->pairs,
                          "power", power, "ring_count", cnt, "raps", raps, "anisotropy_db", aniso, "peak", a->sum.peak,
                          "peak_ring", a->sum.peak_ring, "peak_freq", a->sum.peak_freq, "low", a->sum.low,
                          "anisotropy_mean_db", a->sum.aniso_db);
    Py_XDECREF(power);
    Py_XDECREF(caps);
    Py_XDECREF(hist);
    Py_XDECREF(cnt);
    Py_XDECREF(raps);
    Py_XDECREF(aniso);
    work_free(&w);
    return r;
}
