/* main.c - the `cfpo-analyze` command: options, the loop over the input
 * sets, averaging, the output folder and the summary line. Every number
 * comes from the modules beside it; this file only talks to the user. */
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certify.h"
#include "cfpo.h"
#include "cli.h"
#include "delaunay.h"
#include "density_measures.h"
#include "discrepancy.h"
#include "hsd.h"
#include "integration.h"
#include "lowfreq.h"
#include "mreport.h"
#include "nnhist.h"
#include "omp_compat.h"
#include "outdir.h"
#include "pcf.h"
#include "pointfile.h"
#include "prefixes.h"
#include "power.h"
#include "report.h"
#include "rings.h"
#include "shiftvar.h"

static const char *prog = "cfpo-analyze";

typedef struct {
    const char *out;
    int K, width, exact, check, certify, quiet, threads, no_disc, no_delaunay, integ;
    double pcf_sigma, pcf_rmax;
    int any_n; /* --any-n: the sets may differ in n (maximal Poisson-disk sets) */
    int64_t grid; /* --grid: cells a side for the lattice ratio; -1: cfpo's for n */
    double cert_tol;
    const char *density; /* --density SPEC (density_measures.c) */
    int prefixes;        /* --prefixes (prefixes.c) */
    int prefix_opts;     /* --prefix-base or --prefix-sizes given */
    size_t prefix_base, *prefix_sizes;
    int nprefix_sizes;
    char **files;
    int nfiles;
} options;

static void usage(void)
{
    printf("Usage: cfpo-analyze [options] FILE...\n"
           "Power spectrum, radially averaged power spectrum (RAPS), anisotropy, distance\n"
           "statistics, low-frequency power, L2 discrepancies, integration variances under a\n"
           "random shift and an optional FPD certificate of point sets on the unit torus.\n"
           "Several files (all with the same n, unless --any-n) are averaged, as the paper\n"
           "averages 10 sets.\n"
           "Writes an output folder and prints one SUMMARY line on stdout.\n\n"
           "  -o, --output DIR     output folder (default: NAME.analysis for one file\n"
           "                       NAME.EXT, avg.analysis for several); an earlier output\n"
           "                       folder of this tool is replaced, nothing else is\n"
           "  -K, --kmax K         frequencies k in [-K, K]^2 (default: ceil(6 sqrt(n)),\n"
           "                       between 8 and 2048; at most %d)\n"
           "      --exact          direct summation instead of the NUFFT (O(n K^2))\n"
           "      --check          compute both and report the largest difference\n"
           "                       |P - P_exact| / max(P_exact, 1) as check_maxdiff\n"
           "      --width W        NUFFT kernel width, 4..16 (default %d)\n"
           "      --certify        FPD certificate: can any single point be moved to\n"
           "                       increase its distance to the rest? (exact)\n"
           "      --cert-tol T     certificate tolerance relative to Delta(n) (default %g)\n"
           "      --any-n          average sets whose n differ (maximal Poisson-disk sets):\n"
           "                       n of the frequency scale |k| / sqrt(n) and of the\n"
           "                       measures that use it is the sets' mean, rounded\n"
           "      --grid G         the grid whose imprint lattice_ratio looks for: G cells\n"
           "                       a side, colours of period 3 (G a multiple of 3), else 2\n"
           "                       (G even), else 1 (default: cfpo's grid for n; 0: none)\n"
           "      --no-discrepancy the five L2 discrepancies are skipped (O(n log n),\n"
           "                       about 4 s a set at a million points on 2 cores)\n"
           "      --pcf-sigma S    pair correlation: Gaussian kernel sigma / Delta(n) (default %g)\n"
           "      --pcf-rmax R     pair correlation up to r = R Delta(n) (default %g)\n"
           "      --integration M  UTK's integration test with M Gaussian and M Heaviside\n"
           "                       integrands (default %d; 0: none)\n"
           "      --no-delaunay    psi6, Voronoi area variance and mesh ratio are skipped\n"
#ifndef CFPO_HAVE_CGAL
           "                       (always in this build, made without CGAL; so are the\n"
           "                       capacities under --density)\n"
#endif
           "      --density SPEC   also the measures under a density (cfpo's --density\n"
           "                       SPEC), capacity deviation and the differential-domain\n"
           "                       spectrum among them: DENSITY line, density.txt,\n"
           "                       dda_raps.txt, dda_spectrum.txt\n"
           "      --prefixes       measures of the prefixes in file order (one file):\n"
           "                       prefixes.txt, prefix_* keys in SUMMARY\n"
           "      --prefix-base B  smallest prefix, dyadic sizes from it (default %d)\n"
           "      --prefix-sizes L comma-separated prefix sizes instead of the default\n"
           "  -t, --threads T      OpenMP threads (default: all cores, here %d)\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Input formats: %s\n"
           "Output folder: spectrum.txt (gnuplot nonuniform matrix), raps.txt, nn_hist.txt, pcf.txt,\n"
           "stats.json, plot.gp, pcf.gp (gnuplot draws them). See analysis/README.md.\n"
           "Exit status: 0 success, 1 runtime failure, 2 usage error.\n",
           AN_KMAX, AN_NUFFT_WIDTH, AN_CERT_TOL, AN_PCF_SIGMA, AN_PCF_RMAX, AN_INTEG_M, AN_PREFIX_BASE, omp_get_num_procs(),
           PF_EXTENSIONS);
}

/* --prefix-sizes: a comma-separated list of integers >= 2 */
static void parse_sizes(const char *arg, options *o)
{
    char *copy = strdup(arg), *save = NULL;
    if (!copy) cli_fail(prog, "out of memory");
    int cap = 1;
    for (const char *c = arg; *c; c++) cap += *c == ',';
    free(o->prefix_sizes);
    o->prefix_sizes = malloc((size_t)cap * sizeof *o->prefix_sizes);
    if (!o->prefix_sizes) cli_fail(prog, "out of memory");
    o->nprefix_sizes = 0;
    for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int64_t v;
        if (cli_parse_i64(t, 2, INT64_MAX, &v) != 0)
            cli_usage_error(prog, "bad --prefix-sizes '%s' (comma-separated integers >= 2)", arg);
        o->prefix_sizes[o->nprefix_sizes++] = (size_t)v;
    }
    if (o->nprefix_sizes == 0) cli_usage_error(prog, "bad --prefix-sizes '%s' (no size)", arg);
    free(copy);
}

static void parse(int argc, char **argv, options *o)
{
    enum { OPT_EXACT = 256, OPT_CHECK, OPT_WIDTH, OPT_CERTIFY, OPT_CERT_TOL, OPT_GRID, OPT_ANY_N, OPT_NO_DISC,
           OPT_PCF_SIGMA, OPT_PCF_RMAX, OPT_INTEG, OPT_NO_DT, OPT_DENSITY,
           OPT_PREFIXES, OPT_PREFIX_BASE, OPT_PREFIX_SIZES };
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'},  {"kmax", required_argument, 0, 'K'},
        {"exact", no_argument, 0, OPT_EXACT},   {"check", no_argument, 0, OPT_CHECK},
        {"width", required_argument, 0, OPT_WIDTH}, {"certify", no_argument, 0, OPT_CERTIFY},
        {"cert-tol", required_argument, 0, OPT_CERT_TOL}, {"threads", required_argument, 0, 't'},
        {"grid", required_argument, 0, OPT_GRID}, {"any-n", no_argument, 0, OPT_ANY_N},
        {"no-discrepancy", no_argument, 0, OPT_NO_DISC}, {"no-delaunay", no_argument, 0, OPT_NO_DT},
        {"pcf-sigma", required_argument, 0, OPT_PCF_SIGMA}, {"pcf-rmax", required_argument, 0, OPT_PCF_RMAX},
        {"integration", required_argument, 0, OPT_INTEG},
        {"quiet", no_argument, 0, 'q'},         {"help", no_argument, 0, 'h'},
        {"version", no_argument, 0, 'V'},       {"density", required_argument, 0, OPT_DENSITY},
        {"prefixes", no_argument, 0, OPT_PREFIXES}, {"prefix-base", required_argument, 0, OPT_PREFIX_BASE},
        {"prefix-sizes", required_argument, 0, OPT_PREFIX_SIZES},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->cert_tol = AN_CERT_TOL;
    o->grid = -1;
    o->pcf_sigma = AN_PCF_SIGMA;
    o->pcf_rmax = AN_PCF_RMAX;
    o->integ = AN_INTEG_M;
    o->prefix_base = AN_PREFIX_BASE;
    int c;
    int64_t v;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:K:t:qhV", longs, NULL)) != -1) {
        switch (c) {
        case 'o': o->out = optarg; break;
        case 'K':
            if (cli_parse_i64(optarg, 1, AN_KMAX, &v) != 0)
                cli_usage_error(prog, "bad -K '%s' (an integer in [1, %d])", optarg, AN_KMAX);
            o->K = (int)v;
            break;
        case OPT_EXACT: o->exact = 1; break;
        case OPT_CHECK: o->check = 1; break;
        case OPT_WIDTH:
            if (cli_parse_i64(optarg, 4, 16, &v) != 0)
                cli_usage_error(prog, "bad --width '%s' (an integer in [4, 16])", optarg);
            o->width = (int)v;
            break;
        case OPT_CERTIFY: o->certify = 1; break;
        case OPT_ANY_N: o->any_n = 1; break;
        case OPT_NO_DISC: o->no_disc = 1; break;
        case OPT_NO_DT: o->no_delaunay = 1; break;
        case OPT_PCF_SIGMA:
            if (cli_parse_double(optarg, 0.005, 1, &o->pcf_sigma) != 0)
                cli_usage_error(prog, "bad --pcf-sigma '%s' (a number in [0.005, 1])", optarg);
            break;
        case OPT_PCF_RMAX:
            if (cli_parse_double(optarg, 0.1, 100, &o->pcf_rmax) != 0)
                cli_usage_error(prog, "bad --pcf-rmax '%s' (a number in [0.1, 100])", optarg);
            break;
        case OPT_INTEG:
            if (cli_parse_i64(optarg, 0, 1 << 20, &v) != 0)
                cli_usage_error(prog, "bad --integration '%s' (an integer in [0, %d])", optarg, 1 << 20);
            o->integ = (int)v;
            break;
        case OPT_CERT_TOL:
            if (cli_parse_double(optarg, 0, 1, &o->cert_tol) != 0)
                cli_usage_error(prog, "bad --cert-tol '%s' (a number in [0, 1])", optarg);
            break;
        case OPT_GRID:
            if (cli_parse_i64(optarg, 0, 1 << 20, &o->grid) != 0)
                cli_usage_error(prog, "bad --grid '%s' (an integer in [0, %d])", optarg, 1 << 20);
            break;
        case 't':
            if (cli_parse_i64(optarg, 1, 4096, &v) != 0)
                cli_usage_error(prog, "bad --threads '%s' (an integer in [1, 4096])", optarg);
            o->threads = (int)v;
            break;
        case 'q': o->quiet = 1; break;
        case OPT_DENSITY: o->density = optarg; break;
        case OPT_PREFIXES: o->prefixes = 1; break;
        case OPT_PREFIX_BASE:
            if (cli_parse_i64(optarg, 2, INT64_MAX, &v) != 0)
                cli_usage_error(prog, "bad --prefix-base '%s' (an integer >= 2)", optarg);
            o->prefix_base = (size_t)v;
            o->prefix_opts = 1;
            break;
        case OPT_PREFIX_SIZES: parse_sizes(optarg, o), o->prefix_opts = 1; break;
        case 'h': usage(); exit(0);
        case 'V': printf("cfpo-analyze %s\n", CFPO_VERSION); exit(0);
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, longs, argv[optind - 1]);
        }
    }
    o->files = argv + optind;
    o->nfiles = argc - optind;
    if (o->nfiles < 1) cli_usage_error(prog, "no input file");
    if (o->prefix_opts && !o->prefixes)
        cli_usage_error(prog, "--prefix-base and --prefix-sizes need --prefixes");
    if (o->prefixes && o->nfiles != 1) cli_usage_error(prog, "--prefixes takes one input file");
#ifndef CFPO_HAVE_CGAL
    o->no_delaunay = 1; /* a build without CGAL has no Delaunay measures (delaunay_none.c) */
#endif
}

/* NAME.analysis in the current folder for one file NAME.EXT. */
static char *default_out(const options *o)
{
    if (o->nfiles > 1) return strdup("avg.analysis");
    const char *slash = strrchr(o->files[0], '/');
    const char *base = slash ? slash + 1 : o->files[0];
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    char *s = malloc(len + 16);
    if (s) snprintf(s, len + 16, "%.*s.analysis", (int)len, base);
    return s;
}

/* ------------------------------------------------------------ the run */

typedef struct {
    options opt;
    an_outdir out;
    int out_begun;
    cli_progress progress;
    size_t n;
    double nsum; /* the sets' n summed (--any-n: R.n becomes their mean) */
    int K, set;
    double *P, *Psum, *Pref;
    double *dmin, *davg, *spike; /* per set */
    int *spike_k;                /* per set: kx, ky */
    an_discrepancy *disc;        /* per set; NULL with --no-discrepancy */
    double disc_seconds;
    an_delaunay *dt;             /* per set; NULL with --no-delaunay */
    an_integration *integ;       /* per set; NULL with --integration 0 */
    double *pcf, *pcf_set;       /* the sets' g summed, one set's; NULL: no bins */
    int pcf_bins;
    double dt_seconds, integ_seconds, pcf_seconds;
    uint64_t hist[AN_NN_BINS];
    an_certificate cert;
    an_nufft_info nufft;
    double check_maxdiff, spectrum_seconds;
    an_density dens;
    an_vcells cells; /* this set's Voronoi cells (--density) */
    int have_cells;
    an_prefixes prefixes; /* --prefixes */
    int have_prefixes;
} run;

static run R;

static void fail(const char *fmt, ...) __attribute__((noreturn, format(printf, 1, 2)));
static void fail(const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cli_progress_end(&R.progress);
    if (R.out_begun) an_outdir_abort(&R.out);
    cli_fail(prog, "%s", msg);
}

static void on_exact_progress(double frac, void *user)
{
    (void)user;
    cli_progress_line(&R.progress, 0, "set %d/%d: exact spectrum %.0f%%", R.set + 1,
                      R.opt.nfiles, 100 * frac);
}

/* First set: fixes n and K, allocates, opens the output folder. */
static void start(const char *file, size_t n)
{
    char err[1024];
    R.n = n;
    R.K = R.opt.K ? R.opt.K : an_default_K(n);
    const size_t N = an_side(R.K) * an_side(R.K);
    R.P = malloc(N * sizeof *R.P);
    R.Psum = calloc(N, sizeof *R.Psum);
    R.Pref = R.opt.check ? malloc(N * sizeof *R.Pref) : NULL;
    R.dmin = malloc((size_t)R.opt.nfiles * sizeof *R.dmin);
    R.davg = malloc((size_t)R.opt.nfiles * sizeof *R.davg);
    R.spike = malloc((size_t)R.opt.nfiles * sizeof *R.spike);
    R.spike_k = malloc(2 * (size_t)R.opt.nfiles * sizeof *R.spike_k);
    if (!R.P || !R.Psum || (R.opt.check && !R.Pref) || !R.dmin || !R.davg || !R.spike || !R.spike_k)
        fail("%s: out of memory for K = %d", file, R.K);
    if (!R.opt.no_disc) {
        const double need = an_discrepancy_bytes(n), have = cli_physical_memory();
        if (need > 0.9 * have)
            fail("%s: n = %zu is too large for memory: the discrepancies need %.1f GB, this machine has "
                 "%.1f GB (--no-discrepancy skips them)", file, n, need / 1e9, have / 1e9);
        R.disc = malloc((size_t)R.opt.nfiles * sizeof *R.disc);
        if (!R.disc) fail("out of memory");
    }
    if (R.opt.density && an_dda_check_memory(n, R.K, AN_DDA_RADIUS, cli_physical_memory(), err, sizeof err) != 0)
        fail("%s: %s", file, err);
    if (!R.opt.no_delaunay || R.opt.density) {
        const double need = an_delaunay_bytes(n), have = cli_physical_memory();
        if (need > 0.9 * have)
            fail("%s: n = %zu is too large for memory: the Delaunay triangulation needs %.1f GB, this machine "
                 "has %.1f GB (--no-delaunay skips it)", file, n, need / 1e9, have / 1e9);
        if (!R.opt.no_delaunay) R.dt = malloc((size_t)R.opt.nfiles * sizeof *R.dt);
    }
    if (R.opt.integ) R.integ = malloc((size_t)R.opt.nfiles * sizeof *R.integ);
    R.pcf_bins = an_pcf_bins(n, R.opt.pcf_sigma, R.opt.pcf_rmax);
    if (R.pcf_bins) {
        R.pcf = calloc((size_t)R.pcf_bins, sizeof *R.pcf);
        R.pcf_set = malloc((size_t)R.pcf_bins * sizeof *R.pcf_set);
    }
    if ((!R.opt.no_delaunay && !R.dt) || (R.opt.integ && !R.integ) || (R.pcf_bins && (!R.pcf || !R.pcf_set)))
        fail("out of memory");
    char *out = R.opt.out ? strdup(R.opt.out) : default_out(&R.opt);
    if (!out) fail("out of memory");
    if (an_outdir_begin(&R.out, out, err, sizeof err) != 0) fail("%s", err);
    free(out);
    R.out_begun = 1;
}

static void spectrum(const char *file, const double *xy, size_t n)
{
    char err[1024];
    double t0 = cli_now();
    int bad = R.opt.exact ? an_power_exact(xy, n, R.K, R.P, on_exact_progress, NULL, err, sizeof err)
                          : an_power_nufft(xy, n, R.K, R.opt.width, R.P, &R.nufft, err, sizeof err);
    if (bad) fail("%s: %s", file, err);
    R.spectrum_seconds += cli_now() - t0;
    if (R.opt.check) {
        bad = R.opt.exact ? an_power_nufft(xy, n, R.K, R.opt.width, R.Pref, &R.nufft, err, sizeof err)
                          : an_power_exact(xy, n, R.K, R.Pref, on_exact_progress, NULL, err, sizeof err);
        if (bad) fail("%s: %s", file, err);
        double d = R.opt.exact ? an_power_maxdiff(R.Pref, R.P, R.K) : an_power_maxdiff(R.P, R.Pref, R.K);
        if (!(d <= R.check_maxdiff)) R.check_maxdiff = d;
    }
    const size_t N = an_side(R.K) * an_side(R.K);
    for (size_t t = 0; t < N; t++) R.Psum[t] += R.P[t];
    an_rings rings; /* this set's own spike ratio */
    if (an_rings_compute(R.P, R.K, &rings) != 0) fail("%s: out of memory", file);
    R.spike[R.set] = rings.spike_ratio;
    R.spike_k[2 * R.set] = rings.spike_kx;
    R.spike_k[2 * R.set + 1] = rings.spike_ky;
    an_rings_free(&rings);
}

static void distances(const char *file, const double *xy, size_t n)
{
    if (n < 2) return;
    an_nn nn;
    if (an_nn_compute(xy, n, &nn, R.hist) != 0) fail("%s: out of memory", file);
    R.dmin[R.set] = nn.delta_min;
    R.davg[R.set] = nn.delta_avg;
    free(nn.nn);
}

static void discrepancies(const char *file, const double *xy, size_t n)
{
    char err[1024];
    cli_progress_line(&R.progress, 1, "set %d/%d: discrepancies", R.set + 1, R.opt.nfiles);
    const double t0 = cli_now();
    if (an_discrepancy_compute(xy, n, &R.disc[R.set], err, sizeof err) != 0) fail("%s: %s", file, err);
    R.disc_seconds += cli_now() - t0;
}

/* pair correlation, Delaunay measures, integration test */
static void structure(const char *file, const double *xy, size_t n)
{
    char err[1024];
    if (R.pcf) {
        cli_progress_line(&R.progress, 1, "set %d/%d: pair correlation", R.set + 1, R.opt.nfiles);
        const double t0 = cli_now();
        const int B = an_pcf_bins(n, R.opt.pcf_sigma, R.opt.pcf_rmax); /* --any-n: the least of the sets' */
        if (B < R.pcf_bins) R.pcf_bins = B;
        if (R.pcf_bins < 1) fail("%s: too few points for the pair correlation", file);
        if (an_pcf_compute(xy, n, R.opt.pcf_sigma, R.opt.pcf_rmax, R.pcf_bins, R.pcf_set) != 0)
            fail("%s: out of memory", file);
        for (int b = 0; b < R.pcf_bins; b++) R.pcf[b] += R.pcf_set[b];
        R.pcf_seconds += cli_now() - t0;
    }
    if (R.dt || R.opt.density) { /* with --density, the Voronoi cells too (capacities) */
        cli_progress_line(&R.progress, 1, "set %d/%d: Delaunay", R.set + 1, R.opt.nfiles);
        const double t0 = cli_now();
        an_delaunay dt;
        const int bad = an_delaunay_compute_cells(xy, n, &dt, R.opt.density ? &R.cells : NULL, err, sizeof err);
        R.have_cells = !bad && R.opt.density;
        if (R.dt) R.dt[R.set] = bad ? (an_delaunay){NAN, NAN, NAN, NAN, NAN} : dt; /* undefined for this set */
        R.dt_seconds += cli_now() - t0;
    }
    if (R.integ) {
        cli_progress_line(&R.progress, 1, "set %d/%d: integration test", R.set + 1, R.opt.nfiles);
        const double t0 = cli_now();
        if (an_integration_compute(xy, n, R.opt.integ, AN_INTEG_SEED, &R.integ[R.set]) != 0)
            fail("%s: out of memory", file);
        R.integ_seconds += cli_now() - t0;
    }
}

static void certificate(const char *file, const double *xy, size_t n)
{
    char err[1024];
    an_certificate c;
    cli_progress_line(&R.progress, 1, "set %d/%d: certificate", R.set + 1, R.opt.nfiles);
    if (an_certify(xy, n, R.opt.cert_tol, &c, NULL, NULL, err, sizeof err) != 0)
        fail("%s: %s", file, err);
    an_certificate_merge(&R.cert, &c);
}

static void analyze_set(const char *file)
{
    char err[1024];
    double *xy;
    size_t n;
    if (pf_read(file, &xy, &n, err, sizeof err) != 0) fail("%s", err);
    if (R.set == 0) start(file, n);
    else if (n != R.n && !R.opt.any_n)
        fail("%s: has %zu points, but %s has %zu; averaged sets must have the same n", file, n,
             R.opt.files[0], R.n);
    if (R.opt.any_n && n < 2) fail("%s: --any-n needs at least 2 points a set", file);
    R.nsum += (double)n;
    if (R.opt.certify && n < 2) fail("%s: the certificate needs at least 2 points", file);
    if (R.opt.prefixes) { /* first: a size beyond n fails before the rest is computed */
        cli_progress_line(&R.progress, 1, "set %d/%d: prefixes", R.set + 1, R.opt.nfiles);
        if (n < 2) fail("%s: --prefixes needs at least 2 points", file);
        if (an_prefixes_compute(xy, n, R.opt.prefix_base, R.opt.prefix_sizes, R.opt.nprefix_sizes, R.opt.width,
                                &R.prefixes, err, sizeof err) != 0)
            fail("%s: %s", file, err);
        R.have_prefixes = 1;
    }
    cli_progress_line(&R.progress, 1, "set %d/%d: spectrum", R.set + 1, R.opt.nfiles);
    spectrum(file, xy, n);
    distances(file, xy, n);
    if (R.disc) discrepancies(file, xy, n);
    structure(file, xy, n);
    if (R.opt.certify) certificate(file, xy, n);
    if (R.opt.density && n >= 2) {
        cli_progress_line(&R.progress, 1, "set %d/%d: density measures", R.set + 1, R.opt.nfiles);
        if (an_density_add(&R.dens, xy, n, R.have_cells ? &R.cells : NULL, R.K, err, sizeof err) != 0)
            fail("%s: %s", file, err);
    }
    an_vcells_free(&R.cells);
    R.have_cells = 0;
    free(xy);
}

static void write_outputs(const an_report *rep, const an_measures *m)
{
    char err[1024];
    char *p;
#define WRITE(name, call)                                        \
    do {                                                         \
        if (!(p = an_outdir_file(&R.out, name))) fail("out of memory"); \
        if ((call) != 0) {                                       \
            free(p);                                             \
            an_outdir_message(&R.out, err, sizeof err);          \
            fail("%s", err);                                     \
        }                                                        \
        free(p);                                                 \
    } while (0)
    WRITE("spectrum.txt", an_write_spectrum(p, R.Psum, R.K, err, sizeof err));
    WRITE("raps.txt", an_write_raps(p, rep, err, sizeof err));
    WRITE("nn_hist.txt", an_write_nnhist(p, rep, err, sizeof err));
    WRITE("plot.gp", an_write_plot(p, rep, err, sizeof err));
    WRITE("stats.json", an_write_json(p, rep, err, sizeof err));
    WRITE("pcf.txt", an_measures_write_pcf(p, m, err, sizeof err));
    WRITE("pcf.gp", an_measures_write_pcf_plot(p, m, err, sizeof err));
    if (R.have_prefixes) WRITE("prefixes.txt", an_prefixes_write(p, &R.prefixes, err, sizeof err));
    if (R.opt.density) {
        WRITE("density.txt", an_density_write(&R.dens, p, err, sizeof err));
        char *q = an_outdir_file(&R.out, "dda_spectrum.txt");
        if (!q) fail("out of memory");
        WRITE("dda_raps.txt", an_density_write_dda(&R.dens, p, q, err, sizeof err));
        free(q);
    }
#undef WRITE
}

static double mean_of(const double *v, int m)
{
    double s = 0;
    for (int i = 0; i < m; i++) s += v[i];
    return s / m;
}

int main(int argc, char **argv)
{
    parse(argc, argv, &R.opt);
    if (R.opt.threads) omp_set_num_threads(R.opt.threads);
    cli_progress_init(&R.progress, R.opt.quiet);
    R.check_maxdiff = NAN;
    if (R.opt.density) {
        char derr[1024];
        if (an_density_begin(&R.dens, R.opt.density, derr, sizeof derr) != 0) cli_fail(prog, "%s", derr);
    }
    const double t0 = cli_now();
    for (R.set = 0; R.set < R.opt.nfiles; R.set++) analyze_set(R.opt.files[R.set]);
    cli_progress_end(&R.progress);

    const int sets = R.opt.nfiles;
    if (R.opt.any_n) R.n = (size_t)floor(R.nsum / sets + 0.5);
    const size_t N = an_side(R.K) * an_side(R.K);
    for (size_t t = 0; t < N; t++) R.Psum[t] /= sets;
    an_rings rings;
    an_hsd hsd;
    if (an_rings_compute(R.Psum, R.K, &rings) != 0 || an_hsd_compute(R.Psum, R.K, R.n, &rings, &hsd) != 0)
        fail("out of memory");
    an_lattice lattice;
    const int lg = an_lattice_grid(R.opt.grid, R.n);
    an_lattice_compute(R.Psum, &rings, lg, an_lattice_period(lg), &lattice);
    an_lowfreq lowfreq;
    an_shiftvar shiftvar;
    if (an_lowfreq_compute(R.Psum, R.K, R.n, &rings, &lowfreq) != 0) fail("out of memory");
    an_shiftvar_compute(R.Psum, R.K, R.n, &shiftvar);
    for (int b = 0; R.pcf && b < R.pcf_bins; b++) R.pcf[b] /= sets;
    const an_measures measures = {.sets = sets, .n = R.n, .disc = R.disc, .lowfreq = &lowfreq,
                                  .shiftvar = &shiftvar, .disc_seconds = R.disc_seconds,
                                  .dt = R.dt, .dt_seconds = R.dt_seconds, .integ = R.integ,
                                  .integ_seed = AN_INTEG_SEED, .integ_seconds = R.integ_seconds,
                                  .pcf = R.pcf, .pcf_bins = R.pcf_bins, .pcf_sigma = R.opt.pcf_sigma,
                                  .pcf_rmax = R.opt.pcf_rmax, .pcf_seconds = R.pcf_seconds};
    char *msum = an_measures_summary(&measures), *mjson = an_measures_json(&measures);
    char *psum = an_prefixes_summary(R.have_prefixes ? &R.prefixes : NULL);
    if (msum && psum) { /* the prefix keys follow the measures' */
        char *both = malloc(strlen(msum) + strlen(psum) + 1);
        if (both) strcpy(both, msum), strcat(both, psum);
        free(msum);
        msum = both;
    }
    free(psum);
    char *outname = strdup(R.out.final);
    if (!outname || !msum || !mjson) fail("out of memory");
    an_report rep = {
        .files = (const char *const *)R.opt.files, .sets = sets, .n = R.n, .K = R.K,
        .exact = R.opt.exact, .nufft = R.nufft, .check_maxdiff = R.check_maxdiff,
        .delta_min = R.n >= 2 ? R.dmin : NULL, .delta_avg = R.n >= 2 ? R.davg : NULL,
        .delta_min_mean = R.n >= 2 ? mean_of(R.dmin, sets) : NAN,
        .delta_avg_mean = R.n >= 2 ? mean_of(R.davg, sets) : NAN,
        .nn_hist = R.n >= 2 ? R.hist : NULL, .rings = &rings, .hsd = &hsd,
        .spike = R.spike, .spike_k = R.spike_k, .spike_mean = mean_of(R.spike, sets), .lattice = &lattice,
        .cert = R.opt.certify ? &R.cert : NULL, .threads = omp_get_max_threads(),
        .spectrum_seconds = R.spectrum_seconds, .out = outname,
        .summary_extra = msum, .json_extra = mjson};
    rep.seconds = cli_now() - t0;
    if (R.opt.density && an_density_finish(&R.dens, R.n) != 0) fail("out of memory");
    write_outputs(&rep, &measures);
    char err[1024];
    if (an_outdir_commit(&R.out, err, sizeof err) != 0) {
        R.out_begun = 0;
        fail("%s", err);
    }
    R.out_begun = 0;
    rep.seconds = cli_now() - t0;
    rep.peak_bytes = cli_peak_rss();
    an_print_summary(stdout, &rep);
    an_print_imprint(stdout, &rep);
    if (R.opt.density) an_density_print(&R.dens, stdout), an_density_free(&R.dens);
    an_rings_free(&rings);
    free(outname);
    an_prefixes_free(&R.prefixes); free(R.opt.prefix_sizes);
    free(msum); free(mjson); free(R.disc); free(R.dt); free(R.integ); free(R.pcf); free(R.pcf_set);
    free(R.P); free(R.Psum); free(R.Pref); free(R.dmin); free(R.davg); free(R.spike); free(R.spike_k);
    return 0;
}
