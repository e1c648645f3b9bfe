/* ccdt.cpp - see ccdt.h. CCDT on CGAL's Periodic_2_Delaunay_triangulation_2
 * (the typedef block of cgal_types.h; the face info is not used here).
 *
 * The step for point x (vertex v), with a = 1/(2n) the mean area:
 *   1. For each incident triangle (v, p, q) (counter-clockwise), its area
 *      as a function of v's displacement u is A0 + g.u with
 *      g = ((p - q).y, -(p - q).x) / 2. Minimise sum (A0 + g.u - a)^2:
 *      (sum g g^T) u = -sum g (A0 - a). No move if the system is singular
 *      or |u| <= tol * L.
 *   2. S = v, its neighbours and theirs (the 2-ring). before = sum of the
 *      squared areas of the triangles incident to S. Remove v, insert
 *      x + u. If a new neighbour falls outside S, put the point back, add
 *      the new neighbours to S and start 2 again.
 *   3. after = the same sum; keep the move when after < before (the energy
 *      of the triangulation dropped by before - after), else put the point
 *      back. A Delaunay triangulation is unique (CGAL breaks ties
 *      symbolically), so putting back restores the triangulation.
 * Outside CGAL's 1-sheeted cover (a handful of points only) the sums run
 * over every triangle. */
#include "cgal_types.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <vector>

#include "ccdt.h"
extern "C" {
#include "cli.h"
#include "geom.h"
#include "grid.h"
#include "rng.h"
#include "stats.h"
#include "stoprule.h"
}

using namespace bl;

namespace {
const uint64_t START_STREAM = 0x4343445453545254ULL; /* "CCDTSTRT" */
}

struct ccdt_engine {
    int64_t n = 0;
    double L = 0, tol = 0, mean = 0;
    PDT T;
    std::vector<Vertex_handle> vh; /* by id */
    std::vector<double> xy, start;
    std::vector<uint32_t> vmark;   /* by id: == stamp when in S */
    uint32_t stamp = 0;
    std::vector<uint32_t> S;
    std::vector<Face_handle> faces;
    double energy = 0;
    int64_t rejected = 0;
};

static double area(const PDT &T, Face_handle f)
{
    const Point p0 = T.point(f, 0), p1 = T.point(f, 1), p2 = T.point(f, 2);
    return 0.5 * ((p1.x() - p0.x()) * (p2.y() - p0.y()) - (p1.y() - p0.y()) * (p2.x() - p0.x()));
}

static double energy_all(const PDT &T)
{
    double e = 0;
    for (auto it = T.periodic_triangles_begin(PDT::UNIQUE); it != T.periodic_triangles_end(PDT::UNIQUE); ++it) {
        const auto t = T.triangle(*it);
        const double a = CGAL::to_double(t.area());
        e += a * a;
    }
    return e;
}

static void add_to_S(ccdt_engine *E, uint32_t id)
{
    if (E->vmark[id] == E->stamp) return;
    E->vmark[id] = E->stamp;
    E->S.push_back(id);
}

/* Sum of the squared areas of the faces incident to S (each once). */
static double energy_S(ccdt_engine *E)
{
    if (!E->T.is_1_cover()) return energy_all(E->T);
    E->faces.clear();
    for (uint32_t id : E->S) {
        auto fc = E->T.incident_faces(E->vh[id]), done = fc;
        do {
            E->faces.push_back(fc);
        } while (++fc != done);
    }
    std::sort(E->faces.begin(), E->faces.end());
    E->faces.erase(std::unique(E->faces.begin(), E->faces.end()), E->faces.end());
    double e = 0;
    for (Face_handle f : E->faces) {
        const double a = area(E->T, f);
        e += a * a;
    }
    return e;
}

/* Moves point id to (x, y) in the triangulation (remove, insert). */
static void place(ccdt_engine *E, uint32_t id, double x, double y)
{
    Vertex_handle v = E->vh[id];
    Face_handle hint;
    {
        auto vc = E->T.adjacent_vertices(v);
        Vertex_handle u = vc;
        hint = u->face();
    }
    E->T.remove(v);
    if (!E->T.tds().faces().is_used(hint)) hint = Face_handle();
    Vertex_handle w = E->T.insert(Point(x, y), hint);
    w->info() = id;
    E->vh[id] = w;
}

/* New neighbours of id outside S: added to S; returns how many. */
static int grow_S(ccdt_engine *E, uint32_t id)
{
    int added = 0;
    auto vc = E->T.adjacent_vertices(E->vh[id]), done = vc;
    do {
        Vertex_handle u = vc;
        if (E->vmark[u->info()] != E->stamp) {
            add_to_S(E, u->info());
            added++;
        }
    } while (++vc != done);
    return added;
}

/* The least-squares displacement of id; 0 when singular. */
static int optimum(const ccdt_engine *E, uint32_t id, double *ux, double *uy)
{
    Vertex_handle v = E->vh[id];
    double m00 = 0, m01 = 0, m11 = 0, b0 = 0, b1 = 0;
    auto fc = E->T.incident_faces(v), done = fc;
    do {
        Face_handle f = fc;
        const int i = f->index(v);
        const Point pv = E->T.point(f, i), p = E->T.point(f, PDT::ccw(i)), q = E->T.point(f, PDT::cw(i));
        const double a0 = 0.5 * ((p.x() - pv.x()) * (q.y() - pv.y()) - (p.y() - pv.y()) * (q.x() - pv.x()));
        const double gx = 0.5 * (p.y() - q.y()), gy = -0.5 * (p.x() - q.x());
        m00 += gx * gx;
        m01 += gx * gy;
        m11 += gy * gy;
        b0 -= gx * (a0 - E->mean);
        b1 -= gy * (a0 - E->mean);
    } while (++fc != done);
    const double det = m00 * m11 - m01 * m01;
    if (!(det > 1e-12 * (m00 * m11 + 1e-300))) return 0;
    *ux = (m11 * b0 - m01 * b1) / det;
    *uy = (m00 * b1 - m01 * b0) / det;
    return 1;
}

/* Tries moving id by (ux, uy); keeps the move when the energy drops.
 * Returns 1 when kept, 0 when undone, -1 when nothing was tried. */
static int try_move(ccdt_engine *E, uint32_t id, double ux, double uy)
{
    const double x = E->xy[2 * id], y = E->xy[2 * id + 1];
    const double nx = cfpo_wrap01(x + ux), ny = cfpo_wrap01(y + uy);
    if (nx == x && ny == y) return -1;
    E->stamp++;
    E->S.clear();
    add_to_S(E, id);
    {
        std::vector<uint32_t> ring;
        auto vc = E->T.adjacent_vertices(E->vh[id]), done = vc;
        do {
            Vertex_handle u = vc;
            ring.push_back(u->info());
        } while (++vc != done);
        for (uint32_t r : ring) {
            add_to_S(E, r);
            auto wc = E->T.adjacent_vertices(E->vh[r]), wdone = wc;
            do {
                Vertex_handle u = wc;
                add_to_S(E, u->info());
            } while (++wc != wdone);
        }
    }
    const int64_t nv = (int64_t)E->T.number_of_vertices();
    double before, after;
    for (;;) {
        before = energy_S(E);
        place(E, id, nx, ny);
        if ((int64_t)E->T.number_of_vertices() != nv) { /* landed on a point: undo */
            E->vh[id] = E->T.insert(Point(x, y));
            E->vh[id]->info() = id;
            return -1;
        }
        if (!E->T.is_1_cover() || grow_S(E, id) == 0) break;
        place(E, id, x, y);
    }
    after = energy_S(E);
    if (after < before) {
        E->energy += after - before;
        E->xy[2 * id] = nx;
        E->xy[2 * id + 1] = ny;
        return 1;
    }
    place(E, id, x, y);
    return 0;
}

/* The step for one point; returns 1 when it moved. */
static int step(ccdt_engine *E, uint32_t id, double tolL)
{
    double ux, uy;
    if (!optimum(E, id, &ux, &uy) || ux * ux + uy * uy <= tolL * tolL) return 0;
    int r = try_move(E, id, ux, uy);
    if (r == 0) E->rejected++;
    return r == 1;
}

static int build(ccdt_engine *E, char *err, size_t errlen)
{
    const int64_t n = E->n;
    if (build_indexed(E->T, E->xy, n, E->vh, err, errlen) != 0) return -1;
    E->vmark.assign((size_t)n, 0);
    E->mean = 0.5 / (double)n;
    E->energy = energy_all(E->T);
    return 0;
}

static ccdt_engine *make(int64_t n, const double *xy, uint64_t seed, double L, double tol, char *err,
                         size_t errlen)
{
    ccdt_engine *E = new (std::nothrow) ccdt_engine;
    if (!E) {
        snprintf(err, errlen, "out of memory");
        return nullptr;
    }
    try {
        E->n = n;
        E->L = L;
        E->tol = tol;
        E->xy.resize(2 * (size_t)n);
        for (int64_t i = 0; i < 2 * n; i++)
            E->xy[(size_t)i] = xy ? xy[i] : cfpo_rand01(seed, START_STREAM, (uint64_t)i);
        if (build(E, err, errlen) != 0) {
            delete E;
            return nullptr;
        }
    } catch (const std::bad_alloc &) {
        snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
        delete E;
        return nullptr;
    }
    return E;
}

extern "C" {

ccdt_engine *ccdt_create(int64_t n, uint64_t seed, double tol, char *err, size_t errlen)
{
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return nullptr;
    }
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, seed, err, errlen) != 0) return nullptr;
    return make(n, nullptr, seed, G.L, tol, err, errlen);
}

ccdt_engine *ccdt_create_from(int64_t n, const double *xy, double L, double tol, char *err, size_t errlen)
{
    return make(n, xy, 0, L, tol, err, errlen);
}

void ccdt_free(ccdt_engine *E) { delete E; }

void ccdt_iterate(ccdt_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const double tolL = E->tol * E->L;
    E->start = E->xy;
    E->rejected = 0;
    int64_t moved = 0;
    for (int64_t id = 0; id < E->n; id++) moved += step(E, (uint32_t)id, tolL);
    double maxd2 = 0;
    for (int64_t i = 0; i < E->n; i++)
        maxd2 = std::max(maxd2, cfpo_torus_dist2(E->start[2 * i], E->start[2 * i + 1], E->xy[2 * i],
                                                 E->xy[2 * i + 1]));
    s->moved = moved;
    s->solved = E->n;
    s->max_disp = std::sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = cfpo_net_converged(moved, s->max_disp, E->tol);
    ccdt_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

int64_t ccdt_rejected(const ccdt_engine *E) { return E->rejected; }
double ccdt_energy(const ccdt_engine *E) { return E->energy; }
double ccdt_energy_recomputed(const ccdt_engine *E) { return energy_all(E->T); }

double ccdt_area_cv(const ccdt_engine *E)
{
    const double var = E->energy / (2.0 * (double)E->n) - E->mean * E->mean;
    return std::sqrt(std::max(var, 0.0)) / E->mean;
}

double ccdt_area_maxdev(const ccdt_engine *E)
{
    double m = 0;
    for (auto it = E->T.periodic_triangles_begin(PDT::UNIQUE); it != E->T.periodic_triangles_end(PDT::UNIQUE); ++it)
        m = std::max(m, std::fabs(CGAL::to_double(E->T.triangle(*it).area()) - E->mean));
    return m / E->mean;
}

void ccdt_deltas(ccdt_engine *E, double *dmin, double *davg)
{
    if (cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg) != 0) *dmin = *davg = NAN;
}

const double *ccdt_points(const ccdt_engine *E) { return E->xy.data(); }

int ccdt_check(const ccdt_engine *E)
{
    if (!E->T.is_valid()) return 0;
    if ((int64_t)E->T.number_of_vertices() != E->n) return 0;
    for (int64_t i = 0; i < E->n; i++) {
        const Point &p = E->vh[(size_t)i]->point();
        if (E->vh[(size_t)i]->info() != (uint32_t)i || p.x() != E->xy[2 * i] || p.y() != E->xy[2 * i + 1])
            return 0;
    }
    int64_t nt = 0;
    for (auto it = E->T.periodic_triangles_begin(PDT::UNIQUE); it != E->T.periodic_triangles_end(PDT::UNIQUE); ++it) nt++;
    return nt == 2 * E->n;
}

} // extern "C"
