/* cgal_types.h - the one typedef block for CGAL's periodic Delaunay
 * triangulation on the unit torus, shared by fpo.cpp, ccdt.cpp and
 * coverage.cpp, and the build of a triangulation of indexed points.
 *
 * Vertex info: the point's id. Face info: a registration stamp (0 = not
 * registered, i.e. new or changed since it was last looked at) and the
 * cached circumcircle, so the FPO priority queue can invalidate entries
 * lazily. Kernel: exact predicates, inexact constructions (the predicates
 * decide the triangulation exactly; circumcentres are computed in double). */
#ifndef CFPO_BASELINES_CGAL_TYPES_H
#define CFPO_BASELINES_CGAL_TYPES_H

#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace bl {

struct FaceInfo {
    std::uint64_t stamp = 0;  /* 0: unregistered; else unique per registration */
    double r2 = 0, cx = 0, cy = 0; /* circumradius^2 and centre (unwrapped) */
    double key = 0; /* FPO's heap key: r2, or under a density r2 q(c) min q(vertex) */
};

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Periodic_2_Delaunay_triangulation_traits_2<K> Gt;
typedef CGAL::Periodic_2_triangulation_vertex_base_2<Gt> Vbb;
typedef CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Gt, Vbb> Vb;
typedef CGAL::Periodic_2_triangulation_face_base_2<Gt> Fbb;
typedef CGAL::Triangulation_face_base_with_info_2<FaceInfo, Gt, Fbb> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Periodic_2_Delaunay_triangulation_2<Gt, Tds> PDT;
typedef PDT::Point Point;
typedef PDT::Face_handle Face_handle;
typedef PDT::Vertex_handle Vertex_handle;

/* Circumcircle of face f, from its three points with their periodic
 * offsets applied: centre (cx, cy) (not wrapped) and radius^2. */
inline void circumcircle(const PDT &T, Face_handle f, double *cx, double *cy, double *r2)
{
    const Point p0 = T.point(f, 0), p1 = T.point(f, 1), p2 = T.point(f, 2);
    const double ax = p1.x() - p0.x(), ay = p1.y() - p0.y();
    const double bx = p2.x() - p0.x(), by = p2.y() - p0.y();
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    const double d = 2.0 * (ax * by - ay * bx);
    const double ux = (by * a2 - ay * b2) / d, uy = (ax * b2 - bx * a2) / d;
    *cx = p0.x() + ux;
    *cy = p0.y() + uy;
    *r2 = ux * ux + uy * uy;
}

/* Triangulates the n points of xy (x0 y0 x1 y1 ...), point i with info i,
 * and fills vh[i] with its vertex. 0, or -1 with a message when points
 * coincide (CGAL keeps one of them). */
inline int build_indexed(PDT &T, const std::vector<double> &xy, std::int64_t n, std::vector<Vertex_handle> &vh,
                         char *err, std::size_t errlen)
{
    std::vector<std::pair<Point, std::uint32_t>> pts;
    pts.reserve((std::size_t)n);
    for (std::int64_t i = 0; i < n; i++) pts.emplace_back(Point(xy[2 * i], xy[2 * i + 1]), (std::uint32_t)i);
    T.insert(pts.begin(), pts.end(), true);
    if ((std::int64_t)T.number_of_vertices() != n) {
        std::snprintf(err, errlen, "the start has %lld distinct points, not %lld (duplicates)",
                      (long long)T.number_of_vertices(), (long long)n);
        return -1;
    }
    vh.assign((std::size_t)n, Vertex_handle());
    for (auto v = T.vertices_begin(); v != T.vertices_end(); ++v) {
        Vertex_handle h = v;
        if (!T.is_virtual(h)) vh[h->info()] = h;
    }
    return 0;
}

} // namespace bl

#endif
