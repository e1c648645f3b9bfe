/* ccdt.cpp - see ccdt.h. CCDT on CGAL's Periodic_2_Delaunay_triangulation_2
 * (the typedef block of cgal_types.h; the face info is not used here).
 *
 * The connectivity of the geometry phase is a copy of the last Delaunay
 * triangulation in flat arrays: per triangle its three vertex ids
 * counter-clockwise and each corner's lattice offset (a corner's position
 * is xy[id] + offset; xy is not wrapped during the phase), stored in a
 * canonical order (smallest id first, triangles sorted) so that nothing
 * depends on the order in which CGAL stores its faces; and per vertex the
 * list of its corners (CSR).
 *
 * The update of vertex v, with a = 1/(2n) the mean area: each incident
 * triangle (v, p, q) has the area A0 + g.u after v moves by u, with
 * g = ((p - q).y, (q - p).x) / 2. Minimise sum (A0 + g.u - a)^2:
 * (sum g g^T) u = -sum g (A0 - a). Along the segment s u, s in [0, 1], the
 * sum is a convex quadratic that is smallest at s = 1, so every s <= 1
 * lowers it; s = min(1, 0.9 s0) where s0 is where the first incident area
 * would reach 0 (the binding triangle keeps a tenth of its area). */
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
const int MAX_SWEEPS = 8;                             /* geometry sweeps per iteration */
const double KEEP = 0.9;                              /* fraction of the step to the first zero area */
const double SHRINK = 0.5, GROW = 1.25;               /* the step after the energy rose / fell */

struct Conn {
    std::vector<uint32_t> tri;     /* 3 ids per triangle, counter-clockwise */
    std::vector<int8_t> off;       /* 6 per triangle: x and y offset of each corner */
    std::vector<uint32_t> first;   /* n + 1: CSR of corners by vertex */
    std::vector<uint32_t> corner;  /* 3 * triangles: t * 3 + k */
};
} // namespace

struct ccdt_engine {
    int64_t n = 0;
    double L = 0, tol = 0, mean = 0;
    PDT T;
    std::vector<Vertex_handle> vh; /* by id */
    std::vector<double> xy, start;
    std::vector<int8_t> shift;     /* by id: x, y lattice shift of the last wrap */
    Conn C, old;
    double lambda = 1, step = 0;
    bool in_sync = false;          /* C is T's triangulation of xy (wrapped) */
    int sweeps = 0;
    int64_t new_edges = 0;
    int ref_iters = 0, done_iters = 0; /* the reference schedule: ref_iters > 0 */
};

static inline double tri_area(const ccdt_engine *E, size_t t)
{
    const uint32_t *id = &E->C.tri[3 * t];
    const int8_t *o = &E->C.off[6 * t];
    const double *X = E->xy.data();
    const double x0 = X[2 * id[0]] + o[0], y0 = X[2 * id[0] + 1] + o[1];
    const double x1 = X[2 * id[1]] + o[2], y1 = X[2 * id[1] + 1] + o[3];
    const double x2 = X[2 * id[2]] + o[4], y2 = X[2 * id[2] + 1] + o[5];
    return 0.5 * ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0));
}

/* Copies T's triangulation into E->C (canonical order, CSR). */
static void extract(ccdt_engine *E)
{
    struct Tri {
        uint32_t id[3];
        int8_t off[6];
    };
    std::vector<Tri> ts;
    ts.reserve(2 * (size_t)E->n);
    for (auto it = E->T.periodic_triangles_begin(PDT::UNIQUE); it != E->T.periodic_triangles_end(PDT::UNIQUE); ++it) {
        Face_handle f = it.get_face();
        Tri t;
        for (int k = 0; k < 3; k++) {
            const uint32_t id = E->T.get_original_vertex(f->vertex(k))->info();
            const Point p = E->T.point(f, k);
            t.id[k] = id;
            t.off[2 * k] = (int8_t)std::lround(p.x() - E->xy[2 * id]);
            t.off[2 * k + 1] = (int8_t)std::lround(p.y() - E->xy[2 * id + 1]);
        }
        int m = 0; /* rotate: smallest id first, its offset (0, 0) */
        for (int k = 1; k < 3; k++)
            if (t.id[k] < t.id[m]) m = k;
        Tri r;
        for (int k = 0; k < 3; k++) {
            const int j = (m + k) % 3;
            r.id[k] = t.id[j];
            r.off[2 * k] = (int8_t)(t.off[2 * j] - t.off[2 * m]);
            r.off[2 * k + 1] = (int8_t)(t.off[2 * j + 1] - t.off[2 * m + 1]);
        }
        ts.push_back(r);
    }
    std::sort(ts.begin(), ts.end(), [](const Tri &a, const Tri &b) {
        for (int k = 0; k < 3; k++)
            if (a.id[k] != b.id[k]) return a.id[k] < b.id[k];
        return std::lexicographical_compare(a.off, a.off + 6, b.off, b.off + 6);
    });
    Conn &C = E->C;
    const size_t nt = ts.size(), n = (size_t)E->n;
    C.tri.resize(3 * nt);
    C.off.resize(6 * nt);
    for (size_t t = 0; t < nt; t++) {
        std::memcpy(&C.tri[3 * t], ts[t].id, sizeof ts[t].id);
        std::memcpy(&C.off[6 * t], ts[t].off, sizeof ts[t].off);
    }
    C.first.assign(n + 1, 0);
    for (uint32_t id : C.tri) C.first[id + 1]++;
    for (size_t i = 0; i < n; i++) C.first[i + 1] += C.first[i];
    C.corner.resize(3 * nt);
    std::vector<uint32_t> fill(C.first.begin(), C.first.end() - 1);
    for (size_t c = 0; c < 3 * nt; c++) C.corner[fill[C.tri[c]]++] = (uint32_t)c;
}

/* Half-edges of C (a -> b, offset of b relative to a) that O lacks, / 2;
 * O's offsets move by the shifts sh of the wrap. */
static int64_t count_new_edges(const Conn &C, const Conn &O, const std::vector<int8_t> &sh)
{
    int64_t h = 0;
    const size_t nc = C.tri.size();
    for (size_t c = 0; c < nc; c++) {
        const size_t t = c / 3, k = c % 3, j = 3 * t + (k + 1) % 3;
        const uint32_t a = C.tri[c], b = C.tri[j];
        const int dx = C.off[2 * j] - C.off[2 * c] + sh[2 * a] - sh[2 * b];
        const int dy = C.off[2 * j + 1] - C.off[2 * c + 1] + sh[2 * a + 1] - sh[2 * b + 1];
        bool found = false;
        for (uint32_t e = O.first[a]; e < O.first[a + 1] && !found; e++) {
            const size_t oc = O.corner[e], ot = oc / 3, oj = 3 * ot + (oc % 3 + 1) % 3;
            found = O.tri[oj] == b && O.off[2 * oj] - O.off[2 * oc] == dx && O.off[2 * oj + 1] - O.off[2 * oc + 1] == dy;
        }
        h += !found;
    }
    return h / 2;
}

/* The Delaunay phase: wrap the points, re-triangulate, copy the new
 * connectivity; counts the edges not in the previous connectivity (moved to
 * E->old when keep is 0; kept there when 1, for a retry). */
static int delaunay(ccdt_engine *E, int keep, char *err, size_t errlen)
{
    const int64_t n = E->n;
    if (!keep) std::swap(E->C, E->old);
    E->shift.resize(2 * (size_t)n);
    for (size_t i = 0; i < 2 * (size_t)n; i++) {
        const double w = cfpo_wrap01(E->xy[i]);
        E->shift[i] = (int8_t)std::lround(E->xy[i] - w);
        E->xy[i] = w;
    }
    E->T.clear();
    if (build_indexed(E->T, E->xy, n, E->vh, err, errlen) != 0) return -1;
    extract(E);
    E->new_edges = E->old.tri.empty() ? 0 : count_new_edges(E->C, E->old, E->shift);
    E->in_sync = true;
    return 0;
}

/* One Gauss-Seidel sweep over the vertices in id order; returns the
 * largest move. */
static double sweep(ccdt_engine *E, bool full)
{
    const Conn &C = E->C;
    double *X = E->xy.data();
    double maxd2 = 0;
    double A0[64], G[64][2];
    for (int64_t v = 0; v < E->n; v++) {
        double m00 = 0, m01 = 0, m11 = 0, b0 = 0, b1 = 0;
        int deg = 0;
        for (uint32_t e = C.first[v]; e < C.first[v + 1]; e++) {
            const size_t c = C.corner[e], t = c / 3, k = c % 3;
            const size_t cp = 3 * t + (k + 1) % 3, cq = 3 * t + (k + 2) % 3;
            const double ox = C.off[2 * c], oy = C.off[2 * c + 1];
            const double vx = X[2 * v], vy = X[2 * v + 1];
            const double px = X[2 * C.tri[cp]] + C.off[2 * cp] - ox, py = X[2 * C.tri[cp] + 1] + C.off[2 * cp + 1] - oy;
            const double qx = X[2 * C.tri[cq]] + C.off[2 * cq] - ox, qy = X[2 * C.tri[cq] + 1] + C.off[2 * cq + 1] - oy;
            const double a0 = 0.5 * ((px - vx) * (qy - vy) - (py - vy) * (qx - vx));
            const double gx = 0.5 * (py - qy), gy = 0.5 * (qx - px);
            m00 += gx * gx;
            m01 += gx * gy;
            m11 += gy * gy;
            b0 -= gx * (a0 - E->mean);
            b1 -= gy * (a0 - E->mean);
            if (deg < 64) {
                A0[deg] = a0;
                G[deg][0] = gx;
                G[deg][1] = gy;
            }
            deg++;
        }
        const double det = m00 * m11 - m01 * m01;
        if (deg > 64 || !(det > 1e-12 * (m00 * m11 + 1e-300))) continue;
        const double ux = (m11 * b0 - m01 * b1) / det, uy = (m00 * b1 - m01 * b0) / det;
        double s = 1;
        for (int i = 0; i < deg && !full; i++) { /* area A0 + s d: first zero at s = A0 / -d */
            const double d = G[i][0] * ux + G[i][1] * uy;
            if (d < 0) s = std::min(s, KEEP * A0[i] / -d);
        }
        if (!(s > 0)) continue;
        X[2 * v] += s * ux;
        X[2 * v + 1] += s * uy;
        maxd2 = std::max(maxd2, s * s * (ux * ux + uy * uy));
    }
    E->in_sync = false;
    return std::sqrt(maxd2);
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
        E->mean = 0.5 / (double)n;
        E->xy.resize(2 * (size_t)n);
        for (int64_t i = 0; i < 2 * n; i++)
            E->xy[(size_t)i] = xy ? xy[i] : cfpo_rand01(seed, START_STREAM, (uint64_t)i);
        if (delaunay(E, 0, err, errlen) != 0) {
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
    if (n > CCDT_MAX_N) {
        snprintf(err, errlen, "n = %lld is too large (at most %lld: 32-bit corner ids)", (long long)n,
                 (long long)CCDT_MAX_N);
        return nullptr;
    }
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_PAPER, seed, err, errlen) != 0) return nullptr;
    return make(n, nullptr, seed, G.L, tol, err, errlen);
}

ccdt_engine *ccdt_create_from(int64_t n, const double *xy, double L, double tol, char *err, size_t errlen)
{
    if (n > CCDT_MAX_N) {
        snprintf(err, errlen, "n = %lld is too large", (long long)n);
        return nullptr;
    }
    return make(n, xy, 0, L, tol, err, errlen);
}

void ccdt_free(ccdt_engine *E) { delete E; }

double ccdt_sweep(ccdt_engine *E) { return sweep(E, false) / E->L; }

int64_t ccdt_delaunay(ccdt_engine *E)
{
    char err[256];
    if (delaunay(E, 0, err, sizeof err) != 0) return -1;
    return E->new_edges;
}

void ccdt_iterate(ccdt_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const double tolL = E->tol * E->L;
    const int64_t n = E->n;
    E->start = E->xy;
    const double e0 = ccdt_energy(E);
    E->sweeps = 0;
    const bool ref = E->ref_iters > 0;
    while (E->sweeps < (ref ? 1 : MAX_SWEEPS)) {
        E->sweeps++;
        if (sweep(E, ref) < tolL) break;
    }
    char err[256];
    const double lam = ref ? 1.0 : E->lambda; /* the step: lam of the way to the phase's result */
    if (lam < 1)
        for (size_t i = 0; i < 2 * (size_t)n; i++) E->xy[i] = E->start[i] + lam * (E->xy[i] - E->start[i]);
    E->step = lam;
    if (delaunay(E, 0, err, sizeof err) != 0) { /* points met (the step rule prevents it): stay */
        E->xy = E->start;
        delaunay(E, 1, err, sizeof err);
        E->step = 0;
    }
    if (!ref) E->lambda = ccdt_energy(E) > e0 ? SHRINK * lam : std::min(1.0, GROW * lam);
    E->done_iters++;
    int64_t moved = 0;
    double maxd2 = 0;
    for (int64_t i = 0; i < n; i++) {
        const double d2 = cfpo_torus_dist2(E->start[2 * i], E->start[2 * i + 1], E->xy[2 * i], E->xy[2 * i + 1]);
        maxd2 = std::max(maxd2, d2);
        moved += d2 > tolL * tolL;
    }
    s->moved = moved;
    s->solved = n * E->sweeps;
    s->max_disp = std::sqrt(maxd2) / E->L;
    s->max_move = s->max_disp;
    s->converged = ref ? E->done_iters >= E->ref_iters : cfpo_net_converged(moved, s->max_disp, E->tol);
    ccdt_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

double ccdt_step(const ccdt_engine *E) { return E->step; }
void ccdt_set_reference(ccdt_engine *E, int iterations) { E->ref_iters = iterations > 0 ? iterations : 0; }
int ccdt_sweeps(const ccdt_engine *E) { return E->sweeps; }
int64_t ccdt_new_edges(const ccdt_engine *E) { return E->new_edges; }

double ccdt_energy(const ccdt_engine *E)
{
    double e = 0;
    const size_t nt = E->C.tri.size() / 3;
    for (size_t t = 0; t < nt; t++) {
        const double a = tri_area(E, t);
        e += a * a;
    }
    return e;
}

double ccdt_energy_recomputed(const ccdt_engine *E)
{
    double e = 0;
    for (auto it = E->T.periodic_triangles_begin(PDT::UNIQUE); it != E->T.periodic_triangles_end(PDT::UNIQUE); ++it) {
        const double a = CGAL::to_double(E->T.triangle(*it).area());
        e += a * a;
    }
    return e;
}

double ccdt_area_cv(const ccdt_engine *E)
{
    const double var = ccdt_energy(E) / (double)(E->C.tri.size() / 3) - E->mean * E->mean;
    return std::sqrt(std::max(var, 0.0)) / E->mean;
}

double ccdt_area_maxdev(const ccdt_engine *E)
{
    double m = 0;
    const size_t nt = E->C.tri.size() / 3;
    for (size_t t = 0; t < nt; t++) m = std::max(m, std::fabs(tri_area(E, t) - E->mean));
    return m / E->mean;
}

double ccdt_area_min(const ccdt_engine *E)
{
    double m = INFINITY;
    const size_t nt = E->C.tri.size() / 3;
    for (size_t t = 0; t < nt; t++) m = std::min(m, tri_area(E, t));
    return m / E->mean;
}

double ccdt_area_sum(const ccdt_engine *E)
{
    double a = 0;
    const size_t nt = E->C.tri.size() / 3;
    for (size_t t = 0; t < nt; t++) a += tri_area(E, t);
    return a;
}

void ccdt_deltas(ccdt_engine *E, double *dmin, double *davg)
{
    if (cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg) != 0) *dmin = *davg = NAN;
}

const double *ccdt_points(const ccdt_engine *E) { return E->xy.data(); }

int ccdt_check(const ccdt_engine *E)
{
    if (!E->in_sync || !E->T.is_valid()) return 0;
    if ((int64_t)E->T.number_of_vertices() != E->n) return 0;
    for (int64_t i = 0; i < E->n; i++) {
        const Point &p = E->vh[(size_t)i]->point();
        if (E->vh[(size_t)i]->info() != (uint32_t)i || p.x() != E->xy[2 * i] || p.y() != E->xy[2 * i + 1])
            return 0;
    }
    int64_t nt = 0;
    for (auto it = E->T.periodic_triangles_begin(PDT::UNIQUE); it != E->T.periodic_triangles_end(PDT::UNIQUE); ++it) nt++;
    if (nt != 2 * E->n || (int64_t)E->C.tri.size() != 3 * nt) return 0;
    /* the copy: every vertex in 6 corners on average, every area positive */
    for (int64_t i = 0; i < E->n; i++)
        if (E->C.first[i + 1] - E->C.first[i] < 3) return 0;
    return ccdt_area_min(E) > 0;
}

} // extern "C"
