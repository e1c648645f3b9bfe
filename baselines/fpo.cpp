/* fpo.cpp - see fpo.h. FPO and LFPO on CGAL's Periodic_2_Delaunay_triangulation_2.
 *
 * One step for point x (vertex v):
 *   1. d0 = distance from x to its nearest other point: the nearest
 *      neighbour is a Delaunay neighbour, so the minimum over v's 1-ring.
 *   2. Unregister v's star (stamp 0: those faces die or are reused by the
 *      removal), remove v, register the faces of the hole: the faces
 *      around v's former neighbours whose stamp is 0.
 *   3. Largest empty circle of X \ {x}: global FPO pops the priority queue
 *      (a max-heap of (r^2, stamp, face)); an entry is stale when its face
 *      is no longer alive in the triangulation's container or carries
 *      another stamp, and is dropped when it reaches the top (lazy
 *      invalidation). LFPO takes the largest circumcircle among the faces
 *      around v's former neighbours (the 2-ring of x), without the heap.
 *   4. If the circle's radius exceeds d0 + tol * L, insert x at its centre
 *      (the circle's face is the location hint); otherwise insert it back
 *      where it was. Every face around the new vertex is new: register it.
 * The heap is compacted when stale entries outnumber live ones 3 to 1.
 * If the triangulation leaves CGAL's 1-sheeted cover (possible only for
 * very few points), every face is re-registered after each change. */
#include "cgal_types.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>
#include <vector>

#include "fpo.h"
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

/* Random start: stream for the coordinates of point id (counter 2id, 2id+1). */
const uint64_t START_STREAM = 0x46504f5354415254ULL; /* "FPOSTART" */

struct Entry {
    double r2;
    uint64_t stamp;
    Face_handle f;
};
/* Max-heap on r^2; equal radii: the earlier registration first. */
struct EntryLess {
    bool operator()(const Entry &a, const Entry &b) const
    {
        return a.r2 < b.r2 || (a.r2 == b.r2 && a.stamp > b.stamp);
    }
};

} // namespace

struct fpo_engine {
    int64_t n = 0;
    fpo_options o{};
    cfpo_grid G{};
    PDT T;
    std::vector<Vertex_handle> vh; /* by id */
    std::vector<double> xy;        /* by id */
    std::vector<double> start;     /* positions at the start of the iteration */
    std::vector<Entry> heap;
    uint64_t next_stamp = 1;
    std::vector<Vertex_handle> ring;
    std::vector<double> nn;        /* scratch for statistics */
};

static bool alive(const fpo_engine *E, Face_handle f, uint64_t stamp)
{
    return E->T.tds().faces().is_used(f) && f->info().stamp == stamp;
}

static void register_face(fpo_engine *E, Face_handle f)
{
    FaceInfo &I = f->info();
    I.stamp = E->next_stamp++;
    circumcircle(E->T, f, &I.cx, &I.cy, &I.r2);
    if (!E->o.local) {
        E->heap.push_back(Entry{I.r2, I.stamp, f});
        std::push_heap(E->heap.begin(), E->heap.end(), EntryLess());
    }
}

static void register_all(fpo_engine *E)
{
    E->heap.clear();
    for (auto f = E->T.faces_begin(); f != E->T.faces_end(); ++f) {
        Face_handle fh = f;
        fh->info().stamp = 0;
        register_face(E, fh);
    }
}

/* Rebuilds the heap from the live faces when it is mostly stale. */
static void maybe_compact(fpo_engine *E)
{
    const size_t live = E->T.tds().number_of_faces();
    if (E->o.local || E->heap.size() < 4 * live + 1024) return;
    E->heap.clear();
    for (auto f = E->T.faces_begin(); f != E->T.faces_end(); ++f) {
        Face_handle fh = f;
        E->heap.push_back(Entry{fh->info().r2, fh->info().stamp, fh});
    }
    std::make_heap(E->heap.begin(), E->heap.end(), EntryLess());
}

/* The live face with the largest circumcircle (global FPO). */
static Face_handle heap_top(fpo_engine *E)
{
    while (!E->heap.empty()) {
        const Entry &e = E->heap.front();
        if (alive(E, e.f, e.stamp)) return e.f;
        std::pop_heap(E->heap.begin(), E->heap.end(), EntryLess());
        E->heap.pop_back();
    }
    return Face_handle(); /* unreachable: a triangulation has faces */
}

/* The largest circumcircle among the faces around the ring (LFPO). */
static Face_handle ring_best(fpo_engine *E)
{
    Face_handle best;
    double br2 = -1;
    for (Vertex_handle u : E->ring) {
        auto fc = E->T.incident_faces(u), done = fc;
        do {
            Face_handle f = fc;
            if (f->info().r2 > br2) {
                br2 = f->info().r2;
                best = f;
            }
        } while (++fc != done);
    }
    return best;
}

/* The largest circumcircle of all faces, by a scan (LFPO after a change
 * of CGAL's cover, when the ring's handles are gone). */
static Face_handle scan_best(fpo_engine *E)
{
    Face_handle best;
    double br2 = -1;
    for (auto f = E->T.faces_begin(); f != E->T.faces_end(); ++f)
        if (f->info().r2 > br2) {
            br2 = f->info().r2;
            best = f;
        }
    return best;
}

/* Registers the faces around the ring that are new since unregistering. */
static void register_hole(fpo_engine *E)
{
    for (Vertex_handle u : E->ring) {
        auto fc = E->T.incident_faces(u), done = fc;
        do {
            Face_handle f = fc;
            if (f->info().stamp == 0) register_face(E, f);
        } while (++fc != done);
    }
}

static Vertex_handle insert_point(fpo_engine *E, uint32_t id, double x, double y, Face_handle hint)
{
    const bool was1 = E->T.is_1_cover();
    Vertex_handle v = E->T.insert(Point(x, y), hint);
    v->info() = id;
    if (!was1 || !E->T.is_1_cover()) {
        register_all(E);
    } else {
        auto fc = E->T.incident_faces(v), done = fc;
        do {
            register_face(E, fc);
        } while (++fc != done);
    }
    return v;
}

/* The step for one point; returns 1 when it moved. */
static int step(fpo_engine *E, uint32_t id, double tolL)
{
    Vertex_handle v = E->vh[id];
    const double x = E->xy[2 * id], y = E->xy[2 * id + 1];
    E->ring.clear();
    double d02 = INFINITY;
    {
        auto vc = E->T.adjacent_vertices(v), done = vc;
        do {
            Vertex_handle u = vc;
            /* Once each (a 9-sheeted cover may repeat a neighbour), in
             * circulator order: nothing depends on addresses. */
            if (std::find(E->ring.begin(), E->ring.end(), u) == E->ring.end()) E->ring.push_back(u);
            const Point &p = u->point();
            d02 = std::min(d02, cfpo_torus_dist2(x, y, p.x(), p.y()));
        } while (++vc != done);
        auto fc = E->T.incident_faces(v), fdone = fc;
        do {
            Face_handle f = fc;
            f->info().stamp = 0;
        } while (++fc != fdone);
    }
    const bool was1 = E->T.is_1_cover();
    E->T.remove(v);
    if (!was1 || !E->T.is_1_cover()) {
        register_all(E);
        /* After a cover change the ring's handles may be gone. */
        E->ring.clear();
    } else {
        register_hole(E);
    }
    Face_handle best;
    if (!E->o.local) best = heap_top(E);
    else best = E->ring.empty() ? scan_best(E) : ring_best(E);
    const FaceInfo &I = best->info();
    const double thr = std::sqrt(d02) + tolL;
    int moved = 0;
    double nx = x, ny = y;
    Face_handle hint = E->ring.empty() ? Face_handle() : E->ring[0]->face();
    if (I.r2 > thr * thr) {
        nx = cfpo_wrap01(I.cx);
        ny = cfpo_wrap01(I.cy);
        hint = best;
        moved = 1;
    }
    E->vh[id] = insert_point(E, id, nx, ny, hint);
    E->xy[2 * id] = nx;
    E->xy[2 * id + 1] = ny;
    maybe_compact(E);
    return moved;
}

static void make_start(fpo_engine *E)
{
    const int64_t n = E->n;
    if (E->o.start == FPO_START_RANDOM) {
        for (int64_t i = 0; i < n; i++) {
            E->xy[2 * i] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i);
            E->xy[2 * i + 1] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i + 1);
        }
        return;
    }
    int64_t id = 0; /* cfpo's ids: cells row-major, a cell's points consecutive */
    for (int64_t cy = 0; cy < E->G.g; cy++)
        for (int64_t cx = 0; cx < E->G.g; cx++) {
            uint64_t cnt = cfpo_grid_cell_count(&E->G, (uint64_t)(cy * E->G.g + cx));
            for (uint64_t k = 0; k < cnt; k++, id++)
                cfpo_grid_cell_point(&E->G, cx, cy, k, &E->xy[2 * id], &E->xy[2 * id + 1]);
        }
}

static int build(fpo_engine *E, char *err, size_t errlen)
{
    if (build_indexed(E->T, E->xy, E->n, E->vh, err, errlen) != 0) return -1;
    register_all(E);
    return 0;
}

extern "C" {

void fpo_options_init(fpo_options *o)
{
    std::memset(o, 0, sizeof *o);
    o->seed = 1;
    o->local = 0;
    o->start = FPO_START_RANDOM;
    o->tol = CFPO_DEFAULT_TOL;
}

uint64_t fpo_bytes(int64_t n)
{
    return (uint64_t)n * 720 + ((uint64_t)8 << 20);
}

int fpo_validate(int64_t n, const fpo_options *o, char *err, size_t errlen)
{
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return -1;
    }
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_FULL, o->seed, err, errlen) != 0) return -1;
    const double need = (double)fpo_bytes(n), have = cli_physical_memory();
    if (need > 0.9 * have) {
        snprintf(err, errlen, "n = %lld is too large for memory: the triangulation needs about %.1f GB, "
                 "this machine has %.1f GB", (long long)n, need / 1e9, have / 1e9);
        return -2;
    }
    return 0;
}

fpo_engine *fpo_create(int64_t n, const fpo_options *o, char *err, size_t errlen)
{
    if (n >= (int64_t)UINT32_MAX) {
        snprintf(err, errlen, "n = %lld is too large (ids are 32-bit)", (long long)n);
        return nullptr;
    }
    cfpo_grid G;
    if (cfpo_grid_init(&G, n, CFPO_VARIANT_FULL, o->seed, err, errlen) != 0) return nullptr;
    fpo_engine *E = new (std::nothrow) fpo_engine;
    if (!E) {
        snprintf(err, errlen, "out of memory");
        return nullptr;
    }
    try {
        E->n = n;
        E->o = *o;
        E->G = G;
        E->xy.resize(2 * (size_t)n);
        E->start.resize(2 * (size_t)n);
        E->nn.resize((size_t)n);
        make_start(E);
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

void fpo_free(fpo_engine *E) { delete E; }

const double *fpo_points(const fpo_engine *E) { return E->xy.data(); }

double fpo_scale(const fpo_engine *E) { return E->G.L; }

void fpo_deltas(fpo_engine *E, double *dmin, double *davg)
{
    /* Out of memory: NaN statistics, as ccvt, ccdt and bnot (no exit: the
     * engine also runs inside the Python package). */
    if (cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg) != 0) *dmin = *davg = NAN;
}

void fpo_iterate(fpo_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const double tolL = E->o.tol * E->G.L;
    E->start = E->xy;
    int64_t moved = 0;
    for (int64_t id = 0; id < E->n; id++) moved += step(E, (uint32_t)id, tolL);
    double maxd2 = 0;
    for (int64_t i = 0; i < E->n; i++) {
        double d2 = cfpo_torus_dist2(E->start[2 * i], E->start[2 * i + 1], E->xy[2 * i],
                                     E->xy[2 * i + 1]);
        maxd2 = std::max(maxd2, d2);
    }
    s->moved = moved;
    s->solved = E->n;
    s->max_disp = std::sqrt(maxd2) / E->G.L;
    s->converged = cfpo_net_converged(moved, s->max_disp, E->o.tol);
    fpo_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = cli_now() - t0;
}

int fpo_check(const fpo_engine *E)
{
    if (!E->T.is_valid()) return 0;
    if ((int64_t)E->T.number_of_vertices() != E->n) return 0;
    for (int64_t i = 0; i < E->n; i++) {
        const Point &p = E->vh[(size_t)i]->point();
        if (E->vh[(size_t)i]->info() != (uint32_t)i || p.x() != E->xy[2 * i] ||
            p.y() != E->xy[2 * i + 1])
            return 0;
    }
    /* The bookkeeping behind the lazy invalidation: every face registered
     * once (distinct non-zero stamps) with its own circumcircle cached, and
     * the best live heap entry is the largest circumcircle of all faces. */
    std::vector<uint64_t> stamps;
    double best = -1;
    for (auto f = E->T.faces_begin(); f != E->T.faces_end(); ++f) {
        const FaceInfo &I = f->info();
        double cx, cy, r2;
        circumcircle(E->T, f, &cx, &cy, &r2);
        if (I.stamp == 0 || I.r2 != r2 || I.cx != cx || I.cy != cy) return 0;
        stamps.push_back(I.stamp);
        best = std::max(best, r2);
    }
    std::sort(stamps.begin(), stamps.end());
    if (std::adjacent_find(stamps.begin(), stamps.end()) != stamps.end()) return 0;
    if (!E->o.local) {
        double top = -1;
        for (const Entry &e : E->heap)
            if (alive(E, e.f, e.stamp)) {
                if (e.r2 != e.f->info().r2) return 0;
                top = std::max(top, e.r2);
            }
        if (top != best) return 0;
    }
    return 1;
}

} // extern "C"
