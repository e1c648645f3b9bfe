/* analyze3d.c - the cfpo3d-analyze command: measures of a 3-D set
 * (docs/cli.md, "cfpo3d-analyze"): delta_min and delta_avg over Delta3(n),
 * the packing fraction of spheres whose diameter is delta_min, and
 * Steinhardt's Q6 with the crystal-like count (q6.h). One line on stdout. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
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
           "  -h, --help\n\n"
           "prints: ANALYZE3D n= delta_min= delta_avg= packing_fraction= q6_global= q6_local= crystal_like= crystal_fraction=\n");
}

int main(int argc, char **argv)
{
    static const struct option lo[] = {{"neighbours", required_argument, 0, 'k'},
                                       {"bond", required_argument, 0, 'b'},
                                       {"bonds", required_argument, 0, 'B'},
                                       {"help", no_argument, 0, 'h'},
                                       {0, 0, 0, 0}};
    int64_t k = 12, bonds = 8;
    double bond = 0.7;
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
    if (cfpo3_nn_stats(p, n, NULL, &dmin, &davg) != 0 || cfpo3_q6(p, n, (int)k, bond, (int)bonds, &q) != 0)
        cli_fail(prog, "out of memory");
    const double d = dmin * cfpo3_delta_bound((double)n);
    printf("ANALYZE3D n=%zu delta_min=%.6f delta_avg=%.6f packing_fraction=%.6f q6_global=%.6f q6_local=%.6f "
           "crystal_like=%lld crystal_fraction=%.6f neighbours=%lld bond=%g bonds=%lld\n",
           n, dmin, davg, M_PI / 6.0 * (double)n * d * d * d, q.q6_global, q.q6_local, (long long)q.crystal,
           q.crystal_frac, (long long)k, bond, (long long)bonds);
    free(p);
    return 0;
}
