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
 * very few points), every face is re-registered after each change.
 * Under a density (fpo.h) d0 is the exact smallest measure over all points
 * (a grid search, mgrid.h: the nearest in the measure need not be a
 * Delaunay neighbour), the heap is ordered by the faces' keys, and a face
 * is judged by its exact value (face_value). */
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
#include "dens_draw.h"
#include "dens_measure.h"
#include "mgrid.h"
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
/* Under a density: the start's four further numbers of point id (counter 4id + k). */
const uint64_t START_DENS_STREAM = 0x46504f5344454e53ULL; /* "FPOSDENS" */

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
    /* under a density */
    const cfpo_density *dens = nullptr;
    std::vector<double> q;         /* sqrt(rho) at each point, by id */
    std::vector<double> qstart;    /* q at the start of the iteration */
    std::vector<Entry> popped;     /* live heap entries taken off by the search */
    mgrid M{};
    bool has_M = false;
    ~fpo_engine()
    {
        if (has_M) mgrid_free(&M);
    }
};

/* sqrt(rho) at a point of [0, 1)^2. */
static double q_at(const fpo_engine *E, double x, double y) { return std::sqrt(cfpo_density_at(E->dens, x, y)); }

static bool alive(const fpo_engine *E, Face_handle f, uint64_t stamp)
{
    return E->T.tds().faces().is_used(f) && f->info().stamp == stamp;
}

static void register_face(fpo_engine *E, Face_handle f)
{
    FaceInfo &I = f->info();
    I.stamp = E->next_stamp++;
    circumcircle(E->T, f, &I.cx, &I.cy, &I.r2);
    I.key = I.r2;
    if (E->dens) {
        double qv = INFINITY;
        for (int k = 0; k < 3; k++) qv = std::min(qv, E->q[f->vertex(k)->info()]);
        I.key = I.r2 * (q_at(E, cfpo_wrap01(I.cx), cfpo_wrap01(I.cy)) * qv);
    }
    if (!E->o.local) {
        E->heap.push_back(Entry{I.key, I.stamp, f});
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
        E->heap.push_back(Entry{fh->info().key, fh->info().stamp, fh});
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

/* A face's value: its key (r^2) without a density; under one the exact
 * smallest d^2 q_c q_j from its centre c over all points, i.e. the key
 * (the vertices, at distance r) or a nearer point in the measure. */
static double face_value(const fpo_engine *E, Face_handle f)
{
    const FaceInfo &I = f->info();
    if (!E->dens || !(I.key > 0)) return I.key;
    const int64_t ex[3] = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    const double cx = cfpo_wrap01(I.cx), cy = cfpo_wrap01(I.cy);
    return mgrid_min(&E->M, cx, cy, q_at(E, cx, cy), ex, 3, I.key);
}

/* Keeps f when its value beats *best (a face whose key, an upper bound of
 * its value, does not beat it is not evaluated). */
static void consider(const fpo_engine *E, Face_handle f, Face_handle *best, double *bv)
{
    if (!(f->info().key > *bv)) return;
    const double v = face_value(E, f);
    if (v > *bv) {
        *bv = v;
        *best = f;
    }
}

/* The face of largest value around the ring (LFPO). */
static Face_handle ring_best(fpo_engine *E, double *bv)
{
    Face_handle best;
    *bv = -1;
    for (Vertex_handle u : E->ring) {
        auto fc = E->T.incident_faces(u), done = fc;
        do {
            consider(E, fc, &best, bv);
        } while (++fc != done);
    }
    return best;
}

/* The face of largest value of all, by a scan (LFPO after a change of
 * CGAL's cover, when the ring's handles are gone). */
static Face_handle scan_best(fpo_engine *E, double *bv)
{
    Face_handle best;
    *bv = -1;
    for (auto f = E->T.faces_begin(); f != E->T.faces_end(); ++f) consider(E, f, &best, bv);
    return best;
}

/* The face of largest value of all (global FPO): the heap's top without a
 * density; under one, branch and bound: live entries are taken off in key
 * order while the next key exceeds the best value so far, then put back. */
static Face_handle heap_best(fpo_engine *E, double *bv)
{
    if (!E->dens) {
        Face_handle f = heap_top(E);
        *bv = f->info().key;
        return f;
    }
    Face_handle best;
    bool found = false;
    *bv = -1;
    E->popped.clear();
    while (!E->heap.empty()) {
        const Entry e = E->heap.front();
        const bool live = alive(E, e.f, e.stamp);
        if (live && found && !(e.r2 > *bv)) break;
        std::pop_heap(E->heap.begin(), E->heap.end(), EntryLess());
        E->heap.pop_back();
        if (!live) continue;
        E->popped.push_back(e);
        const double v = face_value(E, e.f);
        if (!found || v > *bv) {
            *bv = v;
            best = e.f;
            found = true;
        }
    }
    for (const Entry &e : E->popped) {
        E->heap.push_back(e);
        std::push_heap(E->heap.begin(), E->heap.end(), EntryLess());
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
    if (E->dens) { /* the exact smallest measure over all other points */
        mgrid_remove(&E->M, id);
        d02 = mgrid_min(&E->M, x, y, E->q[id], nullptr, 0, INFINITY);
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
    double val;
    if (!E->o.local) best = heap_best(E, &val);
    else best = E->ring.empty() ? scan_best(E, &val) : ring_best(E, &val);
    const FaceInfo &I = best->info();
    const double thr = std::sqrt(d02) + tolL;
    int moved = 0;
    double nx = x, ny = y, nq = E->dens ? E->q[id] : 1;
    Face_handle hint = E->ring.empty() ? Face_handle() : E->ring[0]->face();
    if (val > thr * thr) {
        const double cx = cfpo_wrap01(I.cx), cy = cfpo_wrap01(I.cy);
        const double cq = E->dens ? q_at(E, cx, cy) : 1;
        /* under a density, the exact test: the new place's smallest
         * measure, every point included, must exceed the old one */
        if (!E->dens || mgrid_min(&E->M, cx, cy, cq, nullptr, 0, INFINITY) > d02) {
            nx = cx;
            ny = cy;
            nq = cq;
            hint = best;
            moved = 1;
        }
    }
    if (E->dens) E->q[id] = nq; /* before the insertion registers the new faces */
    E->vh[id] = insert_point(E, id, nx, ny, hint);
    E->xy[2 * id] = nx;
    E->xy[2 * id + 1] = ny;
    if (E->dens) mgrid_insert(&E->M, id);
    maybe_compact(E);
    return moved;
}

static int make_start(fpo_engine *E)
{
    const int64_t n = E->n;
    if (E->o.start == FPO_START_RANDOM && E->dens) {
        dens_draw s;
        if (dens_draw_init(&s, E->dens) != 0) return -1;
        for (int64_t i = 0; i < n; i++) {
            E->xy[2 * i] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i);
            E->xy[2 * i + 1] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i + 1);
            dens_draw_at(&s, E->o.seed, START_DENS_STREAM, (uint64_t)i, &E->xy[2 * i], &E->xy[2 * i + 1]);
        }
        dens_draw_free(&s);
        return 0;
    }
    if (E->o.start == FPO_START_RANDOM) {
        for (int64_t i = 0; i < n; i++) {
            E->xy[2 * i] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i);
            E->xy[2 * i + 1] = cfpo_rand01(E->o.seed, START_STREAM, 2 * (uint64_t)i + 1);
        }
        return 0;
    }
    int64_t id = 0; /* cfpo's ids: cells row-major, a cell's points consecutive */
    for (int64_t cy = 0; cy < E->G.g; cy++)
        for (int64_t cx = 0; cx < E->G.g; cx++) {
            uint64_t cnt = cfpo_grid_cell_count(&E->G, (uint64_t)(cy * E->G.g + cx));
            for (uint64_t k = 0; k < cnt; k++, id++)
                cfpo_grid_cell_point(&E->G, cx, cy, k, &E->xy[2 * id], &E->xy[2 * id + 1]);
        }
    return 0;
}

static int build(fpo_engine *E, char *err, size_t errlen)
{
    if (E->dens) { /* q and the grid before the faces' keys */
        for (int64_t i = 0; i < E->n; i++) E->q[(size_t)i] = q_at(E, E->xy[2 * i], E->xy[2 * i + 1]);
        if (mgrid_init(&E->M, (size_t)E->n, (size_t)E->n, E->xy.data(), E->q.data(), std::sqrt(E->dens->rho_min)) != 0) {
            snprintf(err, errlen, "out of memory for n = %lld", (long long)E->n);
            return -1;
        }
        E->has_M = true;
        for (int64_t i = 0; i < E->n; i++) mgrid_insert(&E->M, i);
    }
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

/* Bytes the engine needs for n points: CGAL's periodic triangulation
 * (vertices, about 2n faces with their offsets), the circumradius heap,
 * the points and caches. About 680 bytes a point measured at n = 2^18
 * (peak resident set of cfpo-fpo); the model rounds up to 720. */
static uint64_t fpo_bytes(int64_t n)
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
    if (o->density) {
        if (o->start == FPO_START_GRID) {
            snprintf(err, errlen, "--start grid does not go with --density (the start is drawn from the density)");
            return -1;
        }
        if (cfpo_density_check_n(o->density, n, err, errlen) != 0) return -1;
    }
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
    if (o->density && o->start == FPO_START_GRID) {
        snprintf(err, errlen, "--start grid does not go with --density (the start is drawn from the density)");
        return nullptr;
    }
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
        E->dens = o->density;
        if (E->dens) {
            E->q.resize((size_t)n);
            E->qstart.resize((size_t)n);
        }
        if (make_start(E) != 0) {
            snprintf(err, errlen, "out of memory for n = %lld", (long long)n);
            delete E;
            return nullptr;
        }
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


void fpo_deltas(fpo_engine *E, double *dmin, double *davg)
{
    /* Out of memory: NaN statistics, as ccvt, ccdt and bnot (no exit: the
     * engine also runs inside the Python package). */
    const int rc = E->dens ? cfpo_dens_nn(E->dens, E->xy.data(), (size_t)E->n, nullptr, dmin, davg)
                           : cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg);
    if (rc != 0) *dmin = *davg = NAN;
}

void fpo_iterate(fpo_engine *E, cfpo_iter_stats *s)
{
    const double t0 = cli_now();
    const double tolL = E->o.tol * E->G.L;
    E->start = E->xy;
    E->qstart = E->q;
    int64_t moved = 0;
    for (int64_t id = 0; id < E->n; id++) moved += step(E, (uint32_t)id, tolL);
    double maxd2 = 0;
    for (int64_t i = 0; i < E->n; i++) {
        double d2 = cfpo_torus_dist2(E->start[2 * i], E->start[2 * i + 1], E->xy[2 * i],
                                     E->xy[2 * i + 1]);
        if (E->dens) d2 *= E->qstart[(size_t)i] * E->q[(size_t)i]; /* the displacement's measure */
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
        if (E->dens && (E->q[(size_t)i] != q_at(E, E->xy[2 * i], E->xy[2 * i + 1]) || E->M.cell[i] < 0)) return 0;
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
        best = std::max(best, I.key);
    }
    std::sort(stamps.begin(), stamps.end());
    if (std::adjacent_find(stamps.begin(), stamps.end()) != stamps.end()) return 0;
    if (!E->o.local) {
        double top = -1;
        for (const Entry &e : E->heap)
            if (alive(E, e.f, e.stamp)) {
                if (e.r2 != e.f->info().key) return 0;
                top = std::max(top, e.r2);
            }
        if (top != best) return 0;
    }
    return 1;
}

} // extern "C"
