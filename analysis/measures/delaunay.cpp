/* delaunay.cpp - see delaunay.h. One triangulation per set; every sum runs
 * over the points in index order (per-point values first), so the result
 * does not depend on CGAL's iteration order. */
#include "cgal_types.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <complex>
#include <cstdio>
#include <new>
#include <vector>

#include "delaunay.h"

using namespace bl;

extern "C" double an_delaunay_bytes(size_t n) { return 400.0 * (double)n + 4096.0; }

namespace {

struct Site {
    double z = 0;    /* |sum_j exp(6 i arg(v_j - v_{j+1}))| */
    double area = 0; /* Voronoi cell */
    unsigned deg = 0;
};

int measure(const double *xy, size_t n, an_delaunay *out, an_vcells *cells, char *err, size_t errlen)
{
    PDT T;
    std::vector<double> pts(xy, xy + 2 * n);
    std::vector<Vertex_handle> vh;
    if (build_indexed(T, pts, (std::int64_t)n, vh, err, errlen) != 0) return -1;
    if (!T.is_1_cover()) {
        /* The bulk insertion starts from dummy points; removing them can
         * leave a small set in the 9-sheeted cover for good. One point at a
         * time, CGAL goes to the 1-sheeted cover as soon as every edge is
         * shorter than sqrt(0.166). */
        T.clear();
        for (size_t i = 0; i < n; i++) T.insert(Point(xy[2 * i], xy[2 * i + 1]))->info() = (std::uint32_t)i;
        vh.assign(n, Vertex_handle());
        size_t mapped = 0;
        for (auto v = T.vertices_begin(); v != T.vertices_end(); ++v) {
            Vertex_handle h = v;
            if (!T.is_virtual(h)) vh[h->info()] = h, mapped++;
        }
        if (mapped != n) {
            std::snprintf(err, errlen, "the triangulation holds %zu of %zu points", mapped, n);
            return -1;
        }
    }
    if (!T.is_1_cover()) {
        std::snprintf(err, errlen, "%zu points are too few or too clustered for a Delaunay triangulation of "
                      "the torus (CGAL keeps a 9-sheeted cover)", n);
        return -1;
    }
    double r2max = 0, e2min = INFINITY;
    for (auto f = T.faces_begin(); f != T.faces_end(); ++f) {
        circumcircle(T, f, &f->info().cx, &f->info().cy, &f->info().r2);
        if (f->info().r2 > r2max) r2max = f->info().r2;
        for (int j = 0; j < 3; j++) {
            const Point a = T.point(f, j), b = T.point(f, (j + 1) % 3);
            const double dx = a.x() - b.x(), dy = a.y() - b.y(), e2 = dx * dx + dy * dy;
            if (e2 < e2min) e2min = e2;
        }
    }
    std::vector<Site> site(n);
    std::vector<double> cv; /* the Voronoi vertices, site by site (cells) */
    std::vector<size_t> cstart;
    if (cells) cv.reserve(14 * n), cstart.reserve(n + 1);
    for (size_t id = 0; id < n; id++) {
        if (cells) cstart.push_back(cv.size() / 2);
        const Vertex_handle v = vh[id];
        auto fc = T.incident_faces(v), done = fc;
        std::complex<double> z = 0;
        double area = 0, ux0 = 0, uy0 = 0, upx = 0, upy = 0;
        unsigned deg = 0;
        do {
            const Face_handle f = fc;
            const int i = f->index(v);
            const Point p = T.point(f, i), a = T.point(f, PDT::ccw(i)), b = T.point(f, PDT::cw(i));
            /* the bond between consecutive neighbours, as a unit complex number to the 6th */
            std::complex<double> w(a.x() - b.x(), a.y() - b.y());
            w /= std::abs(w);
            const std::complex<double> w2 = w * w;
            z += w2 * w2 * w2;
            /* Voronoi vertex relative to the site */
            const double ux = f->info().cx - p.x(), uy = f->info().cy - p.y();
            if (cells) cv.push_back(xy[2 * id] + ux), cv.push_back(xy[2 * id + 1] + uy);
            if (deg == 0) { ux0 = ux; uy0 = uy; }
            else area += upx * uy - upy * ux;
            upx = ux;
            upy = uy;
            deg++;
        } while (++fc != done);
        area += upx * uy0 - upy * ux0;
        if (cells && area < 0) { /* counter-clockwise */
            const size_t b = cstart.back();
            for (size_t a = b, c = cv.size() / 2 - 1; a < c; a++, c--) {
                std::swap(cv[2 * a], cv[2 * c]);
                std::swap(cv[2 * a + 1], cv[2 * c + 1]);
            }
        }
        site[id].z = std::abs(z);
        site[id].area = 0.5 * std::fabs(area);
        site[id].deg = deg;
    }
    double zs = 0, a1 = 0, a2 = 0, degs = 0;
    for (size_t id = 0; id < n; id++) {
        zs += site[id].z;
        degs += site[id].deg;
        a1 += site[id].area;
        a2 += site[id].area * site[id].area;
    }
    out->psi6 = zs / degs;
    out->area_var = (double)n * a2 / (a1 * a1) - 1.0; /* the cells tile the torus: a1 = 1 up to rounding */
    out->covering = std::sqrt(r2max);
    out->delta_min = std::sqrt(e2min);
    out->mesh_ratio = 2.0 * out->covering / out->delta_min;
    if (cells) {
        cstart.push_back(cv.size() / 2);
        cells->start = static_cast<size_t *>(std::malloc(cstart.size() * sizeof(size_t)));
        cells->v = static_cast<double *>(std::malloc(std::max<size_t>(cv.size(), 1) * sizeof(double)));
        if (!cells->start || !cells->v) {
            an_vcells_free(cells);
            throw std::bad_alloc();
        }
        std::copy(cstart.begin(), cstart.end(), cells->start);
        std::copy(cv.begin(), cv.end(), cells->v);
        cells->n = n;
    }
    return 0;
}

} // namespace

extern "C" int an_delaunay_compute(const double *xy, size_t n, an_delaunay *out, char *err, size_t errlen)
{
    return an_delaunay_compute_cells(xy, n, out, nullptr, err, errlen);
}

extern "C" int an_delaunay_compute_cells(const double *xy, size_t n, an_delaunay *out, an_vcells *cells, char *err,
                                         size_t errlen)
{
    if (cells) *cells = an_vcells{};
    if (n < 1 || n >= ((size_t)1 << 32)) {
        std::snprintf(err, errlen, "bad n = %zu for the Delaunay measures", n);
        return -1;
    }
    try {
        return measure(xy, n, out, cells, err, errlen);
    } catch (const std::bad_alloc &) {
        std::snprintf(err, errlen, "out of memory for the Delaunay triangulation of %zu points", n);
        return -1;
    }
}
