/* cgal3_types.h - layer 2, C++ only, where CGAL is: the types of CGAL's
 * periodic 3-D Delaunay triangulation that the 3-D measures
 * (measures3_vor.cpp, measures3_fpd.cpp) and 3-D FPO (baselines/fpo3.cpp)
 * share: the kernel, the periodic traits and vertices that carry the
 * point's index. PDT is the triangulation with plain cells; a user that
 * keeps data in its cells builds its own from CbDS. */
#ifndef CFPO_CGAL3_TYPES_H
#define CFPO_CGAL3_TYPES_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_3_Delaunay_triangulation_3.h>
#include <CGAL/Periodic_3_Delaunay_triangulation_traits_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

extern "C" {
#include "rng.h"
}

namespace cfpo_cgal3 {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Periodic_3_Delaunay_triangulation_traits_3<K> Gt;
typedef CGAL::Periodic_3_triangulation_ds_vertex_base_3<> VbDS;
typedef CGAL::Triangulation_vertex_base_3<Gt, VbDS> Vbb;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, Gt, Vbb> Vb;
typedef CGAL::Periodic_3_triangulation_ds_cell_base_3<> CbDS;
typedef CGAL::Triangulation_cell_base_3<Gt, CbDS> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Periodic_3_Delaunay_triangulation_3<Gt, Tds> PDT;

/* Inserts the n points p (x y z) into T, each vertex carrying its
 * point's index, vh[i] the vertex of point i (vh: n entries). In a fixed
 * pseudo-random order: a spatially ordered set (grown from a seed, or
 * sorted by cells) keeps CGAL's triangulation in its 27-sheeted covering
 * until nearly the end, slow and large. */
template <class Tri>
void insert_all(Tri &T, const double *p, size_t n, std::vector<typename Tri::Vertex_handle> &vh)
{
    for (size_t k = 0; k < n; k++) {
        const size_t i = (size_t)cfpo_permute(k, n, 0x564f524f4e4f49ULL);
        typename Tri::Vertex_handle v = T.insert(typename Tri::Point(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
        v->info() = (uint32_t)i;
        vh[i] = v;
    }
}

} // namespace cfpo_cgal3

#endif
