/* test_prefixes.c - the prefix measures (prefixes.h) against brute force:
 * the running distances d_j and the exact worst prefix against O(n^2)
 * loops, each row's delta_min and delta_avg against an O(m^2) loop, the
 * plan of sizes, and the property the measure exists for: a greedy
 * farthest-point order of a set has better prefixes than a shuffle of it. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cfpo.h"
#include "prefixes.h"
#include "sets.h"
#include "testutil.h"

static int passed_, failed_;

static double d2(const double *a, const double *b)
{
    double dx = fabs(a[0] - b[0]), dy = fabs(a[1] - b[1]);
    dx = fmin(dx, 1 - dx), dy = fmin(dy, 1 - dy);
    return dx * dx + dy * dy;
}

/* delta_min and delta_avg of the first m points / Delta(m), O(m^2) */
static void brute_delta(const double *xy, size_t m, double *dmin, double *davg)
{
    double mn = INFINITY, sum = 0;
    for (size_t i = 0; i < m; i++) {
        double b = INFINITY;
        for (size_t j = 0; j < m; j++)
            if (j != i) b = fmin(b, d2(xy + 2 * i, xy + 2 * j));
        mn = fmin(mn, sqrt(b));
        sum += sqrt(b);
    }
    *dmin = mn / an_prefix_delta(m);
    *davg = sum / (double)m / an_prefix_delta(m);
}

/* the worst delta_min(P_m) / Delta(m) over m in [m0, n], every prefix directly */
static double brute_worst(const double *xy, size_t n, size_t m0, size_t *at)
{
    double dm = INFINITY, worst = INFINITY;
    for (size_t m = 2; m <= n; m++) {
        for (size_t i = 0; i + 1 < m; i++) dm = fmin(dm, sqrt(d2(xy + 2 * (m - 1), xy + 2 * i)));
        if (m >= m0 && dm / an_prefix_delta(m) < worst) worst = dm / an_prefix_delta(m), *at = m;
    }
    return worst;
}

static void check_running(const char *name, const double *xy, size_t n)
{
    double *d = malloc((n ? n : 1) * sizeof *d);
    CHECK(an_prefix_running(xy, n, d) == 0, "%s: running", name);
    int bad = 0;
    for (size_t j = 1; j < n; j++) {
        double b = INFINITY;
        for (size_t i = 0; i < j; i++) b = fmin(b, d2(xy + 2 * j, xy + 2 * i));
        if (!(fabs(d[j] - sqrt(b)) <= 1e-15)) bad++;
    }
    CHECK(bad == 0, "%s: %d running distances differ from brute force", name, bad);
    for (size_t m0 = 2; n >= 2 && m0 <= n; m0 = m0 * 3 + 1) {
        size_t at = 0, bat = 0;
        const double w = an_prefix_worst(d, n, m0, &at), bw = brute_worst(xy, n, m0, &bat);
        CHECK(fabs(w - bw) <= 1e-12 * bw && at == bat, "%s: worst from %zu: %.12g at %zu, brute %.12g at %zu", name,
              m0, w, at, bw, bat);
    }
    free(d);
}

static void shuffle(double *xy, size_t n, uint64_t seed)
{
    for (size_t i = n - 1; i > 0; i--) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        const size_t j = (size_t)((seed >> 33) % (i + 1));
        double t0 = xy[2 * i], t1 = xy[2 * i + 1];
        xy[2 * i] = xy[2 * j], xy[2 * i + 1] = xy[2 * j + 1];
        xy[2 * j] = t0, xy[2 * j + 1] = t1;
    }
}

/* greedy farthest-point order, O(n^2), from point 0 */
static void greedy(const double *in, size_t n, double *out)
{
    double *best = malloc(n * sizeof *best);
    char *used = calloc(n, 1);
    for (size_t i = 0; i < n; i++) best[i] = INFINITY;
    size_t cur = 0;
    for (size_t k = 0; k < n; k++) {
        used[cur] = 1;
        out[2 * k] = in[2 * cur], out[2 * k + 1] = in[2 * cur + 1];
        size_t nx = 0;
        double far = -1;
        for (size_t i = 0; i < n; i++) {
            if (used[i]) continue;
            best[i] = fmin(best[i], d2(in + 2 * i, in + 2 * cur));
            if (best[i] > far) far = best[i], nx = i;
        }
        cur = nx;
    }
    free(best);
    free(used);
}

/* the worst dyadic prefix short of the whole set */
static double worst_dyadic(const an_prefixes *p)
{
    double w = INFINITY;
    for (int i = 0; i < p->count; i++)
        if (p->rows[i].kind == AN_PREFIX_DYADIC && p->rows[i].m < p->rows[p->count - 1].m) w = fmin(w, p->rows[i].dmin);
    return w;
}

int main(void)
{
    char err[256];
    const size_t n = 576;
    double *xy = malloc(2 * 1024 * sizeof *xy), *ord = malloc(2 * 1024 * sizeof *ord);

    /* running distances and the exact worst prefix */
    set_white(xy, n, 41);
    check_running("white", xy, n);
    set_jittered(xy, 24, 42);
    check_running("jittered", xy, n);
    check_running("three points", xy, 3);
    check_running("two points", xy, 2);
    check_running("one point", xy, 1);
    for (size_t i = 0; i < 100; i++) xy[2 * (200 + i)] = xy[2 * i], xy[2 * (200 + i) + 1] = xy[2 * i + 1];
    check_running("duplicates", xy, 300);
    for (size_t i = 0; i < 400; i++) xy[2 * i] = 0.3 + 0.01 * xy[2 * i], xy[2 * i + 1] *= 0.02; /* a cluster */
    check_running("cluster", xy, 400);

    /* the plan */
    an_prefix_row *rows;
    int count;
    CHECK(an_prefix_plan(1000, 16, NULL, 0, &rows, &count, err, sizeof err) == 0, "plan: %s", err);
    const size_t want[] = {16, 17, 23, 32, 33, 45, 64, 65, 91, 128, 129, 181, 256, 257, 362, 512, 1000};
    int same = count == (int)(sizeof want / sizeof *want);
    for (int i = 0; same && i < count; i++) same = rows[i].m == want[i];
    CHECK(same, "plan of 1000 from 16: %d rows", count);
    free(rows);
    const size_t given[] = {300, 5, 300, 77};
    CHECK(an_prefix_plan(1000, 16, given, 4, &rows, &count, err, sizeof err) == 0 && count == 3 && rows[0].m == 5 &&
              rows[1].m == 77 && rows[2].m == 300 && rows[0].kind == AN_PREFIX_GIVEN,
          "given sizes sorted and unique");
    free(rows);
    CHECK(an_prefix_plan(100, 128, NULL, 0, &rows, &count, err, sizeof err) != 0 && strstr(err, "base"),
          "a base above n is refused");
    const size_t big[] = {101};
    CHECK(an_prefix_plan(100, 16, big, 1, &rows, &count, err, sizeof err) != 0 && strstr(err, "101"),
          "a size above n is refused");

    /* rows against brute force */
    set_white(xy, n, 43);
    an_prefixes P;
    CHECK(an_prefixes_compute(xy, n, 16, NULL, 0, 0, &P, err, sizeof err) == 0, "compute: %s", err);
    for (int i = 0; i < P.count; i++) {
        double dmin, davg;
        brute_delta(xy, P.rows[i].m, &dmin, &davg);
        CHECK(fabs(P.rows[i].dmin - dmin) <= 1e-12 && fabs(P.rows[i].davg - davg) <= 1e-12,
              "row %zu: %.12g %.12g, brute %.12g %.12g", P.rows[i].m, P.rows[i].dmin, P.rows[i].davg, dmin, davg);
        CHECK(P.rows[i].m < 25 ? isnan(P.rows[i].p0) : P.rows[i].p0 > 0, "row %zu: p0 %g", P.rows[i].m, P.rows[i].p0);
        CHECK(P.rows[i].var[0] > 0, "row %zu: a variance", P.rows[i].m);
    }
    size_t bat;
    CHECK(fabs(P.worst_any - brute_worst(xy, n, 16, &bat)) <= 1e-12 && P.worst_any_m == bat, "worst any");
    an_prefixes_free(&P);

    /* greedy farthest-point order of a CFPO set beats a shuffle of the same points */
    cfpo_options o;
    cfpo_options_init(&o);
    o.seed = 44;
    o.threads = 1;
    cfpo_result res;
    CHECK(cfpo_sample(1024, &o, xy, &res, err, sizeof err) == 0, "cfpo: %s", err);
    greedy(xy, 1024, ord);
    an_prefixes G, S;
    CHECK(an_prefixes_compute(ord, 1024, 16, NULL, 0, 0, &G, err, sizeof err) == 0, "greedy: %s", err);
    shuffle(ord, 1024, 45);
    CHECK(an_prefixes_compute(ord, 1024, 16, NULL, 0, 0, &S, err, sizeof err) == 0, "shuffled: %s", err);
    printf("greedy: worst dyadic %.4f, any %.4f; shuffled: %.4f, %.4f\n", worst_dyadic(&G), G.worst_any,
           worst_dyadic(&S), S.worst_any);
    CHECK(worst_dyadic(&G) > worst_dyadic(&S) && G.worst_any > S.worst_any, "greedy order has better prefixes");
    CHECK(fabs(G.rows[G.count - 1].dmin - S.rows[S.count - 1].dmin) <= 1e-12, "the full sets are the same");
    an_prefixes_free(&G);
    an_prefixes_free(&S);
    free(xy);
    free(ord);
    return test_report(passed_, failed_);
}
