/* bnot_types.hpp - the inside of bnot.h's engine, shared by bnot_power.cpp
 * (the power diagram and the capacity solve), bnot.cpp (the engine, the
 * run to a move tolerance) and bnot_rule.cpp (the authors' two-phase
 * stopping rule and the regularity breaker). Not a public header. */
#ifndef CFPO_BASELINES_BNOT_TYPES_HPP
#define CFPO_BASELINES_BNOT_TYPES_HPP
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_face_base_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <utility>
#include <vector>

#include "bnot.h"
#include "dens_poly.h"
extern "C" {
#include "cli.h"
#include "dens_draw.h"
#include "dens_measure.h"
#include "geom.h"
#include "grid.h"
#include "rng.h"
#include "stats.h"
#include "stoprule.h"
}

namespace bnot_detail {

const uint64_t START_STREAM = 0x424e4f5453545254ULL; /* "BNOTSTRT" */
/* the start's thinning and inverse-CDF numbers under a density (dens_draw.h) */
const uint64_t START_DENS_STREAM = 0x424e4f5444454e53ULL; /* "BNOTDENS" */
const double CG_RTOL = 1e-3;
const int MAX_NEWTON = 100;
/* the authors' rule (bnot_rule.cpp) */
const uint64_t BREAK_STREAM = 0x424e4f5442524b52ULL; /* "BNOTBRKR" */
enum Phase { TOL_RUN = 0, COARSE = 1, FINE = 2, DONE = 3 };

struct VInfo {
    uint32_t id = UINT32_MAX; /* the site; UINT32_MAX: not set yet */
    uint8_t orig = 0;         /* 1: the site itself, 0: a copy */
};
struct FInfo {
    double cx = 0, cy = 0; /* power centre */
};

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Regular_triangulation_vertex_base_2<K> Vbase;
typedef CGAL::Triangulation_vertex_base_with_info_2<VInfo, K, Vbase> Vb;
typedef CGAL::Regular_triangulation_face_base_2<K> Fbase;
typedef CGAL::Triangulation_face_base_with_info_2<FInfo, K, Fbase> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Regular_triangulation_2<K, Tds> RT;
typedef RT::Vertex_handle Vertex_handle;
typedef RT::Face_handle Face_handle;
typedef K::Weighted_point_2 WPoint;
typedef K::Point_2 Point;

struct Ins {
    double x, y;
    uint32_t id;
    uint8_t orig;
};

} // namespace bnot_detail
using namespace bnot_detail;

struct bnot_engine {
    int64_t n = 0;
    double L = 0, tol = 0, cap_tol = BNOT_CAP_TOL, target = 0, margin = 0;
    RT T;
    std::vector<double> xy, w, area, cen, mom, cs;
    std::vector<Vertex_handle> vh;
    std::vector<Ins> ins;
    std::vector<std::pair<uint64_t, uint32_t>> order;
    /* Hessian, one row per site: off-diagonal entries (col, val) > 0
     * meaning H_ij = -val; diagonal = the row's sum. */
    std::vector<int64_t> rowp;
    std::vector<uint32_t> col;
    std::vector<double> val, diag;
    std::vector<double> r, z, p, q, d, wold; /* CG and line search */
    mutable std::vector<double> abscen;
    double energy = 0, energy_moved = 0, cap_err = 0, res2 = 0, min_area = 0;
    int64_t empty = 0, cg_iters = 0;
    int newton = 0, ok = 1;
    /* the authors' rule (rule.epsilon > 0): the solve stops when
     * |A - 1/n| (2-norm) < res_tol or after max_newton steps (res_tol 0:
     * every |A_i n - 1| <= cap_tol, at most MAX_NEWTON steps) */
    bnot_rule rule;
    double res_tol = 0, gthr = 0, gnorm = NAN;
    int max_newton = MAX_NEWTON, phase = TOL_RUN, round = 1, round_iter = 0;
    int64_t breaks = 0, last_regular = 0;
    uint64_t rng_seed = 0, rng_ctr = 0;
    int step_phase = TOL_RUN; /* the phase of the last iteration's step */
    std::vector<double> xy0, stepv;
    std::vector<uint8_t> flag;
    std::vector<uint32_t> pick;
    /* under a density: the density (deltas in its measure) and, when it is
     * not constant (or pixels forces it), its integrals over the cells */
    const cfpo_density *dens = nullptr;
    dens_poly dp = {nullptr, nullptr};
    bool pixels = false;
    bnot_engine() = default;
    bnot_engine(const bnot_engine &) = delete;
    bnot_engine &operator=(const bnot_engine &) = delete;
    ~bnot_engine() { dens_poly_free(&dp); }
};

/* The diagram for E->w and everything derived from it (bnot_power.cpp). */
void bnot_build(bnot_engine *E);
/* Damped Newton on the weights from the current ones (0 when a cell is
 * empty) until the capacity tolerance holds (bnot_power.cpp). */
void bnot_solve(bnot_engine *E);
/* One iteration of the authors' schedule (bnot_rule.cpp). */
void bnot_rule_iterate(bnot_engine *E, cfpo_iter_stats *s);

#endif
