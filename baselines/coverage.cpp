/* coverage.cpp - see coverage.h. */
#include "cgal_types.h"

#include <utility>
#include <vector>

#include "coverage.h"

using namespace bl;

extern "C" double bl_covering_radius(const double *xy, size_t n)
{
    std::vector<std::pair<Point, std::uint32_t>> pts;
    pts.reserve(n);
    for (size_t i = 0; i < n; i++) pts.emplace_back(Point(xy[2 * i], xy[2 * i + 1]), (std::uint32_t)i);
    PDT T;
    T.insert(pts.begin(), pts.end(), true);
    if (T.number_of_vertices() != n) return -1;
    double best = 0;
    for (auto f = T.faces_begin(); f != T.faces_end(); ++f) {
        double cx, cy, r2;
        circumcircle(T, f, &cx, &cy, &r2);
        if (r2 > best) best = r2;
    }
    return std::sqrt(best);
}
