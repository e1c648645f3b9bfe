/* test_tiles.c - the cut of the grid into tiles: every cell has exactly
 * one owner, tiles are contiguous and cover the grid, uneven cuts differ
 * by at most one cell, the chosen cut is the most square feasible one, and
 * too-small tiles are refused naming the largest usable rank count. */
#include <stdio.h>
#include <string.h>

#include "testutil.h"
#include "tiles.h"

static int passed_, failed_;

int main(void)
{
    /* Owner arithmetic against the extents, for many grids and cuts. */
    for (int64_t g = 3; g <= 60; g += 3)
        for (int parts = 1; parts <= g / 3; parts++) {
            int64_t covered = 0, mn = g, mx = 0;
            int okc = 1;
            for (int t = 0; t < parts; t++) {
                int64_t s = cfpo_tile_start(g, parts, t), l = cfpo_tile_len(g, parts, t);
                if (s != covered) okc = 0;
                covered += l;
                if (l < mn) mn = l;
                if (l > mx) mx = l;
                for (int64_t x = s; x < s + l; x++)
                    if (cfpo_tile_of(g, parts, x) != t) okc = 0;
            }
            CHECK(okc && covered == g, "g=%lld parts=%d: tiles do not cover the grid in order", (long long)g, parts);
            CHECK(mx - mn <= 1 && mn >= 3, "g=%lld parts=%d: tile sides %lld..%lld", (long long)g, parts,
                  (long long)mn, (long long)mx);
        }
    cfpo_tiling T;
    char err[256];
    /* The most square cut. */
    CHECK(cfpo_tiling_init(&T, 57, 6, 0, 0, err, sizeof err) == 0 && T.px == 2 && T.py == 3, "6 ranks: 2x3");
    CHECK(cfpo_tiling_init(&T, 57, 4, 0, 0, err, sizeof err) == 0 && T.px == 2 && T.py == 2, "4 ranks: 2x2");
    CHECK(cfpo_tiling_init(&T, 57, 7, 0, 0, err, sizeof err) == 0 && T.px == 1 && T.py == 7, "7 ranks: 1x7");
    CHECK(cfpo_tiling_init(&T, 1000, 1024, 0, 0, err, sizeof err) == 0 && T.px == 32 && T.py == 32, "1024: 32x32");
    /* A forced cut must match P. */
    CHECK(cfpo_tiling_init(&T, 57, 6, 3, 2, err, sizeof err) == 0 && T.px == 3 && T.py == 2, "forced 3x2");
    CHECK(cfpo_tiling_init(&T, 57, 6, 4, 2, err, sizeof err) == -1 && strstr(err, "does not give"), "4x2 for 6: %s", err);
    /* Too small: 9x9 cells allow 3 tiles a side, 9 ranks. */
    CHECK(cfpo_tiling_init(&T, 9, 9, 0, 0, err, sizeof err) == 0 && T.px == 3, "9 ranks on 9x9");
    CHECK(cfpo_tiling_init(&T, 9, 5, 0, 0, err, sizeof err) == -1 && strstr(err, "at most 9 ranks"), "5 on 9x9: %s", err);
    CHECK(cfpo_tiling_init(&T, 9, 16, 0, 0, err, sizeof err) == -1 && strstr(err, "tiles too small"), "16 on 9x9: %s", err);
    CHECK(cfpo_tiling_init(&T, 9, 4, 4, 1, err, sizeof err) == -1 && strstr(err, "at most 3 tiles per side"),
          "4x1 on 9x9: %s", err);
    CHECK(cfpo_tiling_max_ranks(57) == 361, "57x57: 19^2 ranks at most");
    /* Every cell of a 2-D cut has one owner, the rank of its tile. */
    cfpo_tiling_init(&T, 20 * 3, 12, 0, 0, err, sizeof err);
    int counts[12] = {0};
    for (int64_t y = 0; y < T.g; y++)
        for (int64_t x = 0; x < T.g; x++) counts[cfpo_tiling_owner(&T, x, y)]++;
    int balanced = 1;
    for (int r = 0; r < 12; r++)
        if (counts[r] < 3 * 3 || counts[r] > (T.g / T.px + 1) * (T.g / T.py + 1)) balanced = 0;
    CHECK(balanced, "owners of a 60x60 grid on 12 ranks are unbalanced");
    return test_report(passed_, failed_);
}
