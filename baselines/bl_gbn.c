/* bl_gbn.c - Gaussian blue noise (gbn.h) as a baseline method
 * (bl_method.h): its options with the authors' defaults, its memory
 * model and its engine. */
#include "bl_method.h"
#include "gbn.h"

enum { SIGMA, STEP, ITERATIONS, CUTOFF, THREADS };

static const bl_option OPTS[] = {
    {.cli = "sigma", .py = "sigma", .type = BL_REAL, .min = 0, .max = 10, .open_min = 1, .def = GBN_SIGMA,
     .bad = "is not a number in (0, 10]",
     .help = "      --sigma G        the Gaussian's width in units of n^(-1/2) (default %g, the\n"
             "                       authors')\n"},
    {.cli = "step", .py = "step", .type = BL_REAL, .min = 0, .max = 10, .open_min = 1, .def = GBN_STEP,
     .bad = "is not a number in (0, 10]",
     .help = "      --step H         the time step (default %g, the authors'; divided by\n"
             "                       sigma^2 when sigma > 1, as their code)\n"},
    {.cli = "iterations", .py = "iterations", .type = BL_INT, .lo = 1, .hi = 1000000000, .def = GBN_ITERATIONS,
     .bad = "is not a whole number in 1..1e9",
     .help = "      --iterations K   converged after K steps (default %g, the authors' run)\n"},
    {.cli = "cutoff", .py = "cutoff", .type = BL_REAL, .min = 3, .max = 20, .def = GBN_CUTOFF,
     .bad = "is not a number in [3, 20]",
     .help = "      --cutoff C       the kernel is summed within C * sigma n^(-1/2) only\n"
             "                       (default %g: terms left out below 1e-7 of the spacing)\n"},
    {.cli = "threads", .py = "threads", .type = BL_INT, .lo = 0, .hi = 4096, .def = 1,
     .bad = "is not a whole number in 0..4096",
     .help = "      --threads T      OpenMP threads (default %g; 0: all cores); the same points\n"
             "                       for any T\n"},
};

static void options_of(const bl_value *v, double tol, gbn_options *o)
{
    gbn_options_init(o);
    o->tol = tol;
    o->sigma = v[SIGMA].d;
    o->step = v[STEP].d;
    o->iterations = (int)v[ITERATIONS].i;
    o->cutoff = v[CUTOFF].d;
    o->threads = (int)v[THREADS].i;
}

static int check_n(const bl_value *v, int64_t n, double tol, char *err, size_t errlen)
{
    (void)v;
    return bl_check_n_memory("gbn", n, tol, gbn_bytes(n), err, errlen);
}

static void *create(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    gbn_options o;
    options_of(v, tol, &o);
    o.seed = seed;
    return gbn_create(n, &o, err, errlen);
}

static void iterate(void *E, cfpo_iter_stats *s) { gbn_iterate(E, s); }
static void deltas(void *E, double *a, double *b) { gbn_deltas(E, a, b); }
static const double *points(void *E) { return gbn_points(E); }
static void destroy(void *E) { gbn_free(E); }

const bl_method bl_gbn = {
    .name = "gbn",
    .prog = "cfpo-gbn",
    .kind = BL_ITERATIVE,
    .about = "Gaussian blue noise (Ahmed, Ren, Wonka 2022) on the unit torus, as the authors'\n"
             "toroidal code runs it: from uniform points, gradient steps on the energy\n"
             "sum exp(-|x_i - x_j|^2 / (2 s^2)), s = sigma / sqrt(n), every point moved at\n"
             "once by step * sum_j d_ij exp(...) (d_ij the nearest image of x_i - x_j);\n"
             "converged after --iterations steps (or when no point moves --tol * L). The\n"
             "kernel is summed over a cell list within --cutoff s. Prints one SUMMARY line\n"
             "on stdout.",
    BL_OPTIONS(OPTS),
    BL_ENGINE,
};
