/* cgal_types.h - the one typedef block for CGAL's periodic Delaunay
 * triangulation on the unit torus, shared by fpo.cpp and coverage.cpp.
 *
 * Vertex info: the point's id. Face info: a registration stamp (0 = not
 * registered, i.e. new or changed since it was last looked at) and the
 * cached circumcircle, so the FPO priority queue can invalidate entries
 * lazily. Kernel: exact predicates, inexact constructions (the predicates
 * decide the triangulation exactly; circumcentres are computed in double). */
#ifndef CFPO_BASELINES_CGAL_TYPES_H
#define CFPO_BASELINES_CGAL_TYPES_H

#include <cstdint>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace bl {

struct FaceInfo {
    std::uint64_t stamp = 0;  /* 0: unregistered; else unique per registration */
    double r2 = 0, cx = 0, cy = 0; /* circumradius^2 and centre (unwrapped) */
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

} // namespace bl

#endif
