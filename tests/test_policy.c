/* test_policy.c - the variants' per-iteration policy (src/engine/policy.h).
 *
 * Properties: the adaptive variant's decisions by iteration are the
 * uniform schedule docs/method.md documents (near solves in two cells in iterations 1-6,
 * one after; no over-relaxation in 1-3, w = 3.0 else 1.8 in 4-19, 1.8
 * else 1.4 from 20; the grid's offsets, one per axis, each in [0, L),
 * new before each of iterations 1-8 and then before 9, 13, 17, ..., kept
 * in between, none before iteration 1); each axis's offsets walk 3/7 of
 * a cell a move around the colours' period 3 L from its own start, with
 * the sweep's first colour turning with them, so that every move's print
 * at the frequencies m g / 3 (m = 1..4) turns by 360 m / 7 degrees and
 * seven moves cancel exactly (the guard of the grid imprint: random
 * offsets fail it; test_imprint measures the print itself); the sweep solves every colour once; the margin is L - max(delta(X), 0.7 Delta(n)) up
 * to a relative 1e-9 and never reaches past L - delta(X) (the convergence
 * argument's bound) nor below 0; the per-point square keeps every spot at
 * least t from the points beyond the block, and a point with t >= 1.5 L
 * stays; over-relaxation takes the first weight whose spot is in the
 * square and clear of the floor, else keeps the solver's spot; the paper's
 * and the simplified variants get the fixed margin, no shift, exact solves
 * and no push; the near phase starts only in the adaptive variant and ends
 * at its first converged sweep; and every function is pure (the same
 * arguments give the same decisions, whatever was asked in between). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grid.h"
#include "policy.h"
#include "testutil.h"

static int passed_, failed_;

static int same_policy(const cfpo_policy *a, const cfpo_policy *b)
{
    return a->iteration == b->iteration && a->L == b->L && a->margin == b->margin && a->shift_x == b->shift_x &&
           a->shift_y == b->shift_y && a->rot_x == b->rot_x && a->rot_y == b->rot_y && a->brick == b->brick &&
           a->brick_key == b->brick_key &&
           a->cut == b->cut && a->freeze == b->freeze && a->near == b->near && a->near_cells == b->near_cells &&
           a->relax == b->relax && (a->relax < 1 || a->w[0] == b->w[0]) && (a->relax < 2 || a->w[1] == b->w[1]) &&
           a->unprint == b->unprint && a->transport == b->transport;
}

static cfpo_grid grid(int64_t n, int variant, uint64_t seed)
{
    cfpo_grid G;
    char err[256];
    if (cfpo_grid_init(&G, n, variant, seed, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
    return G;
}

/* The documented table, row by row: iterations [from, to], the near
 * solve's cells, the weights (0: no over-relaxation). */
static const struct {
    int from, to, cells;
    double w0, w1;
} table[] = {
    {1, 3, 2, 0, 0},
    {4, 6, 2, 3.0, 1.8},
    {7, 19, 1, 3.0, 1.8},
    {20, 2000, 1, 1.8, 1.4},
};

static void test_schedule_table(void)
{
    const cfpo_grid G = grid(65536, CFPO_VARIANT_ADAPTIVE, 3);
    int bad = 0, rows = 0;
    for (size_t r = 0; r < sizeof table / sizeof table[0]; r++)
        for (int k = table[r].from; k <= table[r].to; k++) {
            rows++;
            const cfpo_policy P = cfpo_policy_at(&G, k, 1, 0.9);
            const int want_relax = table[r].w0 > 0 ? 2 : 0;
            if (P.iteration != k || !P.near || P.near_cells != table[r].cells || P.relax != want_relax ||
                (want_relax && (P.w[0] != table[r].w0 || P.w[1] != table[r].w1)) || !P.cut ||
                P.freeze != 1.5 * G.L || P.L != G.L) {
                if (bad++ < 5)
                    fprintf(stderr, "iteration %d: near %d cells %d relax %d w %g %g cut %d\n", k, P.near,
                            P.near_cells, P.relax, P.w[0], P.w[1], P.cut);
            }
            /* Out of the near phase, the solver is LocalCFPO; the rest holds. */
            const cfpo_policy Q = cfpo_policy_at(&G, k, 0, 0.9);
            if (Q.near || Q.relax != P.relax || Q.margin != P.margin || Q.shift_x != P.shift_x || Q.shift_y != P.shift_y)
                bad++;
        }
    CHECK(bad == 0, "the uniform schedule's decisions differ from the documented table in %d of %d iterations", bad,
          rows);
}

/* The iteration of the grid's j-th move (j from 0): before each of
 * iterations 1-8, then before 9, 13, 17, ... */
static int move_iteration(int j) { return j < 8 ? j + 1 : 9 + 4 * (j - 8); }

/* The hyperuniform variant up to 65,536 points keeps the earlier
 * schedule: one offset for both axes, moved before iterations 1, 5, 9, ...
 * by 3/7 of a cell, the adaptive variant's x walk at its first move (seed
 * 4: n = 65,536, the last n that keeps it). Above, it walks as the
 * adaptive variant, axis by axis and iteration by iteration. */
static void test_shift_hyperuniform(void)
{
    int bad = 0, moves = 0;
    for (uint64_t seed = 1; seed <= 4; seed++) {
        const cfpo_grid G = grid(seed == 4 ? 65536 : 4096 * (int64_t)seed, CFPO_VARIANT_HYPERUNIFORM, seed);
        const cfpo_grid A = grid(4096 * seed, CFPO_VARIANT_ADAPTIVE, seed);
        if (cfpo_policy_walk(&G, 1, 0) != cfpo_policy_walk(&A, 1, 0)) bad++;
        double pw = -1;
        for (int k = 1; k <= 400; k++) {
            const double w = cfpo_policy_walk(&G, k, 0);
            const cfpo_policy P = cfpo_policy_at(&G, k, 1, 0.5);
            if (cfpo_policy_walk(&G, k, 1) != w || P.shift_x != P.shift_y || P.rot_x != P.rot_y) bad++;
            if ((k - 1) % 4 == 0) {
                moves++;
                if (pw >= 0 && fabs(fmod(w - pw + 3, 3) - 3.0 / 7) > 1e-12) bad++;
            } else if (w != pw) {
                bad++;
            }
            pw = w;
        }
    }
    CHECK(bad == 0, "hyperuniform grid shift: %d violations over %d moves", bad, moves);
    bad = 0;
    for (uint64_t seed = 1; seed <= 4; seed++) {
        const int64_t n = seed == 4 ? 65537 : 262144 * (int64_t)seed;
        const cfpo_grid G = grid(n, CFPO_VARIANT_HYPERUNIFORM, seed), A = grid(n, CFPO_VARIANT_ADAPTIVE, seed);
        for (int k = 0; k <= 400; k++)
            for (int a = 0; a < 2; a++)
                if (cfpo_policy_walk(&G, k, a) != cfpo_policy_walk(&A, k, a)) bad++;
    }
    CHECK(bad == 0, "hyperuniform above 65,536 points: %d walks differ from the adaptive variant's", bad);
}

static void test_shift(void)
{
    int bad = 0, moves = 0;
    for (uint64_t seed = 1; seed <= 4; seed++) {
        const cfpo_grid G = grid(4096 * seed, CFPO_VARIANT_ADAPTIVE, seed);
        const cfpo_policy P0 = cfpo_policy_at(&G, 0, 1, 1);
        if (cfpo_policy_shift(&G, 0, 0) != 0 || cfpo_policy_shift(&G, 0, 1) != 0 || P0.shift_x != 0 || P0.shift_y != 0)
            bad++;
        double px = 0, py = 0;
        for (int k = 1, j = 0; k <= 400; k++) {
            const double sx = cfpo_policy_shift(&G, k, 0), sy = cfpo_policy_shift(&G, k, 1);
            if (!(sx >= 0 && sx < G.L && sy >= 0 && sy < G.L)) bad++;
            const cfpo_policy P = cfpo_policy_at(&G, k, 1, 0.5);
            if (P.shift_x != sx || P.shift_y != sy) bad++;
            if (k == move_iteration(j)) { /* a new offset on both axes */
                moves++;
                j++;
                if (sx == px || sy == py) bad++;
            } else if (sx != px || sy != py) {
                bad++;
            }
            if (sx == sy) bad++; /* the axes' offsets are apart */
            px = sx, py = sy;
        }
        const cfpo_grid H = grid(4096 * seed, CFPO_VARIANT_ADAPTIVE, seed + 100);
        if (cfpo_policy_shift(&H, 1, 0) == cfpo_policy_shift(&G, 1, 0) ||
            cfpo_policy_shift(&H, 1, 1) == cfpo_policy_shift(&G, 1, 1))
            bad++; /* the seed keys it */
    }
    CHECK(bad == 0, "grid shift: %d violations over %d moves of the grid", bad, moves);
}

/* The walk on each axis: sigma_j / L in [0, 3), steps of 3/7 mod 3 from
 * one move of the grid to the next, shift = L frac, rot = floor; the
 * prints' phasors exp(2 pi i m sigma_j / (3 L)) of seven consecutive
 * moves sum to 0 and each move turns the last one's by more than 150
 * degrees at m = 3 and 4 (cos < -0.85); the two axes' walks start apart;
 * the sweep's colours are a permutation (the balanced order) from colour
 * (rot_y, rot_x). */
static void test_walk(void)
{
    int bad = 0, moves = 0;
    for (int variant = 0; variant < 2; variant++) /* hyperuniform: above 65,536 points (test_shift_hyperuniform) */
        for (uint64_t seed = 1; seed <= 4; seed++) {
            const cfpo_grid G = grid(variant ? 65536 + 4096 * (int64_t)seed : 4096 * (int64_t)seed,
                                     variant ? CFPO_VARIANT_HYPERUNIFORM : CFPO_VARIANT_ADAPTIVE, seed);
            double w[2][64];
            for (int j = 0; j < 64; j++) {
                const int k = move_iteration(j), last = j < 7 ? k : move_iteration(j + 1) - 1;
                moves++;
                const cfpo_policy P = cfpo_policy_at(&G, k, 1, 0.5);
                for (int a = 0; a < 2; a++) {
                    w[a][j] = cfpo_policy_walk(&G, k, a);
                    const int rot = a ? P.rot_y : P.rot_x;
                    const double sh = a ? P.shift_y : P.shift_x;
                    if (!(w[a][j] >= 0 && w[a][j] < 3) || rot != (int)floor(w[a][j]) ||
                        fabs(sh - G.L * (w[a][j] - floor(w[a][j]))) > 1e-15 || cfpo_policy_walk(&G, last, a) != w[a][j]) {
                        if (bad++ < 5) fprintf(stderr, "move %d axis %d: walk %.17g rot %d shift %g\n", j, a, w[a][j], rot, sh / G.L);
                    }
                    if (j > 0) {
                        double d = fmod(w[a][j] - w[a][j - 1] + 3, 3);
                        if (fabs(d - 3.0 / 7) > 1e-12) bad++;
                    }
                }
                if (fabs(w[0][j] - w[1][j]) < 1e-9) bad++;
                int seen = 0;
                for (int c = 0; c < 9; c++) seen |= 1 << cfpo_policy_colour(&P, 3, c);
                if (seen != 0x1ff || cfpo_policy_colour(&P, 3, 0) != 3 * P.rot_y + P.rot_x) bad++;
            }
            for (int a = 0; a < 2; a++)
                for (int m = 1; m <= 4; m++)
                    for (int j0 = 0; j0 + 7 <= 64; j0 += 5) {
                        double re = 0, im = 0;
                        for (int j = j0; j < j0 + 7; j++) {
                            re += cos(2 * M_PI * m * w[a][j] / 3);
                            im += sin(2 * M_PI * m * w[a][j] / 3);
                        }
                        const double turn = cos(2 * M_PI * m * (w[a][j0 + 1] - w[a][j0]) / 3);
                        if (hypot(re, im) > 1e-9 || (m >= 3 && !(turn < -0.85))) {
                            if (bad++ < 10) fprintf(stderr, "axis %d m %d moves %d..%d: sum %g, turn cos %g\n", a, m, j0, j0 + 6, hypot(re, im), turn);
                        }
                    }
        }
    CHECK(bad == 0, "grid walk: %d violations over %d moves", bad, moves);
    const cfpo_grid P = grid(4096, CFPO_VARIANT_PAPER, 1);
    const cfpo_policy Q = cfpo_policy_at(&P, 5, 0, 1);
    CHECK(cfpo_policy_walk(&P, 5, 0) == 0 && cfpo_policy_walk(&P, 5, 1) == 0 && Q.rot_x == 0 && Q.rot_y == 0,
          "paper variant: a walk or a turned sweep");
}

static void test_margin(void)
{
    int bad = 0, tried = 0;
    for (int64_t n = 100; n <= 1 << 20; n *= 3) {
        const cfpo_grid G = grid(n, CFPO_VARIANT_ADAPTIVE, 1);
        const double early = cfpo_policy_at(&G, 1, 1, 0.1).margin;
        if (fabs(early - (G.L - 0.7 * G.delta)) > 1e-15) bad++;
        double last = INFINITY;
        for (double dmin = 0; dmin <= 2.0; dmin += 1.0 / 64) {
            tried++;
            const double e = cfpo_policy_at(&G, 7, 1, dmin).margin;
            if (e != cfpo_policy_at(&G, 300, 0, dmin).margin) bad++; /* the iteration does not matter */
            /* The convergence argument's bound: S reaches no further than
             * L - delta(X) past the cell; early, no further than
             * L - 0.7 Delta(n) (up to rounding). */
            if (e < 0 || e > fmax(0, G.L - dmin * G.delta) || e + 0.7 * G.delta > G.L * (1 + 1e-15)) bad++;
            if (e > last) bad++; /* a larger delta(X), no larger margin */
            const double want = fmax(0, G.L - fmax(dmin, 0.7) * G.delta);
            if (fabs(e - want) > 2e-9 * G.delta) bad++;
            last = e;
        }
    }
    CHECK(bad == 0, "adaptive margin: %d violations in %d cases", bad, tried);
}

static void test_square(void)
{
    const cfpo_grid G = grid(65536, CFPO_VARIANT_ADAPTIVE, 1);
    const cfpo_policy P = cfpo_policy_at(&G, 10, 1, 0.8);
    int bad = 0, stays = 0, tried = 0;
    for (double t = 0; t < 2 * G.L; t += G.L / 256) {
        tried++;
        cfpo_square S;
        const int moves = cfpo_policy_square(&P, t, &S);
        if (!moves) {
            stays++;
            if (t < 1.5 * G.L) bad++;
            continue;
        }
        if (t >= 1.5 * G.L) bad++;
        /* Every spot of S at least t from the points beyond the 3x3 block. */
        const double tt = t * (1 - 1e-12); /* up to rounding */
        if (S.x0 + G.L < tt || 2 * G.L - S.x1 < tt || S.y0 + G.L < tt || 2 * G.L - S.y1 < tt) bad++;
        /* No farther than the margin, and square about the cell. */
        if (-S.x0 > P.margin || S.x1 - G.L > P.margin * (1 + 1e-12) || S.x0 != S.y0 || S.x1 != S.y1 ||
            fabs((S.x1 - G.L) + S.x0) > 1e-15)
            bad++;
        if (t <= G.L - P.margin && S.x0 != -P.margin) bad++; /* the margin itself when t allows it */
    }
    CHECK(bad == 0 && stays > 0, "adaptive square: %d violations in %d cases (%d stayed)", bad, tried, stays);
    /* The paper's variant: the cell grown by L - Delta(n), whatever t. */
    const cfpo_grid H = grid(65536, CFPO_VARIANT_PAPER, 1);
    const cfpo_policy Q = cfpo_policy_at(&H, 10, 0, 0.8);
    cfpo_square S;
    const cfpo_square want = cfpo_grid_square(&H);
    CHECK(cfpo_policy_square(&Q, 1.9 * H.L, &S) == 1 && memcmp(&S, &want, sizeof S) == 0,
          "paper square [%g %g %g %g], want the grid's", S.x0, S.y0, S.x1, S.y1);
}

static void test_relax(void)
{
    const cfpo_grid G = grid(65536, CFPO_VARIANT_ADAPTIVE, 1);
    const double L = G.L;
    /* x at the cell's centre, one other point at its lower-left corner. */
    const double bx[2] = {0.5 * L, 0}, by[2] = {0.5 * L, 0};
    const double x = bx[0], y = by[0], floor2 = (0.2 * L) * (0.2 * L);
    const cfpo_square S = {-0.2 * L, -0.2 * L, 1.2 * L, 1.2 * L};
    double nx, ny;
    int bad = 0;
    /* Before iteration 4: the solver's spot. */
    cfpo_policy P = cfpo_policy_at(&G, 3, 1, 0.5);
    nx = 0.6 * L, ny = 0.5 * L;
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (nx != 0.6 * L || ny != 0.5 * L) bad++;
    /* Iteration 4: w = 3.0 (to 0.8 L). */
    P = cfpo_policy_at(&G, 4, 1, 0.5);
    nx = 0.6 * L, ny = 0.5 * L;
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (nx != x + 3.0 * (0.6 * L - x) || ny != 0.5 * L) bad++;
    /* w = 3.0 leaves the square (to 1.4 L), w = 1.8 does not (to 1.04 L). */
    nx = 0.8 * L, ny = 0.5 * L;
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (nx != x + 1.8 * (0.8 * L - x)) bad++;
    /* Iteration 20: the mild weights, 1.8 then 1.4. */
    P = cfpo_policy_at(&G, 20, 0, 0.5);
    nx = 0.9 * L, ny = 0.5 * L; /* 1.8: 1.22 L, out; 1.4: 1.06 L */
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (nx != x + 1.4 * (0.9 * L - x)) bad++;
    /* Towards the other point: every pushed spot within the floor of it. */
    nx = 0.2 * L, ny = 0.2 * L; /* 1.8: -0.04 L; 1.4: 0.08 L, both within 0.2 L of (0, 0) */
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (nx != 0.2 * L || ny != 0.2 * L) bad++;
    /* The paper's variant never pushes. */
    const cfpo_grid H = grid(65536, CFPO_VARIANT_PAPER, 1);
    P = cfpo_policy_at(&H, 50, 0, 0.5);
    nx = 0.6 * L, ny = 0.5 * L;
    cfpo_policy_relax(&P, &S, bx, by, 2, 0, x, y, floor2, &nx, &ny);
    if (P.relax != 0 || nx != 0.6 * L) bad++;
    CHECK(bad == 0, "over-relaxation: %d of 6 cases wrong", bad);
}

static void test_other_variants(void)
{
    int bad = 0;
    const int variants[2] = {CFPO_VARIANT_PAPER, CFPO_VARIANT_SIMPLIFIED};
    for (int v = 0; v < 2; v++) {
        const cfpo_grid G = grid(4096, variants[v], 5);
        if (cfpo_policy_starts_near(variants[v])) bad++;
        for (int k = 0; k <= 100; k++) {
            const cfpo_policy P = cfpo_policy_at(&G, k, 0, 0.3 + 0.01 * k);
            if (P.margin != G.margin || P.shift_x != 0 || P.shift_y != 0 || P.cut || P.near || P.relax ||
                cfpo_policy_shift(&G, k, 0) != 0 || cfpo_policy_shift(&G, k, 1) != 0)
                bad++;
        }
    }
    CHECK(bad == 0, "paper and simplified: %d decisions not the fixed ones", bad);
    CHECK(cfpo_policy_starts_near(CFPO_VARIANT_ADAPTIVE), "the adaptive variant starts in the near phase");
    CHECK(cfpo_policy_near_ends(1, 1) && !cfpo_policy_near_ends(1, 0) && !cfpo_policy_near_ends(0, 1) &&
              !cfpo_policy_near_ends(0, 0),
          "the near phase ends exactly at its first converged sweep");
}

/* Pure: a table of decisions asked in one order equals the same table
 * asked in the reverse order, interleaved with other questions. */
static void test_pure(void)
{
    enum { K = 120 };
    const cfpo_grid G = grid(20000, CFPO_VARIANT_ADAPTIVE, 9);
    const cfpo_grid H = grid(5000, CFPO_VARIANT_ADAPTIVE, 2);
    static cfpo_policy a[K][2];
    for (int k = 0; k < K; k++)
        for (int near = 0; near < 2; near++) a[k][near] = cfpo_policy_at(&G, k, near, 0.5 + 0.004 * k);
    int bad = 0;
    for (int k = K - 1; k >= 0; k--)
        for (int near = 1; near >= 0; near--) {
            (void)cfpo_policy_at(&H, K - k, !near, 0.1 * near);
            const cfpo_policy b = cfpo_policy_at(&G, k, near, 0.5 + 0.004 * k);
            if (!same_policy(&a[k][near], &b)) bad++;
        }
    CHECK(bad == 0, "policy not a pure function: %d of %d answers changed", bad, 2 * K);
}

/* The grid's print is removed before iterations 2-9 (policy.h) of the
 * adaptive-like variants above 65,536 points, and never otherwise; the
 * removal's sweep is a transport one along the print's field that keeps
 * delta(X), with the iteration's grid and colouring. */
static void test_unprint(void)
{
    const int variants[2] = {CFPO_VARIANT_ADAPTIVE, CFPO_VARIANT_HYPERUNIFORM};
    int wrong = 0;
    for (int v = 0; v < 2; v++)
        for (int big = 0; big < 2; big++) {
            const cfpo_grid G = grid(big ? 65537 : 65536, variants[v], 3);
            for (int k = 1; k <= 60; k++) {
                const cfpo_policy P = cfpo_policy_at(&G, k, k < 12, 0.9);
                const int want = big && k >= 2 && k <= 9;
                if (P.unprint != want) {
                    wrong++;
                    fprintf(stderr, "variant %d, n %lld, iteration %d: unprint %d\n", variants[v],
                            (long long)G.n, k, P.unprint);
                }
            }
        }
    for (int variant = CFPO_VARIANT_PAPER; variant <= CFPO_VARIANT_SIMPLIFIED; variant++) {
        const cfpo_grid G = grid(1 << 20, variant, 3);
        for (int k = 1; k <= 12; k++) wrong += cfpo_policy_at(&G, k, 0, 0.9).unprint != 0;
    }
    CHECK(wrong == 0, "the print's removal: %d iterations wrong", wrong);
    const cfpo_grid G = grid(1 << 20, CFPO_VARIANT_ADAPTIVE, 3);
    const cfpo_policy P = cfpo_policy_at(&G, 5, 1, 0.87);
    const cfpo_policy U = cfpo_policy_unprint(&P, &G, 0.87);
    CHECK(U.transport == CFPO_TRANSPORT_PRINT && U.unprint == 0 && U.near == 0 && U.relax == 0 && U.all == 1,
          "the removal's sweep: transport %d unprint %d near %d relax %d all %d", U.transport, U.unprint, U.near,
          U.relax, U.all);
    CHECK(U.cap == 0.87 * G.delta && U.vmax == CFPO_POLICY_UNPRINT_VMAX * G.delta && U.margin == G.L,
          "the removal's sweep: cap %.17g (delta(X) %.17g), vmax %.17g, margin %.17g (L %.17g)", U.cap, 0.87 * G.delta,
          U.vmax, U.margin, G.L);
    CHECK(U.shift_x == P.shift_x && U.shift_y == P.shift_y && U.brick == P.brick && U.brick_key == P.brick_key &&
              U.rot_x == P.rot_x && U.rot_y == P.rot_y && U.balanced == P.balanced,
          "the removal's sweep takes another grid or colouring than its iteration's");
}

/* The density engine's near solve (policy.h): a block flat within
 * CFPO_POLICY_DENSITY_NEAR_FLAT never falls back; a steeper one takes the
 * same near polygons in every iteration and falls back to all of them in
 * every iteration of the first group of CFPO_POLICY_DENSITY_FALL_EVERY
 * and in the first iteration of each later group only (5, 9, ...: the
 * grid's new offsets), so its solve in a group's later iterations is the
 * first part of its solve in the group's first, which the skip's
 * exactness rests on. */
static void test_density_near(void)
{
    int bad = 0, falls = 0;
    for (int k = 1; k <= 64; k++) {
        int fs = -1, ff = -1;
        const int cs = cfpo_policy_density_near(k, 0.5, 0.5 * 1.21, 10, &fs);
        const int cf = cfpo_policy_density_near(k, 0.5, 0.5 * 1.19, 10, &ff);
        bad += cs != 2 || fs != (k <= 4 || (k - 1) % 4 == 0 ? 10 : 0);
        bad += ff != 0 || cf != (k < CFPO_POLICY_NEAR_TWO_UNTIL ? 2 : 1);
        falls += fs > 0;
    }
    int fs;
    bad += cfpo_policy_density_near(1, 1, 3, 1, &fs) != 1 || fs != 1; /* never more polygons than asked */
    CHECK(bad == 0 && falls == 19, "density near solve: %d wrong answers, %d fall-back iterations of 64 (19 expected)",
          bad, falls);
}

int main(void)
{
    test_density_near();
    test_unprint();
    test_shift_hyperuniform();
    test_schedule_table();
    test_shift();
    test_walk();
    test_margin();
    test_square();
    test_relax();
    test_other_variants();
    test_pure();
    return test_report(passed_, failed_);
}
