/* bench_solve3.c - `cfpo3d-solvebench`: the 3-D local solve alone, on the
 * neighbourhoods of a given point set. Never a test: the benchmark of
 * solve3.c (docs/results/2026-11-29-3d-solve.md).
 *
 * For every point x of the set (ids in order): the engine's grid for n
 * (unshifted), Y(x) the other points of x's 3x3x3 block gathered cell by
 * cell (z, y, x from -1 to 1, points by id) and ordered by distance to x
 * (stable), relative to x; the cube S(x) is x's cell grown by the engine's
 * margin min(e, L - t), e = L - max(delta(X), 0.7 Delta3), t = r0 + tol L.
 * Each neighbourhood is then solved `reps` times (exact, or the near solve
 * over x's own cell with --near). Prints the solves, the time a solve, the
 * mean m, the work counters and an FNV-1a hash of every answer's bytes
 * (value and point), so that two builds of the solver can be compared bit
 * for bit; --dump FILE writes (value, point) of each solve as 4 doubles.
 * Times are the process CPU time of the solve loop only. */
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "grid3.h"
#include "points3.h"
#include "solve3.h"

typedef struct {
    int m;
    double lo[3], hi[3], floor2;
    double *rel;
} hood;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t fnv(uint64_t h, const void *p, size_t len)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < len; i++) h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}

static int cell_of(double v, int g)
{
    int c = (int)(v * g);
    return c >= g ? g - 1 : (c < 0 ? 0 : c);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: cfpo3d-solvebench POINTS.npy [--near] [--reps R] [--tol T] [--dump FILE]\n");
        return 2;
    }
    int near = 0, reps = 1;
    const char *dump = NULL;
    double tol = 1e-4;
    for (int a = 2; a < argc; a++) {
        if (strcmp(argv[a], "--near") == 0) near = 1;
        else if (strcmp(argv[a], "--reps") == 0 && a + 1 < argc) reps = atoi(argv[++a]);
        else if (strcmp(argv[a], "--tol") == 0 && a + 1 < argc) tol = atof(argv[++a]);
        else if (strcmp(argv[a], "--dump") == 0 && a + 1 < argc) dump = argv[++a];
        else {
            fprintf(stderr, "cfpo3d-solvebench: unknown argument %s\n", argv[a]);
            return 2;
        }
    }
    if (reps < 1) reps = 1;
    char err[512];
    double *p = NULL;
    size_t n = 0;
    if (p3_read(argv[1], &p, &n, err, sizeof err) != 0) {
        fprintf(stderr, "cfpo3d-solvebench: %s\n", err);
        return 1;
    }
    cfpo3_grid G;
    if (cfpo3_grid_choose((int64_t)n, &G, err, sizeof err) != 0) {
        fprintf(stderr, "cfpo3d-solvebench: %s\n", err);
        return 1;
    }
    const int g = G.g;
    const double L = G.L;
    /* points bucketed by cell, ids in order (counting sort) */
    const size_t nc = (size_t)g * g * g;
    int64_t *start = calloc(nc + 1, sizeof *start), *ids = malloc(n * sizeof *ids);
    hood *H = malloc(n * sizeof *H);
    if (!start || !ids || !H) return 1;
    for (size_t i = 0; i < n; i++) {
        const double *x = p + 3 * i;
        start[((size_t)cell_of(x[2], g) * g + cell_of(x[1], g)) * g + cell_of(x[0], g) + 1]++;
    }
    for (size_t c = 0; c < nc; c++) start[c + 1] += start[c];
    int64_t *fill = malloc(nc * sizeof *fill);
    memcpy(fill, start, nc * sizeof *fill);
    for (size_t i = 0; i < n; i++) {
        const double *x = p + 3 * i;
        ids[fill[((size_t)cell_of(x[2], g) * g + cell_of(x[1], g)) * g + cell_of(x[0], g)]++] = (int64_t)i;
    }
    free(fill);
    /* the blocks: Y relative to x, sorted by distance (stable) */
    double *key = malloc(4096 * sizeof *key), *tmp = malloc(3 * 4096 * sizeof *tmp);
    double dX = INFINITY;
    long msum = 0;
    for (size_t i = 0; i < n; i++) {
        const double *x = p + 3 * i;
        const int ci = cell_of(x[0], g), cj = cell_of(x[1], g), ck = cell_of(x[2], g);
        int m = 0;
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    const int a = (ci + dx + g) % g, b = (cj + dy + g) % g, c = (ck + dz + g) % g;
                    const size_t cc = ((size_t)c * g + b) * g + a;
                    for (int64_t k = start[cc]; k < start[cc + 1]; k++) {
                        const int64_t j = ids[k];
                        if ((size_t)j == i || m >= 4096) continue;
                        double r[3];
                        for (int q = 0; q < 3; q++) {
                            r[q] = p[3 * j + q] - x[q];
                            r[q] -= nearbyint(r[q]); /* the periodic image in the block */
                        }
                        const double d = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
                        int at = m++;
                        while (at > 0 && key[at - 1] > d) {
                            key[at] = key[at - 1];
                            memcpy(tmp + 3 * at, tmp + 3 * (at - 1), 3 * sizeof(double));
                            at--;
                        }
                        key[at] = d;
                        memcpy(tmp + 3 * at, r, sizeof r);
                    }
                }
        if (m > CFPO3_MAXM) m = CFPO3_MAXM;
        H[i].m = m;
        H[i].rel = malloc(3 * (size_t)(m > 0 ? m : 1) * sizeof(double));
        memcpy(H[i].rel, tmp, 3 * (size_t)m * sizeof(double));
        H[i].floor2 = m > 0 ? key[0] : INFINITY; /* r0^2 for now */
        if (m > 0 && key[0] < dX) dX = key[0];
        for (int q = 0; q < 3; q++) {
            H[i].lo[q] = (q == 0 ? ci : q == 1 ? cj : ck) * L - x[q];
            H[i].hi[q] = H[i].lo[q] + L;
        }
        msum += m;
    }
    dX = sqrt(dX) + 1e-9;
    const double e = L - (dX > 0.7 * G.delta3 ? dX : 0.7 * G.delta3);
    long nsolve = 0;
    for (size_t i = 0; i < n; i++) {
        const double t = sqrt(H[i].floor2) + tol * L;
        const double ex = e < L - t ? e : L - t;
        H[i].floor2 = t * t;
        if (H[i].m == 0 || t >= 1.5 * L) {
            H[i].m = 0;
            continue;
        }
        for (int q = 0; q < 3; q++) H[i].lo[q] -= ex, H[i].hi[q] += ex;
        nsolve++;
    }
    cfpo3_poly *poly = malloc(2 * sizeof *poly);
    cfpo3_solve_count cnt = {0, 0, 0};
    uint64_t h = 1469598103934665603ULL;
    FILE *df = dump ? fopen(dump, "wb") : NULL;
    if (dump && !df) {
        fprintf(stderr, "cfpo3d-solvebench: cannot write %s\n", dump);
        return 1;
    }
    long found = 0;
    const double t0 = now();
    for (int r = 0; r < reps; r++)
        for (size_t i = 0; i < n; i++) {
            if (H[i].m == 0) continue;
            double best[3] = {0, 0, 0};
            const double v = cfpo3_near_solve(H[i].rel, H[i].m, near ? 1 : H[i].m, H[i].lo, H[i].hi, H[i].floor2,
                                              best, poly, r == 0 ? &cnt : NULL);
            if (r == 0) {
                h = fnv(h, &v, sizeof v);
                if (v >= 0.0) h = fnv(h, best, sizeof best), found++;
                if (df) {
                    const double rec[4] = {v, best[0], best[1], best[2]};
                    fwrite(rec, sizeof rec, 1, df);
                }
            }
        }
    const double secs = now() - t0;
    if (df) fclose(df);
    printf("SOLVEBENCH n=%zu g=%d solve=%s solves=%ld reps=%d mean_m=%.2f found=%ld cells=%.3f tests=%.3f cuts=%.3f "
           "us_per_solve=%.3f hash=%016" PRIx64 "\n",
           n, g, near ? "near" : "exact", nsolve, reps, (double)msum / (double)n, found,
           (double)cnt.cells / (double)nsolve, (double)cnt.tests / (double)nsolve, (double)cnt.cuts / (double)nsolve,
           1e6 * secs / ((double)nsolve * reps), h);
    for (size_t i = 0; i < n; i++) free(H[i].rel);
    free(H);
    free(poly);
    free(key);
    free(tmp);
    free(ids);
    free(start);
    free(p);
    return 0;
}
