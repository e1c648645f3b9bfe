/* fpo3.cpp - Farthest Point Optimization (Schloemer, Heck and Deussen
 * 2011) in three dimensions on CGAL's Periodic_3_Delaunay_triangulation_3,
 * the command cfpo3d-fpo (bl3.h).
 *
 * As the 2-D FPO (fpo.h): one iteration visits every point in id order,
 * removes it, finds the largest empty sphere of the others (the largest
 * circumsphere of a Delaunay cell: the farthest point from the set is a
 * Voronoi vertex, a cell's circumcentre), and inserts the point at its
 * centre when its radius exceeds d0 + tol * L (d0 the point's distance to
 * its nearest neighbour, L the cell side of cfpo3d's grid for this n),
 * back where it was otherwise. The largest sphere comes from a max-heap of
 * cells by circumradius with lazy invalidation (a stamp per registration):
 * the cells a removal or an insertion makes are incident to the removed
 * point's former neighbours or to the inserted vertex and are registered
 * then. A move raises the point's nearest distance to the sphere's radius,
 * so delta_min never falls. Start: n uniform points (stream FPO3START).
 * Converged when no point's net move over an iteration reaches tol * L.
 * The only file of the 3-D baselines that sees CGAL. */
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include "cgal3_types.h"

extern "C" {
#include "bl3.h"
#include "grid3.h"
#include "nn3.h"
#include "rng.h"
#include "solve3.h"
}

namespace {

const uint64_t START3_STREAM = 0x46504f3353544152ULL; /* "FPO3STAR" */

struct CellInfo {
    uint64_t stamp = 0; /* 0: unregistered */
    double r2 = 0, c[3] = {0, 0, 0};
};

using cfpo_cgal3::CbDS;
using cfpo_cgal3::Gt;
using cfpo_cgal3::K;
using cfpo_cgal3::Vb;
typedef CGAL::Triangulation_cell_base_3<Gt, CbDS> Cbb;
typedef CGAL::Triangulation_cell_base_with_info_3<CellInfo, Gt, Cbb> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Periodic_3_Delaunay_triangulation_3<Gt, Tds> PDT;
typedef PDT::Point Point;
typedef PDT::Cell_handle Cell_handle;
typedef PDT::Vertex_handle Vertex_handle;

struct Entry {
    double r2;
    uint64_t stamp;
    Cell_handle c;
};
struct EntryLess {
    bool operator()(const Entry &a, const Entry &b) const { return a.r2 < b.r2 || (a.r2 == b.r2 && a.stamp > b.stamp); }
};

struct Engine {
    PDT T{PDT::Iso_cuboid(0, 0, 0, 1, 1, 1)};
    std::vector<Vertex_handle> vh;
    std::vector<double> p;
    std::vector<Entry> heap;
    uint64_t next_stamp = 1;
    int64_t n = 0;
};

void circumsphere(const PDT &T, Cell_handle c, CellInfo &I)
{
    const Point p0 = T.point(c, 0), p1 = T.point(c, 1), p2 = T.point(c, 2), p3 = T.point(c, 3);
    const double a[3] = {p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z()};
    const double b[3] = {p2.x() - p0.x(), p2.y() - p0.y(), p2.z() - p0.z()};
    const double d[3] = {p3.x() - p0.x(), p3.y() - p0.y(), p3.z() - p0.z()};
    const double a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2],
                 d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    /* u = (a2 (b x d) + b2 (d x a) + d2 (a x b)) / (2 a.(b x d)) */
    const double bxd[3] = {b[1] * d[2] - b[2] * d[1], b[2] * d[0] - b[0] * d[2], b[0] * d[1] - b[1] * d[0]};
    const double dxa[3] = {d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2], d[0] * a[1] - d[1] * a[0]};
    const double axb[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double den = 2.0 * (a[0] * bxd[0] + a[1] * bxd[1] + a[2] * bxd[2]);
    double u[3];
    for (int k = 0; k < 3; k++) u[k] = (a2 * bxd[k] + b2 * dxa[k] + d2 * axb[k]) / den;
    I.c[0] = p0.x() + u[0], I.c[1] = p0.y() + u[1], I.c[2] = p0.z() + u[2];
    I.r2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    if (!std::isfinite(I.r2)) I.r2 = 0; /* a flat cell: never a candidate */
}

void register_cell(Engine &E, Cell_handle c)
{
    CellInfo &I = c->info();
    I.stamp = E.next_stamp++;
    circumsphere(E.T, c, I);
    E.heap.push_back(Entry{I.r2, I.stamp, c});
    std::push_heap(E.heap.begin(), E.heap.end(), EntryLess());
}

bool alive(const Engine &E, const Entry &e)
{
    return E.T.tds().cells().is_used(e.c) && e.c->info().stamp == e.stamp;
}

/* The live cell of largest circumsphere (dead entries popped). */
Cell_handle heap_top(Engine &E)
{
    while (!E.heap.empty() && !alive(E, E.heap.front())) {
        std::pop_heap(E.heap.begin(), E.heap.end(), EntryLess());
        E.heap.pop_back();
    }
    if (E.heap.size() > 8 * E.T.number_of_cells() + 1024) { /* compaction */
        std::vector<Entry> h;
        for (const Entry &e : E.heap)
            if (alive(E, e)) h.push_back(e);
        std::make_heap(h.begin(), h.end(), EntryLess());
        E.heap.swap(h);
    }
    return E.heap.front().c;
}

void register_around(Engine &E, Vertex_handle v)
{
    std::vector<Cell_handle> cells;
    E.T.incident_cells(v, std::back_inserter(cells));
    for (Cell_handle c : cells)
        if (c->info().stamp == 0) register_cell(E, c);
}

/* Every cell registered anew (the heap rebuilt): after CGAL changed its
 * covering, the cells a removal or insertion made need not be incident to
 * the vertices register_around visits. */
void register_all(Engine &E)
{
    E.heap.clear();
    for (auto c = E.T.cells_begin(); c != E.T.cells_end(); ++c) register_cell(E, c);
}

double wrap01(double x)
{
    x -= std::floor(x);
    return x >= 1.0 ? 0.0 : x;
}

double pd2(const double *a, const double *b)
{
    const double dx = cfpo3_pdiff(a[0], b[0]), dy = cfpo3_pdiff(a[1], b[1]), dz = cfpo3_pdiff(a[2], b[2]);
    return dx * dx + dy * dy + dz * dz;
}

/* One point's step: 1 when it moved. */
int step(Engine &E, uint32_t id, double tolL)
{
    Vertex_handle v = E.vh[id];
    std::vector<Vertex_handle> nb;
    E.T.adjacent_vertices(v, std::back_inserter(nb));
    double q0 = INFINITY;
    for (Vertex_handle w : nb) /* a virtual copy (27-sheeted covering) carries no info: its original's */
        q0 = std::min(q0, pd2(&E.p[3 * id], &E.p[3 * E.T.get_original_vertex(w)->info()]));
    const double d0 = std::sqrt(q0);
    E.T.remove(v);
    if (!E.T.is_1_cover()) register_all(E); /* CGAL went to its 27-sheeted covering: small n */
    else
        for (Vertex_handle w : nb) register_around(E, w);
    const Cell_handle best = heap_top(E);
    const CellInfo &I = best->info();
    double x[3] = {E.p[3 * id], E.p[3 * id + 1], E.p[3 * id + 2]};
    int moved = 0;
    if (std::sqrt(I.r2) > d0 + tolL) {
        for (int k = 0; k < 3; k++) x[k] = wrap01(I.c[k]);
        moved = 1;
    }
    Vertex_handle nv = E.T.insert(Point(x[0], x[1], x[2]), moved ? best : Cell_handle());
    nv->info() = id;
    E.vh[id] = nv;
    for (int k = 0; k < 3; k++) E.p[3 * id + k] = x[k];
    if (!E.T.is_1_cover()) register_all(E);
    else register_around(E, nv);
    return moved;
}

} // namespace

static int run_fpo3(int64_t n, uint64_t seed, const double *opt, bl3_iter_fn cb, void *user, double **xyz,
                    int64_t *n_out, bl3_info *info, char *err, size_t errlen)
{
    const double tol = opt[0];
    cfpo3_grid G;
    if (cfpo3_grid_choose(n, &G, err, errlen) != 0) return -1;
    Engine *E = new Engine;
    E->n = n;
    E->p.resize(3 * (size_t)n);
    for (size_t i = 0; i < 3 * (size_t)n; i++) E->p[i] = cfpo_rand01(seed, START3_STREAM, (uint64_t)i);
    E->vh.assign((size_t)n, Vertex_handle());
    Cell_handle hint;
    for (int64_t i = 0; i < n; i++) {
        Vertex_handle v = E->T.insert(Point(E->p[3 * i], E->p[3 * i + 1], E->p[3 * i + 2]), hint);
        v->info() = (uint32_t)i;
        E->vh[(size_t)i] = v;
        hint = v->cell();
    }
    if ((int64_t)E->T.number_of_vertices() != n) {
        std::snprintf(err, errlen, "the start has duplicate points");
        delete E;
        return -1;
    }
    register_all(*E);
    cfpo_iter_stats s = {};
    std::vector<double> before(3 * (size_t)n);
    auto stats = [&](int it) -> int {
        s.iteration = it;
        if (cfpo3_nn_stats(E->p.data(), (size_t)n, NULL, &s.delta_min, &s.delta_avg) != 0) return -1;
        return cb(user, &s);
    };
    int why = stats(0);
    int it = 0;
    while (why == CFPO_STOP_NONE) {
        before = E->p;
        s.moved = 0;
        for (int64_t i = 0; i < n; i++) s.moved += step(*E, (uint32_t)i, tol * G.L);
        double md = 0;
        for (int64_t i = 0; i < n; i++) md = std::max(md, pd2(&before[3 * i], &E->p[3 * i]));
        s.max_disp = std::sqrt(md) / G.L;
        s.converged = cfpo_net_converged(s.moved, s.max_disp, tol);
        s.solved = n;
        why = stats(++it);
        if (why < 0) break;
    }
    if (why < 0) {
        delete E;
        std::snprintf(err, errlen, "out of memory");
        return -1;
    }
    info->iterations = it;
    info->converged = s.converged;
    info->stop = cfpo_stop_name(why);
    *xyz = (double *)std::malloc(3 * (size_t)n * sizeof(double));
    if (!*xyz) {
        delete E;
        std::snprintf(err, errlen, "out of memory");
        return -1;
    }
    std::copy(E->p.begin(), E->p.end(), *xyz);
    *n_out = n;
    delete E;
    return 0;
}

extern "C" const bl3_method bl3_fpo;
const bl3_method bl3_fpo = {
    "fpo3d",
    "cfpo3d-fpo",
    "Farthest Point Optimization (Schloemer, Heck and Deussen 2011) on the unit\n"
    "3-torus, on CGAL's periodic 3-D Delaunay triangulation: each point in turn is\n"
    "moved to the centre of the largest empty sphere of the others (the largest\n"
    "circumsphere of a Delaunay cell) when that gains more than tol * L. Iterative.",
    1,
    1,
    {{"tol", CFPO_DEFAULT_TOL, 0, CFPO_TOL_MAX,
      "      --tol T          a move must gain more than T * L, L = cfpo3d's cell side;\n"
      "                       converged when no point's net move over an iteration\n"
      "                       reaches it (default %g)\n"}},
    run_fpo3,
    39,
};
