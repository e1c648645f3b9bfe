/* test_dens_order.c - the density solve's neighbours in order
 * (src/density/dens_order.c):
 *  - cfpo_dens_order and cfpo_dens_order_fast (its vector route where
 *    the CPU has it) against a reference (every candidate's place
 *    counted by brute force over (key, index)), the kmax smallest kept,
 *    the candidates given in block order or shuffled;
 *  - cfpo_dens_order_block (where the CPU has its route) against the
 *    scalar gather (every j != p with the scalar key below T) and
 *    cfpo_dens_order: the same count, the same keys bit for bit, the same
 *    indices, on random blocks of 1-64 points whose keys tie often
 *    (points on a coarse lattice, q from a set of three values, copies of
 *    points), with kmax 40 and 5, the moving point anywhere in the block. */
#include <stdio.h>
#include <string.h>

#include "dens_order.h"
#include "testutil.h"

static int passed_, failed_;

static unsigned long long rng = 12345;
static double urand(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* The reference list: the candidates' places counted by brute force. */
static int reference(const double *ck, const double *cj, int cnt, int kmax, double *key, int *nj)
{
    for (int i = 0; i < cnt; i++) {
        int r = 0;
        for (int t = 0; t < cnt; t++) r += ck[t] < ck[i] || (ck[t] == ck[i] && cj[t] < cj[i]);
        if (r < kmax) {
            key[r] = ck[i];
            nj[r] = (int)cj[i];
        }
    }
    return cnt < kmax ? cnt : kmax;
}

int main(void)
{
    double bx[64], by[64], br[64], ck[65], cj[65];
    double k1[64], k2[64];
    int n1[64], n2[64];
    int trials = 0, blocks = 0, bad_ref = 0, bad_fast = 0, bad_block = 0, ties = 0, cut = 0;
    const double qs[3] = {1.0, 0.75, 1.3};
    for (int t = 0; t < 20000; t++) {
        const int m = 1 + (int)(urand() * 64);
        for (int j = 0; j < m; j++) {
            if (j > 0 && urand() < 0.2) { /* a copy of an earlier point: equal keys */
                const int c = (int)(urand() * j);
                bx[j] = bx[c]; by[j] = by[c]; br[j] = br[c];
                continue;
            }
            bx[j] = -0.03 + (double)(int)(urand() * 16) * 0.005; /* a lattice: equal distances */
            by[j] = -0.03 + (double)(int)(urand() * 16) * 0.005;
            br[j] = qs[(int)(urand() * 3)];
        }
        const int p = (int)(urand() * m);
        const double ax = bx[p], ay = by[p], T = 0.0004 + 0.003 * urand();
        const int kmax = (t & 3) == 0 ? 5 : 40;
        int cnt = 0;
        for (int j = 0; j < m; j++) { /* the scalar gather's keys */
            const double ex = bx[j] - ax, ey = by[j] - ay, d2 = (ex * ex + ey * ey) * br[j];
            if (d2 < T && j != p) {
                ck[cnt] = d2;
                cj[cnt] = (double)j;
                cnt++;
            }
        }
        for (int a = 0; a < cnt; a++)
            for (int b = a + 1; b < cnt; b++) ties += ck[a] == ck[b];
        for (int a = cnt - 1; a > 0 && (t & 1); a--) { /* any order in (the scalar gather's is the block's) */
            const int b = (int)(urand() * (a + 1));
            double v = ck[a]; ck[a] = ck[b]; ck[b] = v;
            v = cj[a]; cj[a] = cj[b]; cj[b] = v;
        }
        cut += cnt > kmax;
        const int r1 = reference(ck, cj, cnt, kmax, k1, n1);
        const int r2 = cfpo_dens_order(ck, cj, cnt, kmax, k2, n2);
        trials++;
        if (r1 != r2 || memcmp(k1, k2, (size_t)r1 * sizeof *k1) != 0 || memcmp(n1, n2, (size_t)r1 * sizeof *n1) != 0)
            bad_ref++;
        const int r4 = cfpo_dens_order_fast(ck, cj, cnt, kmax, k2, n2);
        if (r1 != r4 || memcmp(k1, k2, (size_t)r1 * sizeof *k1) != 0 || memcmp(n1, n2, (size_t)r1 * sizeof *n1) != 0)
            bad_fast++;
        const int r3 = cfpo_dens_order_block(bx, by, br, m, p, ax, ay, T, kmax, k2, n2);
        if (r3 < 0) continue; /* no AVX-512 route on this CPU */
        blocks++;
        if (r1 != r3 || memcmp(k1, k2, (size_t)r1 * sizeof *k1) != 0 || memcmp(n1, n2, (size_t)r1 * sizeof *n1) != 0)
            bad_block++;
    }
    CHECK(bad_ref == 0, "insertion: %d of %d lists differ from the reference", bad_ref, trials);
    CHECK(bad_fast == 0, "the list's vector route: %d of %d lists differ", bad_fast, trials);
    CHECK(ties > trials, "only %d tied keys in %d lists: ties are not exercised", ties, trials);
    CHECK(cut > trials / 20, "only %d of %d lists cut at kmax", cut, trials);
    CHECK(bad_block == 0, "the block's vector route: %d of %d lists differ", bad_block, blocks);
    printf("%d lists (%d tied key pairs, %d cut at kmax); the block's vector route: %s\n", trials, ties, cut,
           blocks ? "compared on every list" : "not on this CPU");
    return test_report(passed_, failed_);
}
