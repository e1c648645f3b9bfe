/* core_density.c - the density of a SPEC string or a 2-D array
 * (core_density_in), which the run (core_sample.c) and the density
 * measures share. */
#include "core.h"

#include <string.h>

#include "cli.h"
#include "density.h"


int core_density_in(PyObject *dens, cfpo_density *d)
{
    if (dens == Py_None) return 0;
    char err[1024];
    int rc;
    if (PyUnicode_Check(dens)) {
        const char *spec = PyUnicode_AsUTF8(dens);
        if (!spec) return -1;
        Py_BEGIN_ALLOW_THREADS
        rc = cfpo_density_load(spec, d, err, sizeof err);
        Py_END_ALLOW_THREADS
    } else {
        PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(dens, NPY_FLOAT64, 2, 2, NPY_ARRAY_IN_ARRAY);
        if (!a) return -1;
        rc = cfpo_density_from_values((const double *)PyArray_DATA(a), (int64_t)PyArray_DIM(a, 1),
                                      (int64_t)PyArray_DIM(a, 0), "density", d, err, sizeof err);
        Py_DECREF(a);
    }
    if (rc != 0) {
        core_error(PyExc_ValueError, err);
        return -1;
    }
    return 1;
}
