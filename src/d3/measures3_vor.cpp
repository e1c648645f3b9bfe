/* measures3_vor.cpp - see measures3_vor.h. */
#include "measures3_vor.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <new>
#include <vector>

#include "cgal3_types.h"

namespace {

using namespace cfpo_cgal3;
typedef PDT::Point Point;
typedef PDT::Cell_handle Cell_handle;
typedef PDT::Vertex_handle Vertex_handle;
typedef PDT::Edge Edge;

struct V3 {
    double x, y, z;
};
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 P(const Point &p) { return {p.x(), p.y(), p.z()}; }

/* The circumcentre of cell c relative to its vertex of index iv. */
V3 centre_rel(const PDT &T, Cell_handle c, int iv)
{
    const V3 o = P(T.point(c, iv));
    V3 q[3];
    for (int k = 0, m = 0; k < 4; k++)
        if (k != iv) q[m++] = sub(P(T.point(c, k)), o);
    const double a2 = dot(q[0], q[0]), b2 = dot(q[1], q[1]), d2 = dot(q[2], q[2]);
    const V3 bxd = cross(q[1], q[2]), dxa = cross(q[2], q[0]), axb = cross(q[0], q[1]);
    const double den = 2.0 * dot(q[0], bxd);
    return {(a2 * bxd.x + b2 * dxa.x + d2 * axb.x) / den, (a2 * bxd.y + b2 * dxa.y + d2 * axb.y) / den,
            (a2 * bxd.z + b2 * dxa.z + d2 * axb.z) / den};
}

double wrap01(double x)
{
    x -= std::floor(x);
    return x >= 1.0 ? 0.0 : x;
}

} // namespace

extern "C" int cfpo3_voronoi(const double *p, size_t n, int *faces, double *volume, double *centroid, char *err,
                             size_t errlen)
{
    try {
        PDT T(PDT::Iso_cuboid(0, 0, 0, 1, 1, 1));
        std::vector<Vertex_handle> vh(n);
        insert_all(T, p, n, vh);
        if (T.number_of_vertices() != n) {
            std::snprintf(err, errlen, "voronoi: the set has duplicate points");
            return -1;
        }
        if (!T.is_1_cover()) {
            std::snprintf(err, errlen, "voronoi: %zu points are too few or too uneven for a one-sheeted periodic "
                                       "triangulation", n);
            return -1;
        }
        const double amin = 1e-9 * std::pow(1.0 / (double)n, 2.0 / 3.0);
        std::vector<Edge> edges;
        std::vector<V3> poly;
        for (size_t i = 0; i < n; i++) {
            Vertex_handle v = vh[i];
            edges.clear();
            T.incident_edges(v, std::back_inserter(edges));
            int nf = 0;
            double vol = 0;
            V3 cm = {0, 0, 0};
            for (const Edge &e : edges) {
                poly.clear();
                PDT::Cell_circulator cc = T.incident_cells(e), done = cc;
                do {
                    Cell_handle c = cc;
                    poly.push_back(centre_rel(T, c, c->index(v)));
                } while (++cc != done);
                V3 area = {0, 0, 0};
                for (size_t k = 1; k + 1 < poly.size(); k++) {
                    const V3 a = poly[0], b = poly[k], d = poly[k + 1];
                    const V3 cr = cross(sub(b, a), sub(d, a));
                    area = {area.x + cr.x, area.y + cr.y, area.z + cr.z};
                    const double tv = std::fabs(dot(a, cross(b, d))) / 6.0; /* tetrahedron (v, a, b, d) */
                    vol += tv;
                    cm = {cm.x + tv * (a.x + b.x + d.x) / 4, cm.y + tv * (a.y + b.y + d.y) / 4,
                          cm.z + tv * (a.z + b.z + d.z) / 4};
                }
                nf += 0.5 * std::sqrt(dot(area, area)) > amin;
            }
            if (faces) faces[i] = nf;
            if (volume) volume[i] = vol;
            if (centroid) {
                centroid[3 * i] = wrap01(p[3 * i] + cm.x / vol);
                centroid[3 * i + 1] = wrap01(p[3 * i + 1] + cm.y / vol);
                centroid[3 * i + 2] = wrap01(p[3 * i + 2] + cm.z / vol);
            }
        }
        return 0;
    } catch (const std::bad_alloc &) {
        std::snprintf(err, errlen, "voronoi: out of memory for %zu points", n);
        return -1;
    }
}
