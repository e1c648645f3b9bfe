/* pd_main.c - the command line of the Poisson-disk baselines (cfpo-dart,
 * cfpo-bs, cfpo-bridson), in cfpo's style: the options of the three
 * methods' tables (bl_pd.c), parsed against them, the radius check and
 * the run (pd_check.h), trace, progress, output and the SUMMARY line. One
 * function for the three commands; each main_*.c passes its method.
 * Computes nothing itself. */
#include "pd_main.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_run.h"
#include "cfpo.h"
#include "cli.h"
#include "dens_measure.h"
#include "density.h"
#include "pd_check.h"
#include "pointfile.h"
#include "stats.h"

extern const bl_method bl_dart, bl_bs, bl_bridson;

/* Each option of the three commands (the union of their tables) and the
 * command that takes it. */
static const bl_method *const PD[] = {&bl_dart, &bl_bs, &bl_bridson};

/* The default of the option spelt cli in m's table. */
static double def_of(const bl_method *m, const char *cli) { return m->options[bl_option_index(m, cli)].def; }

static const char *const REL_WHY[] = {
    [PD_DART] = "close to dart throwing's jamming limit (about 0.777),\n"
                "                       yet reached reliably",
    [PD_BS] = "measured so that the maximal set has n points on\n"
              "                       average",
    [PD_BRIDSON] = "measured so that the maximal set has n points on\n"
                   "                       average"};

static void usage(const bl_method *m)
{
    const int kind = m->pd_kind;
    printf("Usage: %s -n N [options]\n", m->prog);
    if (kind != PD_DART) printf("       %s -r R [options]\n", m->prog);
    printf("%s\nThe unit torus, periodic distances. Prints one SUMMARY line on stdout.\n\n",
           m->about);
    if (kind == PD_DART)
        printf("  -n, --points N       number of points to place (required)\n");
    else
        printf("  -n, --points N       the expected number of points: sets r = REL * Delta(N);\n"
               "                       the maximal set has about N points (the exact count is\n"
               "                       in the SUMMARY line)\n");
    printf("  -s, --seed S         random seed (default 1)\n"
           "  -r, --radius R       the Poisson-disk radius (minimum distance) itself\n"
           "      --rel-radius REL r = REL * Delta(n), Delta(n) = sqrt(2 / (sqrt(3) n));\n"
           "                       default %.4g: %s\n", m->pd_rel, REL_WHY[kind]);
    if (kind == PD_DART)
        printf("      --density SPEC   adaptive dart throwing under a density, SPEC as `cfpo\n"
               "                       --density` (an image, a .npy array, cos:..., ramp:...,\n"
               "                       balzer): darts drawn proportional to rho, two points in\n"
               "                       conflict when |x_i - x_j| < r / (rho_i rho_j)^(1/4), i.e.\n"
               "                       the symmetric measure below REL; delta_min and delta_avg\n"
               "                       in that measure\n");
    if (kind == PD_DART)
        printf("      --max-fails F    saturation: stop when F consecutive darts are rejected\n"
               "                       (default %.0f); then nothing is written, exit 1\n",
               def_of(m, "max-fails"));
    if (kind == PD_BRIDSON)
        printf("  -k, --candidates K   candidates per active sample (default %g)\n"
               "      --plain          the 2007 algorithm only: retire a sample after K\n"
               "                       failures (not maximal)\n", def_of(m, "candidates"));
    printf("  -o, --output FILE    write the points; format from the extension:\n"
           "                       %s\n"
           "      --trace FILE     progress rows (TSV: points, trials, active, elapsed)\n"
           "  -q, --quiet          no progress line\n"
           "  -h, --help           this help\n"
           "  -V, --version        version\n\n"
           "Exit status: 0 success, 1 runtime failure (e.g. saturation), 2 usage error.\n",
           PF_EXTENSIONS);
}

typedef struct {
    bl_run *run;
} report_ctx;

static void on_report(void *user, int64_t placed, uint64_t trials, int64_t active)
{
    bl_run *r = ((report_ctx *)user)->run;
    double el = cli_now() - r->t0;
    if (r->tf) fprintf(r->tf, "%lld\t%llu\t%lld\t%.6f\n", (long long)placed, (unsigned long long)trials,
                       (long long)active, el);
    cli_progress_line(&r->pg, 0, "points %lld  trials %llu  active %lld  elapsed %.1fs",
                      (long long)placed, (unsigned long long)trials, (long long)active, el);
}

int pd_main(int argc, char **argv, const bl_method *m)
{
    const int kind = m->pd_kind;
    const char *prog = m->prog;
    /* the three tables' options, each once: code OWN + k for opt[k] */
    enum { FIXED = 9, OWN = 2000, MAXU = 3 * BL_MAX_OPTIONS, DENSITY = 1004 };
    struct option longopts[FIXED + MAXU + 1] = {
        {"points", required_argument, 0, 'n'}, {"seed", required_argument, 0, 's'},
        {"output", required_argument, 0, 'o'}, {"trace", required_argument, 0, 't'},
        {"quiet", no_argument, 0, 'q'}, {"help", no_argument, 0, 'h'},
        {"version", no_argument, 0, 'V'}, {"density", required_argument, 0, DENSITY}};
    const bl_option *opt[MAXU];
    const bl_method *owner[MAXU];
    char shortopts[64] = ":n:s:o:qhV";
    int nu = 0, k = FIXED - 1;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < PD[j]->noptions; i++) {
            const bl_option *o = &PD[j]->options[i];
            int seen = 0;
            for (int u = 0; u < nu; u++) seen |= strcmp(opt[u]->cli, o->cli) == 0;
            if (seen) continue;
            const int arg = o->type == BL_FLAG ? no_argument : required_argument;
            longopts[k++] = (struct option){o->cli, arg, 0, o->letter ? o->letter : OWN + nu};
            if (o->letter) snprintf(shortopts + strlen(shortopts), 3, "%c%s", o->letter, arg ? ":" : "");
            opt[nu] = o;
            owner[nu++] = PD[j];
        }
    longopts[k] = (struct option){0, 0, 0, 0};
    bl_value v[BL_MAX_OPTIONS];
    bl_defaults(m, v);
    int64_t n = -1;
    uint64_t seed = 1;
    const char *out = NULL, *trace = NULL, *spec = NULL;
    int quiet = 0, ch;
    char err[600];
    opterr = 0;
    while ((ch = getopt_long(argc, argv, shortopts, longopts, NULL)) != -1) {
        switch (ch) {
        case DENSITY:
            if (kind != PD_DART) cli_usage_error(prog, "--density applies to cfpo-dart only");
            spec = optarg;
            break;
        case 'n': n = cli_arg_points(prog, optarg); break;
        case 's': seed = cli_arg_seed(prog, optarg); break;
        case 'o': out = optarg; break;
        case 't': trace = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(m); return 0;
        case 'V': printf("%s %s\n", prog, CFPO_VERSION); return 0;
        case ':': cli_usage_error(prog, "option '%s' needs a value", argv[optind - 1]);
        default: {
            int u = ch >= OWN && ch < OWN + nu ? ch - OWN : -1;
            for (int w = 0; w < nu && u < 0; w++)
                if (opt[w]->letter && opt[w]->letter == ch) u = w;
            if (u < 0) cli_bad_option(prog, longopts, argv[optind - 1]);
            const int i = bl_option_index(m, opt[u]->cli);
            if (i < 0) {
                if (opt[u]->letter) cli_usage_error(prog, "-%c applies to %s only", opt[u]->letter, owner[u]->prog);
                cli_usage_error(prog, "--%s applies to %s only", opt[u]->cli, owner[u]->prog);
            }
            if (bl_option_parse(m, i, optarg, 0, v, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
        }
        }
    }
    if (optind < argc) cli_usage_error(prog, "unexpected argument '%s'", argv[optind]);
    pd_params p;
    double radius, rel;
    pd_params_of(m, v, seed, &p, &radius, &rel);
    if (pd_check_args(kind, n, radius, rel, &pd_cli_names, err, sizeof err) != 0) cli_usage_error(prog, "%s", err);
    bl_check_output_name(prog, out);
    cfpo_density dens;
    if (spec) {
        if (cfpo_density_load(spec, &dens, err, sizeof err) != 0) cli_fail(prog, "%s", err);
        if (cfpo_density_check_n(&dens, n, err, sizeof err) != 0) cli_usage_error(prog, "--density %s: %s", spec, err);
        p.density = &dens;
    }
    if (pd_setup(kind, n, radius, rel, m->pd_rel, &pd_cli_names, &p, err, sizeof err) != 0)
        cli_usage_error(prog, "%s", err);

    bl_run run;
    bl_run_open(&run, prog, out, trace, kind == PD_DART ? (size_t)n : 0, "points\ttrials\tactive\telapsed", quiet);
    report_ctx rc = {&run};
    p.report = on_report;
    p.user = &rc;
    pd_result res;
    if (pd_sample(kind, &p, &res, err, sizeof err) != 0) cli_fail(prog, "%s", err);
    const double seconds = cli_now() - run.t0;
    on_report(&rc, res.n, res.trials, 0);
    if (pd_verdict(kind, &res, n, &p, &pd_cli_names, err, sizeof err) != 0) {
        if (res.saturated) cli_progress_end(&run.pg);
        cli_fail(prog, "%s", err);
    }
    bl_run_finish(&run, res.xy, (size_t)res.n);
    double dmin = 0, davg = 0;
    if (res.n >= 2 && (spec ? cfpo_dens_nn(&dens, res.xy, (size_t)res.n, NULL, &dmin, &davg)
                            : cfpo_nn_stats(res.xy, (size_t)res.n, NULL, &dmin, &davg)) != 0)
        cli_fail(prog, "out of memory for the statistics");
    cli_summary sm = {.method = m->name, .variant = "-", .n = res.n, .seed = p.seed,
                      .threads = 1, .ranks = 1, .iterations = -1, .seconds = seconds,
                      .delta_min = dmin, .delta_avg = davg, .converged = -1,
                      .peak_bytes = cli_peak_rss()};
    cli_print_summary(stdout, &sm);
    if (spec) {
        printf("DENSITY spec=%s hash=%016llx pixels=%lldx%lld contrast=%.4g support=%.4g\n", spec,
               (unsigned long long)dens.hash, (long long)dens.w, (long long)dens.h, dens.rho_max / dens.rho_min,
               dens.support);
        cfpo_density_free(&dens);
    }
    free(res.xy);
    return 0;
}
