/* measures3_fpd.cpp - see measures3_fpd.h. */
#include "measures3_fpd.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <new>
#include <vector>

#include "cgal3_types.h"

extern "C" {
#include "nn3.h"
#include "solve3.h"
}

namespace {

using namespace cfpo_cgal3;
typedef PDT::Point Point;
typedef PDT::Cell_handle Cell_handle;
typedef PDT::Vertex_handle Vertex_handle;

/* The squared circumradius of cell c (0 for a flat cell). */
double radius2(const PDT &T, Cell_handle c)
{
    const Point p0 = T.point(c, 0);
    double q[3][3];
    for (int k = 1; k < 4; k++) {
        const Point pk = T.point(c, k);
        q[k - 1][0] = pk.x() - p0.x(), q[k - 1][1] = pk.y() - p0.y(), q[k - 1][2] = pk.z() - p0.z();
    }
    double l[3], cr[3][3];
    for (int k = 0; k < 3; k++) l[k] = q[k][0] * q[k][0] + q[k][1] * q[k][1] + q[k][2] * q[k][2];
    for (int k = 0; k < 3; k++) {
        const double *a = q[(k + 1) % 3], *b = q[(k + 2) % 3];
        cr[k][0] = a[1] * b[2] - a[2] * b[1], cr[k][1] = a[2] * b[0] - a[0] * b[2], cr[k][2] = a[0] * b[1] - a[1] * b[0];
    }
    const double den = 2.0 * (q[0][0] * cr[0][0] + q[0][1] * cr[0][1] + q[0][2] * cr[0][2]);
    double u[3];
    for (int a = 0; a < 3; a++) u[a] = (l[0] * cr[0][a] + l[1] * cr[1][a] + l[2] * cr[2][a]) / den;
    const double r2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    return std::isfinite(r2) ? r2 : 0;
}

struct Big {
    double r2;
    std::array<uint32_t, 4> v;
};

} // namespace

extern "C" int cfpo3_fpd_certify(const double *p, size_t n, cfpo3_fpd_result *r, double *each, char *err, size_t errlen)
{
    try {
        if (n < 39) {
            std::snprintf(err, errlen, "certify: %zu points are too few (at least 39)", n);
            return -1;
        }
        PDT T(PDT::Iso_cuboid(0, 0, 0, 1, 1, 1));
        std::vector<Vertex_handle> vh(n);
        insert_all(T, p, n, vh);
        if (T.number_of_vertices() != n) {
            std::snprintf(err, errlen, "certify: the set has duplicate points");
            return -1;
        }
        std::vector<Big> big;
        big.reserve(T.number_of_cells());
        for (auto c = T.cells_begin(); c != T.cells_end(); ++c)
            big.push_back(Big{radius2(T, c), {T.get_original_vertex(c->vertex(0))->info(),
                                             T.get_original_vertex(c->vertex(1))->info(),
                                             T.get_original_vertex(c->vertex(2))->info(),
                                             T.get_original_vertex(c->vertex(3))->info()}});
        std::sort(big.begin(), big.end(), [](const Big &a, const Big &b) { return a.r2 > b.r2; });
        const double D = cfpo3_delta_bound((double)n);
        r->passed = 0;
        r->max_violation = -INFINITY;
        std::vector<Vertex_handle> nb;
        std::vector<Cell_handle> cells;
        for (size_t i = 0; i < n; i++) {
            nb.clear();
            T.adjacent_vertices(vh[i], std::back_inserter(nb));
            double q0 = INFINITY;
            for (Vertex_handle w : nb) {
                const size_t j = T.get_original_vertex(w)->info(); /* virtual copies carry no info */
                const double dx = cfpo3_pdiff(p[3 * i], p[3 * j]), dy = cfpo3_pdiff(p[3 * i + 1], p[3 * j + 1]),
                             dz = cfpo3_pdiff(p[3 * i + 2], p[3 * j + 2]);
                q0 = std::min(q0, dx * dx + dy * dy + dz * dz);
            }
            double R2 = 0;
            for (const Big &b : big) /* the largest cell without x_i */
                if (b.v[0] != i && b.v[1] != i && b.v[2] != i && b.v[3] != i) {
                    R2 = b.r2;
                    break;
                }
            T.remove(vh[i]);
            if (!T.is_1_cover()) /* CGAL went to its 27-sheeted covering (a sparse set): every cell */
                for (auto c = T.cells_begin(); c != T.cells_end(); ++c) R2 = std::max(R2, radius2(T, c));
            else
                for (Vertex_handle w : nb) {
                    cells.clear();
                    T.incident_cells(w, std::back_inserter(cells));
                    for (Cell_handle c : cells) R2 = std::max(R2, radius2(T, c));
                }
            Vertex_handle v = T.insert(Point(p[3 * i], p[3 * i + 1], p[3 * i + 2]), nb[0]->cell());
            v->info() = (uint32_t)i;
            vh[i] = v;
            const double d0 = std::sqrt(q0), R = std::sqrt(R2);
            r->passed += R <= d0 * (1 + 1e-9);
            r->max_violation = std::max(r->max_violation, (R - d0) / D);
            if (each) each[i] = (R - d0) / D;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        std::snprintf(err, errlen, "certify: out of memory for %zu points", n);
        return -1;
    }
}
