/* analyze3d.c - the cfpo3d-analyze command: measures of a 3-D set
 * (docs/cli.md, "cfpo3d-analyze"): delta_min and delta_avg over Delta3(n),
 * the packing fraction of spheres whose diameter is delta_min, and
 * Steinhardt's Q6 with the crystal-like count (q6.h); on request the
 * shell-averaged power spectrum with P0 (measures3_spec.h) and the pair
 * correlation g(r) (measures3_pcf.h), each as a TSV file. One line on
 * stdout. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "measures3_pcf.h"
#include "measures3_spec.h"
#include "measures3_w6.h"
#ifdef CFPO3_HAVE_VORONOI
#include "measures3_fpd.h"
#include "measures3_vor.h"
#endif
#include "nn3.h"
#include "points3.h"
#include "q6.h"
#include "solve3.h"

static const char *prog = "cfpo3d-analyze";

static void usage(void)
{
    printf("usage: cfpo3d-analyze [options] FILE      measures of a set on the unit 3-torus\n\n"
           "  FILE              n x 3 points in [0,1): .npy, text, CSV or raw\n"
           "  --neighbours K    neighbours of the bond order (default 12)\n"
           "  --bond C          bond threshold of the normalised q6 product (default 0.7)\n"
           "  --bonds B         bonds that make a point crystal-like (default 8)\n"
           "  --spectrum FILE   the power spectrum averaged over shells |k| = s (TSV: shell,\n"
           "                    power, frequencies); adds p0= and peak= (the highest shell) and\n"
           "                    the per-mode spike check: spike= (the largest P(k) over its shell's\n"
           "                    mean), spike_k=, spike_shell=, spike_noise= (ln((2K+1)^3/2) + 4) and\n"
           "                    spike_pass= (yes: spike <= spike_noise)\n"
           "  --spike           the spectrum's figures and the spike check without the TSV file\n"
           "  --kmax K          frequencies in [-K, K]^3 (default ceil(2 n^(1/3)), 8..64; at most %d)\n"
           "  --exact           the spectrum by direct summation (O(n K^3)) instead of the NUFFT\n"
           "  --pcf FILE        the pair correlation g(r), r / Delta3(n) in bins of 0.02 up to\n"
           "                    3 (less when 3 Delta3(n) >= 1/2) (TSV: r, g)\n"
           "  --voronoi         Voronoi statistics from CGAL's periodic 3-D triangulation: faces\n"
           "                    per cell (mean, standard deviation) and the variance of n V (V a\n"
           "                    cell's volume); only in builds with CGAL\n"
           "  --certify         (builds with CGAL) the FPD certificate: can any point move farther\n"
           "                    from the rest? adds fpd_pass= fpd_points= fpd_max_violation= fpd_seconds=\n"
           "  -h, --help\n\n"
           "prints: ANALYZE3D n= delta_min= delta_avg= packing_fraction= q6_global= q6_local= crystal_like= crystal_fraction=\n"
           "        neighbours= bond= bonds= w6= w6_local= [p0= peak= peak_shell= kmax= spike= spike_k=\n"
           "        spike_shell= spike_noise= spike_pass=] [pcf_peak= pcf_peak_r=]\n"
           "        [vor_faces= vor_faces_sd= vor_volume_var=] [fpd_pass= fpd_points= fpd_max_violation= fpd_seconds=]\n", CFPO3_SPEC_KMAX);
}

/* The shell-averaged spectrum into path (when not NULL); " p0=... peak=...
 * spike=..." into extra. */
static int spectrum(const double *p, size_t n, int K, int exact, const char *path, char *extra, size_t xl,
                    char *err, size_t errlen)
{
    if (K == 0) K = cfpo3_spec_default_K(n);
    const size_t S = 2 * (size_t)K + 1;
    double *P = malloc(S * S * S * sizeof *P), *sh = malloc(((size_t)K + 1) * sizeof *sh);
    long *cnt = malloc(((size_t)K + 1) * sizeof *cnt);
    int rc = -1;
    if (!P || !sh || !cnt) {
        snprintf(err, errlen, "out of memory for the spectrum");
        goto done;
    }
    if (exact ? cfpo3_power_exact(p, n, K, P) : cfpo3_power_nufft(p, n, K, P, err, errlen)) {
        if (exact) snprintf(err, errlen, "out of memory for the spectrum");
        goto done;
    }
    cfpo3_power_shells(P, K, sh, cnt);
    long c0;
    const double p0 = cfpo3_power_p0(P, K, n, &c0);
    const int peak = cfpo3_power_peak(sh, K);
    cfpo3_spike sp;
    cfpo3_power_spike(P, K, sh, cnt, &sp);
    if (path) {
        cli_atomic f;
        if (cli_atomic_open(&f, path, err, errlen) != 0) goto done;
        fprintf(f.f, "shell\tpower\tfrequencies\n");
        for (int s = 1; s <= K; s++) fprintf(f.f, "%d\t%.6g\t%ld\n", s, sh[s], cnt[s]);
        if (cli_atomic_commit(&f, err, errlen) != 0) goto done;
    }
    snprintf(extra, xl, " p0=%.6g peak=%.6g peak_shell=%d kmax=%d spike=%.4g spike_k=%d,%d,%d spike_shell=%d spike_noise=%.2f spike_pass=%s",
             p0, sh[peak], peak, K, sp.ratio, sp.kx, sp.ky, sp.kz, sp.shell, sp.noise, sp.pass ? "yes" : "no");
    rc = 0;
done:
    free(P), free(sh), free(cnt);
    return rc;
}

/* g(r) into path; " pcf_peak=... pcf_peak_r=..." into extra. */
static int pcf(const double *p, size_t n, const char *path, char *extra, size_t xl, char *err, size_t errlen)
{
    const double dr = 0.02;
    const int bins = cfpo3_pcf_bins(n, 3.0, dr);
    double *g = malloc((size_t)(bins > 0 ? bins : 1) * sizeof *g);
    if (!g || bins < 1 || cfpo3_pcf(p, n, bins * dr, dr, g, bins) != 0) {
        free(g);
        snprintf(err, errlen, bins < 1 ? "--pcf: too few points for g(r)" : "out of memory for g(r)");
        return -1;
    }
    int pk = 0;
    for (int b = 0; b < bins; b++)
        if (g[b] > g[pk]) pk = b;
    cli_atomic f;
    if (cli_atomic_open(&f, path, err, errlen) != 0) {
        free(g);
        return -1;
    }
    fprintf(f.f, "r\tg\n");
    for (int b = 0; b < bins; b++) fprintf(f.f, "%.4f\t%.6g\n", (b + 0.5) * dr, g[b]);
    const int rc = cli_atomic_commit(&f, err, errlen);
    if (rc == 0) snprintf(extra, xl, " pcf_peak=%.4f pcf_peak_r=%.3f", g[pk], (pk + 0.5) * dr);
    free(g);
    return rc;
}

#ifdef CFPO3_HAVE_VORONOI
/* " vor_faces=... vor_faces_sd=... vor_volume_var=..." into extra. */
static int vor_stats(const double *p, size_t n, char *extra, size_t xl, char *err, size_t errlen)
{
    int *f = malloc(n * sizeof *f);
    double *v = malloc(n * sizeof *v);
    if (!f || !v || cfpo3_voronoi(p, n, f, v, NULL, err, errlen) != 0) {
        if (!f || !v) snprintf(err, errlen, "out of memory for the Voronoi cells");
        free(f), free(v);
        return -1;
    }
    double sf = 0, sf2 = 0, sv = 0, sv2 = 0;
    for (size_t i = 0; i < n; i++) {
        const double nv = v[i] * (double)n;
        sf += f[i], sf2 += (double)f[i] * f[i], sv += nv, sv2 += nv * nv;
    }
    const double mf = sf / (double)n, mv = sv / (double)n;
    snprintf(extra, xl, " vor_faces=%.4f vor_faces_sd=%.4f vor_volume_var=%.6g", mf, sqrt(fmax(0, sf2 / (double)n - mf * mf)),
             fmax(0, sv2 / (double)n - mv * mv));
    free(f), free(v);
    return 0;
}
#endif

int main(int argc, char **argv)
{
    static const struct option lo[] = {{"neighbours", required_argument, 0, 'k'},
                                       {"bond", required_argument, 0, 'b'},
                                       {"bonds", required_argument, 0, 'B'},
                                       {"spectrum", required_argument, 0, 'S'},
                                       {"kmax", required_argument, 0, 'K'},
                                       {"exact", no_argument, 0, 'E'},
                                       {"spike", no_argument, 0, 'X'},
                                       {"pcf", required_argument, 0, 'P'},
                                       {"voronoi", no_argument, 0, 'Y'},
                                       {"certify", no_argument, 0, 'C'},
                                       {"help", no_argument, 0, 'h'},
                                       {0, 0, 0, 0}};
    int64_t k = 12, bonds = 8;
    double bond = 0.7;
    const char *spec_out = NULL, *pcf_out = NULL;
    int64_t kmax = 0;
    int exact = 0, voronoi = 0, certify = 0, spike = 0;
    opterr = 0;
    int ch;
    while ((ch = getopt_long(argc, argv, ":h", lo, NULL)) != -1) {
        switch (ch) {
        case 'k':
            if (cli_parse_i64(optarg, 1, 64, &k) != 0) cli_usage_error(prog, "--neighbours must be 1..64, not '%s'", optarg);
            break;
        case 'b':
            if (cli_parse_double(optarg, 0.0, 1.0, &bond) != 0) cli_usage_error(prog, "--bond must be in [0, 1], not '%s'", optarg);
            break;
        case 'B':
            if (cli_parse_i64(optarg, 0, 64, &bonds) != 0) cli_usage_error(prog, "--bonds must be 0..64, not '%s'", optarg);
            break;
        case 'S': spec_out = optarg; break;
        case 'P': pcf_out = optarg; break;
        case 'E': exact = 1; break;
        case 'X': spike = 1; break;
        case 'Y':
#ifndef CFPO3_HAVE_VORONOI
            cli_usage_error(prog, "--voronoi needs a build with CGAL (CFPO_CGAL)");
#endif
            voronoi = 1;
            break;
        case 'C':
#ifndef CFPO3_HAVE_VORONOI
            cli_usage_error(prog, "--certify needs a build with CGAL (CFPO_CGAL)");
#endif
            certify = 1;
            break;
        case 'K':
            if (cli_parse_i64(optarg, 1, CFPO3_SPEC_KMAX, &kmax) != 0)
                cli_usage_error(prog, "--kmax must be 1..%d, not '%s'", CFPO3_SPEC_KMAX, optarg);
            break;
        case 'h': usage(); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: cli_bad_option(prog, lo, argv[optind - 1]);
        }
    }
    if (optind != argc - 1) cli_usage_error(prog, "one input file is needed");
    char err[512];
    double *p;
    size_t n;
    if (p3_read(argv[optind], &p, &n, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    if (n <= (size_t)k) cli_usage_error(prog, "%s holds %zu points: more than --neighbours %lld are needed", argv[optind], n, (long long)k);
    double dmin, davg;
    cfpo3_q6_result q;
    cfpo3_w6_result w;
    if (cfpo3_nn_stats(p, n, NULL, &dmin, &davg) != 0 || cfpo3_q6(p, n, (int)k, bond, (int)bonds, &q) != 0 ||
        cfpo3_w6(p, n, (int)k, &w) != 0)
        cli_fail(prog, "out of memory");
    const double d = dmin * cfpo3_delta_bound((double)n);
    char extra[512];
    snprintf(extra, sizeof extra, " w6=%.6f w6_local=%.6f", w.w6, w.w6_local);
    if ((spec_out || spike) && spectrum(p, n, (int)kmax, exact, spec_out, extra + strlen(extra), sizeof extra - strlen(extra), err, sizeof err) != 0)
        cli_fail(prog, "%s", err);
    if (pcf_out && pcf(p, n, pcf_out, extra + strlen(extra), sizeof extra - strlen(extra), err, sizeof err) != 0)
        cli_fail(prog, "%s", err);
#ifdef CFPO3_HAVE_VORONOI
    if (voronoi && vor_stats(p, n, extra + strlen(extra), sizeof extra - strlen(extra), err, sizeof err) != 0)
        cli_fail(prog, "%s", err);
    if (certify) {
        cfpo3_fpd_result fr;
        const double t0 = cli_now();
        if (cfpo3_fpd_certify(p, n, &fr, NULL, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        const size_t l = strlen(extra);
        snprintf(extra + l, sizeof extra - l, " fpd_pass=%s fpd_points=%zu fpd_max_violation=%.3g fpd_seconds=%.3f",
                 fr.passed == n ? "yes" : "no", fr.passed, fr.max_violation, cli_now() - t0);
    }
#else
    (void)voronoi, (void)certify;
#endif
    printf("ANALYZE3D n=%zu delta_min=%.6f delta_avg=%.6f packing_fraction=%.6f q6_global=%.6f q6_local=%.6f "
           "crystal_like=%lld crystal_fraction=%.6f neighbours=%lld bond=%g bonds=%lld%s\n",
           n, dmin, davg, M_PI / 6.0 * (double)n * d * d * d, q.q6_global, q.q6_local, (long long)q.crystal,
           q.crystal_frac, (long long)k, bond, (long long)bonds, extra);
    free(p);
    return 0;
}
