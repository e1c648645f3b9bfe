/* lloyd.cpp - see lloyd.h. */
#include "lloyd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <vector>

#include "cgal_types.h"

extern "C" {
#include "cli.h"
#include "grid.h"
#include "rng.h"
#include "stats.h"
#include "stoprule.h"
}

using namespace bl;

namespace {
const std::uint64_t START_STREAM = 0x4c4c4f5944535452ULL; /* "LLOYDSTR" */
}

struct lloyd_engine {
    std::int64_t n;
    double tol, L;
    int iterations, done;
    std::vector<double> xy, area, cx, cy;
};

extern "C" {

double lloyd_bytes(std::int64_t n) { return (double)n * 760 + 8.0 * 1024 * 1024; }

lloyd_engine *lloyd_create(std::int64_t n, std::uint64_t seed, double tol, int iterations, char *err, size_t errlen)
{
    cfpo_grid G;
    if (n >= (std::int64_t)UINT32_MAX) {
        std::snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return nullptr;
    }
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_FULL, seed, err, errlen) != 0) return nullptr;
    lloyd_engine *E = new (std::nothrow) lloyd_engine;
    if (!E) {
        std::snprintf(err, errlen, "out of memory");
        return nullptr;
    }
    try {
        E->n = n;
        E->tol = tol;
        E->iterations = iterations;
        E->done = 0;
        E->L = G.L;
        E->xy.resize(2 * (size_t)n);
        E->area.resize((size_t)n);
        E->cx.resize((size_t)n);
        E->cy.resize((size_t)n);
        for (std::int64_t i = 0; i < 2 * n; i++) E->xy[(size_t)i] = cfpo_rand01(seed, START_STREAM, (std::uint64_t)i);
    } catch (const std::bad_alloc &) {
        std::snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        delete E;
        return nullptr;
    }
    return E;
}

void lloyd_free(lloyd_engine *E) { delete E; }

const double *lloyd_points(const lloyd_engine *E) { return E->xy.data(); }

void lloyd_deltas(lloyd_engine *E, double *dmin, double *davg)
{
    if (cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg) != 0) *dmin = *davg = NAN;
}

int lloyd_cells(const lloyd_engine *E, double *area, double *cx, double *cy)
{
    PDT T;
    std::vector<Vertex_handle> vh;
    char err[160];
    try {
        if (build_indexed(T, E->xy, E->n, vh, err, sizeof err) != 0) return -1;
    } catch (const std::bad_alloc &) {
        return -1;
    }
    std::vector<double> px, py;
    for (std::int64_t i = 0; i < E->n; i++) {
        const Vertex_handle v = vh[(size_t)i];
        const double sx = E->xy[2 * (size_t)i], sy = E->xy[2 * (size_t)i + 1];
        /* the circumcentres of v's faces in counter-clockwise order, each
         * taken relative to v's own copy of the face (its offset removed) */
        px.clear();
        py.clear();
        auto f = T.incident_faces(v), done = f;
        do {
            const int k = f->index(v);
            const Point pv = T.point(f, k);
            double ccx, ccy, r2;
            circumcircle(T, f, &ccx, &ccy, &r2);
            px.push_back(ccx - pv.x() + sx);
            py.push_back(ccy - pv.y() + sy);
        } while (++f != done);
        /* the polygon's area and centroid (shoelace), relative to the site */
        double a2 = 0, mx = 0, my = 0;
        const size_t m = px.size();
        for (size_t j = 0; j < m; j++) {
            const double x0 = px[j] - sx, y0 = py[j] - sy, x1 = px[(j + 1) % m] - sx, y1 = py[(j + 1) % m] - sy;
            const double c = x0 * y1 - x1 * y0;
            a2 += c;
            mx += (x0 + x1) * c;
            my += (y0 + y1) * c;
        }
        area[i] = 0.5 * a2;
        cx[i] = sx + mx / (3 * a2);
        cy[i] = sy + my / (3 * a2);
    }
    return 0;
}

static double wrap01(double x)
{
    x -= std::floor(x);
    return x >= 1.0 ? 0.0 : x;
}

void lloyd_iterate(lloyd_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const double tolL = E->tol * E->L;
    std::int64_t moved = 0;
    double maxd2 = 0;
    if (lloyd_cells(E, E->area.data(), E->cx.data(), E->cy.data()) == 0) {
        for (std::int64_t i = 0; i < E->n; i++) {
            const double dx = E->cx[(size_t)i] - E->xy[2 * (size_t)i], dy = E->cy[(size_t)i] - E->xy[2 * (size_t)i + 1];
            const double d2 = dx * dx + dy * dy;
            if (d2 >= tolL * tolL) moved++;
            maxd2 = std::max(maxd2, d2);
            E->xy[2 * (size_t)i] = wrap01(E->cx[(size_t)i]);
            E->xy[2 * (size_t)i + 1] = wrap01(E->cy[(size_t)i]);
        }
    }
    /* (coincident sites, possible only from a degenerate start: nothing moves,
     * the run ends converged with the set as it is) */
    s->moved = moved;
    s->solved = E->n;
    s->max_disp = std::sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    E->done++;
    s->converged = cfpo_net_converged(moved, s->max_disp, E->tol) || (E->iterations > 0 && E->done >= E->iterations);
    lloyd_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

} // extern "C"
