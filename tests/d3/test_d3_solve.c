/* test_d3_solve.c - the 3-D local solve (src/d3/solve3.c) against brute
 * force on random, jittered-lattice and exact FCC neighbourhoods (whose
 * Voronoi vertices are degenerate: six sites at an octahedral hole). For
 * every configuration: the answer lies in S; its claimed value is its true
 * distance to Y (a solver that drops a bisector claims a spot nearer to
 * the dropped site than it says); no point of a 17^3 sample of S, refined
 * by a pattern search, is farther from Y. The last check runs the same
 * comparison on a solver that drops one bisector and must see it fail; a
 * floor below the answer leaves it unchanged, one above it leaves none.
 * The near solve over every cell is the exact solve, bit for bit; over
 * the first cell alone its answer is in S, at the distance it claims and
 * no farther than the exact one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "rng.h"
#include "solve3.h"
#include "testutil.h"

static int passed_, failed_;

static double f(const double *y, int m, const double c[3])
{
    double b = INFINITY;
    for (int j = 0; j < m; j++) {
        const double dx = c[0] - y[3 * j], dy = c[1] - y[3 * j + 1], dz = c[2] - y[3 * j + 2];
        const double d = dx * dx + dy * dy + dz * dz;
        if (d < b) b = d;
    }
    return b;
}

static void clampv(double c[3], const double lo[3], const double hi[3])
{
    for (int a = 0; a < 3; a++) c[a] = c[a] < lo[a] ? lo[a] : (c[a] > hi[a] ? hi[a] : c[a]);
}

/* Largest f over S: a 17^3 sample, the best 8 refined by pattern search. */
static double brute(const double *y, int m, const double lo[3], const double hi[3])
{
    enum { G = 17, TOP = 8 };
    double top[TOP][4];
    int nt = 0;
    for (int i = 0; i < G; i++)
        for (int j = 0; j < G; j++)
            for (int k = 0; k < G; k++) {
                double c[3] = {lo[0] + (hi[0] - lo[0]) * i / (G - 1), lo[1] + (hi[1] - lo[1]) * j / (G - 1),
                               lo[2] + (hi[2] - lo[2]) * k / (G - 1)};
                const double v = f(y, m, c);
                if (nt == TOP && v <= top[TOP - 1][3]) continue;
                int at = nt < TOP ? nt++ : TOP - 1;
                while (at > 0 && top[at - 1][3] < v) {
                    for (int a = 0; a < 4; a++) top[at][a] = top[at - 1][a];
                    at--;
                }
                top[at][0] = c[0], top[at][1] = c[1], top[at][2] = c[2], top[at][3] = v;
            }
    double best = 0.0;
    for (int t = 0; t < nt; t++) {
        double c[3] = {top[t][0], top[t][1], top[t][2]}, v = top[t][3];
        double step = (hi[0] - lo[0]) / (G - 1);
        while (step > 1e-10) {
            int better = 0;
            for (int d = 0; d < 26 && !better; d++) {
                const int dx = d % 3 - 1, dy = (d / 3) % 3 - 1, dz = d / 9 - 1;
                if (!dx && !dy && !dz) continue;
                double q[3] = {c[0] + dx * step, c[1] + dy * step, c[2] + dz * step};
                clampv(q, lo, hi);
                const double w = f(y, m, q);
                if (w > v) {
                    c[0] = q[0], c[1] = q[1], c[2] = q[2], v = w;
                    better = 1;
                }
            }
            if (!better) step *= 0.5;
        }
        if (v > best) best = v;
    }
    return best;
}

/* A configuration of kind 0 random, 1 jittered cubic, 2 exact FCC, 3 FCC
 * with x at an octahedral hole. Unit: the cell side L = 1, x at the origin. */
static int make(int kind, uint64_t seed, double *y, double lo[3], double hi[3])
{
    int m = 0;
    double rnd[4];
    for (int a = 0; a < 4; a++) rnd[a] = cfpo_rand01(seed, 7, (uint64_t)a);
    if (kind == 0) {
        m = 20 + (int)(rnd[0] * 30);
        for (int j = 0; j < m; j++)
            for (int a = 0; a < 3; a++) y[3 * j + a] = -1.5 + 3.0 * cfpo_rand01(seed, 11, (uint64_t)(3 * j + a));
    } else if (kind == 1) {
        const double h = 0.9;
        for (int i = -2; i <= 2; i++)
            for (int j = -2; j <= 2; j++)
                for (int k = -2; k <= 2; k++) {
                    if (!i && !j && !k) continue;
                    const double c[3] = {i * h, j * h, k * h};
                    for (int a = 0; a < 3; a++)
                        y[3 * m + a] = c[a] + 0.3 * (cfpo_rand01(seed, 13, (uint64_t)(3 * m + a)) - 0.5);
                    m++;
                }
    } else {
        const double s = 1.0; /* FCC cube side; neighbour distance s/sqrt 2 */
        const double off = kind == 3 ? 0.5 * s : 0.0;
        for (int i = -2; i <= 2; i++)
            for (int j = -2; j <= 2; j++)
                for (int k = -2; k <= 2; k++)
                    for (int b = 0; b < 4; b++) {
                        static const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
                        const double c[3] = {(i + basis[b][0]) * s + off, (j + basis[b][1]) * s, (k + basis[b][2]) * s};
                        if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0) continue;
                        if (fabs(c[0]) > 1.6 || fabs(c[1]) > 1.6 || fabs(c[2]) > 1.6) continue;
                        y[3 * m] = c[0], y[3 * m + 1] = c[1], y[3 * m + 2] = c[2];
                        m++;
                    }
    }
    const double e = kind >= 2 ? 0.25 + 0.5 * rnd[1] : 0.2 * rnd[1];
    for (int a = 0; a < 3; a++) {
        const double shift = kind >= 2 ? (seed % 2 ? 0.0 : 0.1 * (rnd[2 + (a & 1)] - 0.5)) : 0.0;
        lo[a] = -0.5 - e + shift;
        hi[a] = 0.5 + e + shift;
    }
    /* hint order: nearest to x first */
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0; j--) {
            const double *p = y + 3 * j, *q = y + 3 * (j - 1);
            if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] >= q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) break;
            for (int a = 0; a < 3; a++) {
                const double t = y[3 * j + a];
                y[3 * j + a] = y[3 * (j - 1) + a];
                y[3 * (j - 1) + a] = t;
            }
        }
    return m;
}

/* 1 when c is in S at the distance it claims from Y. */
static int judge_at(const double *y, int m, const double lo[3], const double hi[3], const double c[3], double claimed)
{
    const int in = c[0] >= lo[0] && c[0] <= hi[0] && c[1] >= lo[1] && c[1] <= hi[1] && c[2] >= lo[2] && c[2] <= hi[2];
    return in && fabs(sqrt(f(y, m, c)) - sqrt(claimed)) <= 1e-9;
}

/* 1 when the answer (c, claimed) passes every check against Y. */
static int judge(const double *y, int m, const double lo[3], const double hi[3], const double c[3], double claimed,
                 double *want)
{
    const double truth = f(y, m, c);
    *want = brute(y, m, lo, hi);
    const int in = c[0] >= lo[0] && c[0] <= hi[0] && c[1] >= lo[1] && c[1] <= hi[1] && c[2] >= lo[2] && c[2] <= hi[2];
    return in && fabs(sqrt(truth) - sqrt(claimed)) <= 1e-9 && sqrt(truth) >= sqrt(*want) - 1e-9;
}

int main(void)
{
    static double y[3 * 700];
    cfpo3_poly scr[2];
    int bad = 0, runs = 0, caught = 0, mutants = 0, floorbad = 0, nearbad = 0;
    cfpo3_solve_count cnt = {0, 0, 0};
    for (int kind = 0; kind < 4; kind++)
        for (uint64_t s = 0; s < 20; s++) {
            double lo[3], hi[3], c[3], want;
            const int m = make(kind, 1000 * (uint64_t)kind + s, y, lo, hi);
            const double v = cfpo3_local_solve(y, m, lo, hi, 0.0, c, scr, &cnt);
            runs++;
            if (!judge(y, m, lo, hi, c, v, &want)) {
                bad++;
                if (bad < 5)
                    fprintf(stderr, "kind %d seed %llu: solver %.12f (true %.12f), brute %.12f\n", kind,
                            (unsigned long long)s, sqrt(v), sqrt(f(y, m, c)), sqrt(want));
            }
            /* the near solve: over every cell it is the exact solve; over the
             * first cell its answer is in S, at the distance it claims, and
             * no farther than the exact answer */
            {
                double c2[3];
                const double v2 = cfpo3_near_solve(y, m, m, lo, hi, 0.0, c2, scr, NULL);
                nearbad += !(v2 == v && c2[0] == c[0] && c2[1] == c[1] && c2[2] == c[2]);
                const double v1 = cfpo3_near_solve(y, m, 1, lo, hi, 0.0, c2, scr, NULL);
                nearbad += !(v1 >= 0.0 && judge_at(y, m, lo, hi, c2, v1) && v1 <= v * (1 + 1e-12));
            }
            /* a floor below the answer changes nothing; at or above it, no answer */
            {
                double c2[3];
                const double v2 = cfpo3_local_solve(y, m, lo, hi, 0.98 * v, c2, scr, NULL);
                floorbad += !(v2 == v && c2[0] == c[0] && c2[1] == c[1] && c2[2] == c[2]);
                floorbad += cfpo3_local_solve(y, m, lo, hi, v * (1 + 1e-9), c2, scr, NULL) >= 0.0;
            }
            /* the mutant: one bisector dropped (a site the answer is nearest to) */
            if (s % 3 == 0) {
                int near = 0;
                double bd = INFINITY;
                for (int j = 0; j < m; j++) {
                    const double dx = c[0] - y[3 * j], dy = c[1] - y[3 * j + 1], dz = c[2] - y[3 * j + 2];
                    if (dx * dx + dy * dy + dz * dz < bd) bd = dx * dx + dy * dy + dz * dz, near = j;
                }
                static double ym[3 * 700];
                int mm = 0;
                for (int j = 0; j < m; j++)
                    if (j != near) {
                        ym[3 * mm] = y[3 * j], ym[3 * mm + 1] = y[3 * j + 1], ym[3 * mm + 2] = y[3 * j + 2];
                        mm++;
                    }
                double cm[3];
                const double vm = cfpo3_local_solve(ym, mm, lo, hi, 0.0, cm, scr, NULL);
                /* at an FCC hole six sites tie: dropping one may change
                 * nothing, so the mutant counts on the generic kinds */
                if (kind < 2) {
                    mutants++;
                    if (!judge(y, m, lo, hi, cm, vm, &want)) caught++;
                }
            }
        }
    CHECK(bad == 0, "%d of %d solves disagree with brute force", bad, runs);
    CHECK(floorbad == 0, "%d answers change under a floor", floorbad);
    CHECK(nearbad == 0, "%d near solves wrong", nearbad);
    CHECK(caught == mutants, "the check missed %d of %d (random, jittered) solvers that drop a bisector", mutants - caught, mutants);
    /* the box alone: a corner, at the right distance */
    {
        const double one[3] = {0.1, 0.2, 0.3}, lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
        double c[3];
        const double v = cfpo3_local_solve(one, 1, lo, hi, 0.0, c, scr, NULL);
        CHECK(c[0] == -1 && c[1] == -1 && c[2] == -1 && fabs(v - (1.21 + 1.44 + 1.69)) < 1e-12,
              "one site: answer (%g %g %g) %g", c[0], c[1], c[2], v);
        CHECK(cfpo3_local_solve(one, 0, lo, hi, 0.0, c, scr, NULL) < 0, "no site: no answer");
    }
    /* Voronoi cells of uniform points: Meijering's 27.07 vertices, 15.54 faces a cell */
    {
        const int N = 400;
        double v = 0, fc = 0;
        for (int i = 0; i < N; i++) {
            static double p[3 * 64];
            const int m = 63;
            for (int j = 0; j < 3 * m; j++) p[j] = -1.0 + 2.0 * cfpo_rand01(99, (uint64_t)i, (uint64_t)j);
            const double lo[3] = {-3, -3, -3}, hi[3] = {3, 3, 3}, o[3] = {0, 0, 0};
            cfpo3_poly_box(&scr[0], lo, hi);
            int w = 0;
            (void)o;
            for (int j = 0; j < m; j++) { /* the cell of the origin among 63 points in [-1,1]^3 */
                const double nv[3] = {p[3 * j], p[3 * j + 1], p[3 * j + 2]};
                const double off = 0.5 * (nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
                if (cfpo3_poly_clip(&scr[w], &scr[w ^ 1], nv, off) == 1) w ^= 1;
            }
            v += scr[w].nv;
            fc += scr[w].nf;
        }
        v /= N, fc /= N;
        /* the cell of a point at the centre of 64 uniform points: close to
         * the Poisson-Voronoi figures, which hold as the count grows */
        CHECK(v > 24.0 && v < 30.0 && fc > 14.0 && fc < 17.0, "Voronoi cell: %.2f vertices, %.2f faces", v, fc);
        printf("cells of 64 uniform points: %.2f vertices, %.2f faces (Poisson-Voronoi 27.07, 15.54)\n", v, fc);
    }
    printf("%d solves: %.1f cells, %.1f plane tests, %.1f cuts a solve\n", runs, (double)cnt.cells / runs,
           (double)cnt.tests / runs, (double)cnt.cuts / runs);
    return test_report(passed_, failed_);
}
