/* test_d3_bricks.c - the cut of the 3-D grid into one brick per rank
 * (src/d3/bricks3.c), against brute force, for g = 3 .. 30 and P = 1 ..
 * 64: the cut is refused exactly when P has no factors px py pz of at most
 * g / 3 each; otherwise every cell lies in exactly one brick, each brick
 * is at least 3 cells a side (so it holds cells of all 27 colours) and the
 * sides along an axis differ by at most one cell, the 3x3x3 block of each cell of a brick lies
 * in its rank's region, the region is the brick and the cells one step
 * away (across the wrap), and the neighbour list is exactly the other
 * ranks whose regions meet this one's (at most 26). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bricks3.h"
#include "testutil.h"

static int passed_, failed_;

static int factors_fit(int P, int s)
{
    for (int a = 1; a <= s; a++)
        for (int b = 1; b <= s; b++)
            if (P % (a * b) == 0 && P / (a * b) <= s) return 1;
    return 0;
}

/* the owner of cell (i, j, k) by brute force over the ranks' bricks */
static int owner(cfpo3_bricks *all, int P, int i, int j, int k, int *count)
{
    int who = -1;
    *count = 0;
    for (int r = 0; r < P; r++)
        if (cfpo3_bricks_mine(&all[r], i, j, k)) who = r, (*count)++;
    return who;
}

static void check_cut(int g, int P)
{
    char err[512];
    cfpo3_bricks *all = calloc((size_t)P, sizeof *all);
    int ok = 1;
    for (int r = 0; r < P && ok; r++) ok = cfpo3_bricks_init(&all[r], g, P, r, err, sizeof err) == 0;
    const int s = g / 3;
    CHECK(ok == factors_fit(P, s), "g=%d P=%d: cut %s, brute force says %s", g, P, ok ? "made" : "refused",
          factors_fit(P, s) ? "possible" : "impossible");
    if (!ok) {
        CHECK(strchr(err, '\n') == NULL && strstr(err, "ranks") != NULL, "g=%d P=%d: message '%s'", g, P, err);
        for (int r = 0; r < P; r++) cfpo3_bricks_free(&all[r]);
        free(all);
        return;
    }
    int bad = 0;
    for (int r = 0; r < P; r++)
        for (int a = 0; a < 3; a++) {
            const int lo = all[r].lo[a][all[r].me[a]], hi = all[r].lo[a][all[r].me[a] + 1];
            const int wmin = g / all[r].p[a], wmax = (g + all[r].p[a] - 1) / all[r].p[a];
            if (hi - lo < 3 || hi - lo < wmin || hi - lo > wmax) bad++;
        }
    CHECK(bad == 0, "g=%d P=%d: %d brick sides under 3 cells or uneven", g, P, bad);
    int once = 1, blocks = 1, region = 1;
    for (int k = 0; k < g; k++)
        for (int j = 0; j < g; j++)
            for (int i = 0; i < g; i++) {
                int cnt;
                const int r = owner(all, P, i, j, k, &cnt);
                if (cnt != 1) {
                    once = 0;
                    continue;
                }
                for (int dz = -1; dz <= 1; dz++)
                    for (int dy = -1; dy <= 1; dy++)
                        for (int dx = -1; dx <= 1; dx++)
                            if (!cfpo3_bricks_in_region(&all[r], all[r].me, (i + dx + g) % g, (j + dy + g) % g,
                                                        (k + dz + g) % g))
                                blocks = 0;
                /* region membership for every rank: the cell is in q's
                 * brick or one step (wrapped) from a cell of it */
                for (int q = 0; q < P; q++) {
                    int want = 0;
                    for (int dz = -1; dz <= 1 && !want; dz++)
                        for (int dy = -1; dy <= 1 && !want; dy++)
                            for (int dx = -1; dx <= 1 && !want; dx++)
                                want = cfpo3_bricks_mine(&all[q], (i + dx + g) % g, (j + dy + g) % g, (k + dz + g) % g);
                    if (want != cfpo3_bricks_in_region(&all[0], all[q].me, i, j, k)) region = 0;
                }
            }
    CHECK(once, "g=%d P=%d: a cell in no brick or in two", g, P);
    CHECK(blocks, "g=%d P=%d: a block of a brick's cell leaves the region", g, P);
    CHECK(region, "g=%d P=%d: a region is not its brick grown by one cell", g, P);
    /* neighbours: the other ranks whose regions share a cell */
    int nbok = 1;
    for (int r = 0; r < P && nbok; r++) {
        int want[4096] = {0}, nw = 0;
        for (int q = 0; q < P; q++) {
            if (q == r) continue;
            int meet = 0;
            for (int k = 0; k < g && !meet; k++)
                for (int j = 0; j < g && !meet; j++)
                    for (int i = 0; i < g && !meet; i++)
                        meet = cfpo3_bricks_in_region(&all[r], all[r].me, i, j, k) &&
                               cfpo3_bricks_in_region(&all[r], all[q].me, i, j, k);
            if (meet) want[nw++] = q;
        }
        if (nw != all[r].nnb || nw > 26) nbok = 0;
        for (int t = 0; t < nw && nbok; t++)
            if (all[r].nb[t] != want[t]) nbok = 0;
    }
    CHECK(nbok, "g=%d P=%d: a neighbour list differs from the ranks whose regions meet", g, P);
    for (int r = 0; r < P; r++) cfpo3_bricks_free(&all[r]);
    free(all);
}

int main(void)
{
    for (int g = 3; g <= 30; g += 3)
        for (int P = 1; P <= 64; P++) {
            if (g > 15 && P > 8 && P != 27 && P != 64) continue; /* keep it short */
            check_cut(g, P);
        }
    /* 27 ranks on 9^3 cells: 3x3x3 bricks, each with 26 distinct neighbours */
    cfpo3_bricks B;
    char err[256];
    CHECK(cfpo3_bricks_init(&B, 9, 27, 13, err, sizeof err) == 0 && B.nnb == 26 && B.p[0] == 3 && B.p[1] == 3 &&
              B.p[2] == 3,
          "27 ranks on 9^3: %d neighbours", B.nnb);
    cfpo3_bricks_free(&B);
    return test_report(passed_, failed_);
}
