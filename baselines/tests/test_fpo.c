/* test_fpo.c - FPO and LFPO on CGAL's periodic Delaunay triangulation:
 *  - after every iteration of a small run the triangulation is valid
 *    (CGAL's is_valid()), holds exactly n vertices, and its points are the
 *    engine's points; every face is registered once with its own cached
 *    circumcircle and the heap's best live entry is the largest circle
 *    (fpo_check: the lazy invalidation loses nothing);
 *  - delta_min never decreases, and the first iterations raise it;
 *  - the same seed gives the same bytes, another seed other points;
 *  - --start grid gives exactly cfpo's initial points;
 *  - n below cfpo's minimum is refused with a message. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"
#include "cfpo.h"
#include "fpo.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static void run_checked(int local, int64_t n, int iters)
{
    const char *name = local ? "lfpo" : "fpo";
    fpo_options o;
    fpo_options_init(&o);
    o.local = local;
    o.seed = 3;
    char err[256];
    fpo_engine *E = fpo_create(n, &o, err, sizeof err);
    CHECK(E != NULL, "%s create: %s", name, err);
    if (!E) return;
    CHECK(fpo_check(E), "%s: start triangulation invalid", name);
    double dmin0, davg0;
    fpo_deltas(E, &dmin0, &davg0);
    double prev = dmin0;
    int valid = 1, monotone = 1;
    cfpo_iter_stats s;
    for (int it = 1; it <= iters; it++) {
        fpo_iterate(E, &s);
        valid &= fpo_check(E);
        if (s.delta_min < prev) {
            monotone = 0;
            fprintf(stderr, "%s iteration %d: delta_min %.17g < %.17g\n", name, it, s.delta_min, prev);
        }
        prev = s.delta_min;
        if (s.converged) break;
    }
    CHECK(valid, "%s n=%lld: triangulation invalid after an iteration", name, (long long)n);
    CHECK(monotone, "%s n=%lld: delta_min decreased", name, (long long)n);
    CHECK(prev > dmin0 + 0.3, "%s n=%lld: delta_min only %.4f -> %.4f", name, (long long)n, dmin0, prev);
    fpo_free(E);
}

static void check_determinism(int local)
{
    fpo_options o;
    fpo_options_init(&o);
    o.local = local;
    o.seed = 11;
    char err[256];
    const int64_t n = 200;
    fpo_engine *A = fpo_create(n, &o, err, sizeof err), *B = fpo_create(n, &o, err, sizeof err);
    o.seed = 12;
    fpo_engine *C = fpo_create(n, &o, err, sizeof err);
    cfpo_iter_stats s;
    for (int i = 0; i < 5; i++) {
        fpo_iterate(A, &s);
        fpo_iterate(B, &s);
        fpo_iterate(C, &s);
    }
    CHECK(memcmp(fpo_points(A), fpo_points(B), 2 * n * sizeof(double)) == 0,
          "%s: the same seed gives different points", local ? "lfpo" : "fpo");
    CHECK(memcmp(fpo_points(A), fpo_points(C), 2 * n * sizeof(double)) != 0,
          "%s: seeds 11 and 12 give the same points", local ? "lfpo" : "fpo");
    fpo_free(A);
    fpo_free(B);
    fpo_free(C);
}

static void check_grid_start(void)
{
    const int64_t n = 500;
    fpo_options o;
    fpo_options_init(&o);
    o.seed = 5;
    o.start = FPO_START_GRID;
    char err[256];
    fpo_engine *E = fpo_create(n, &o, err, sizeof err);
    cfpo_options co;
    cfpo_options_init(&co);
    co.seed = 5;
    co.threads = 1;
    co.variant = CFPO_VARIANT_PAPER; /* the stratified start; the default variant starts otherwise */
    cfpo_engine *C = cfpo_engine_create(n, &co, err, sizeof err);
    CHECK(E && C, "grid start: %s", err);
    if (!E || !C) return;
    double *xy = malloc(2 * n * sizeof *xy);
    cfpo_engine_points(C, xy);
    CHECK(memcmp(xy, fpo_points(E), 2 * n * sizeof(double)) == 0, "grid start differs from cfpo's");
    free(xy);
    cfpo_engine_free(C);
    fpo_free(E);
}

int main(void)
{
    run_checked(0, 300, 12);
    run_checked(1, 300, 12);
    check_determinism(0);
    check_determinism(1);
    check_grid_start();
    fpo_options o;
    fpo_options_init(&o);
    char err[256] = "";
    CHECK(fpo_create(5, &o, err, sizeof err) == NULL && strstr(err, "too small"),
          "n = 5 accepted or unclear message '%s'", err);
    return test_report(passed_, failed_);
}
