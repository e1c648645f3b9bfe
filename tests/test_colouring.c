/* test_colouring.c - the uniform engine's colourings (policy.h:
 * cfpo_policy_colour_at, the brick order, the adaptive variant's choice of
 * colouring; cells.h: eng_colour_of and eng_colour_cell, which every
 * phase step enumerates a colour's cells with).
 *
 * Properties: for the plain colouring and for brick rows and brick
 * columns under many keys, on tori of 9 to 33 cells a side, every 3x3
 * block of cells holds each of the 9 colours exactly once and no two
 * cells of one colour lie closer than 3 cells on both axes (so their 3x3
 * blocks are disjoint: a phase is race-free, and relocation's one sender
 * per block is right); the checker finds the faults of a colouring with
 * two rows of one colour made adjacent, and of shifts taken from the
 * wrong axis; a brick colouring is periodic along its rows (columns) but
 * not across them; on every tile of 1x1 to 3x3 tilings each own cell is
 * enumerated by exactly one colour, the one the colouring gives it; the
 * brick order solves every colour once, from colour (rot_y, rot_x), and
 * gives the three rows (columns) of colours the same sum of turns, which
 * the rows-in-turn order does not; the adaptive variant takes brick rows
 * under the grid's even moves and brick columns under the odd ones, with
 * a key kept while the grid stays and new at each move, up to
 * CFPO_POLICY_BRICK_UNTIL, and the plain colouring after it; the
 * hyperuniform variant above 65,536 points takes the same colourings in
 * its adaptive sweeps and the plain ones in the rest; the other variants
 * (and the hyperuniform one up to 65,536 points) keep the plain
 * colouring. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cells.h"
#include "grid.h"
#include "policy.h"
#include "tiles.h"
#include "testutil.h"

static int passed_, failed_;

typedef struct {
    cfpo_policy P;
    int broken;   /* 1: row `row` takes the colours' row of the row below it;
                     2: brick rows with the shift of the column, not the row */
    int64_t row;
} colouring;

static int colour_of(const colouring *c, int64_t g, int64_t x, int64_t y)
{
    if (c->broken == 1) {
        const int64_t yr = y == c->row ? y - 1 : y;
        const int s = cfpo_policy_brick_shift(c->P.brick_key, y);
        return (int)(yr % 3) * 3 + (int)((x + 3 - s) % 3);
    }
    if (c->broken == 2) return (int)(y % 3) * 3 + (int)((x + 3 - cfpo_policy_brick_shift(c->P.brick_key, x)) % 3);
    (void)g;
    return cfpo_policy_colour_at(&c->P, 3, x, y);
}

/* The faults of a colouring of the g x g torus: 3x3 blocks that do not
 * hold each colour once, and pairs of cells of one colour less than 3
 * apart on both axes (each counted from both cells). */
static int64_t faults(const colouring *c, int64_t g)
{
    int *col = malloc((size_t)(g * g) * sizeof *col);
    if (!col) return -1;
    int64_t bad = 0;
    for (int64_t y = 0; y < g; y++)
        for (int64_t x = 0; x < g; x++) {
            col[y * g + x] = colour_of(c, g, x, y);
            if (col[y * g + x] < 0 || col[y * g + x] > 8) bad++;
        }
    for (int64_t y = 0; y < g; y++)
        for (int64_t x = 0; x < g; x++) {
            int seen = 0;
            for (int dy = 0; dy < 3; dy++)
                for (int dx = 0; dx < 3; dx++) seen |= 1 << col[((y + dy) % g) * g + (x + dx) % g];
            if (seen != 0x1ff) bad++;
            for (int dy = -2; dy <= 2; dy++)
                for (int dx = -2; dx <= 2; dx++)
                    if ((dx || dy) && col[((y + dy + g) % g) * g + (x + dx + g) % g] == col[y * g + x]) bad++;
        }
    free(col);
    return bad;
}

static void test_valid(void)
{
    const int64_t gs[4] = {9, 12, 21, 33};
    int64_t bad = 0, tried = 0, caught = 0, caught2 = 0, across = 0, along = 0;
    for (int gi = 0; gi < 4; gi++)
        for (uint64_t key = 0; key < 40; key++)
            for (int mode = 0; mode <= CFPO_BRICK_COLUMNS; mode++) {
                const int64_t g = gs[gi];
                colouring c = {.P = {.brick = mode, .brick_key = cfpo_mix64(key + 77)}};
                bad += faults(&c, g) != 0;
                tried++;
                if (mode == CFPO_BRICK_ROWS) {
                    c.broken = 1;
                    c.row = 1 + (int64_t)(key % (uint64_t)(g - 1));
                    caught += faults(&c, g) > 0;
                    c.broken = 2;
                    caught2 += faults(&c, g) > 0;
                    c.broken = 0;
                    for (int64_t y = 0; y < g; y++)
                        for (int64_t x = 0; x < g; x++) {
                            along += colour_of(&c, g, x, y) != colour_of(&c, g, (x + 3) % g, y);
                            across += colour_of(&c, g, x, y) != colour_of(&c, g, x, (y + 3) % g);
                        }
                }
            }
    CHECK(bad == 0, "%lld of %lld colourings have two cells of one colour within a 3x3 block", (long long)bad,
          (long long)tried);
    CHECK(caught == 4 * 40, "two adjacent rows of one colour: found in %lld of 160 colourings", (long long)caught);
    CHECK(caught2 == 4 * 40, "shifts by column in brick rows: found in %lld of 160 colourings", (long long)caught2);
    CHECK(along == 0 && across > 0, "brick rows: %lld changes along the rows (0), %lld across them (> 0)",
          (long long)along, (long long)across);
}

/* Each own cell of every tile once, by the colour the colouring gives it. */
static void test_enumeration(void)
{
    static cfpo_engine E;
    int64_t bad = 0, cells = 0;
    const int64_t gs[3] = {9, 21, 33};
    for (int gi = 0; gi < 3; gi++)
        for (int mode = 0; mode <= CFPO_BRICK_COLUMNS; mode++)
            for (uint64_t key = 1; key <= 5; key++)
                for (int px = 1; px <= 3; px++)
                    for (int py = 1; py <= 3; py++)
                        for (int tx = 0; tx < px; tx++)
                            for (int ty = 0; ty < py; ty++) {
                                const int64_t g = gs[gi];
                                free(E.brick_sh); /* the last tiling's table */
                                memset(&E, 0, sizeof E);
                                E.G.g = g;
                                E.G.period = 3;
                                E.pol.brick = mode;
                                E.pol.brick_key = cfpo_mix64(key);
                                if (eng_brick_table(&E) != 0) { bad++; continue; }
                                E.x0 = cfpo_tile_start(g, px, tx), E.w = cfpo_tile_len(g, px, tx);
                                E.y0 = cfpo_tile_start(g, py, ty), E.h = cfpo_tile_len(g, py, ty);
                                int *count = calloc((size_t)(E.w * E.h), sizeof *count);
                                if (!count) { bad++; continue; }
                                for (int colour = 0; colour < 9; colour++) {
                                    const eng_colour C = eng_colour_of(&E, colour);
                                    for (int64_t t = 0; t < C.nxc * C.nyc; t++) {
                                        int64_t lx, ly;
                                        if (!eng_colour_cell(&C, t, &lx, &ly)) continue;
                                        if (lx < 0 || lx >= E.w || ly < 0 || ly >= E.h ||
                                            cfpo_policy_colour_at(&E.pol, 3, E.x0 + lx, E.y0 + ly) != colour) {
                                            bad++;
                                            continue;
                                        }
                                        count[ly * E.w + lx]++;
                                    }
                                }
                                for (int64_t i = 0; i < E.w * E.h; i++) bad += count[i] != 1;
                                cells += E.w * E.h;
                                free(count);
                            }
    free(E.brick_sh);
    E.brick_sh = NULL;
    CHECK(bad == 0, "colour enumeration: %lld faults over %lld tile cells", (long long)bad, (long long)cells);
}

/* The three rows (columns) of colours' sums of turns under order f. */
static int turn_spread(const cfpo_policy *P, int (*f)(const cfpo_policy *, int, int))
{
    int sum[3] = {0, 0, 0}, seen = 0;
    for (int j = 0; j < 9; j++) {
        const int c = f(P, 3, j);
        seen |= 1 << c;
        sum[P->brick == CFPO_BRICK_ROWS ? c / 3 : c % 3] += j;
    }
    if (seen != 0x1ff) return -1;
    return (sum[0] != sum[1]) + (sum[1] != sum[2]);
}

static int rows_in_turn(const cfpo_policy *P, int period, int j)
{
    const int r = j % period, i = j / period;
    if (P->brick == CFPO_BRICK_ROWS) return ((r + P->rot_y) % 3) * 3 + (i + P->rot_x) % 3;
    return ((i + P->rot_y) % 3) * 3 + (r + P->rot_x) % 3;
}

static void test_order(void)
{
    int bad = 0, plain = 0;
    for (int mode = CFPO_BRICK_ROWS; mode <= CFPO_BRICK_COLUMNS; mode++)
        for (int rx = 0; rx < 3; rx++)
            for (int ry = 0; ry < 3; ry++) {
                const cfpo_policy P = {.brick = mode, .rot_x = rx, .rot_y = ry, .balanced = 1};
                if (turn_spread(&P, cfpo_policy_colour) != 0 || cfpo_policy_colour(&P, 3, 0) != 3 * ry + rx) bad++;
                plain += turn_spread(&P, rows_in_turn) > 0;
            }
    CHECK(bad == 0, "brick order: %d of 18 sweeps miss a colour or give the rows unequal turns", bad);
    CHECK(plain == 18, "the rows-in-turn order's unequal turns found in %d of 18 sweeps", plain);
}

static cfpo_grid grid(int64_t n, int variant, uint64_t seed)
{
    cfpo_grid G;
    char err[256];
    if (cfpo_grid_init(&G, n, variant, seed, err, sizeof err) != 0) fprintf(stderr, "%s\n", err);
    return G;
}

static int move_of(int k) { return k <= 8 ? k - 1 : 8 + (k - 9) / 4; }

static void test_schedule(void)
{
    int bad = 0;
    for (uint64_t seed = 1; seed <= 3; seed++) {
        const cfpo_grid G = grid(4096 * (int64_t)seed, CFPO_VARIANT_ADAPTIVE, seed);
        cfpo_policy last = cfpo_policy_at(&G, 0, 1, 0.5);
        if (last.brick) bad++;
        for (int k = 1; k <= 100; k++) {
            const cfpo_policy P = cfpo_policy_at(&G, k, k < 30, 0.5);
            const int j = move_of(k), same_move = k > 1 && move_of(k - 1) == j;
            if (k > CFPO_POLICY_BRICK_UNTIL) { /* the plain colours after the early sweeps */
                if (P.brick) bad++;
                last = P;
                continue;
            }
            if (P.brick != (j % 2 ? CFPO_BRICK_COLUMNS : CFPO_BRICK_ROWS)) bad++;
            if (same_move != (P.brick_key == last.brick_key && P.brick == last.brick)) bad++;
            last = P;
        }
    }
    CHECK(bad == 0, "adaptive: %d iterations with the wrong colouring or key", bad);
    /* the hyperuniform variant above 65,536 points: the adaptive
     * variant's colourings in its adaptive sweeps (before its stage), the
     * plain colours in its transport and near rounds */
    int hu = 0, hu_brick = 0;
    for (uint64_t seed = 1; seed <= 2; seed++) {
        const cfpo_grid G = grid(65536 + 4096 * (int64_t)seed, CFPO_VARIANT_HYPERUNIFORM, seed);
        const cfpo_grid A = grid(65536 + 4096 * (int64_t)seed, CFPO_VARIANT_ADAPTIVE, seed);
        const int from = cfpo_policy_stage_from(&G);
        if (from <= 1) hu++;
        for (int k = 0; k <= 80; k++) {
            const cfpo_policy P = cfpo_policy_at(&G, k, 1, 0.5), Q = cfpo_policy_at(&A, k, 1, 0.5);
            if (k >= 1 && k < from) {
                hu_brick += P.brick != 0;
                if (P.brick != Q.brick || P.brick_key != Q.brick_key) hu++;
            } else if (P.brick) hu++;
        }
    }
    CHECK(hu == 0 && hu_brick > 0, "hyperuniform above 65,536 points: %d iterations with the wrong colouring (%d brick)",
          hu, hu_brick);
    int other = 0;
    const int variants[3] = {CFPO_VARIANT_HYPERUNIFORM, CFPO_VARIANT_PAPER, CFPO_VARIANT_SIMPLIFIED};
    for (int v = 0; v < 3; v++)
        for (int64_t n = 4096; n <= 4096 + 65536; n += 65536) {
            if (variants[v] == CFPO_VARIANT_HYPERUNIFORM && n > 65536) continue; /* above */
            const cfpo_grid G = grid(n, variants[v], 3);
            for (int k = 0; k <= 80; k++) other += cfpo_policy_at(&G, k, 0, 0.5).brick != 0;
        }
    CHECK(other == 0, "the other variants: %d iterations not in the plain colouring", other);
}

int main(void)
{
    test_valid();
    test_enumeration();
    test_order();
    test_schedule();
    return test_report(passed_, failed_);
}
