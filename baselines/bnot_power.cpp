/* bnot_power.cpp - the power diagram and the capacity solve of BNOT
 * (bnot_types.hpp), below both the run to a move tolerance (bnot.cpp) and
 * the authors' schedule (bnot_rule.cpp); also the sites' nearest-neighbour
 * statistics. BNOT on CGAL's Regular_triangulation_2 (exact predicates,
 * inexact constructions) of the sites and their periodic copies within the
 * margin.
 *
 * One build (weights w given): triangulate; the power centre of every
 * finite face (solved relative to its first vertex); for every original
 * site, its incident faces counter-clockwise give its power cell, a
 * polygon whose triangle fan from the site gives the area, the centroid
 * and the second moment about the site (signed, so also right when the
 * site lies outside its own cell); the Hessian row of the site from its
 * edges; the margin check. A failed check doubles the margin and builds
 * again. The weights keep mean 0 (they start at 0 and every Newton
 * direction is centred; the diagram only sees their differences).
 *
 * Under a density rho (de Goes et al. 2012 pose the transport from a
 * density; their published periodic code has rho = 1 only): a cell's
 * "area" is its mass, the integral of rho over it, its centroid and
 * second moment are rho-weighted, and a Hessian entry is the integral of
 * rho along the power edge over 2 |p_i - p_j| (the edge moves by dw /
 * (2 |p_i - p_j|) when w_j changes); all exact for the piecewise-constant
 * rho (dens_poly.h). A constant density takes the uniform formulas, equal
 * to those integrals for rho = 1, so that run is the run without one. */
#include "bnot_types.hpp"

/* The triangulation of the sites and their copies within the margin. */
static void triangulate(bnot_engine *E)
{
    const int64_t n = E->n;
    const double m = E->margin;
    E->ins.clear();
    for (int64_t i = 0; i < n; i++)
        for (int oy = -1; oy <= 1; oy++)
            for (int ox = -1; ox <= 1; ox++) {
                const double x = E->xy[2 * i] + ox, y = E->xy[2 * i + 1] + oy;
                if (x < -m || x >= 1 + m || y < -m || y >= 1 + m) continue;
                E->ins.push_back(Ins{x, y, (uint32_t)i, (uint8_t)(ox == 0 && oy == 0)});
            }
    /* serpentine order of B x B bins over the box */
    const size_t cnt = E->ins.size();
    const int64_t B = std::max<int64_t>(1, (int64_t)std::sqrt((double)cnt / 4.0));
    const double side = (1 + 2 * m) / (double)B;
    E->order.resize(cnt);
    for (size_t k = 0; k < cnt; k++) {
        int64_t bx = std::min<int64_t>(B - 1, std::max<int64_t>(0, (int64_t)((E->ins[k].x + m) / side)));
        int64_t by = std::min<int64_t>(B - 1, std::max<int64_t>(0, (int64_t)((E->ins[k].y + m) / side)));
        if (by & 1) bx = B - 1 - bx;
        E->order[k] = std::make_pair((uint64_t)(by * B + bx), (uint32_t)k);
    }
    std::sort(E->order.begin(), E->order.end());
    E->T.clear();
    Face_handle hint;
    for (const auto &o : E->order) {
        const Ins &a = E->ins[o.second];
        Vertex_handle v = E->T.insert(WPoint(Point(a.x, a.y), E->w[a.id]), hint);
        if (v->info().id == UINT32_MAX) {
            v->info().id = a.id;
            v->info().orig = a.orig;
        }
        if (!v->is_hidden()) hint = v->face();
    }
    E->vh.assign((size_t)n, Vertex_handle());
    for (auto v = E->T.finite_vertices_begin(); v != E->T.finite_vertices_end(); ++v)
        if (v->info().orig) E->vh[v->info().id] = v;
}

static void power_centres(bnot_engine *E)
{
    for (auto f = E->T.finite_faces_begin(); f != E->T.finite_faces_end(); ++f) {
        const WPoint &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
        const double ax = b.x() - a.x(), ay = b.y() - a.y(), bx = c.x() - a.x(), by = c.y() - a.y();
        const double A2 = ax * ax + ay * ay + a.weight() - b.weight();
        const double B2 = bx * bx + by * by + a.weight() - c.weight();
        const double det = 2.0 * (ax * by - ay * bx);
        f->info().cx = a.x() + (by * A2 - ay * B2) / det;
        f->info().cy = a.y() + (ax * B2 - bx * A2) / det;
    }
}

/* Cell i: area, centroid, moment, Hessian row, margin check. 0, or -1
 * when a copy left out could change the cell. */
static int cell(bnot_engine *E, int64_t i, double wmax)
{
    const Vertex_handle v = E->vh[(size_t)i];
    const double px = E->xy[2 * i], py = E->xy[2 * i + 1], wi = E->w[(size_t)i], m = E->margin;
    E->cs.clear();
    auto fc = E->T.incident_faces(v), done = fc;
    do {
        Face_handle f = fc;
        if (E->T.is_infinite(f)) return -1;
        const int k = f->index(v);
        Face_handle g = f->neighbor(RT::cw(k));
        if (E->T.is_infinite(g)) return -1;
        const double cx = f->info().cx, cy = f->info().cy;
        if (m < 1) { /* every copy is in when m >= 1 */
            const double dx = std::min(std::min(cx + m, 1 + m - cx), std::min(cy + m, 1 + m - cy));
            const double pw = (cx - px) * (cx - px) + (cy - py) * (cy - py) - wi;
            if (dx <= 0 || pw > dx * dx - wmax) return -1;
        }
        E->cs.push_back(cx - px);
        E->cs.push_back(cy - py);
        const Vertex_handle u = f->vertex(RT::ccw(k));
        if (u->info().id != (uint32_t)i) {
            const double ex = cx - g->info().cx, ey = cy - g->info().cy;
            const double sx = u->point().x() - px, sy = u->point().y() - py;
            /* dA_i/dw_j = -(int of rho along e_ij) / (2 |p_i - p_j|) */
            const double len = E->pixels ? dens_poly_segment(&E->dp, cx, cy, g->info().cx, g->info().cy)
                                         : std::sqrt(ex * ex + ey * ey);
            E->col.push_back(u->info().id);
            E->val.push_back(len / (2.0 * std::sqrt(sx * sx + sy * sy)));
        }
    } while (++fc != done);
    const size_t k = E->cs.size() / 2;
    if (E->pixels) { /* the density's mass, first and second moments */
        double mo[4];
        dens_poly_moments(&E->dp, px, py, E->cs.data(), k, mo);
        E->area[(size_t)i] = mo[0];
        E->cen[2 * i] = mo[0] > 0 ? mo[1] / mo[0] : 0;
        E->cen[2 * i + 1] = mo[0] > 0 ? mo[2] / mo[0] : 0;
        E->mom[(size_t)i] = mo[3];
        return 0;
    }
    double A = 0, gx = 0, gy = 0, M = 0;
    for (size_t j = 0; j < k; j++) {
        const double ux = E->cs[2 * j], uy = E->cs[2 * j + 1];
        const double vx = E->cs[2 * ((j + 1) % k)], vy = E->cs[2 * ((j + 1) % k) + 1];
        const double a = 0.5 * (ux * vy - uy * vx);
        A += a;
        gx += a * (ux + vx);
        gy += a * (uy + vy);
        M += a * (ux * ux + ux * vx + vx * vx + uy * uy + uy * vy + vy * vy);
    }
    E->area[(size_t)i] = A;
    E->cen[2 * i] = A > 0 ? gx / (3 * A) : 0;
    E->cen[2 * i + 1] = A > 0 ? gy / (3 * A) : 0;
    E->mom[(size_t)i] = M / 6;
    return 0;
}

/* The power diagram for the weights E->w and everything derived from it. */
void bnot_build(bnot_engine *E)
{
    const int64_t n = E->n;
    double wmax = -HUGE_VAL;
    for (double x : E->w) wmax = std::max(wmax, x);
    for (;;) {
        triangulate(E);
        power_centres(E);
        E->col.clear();
        E->val.clear();
        int fail = 0;
        E->empty = 0;
        for (int64_t i = 0; i < n && !fail; i++) {
            E->rowp[(size_t)i] = (int64_t)E->col.size();
            if (E->vh[(size_t)i] == Vertex_handle()) {
                E->area[(size_t)i] = E->mom[(size_t)i] = E->cen[2 * i] = E->cen[2 * i + 1] = 0;
                continue;
            }
            fail = cell(E, i, wmax) != 0;
        }
        if (!fail) break;
        E->margin = E->margin >= 0.5 ? 1.0 : 2 * E->margin;
    }
    E->rowp[(size_t)n] = (int64_t)E->col.size();
    const double t = E->target;
    E->energy = 0;
    E->cap_err = 0;
    E->res2 = 0;
    E->min_area = HUGE_VAL;
    for (int64_t i = 0; i < n; i++) {
        double s = 0;
        for (int64_t k = E->rowp[(size_t)i]; k < E->rowp[(size_t)i + 1]; k++) s += E->val[(size_t)k];
        E->diag[(size_t)i] = s;
        const double A = E->area[(size_t)i];
        if (!(A > 0)) E->empty++;
        E->energy += E->mom[(size_t)i];
        E->cap_err = std::max(E->cap_err, std::fabs(A / t - 1));
        E->res2 += (A - t) * (A - t);
        E->min_area = std::min(E->min_area, A);
    }
}

static void hmul(const bnot_engine *E, const std::vector<double> &x, std::vector<double> &y)
{
    for (int64_t i = 0; i < E->n; i++) {
        double s = E->diag[(size_t)i] * x[(size_t)i];
        for (int64_t k = E->rowp[(size_t)i]; k < E->rowp[(size_t)i + 1]; k++) s -= E->val[(size_t)k] * x[E->col[(size_t)k]];
        y[(size_t)i] = s;
    }
}

static double dot(const std::vector<double> &a, const std::vector<double> &b)
{
    double s = 0;
    for (size_t i = 0; i < a.size(); i++) s += a[i] * b[i];
    return s;
}

static void center(std::vector<double> &a)
{
    double s = 0;
    for (double x : a) s += x;
    s /= (double)a.size();
    for (double &x : a) x -= s;
}

/* d = H^+ (1/n - A) by Jacobi-preconditioned conjugate gradients. */
static void newton_direction(bnot_engine *E)
{
    const size_t n = (size_t)E->n;
    for (size_t i = 0; i < n; i++) {
        E->r[i] = E->target - E->area[i];
        E->d[i] = 0;
    }
    center(E->r);
    const double stop2 = CG_RTOL * CG_RTOL * dot(E->r, E->r);
    for (size_t i = 0; i < n; i++) E->z[i] = E->diag[i] > 0 ? E->r[i] / E->diag[i] : E->r[i];
    E->p = E->z;
    double rz = dot(E->r, E->z);
    for (int64_t it = 0; it < 20 * E->n + 100; it++) {
        hmul(E, E->p, E->q);
        const double pq = dot(E->p, E->q);
        if (!(pq > 0)) break;
        const double a = rz / pq;
        for (size_t i = 0; i < n; i++) {
            E->d[i] += a * E->p[i];
            E->r[i] -= a * E->q[i];
        }
        E->cg_iters++;
        if (dot(E->r, E->r) <= stop2) break;
        for (size_t i = 0; i < n; i++) E->z[i] = E->diag[i] > 0 ? E->r[i] / E->diag[i] : E->r[i];
        const double rz2 = dot(E->r, E->z);
        for (size_t i = 0; i < n; i++) E->p[i] = E->z[i] + (rz2 / rz) * E->p[i];
        rz = rz2;
    }
    center(E->d);
}

/* Damped Newton from the current weights (0 when a cell is empty). */
void bnot_solve(bnot_engine *E)
{
    E->newton = 0;
    E->cg_iters = 0;
    E->ok = 1;
    bnot_build(E);
    if (E->empty) {
        std::fill(E->w.begin(), E->w.end(), 0.0);
        bnot_build(E);
    }
    for (;;) {
        if (E->res_tol > 0 ? std::sqrt(E->res2) < E->res_tol : E->cap_err <= E->cap_tol) break;
        if (E->newton >= E->max_newton) {
            E->ok = E->res_tol > 0; /* the authors' rule caps the steps */
            return;
        }
        newton_direction(E);
        E->wold = E->w;
        const double floor = 0.5 * std::min(E->min_area, E->target), res = std::sqrt(E->res2);
        int accepted = 0;
        for (double a = 1; a > 1e-12 && !accepted; a *= 0.5) {
            for (size_t i = 0; i < E->w.size(); i++) E->w[i] = E->wold[i] + a * E->d[i];
            bnot_build(E);
            accepted = E->empty == 0 && E->min_area >= floor && std::sqrt(E->res2) <= (1 - a / 2) * res;
        }
        E->newton++;
        if (!accepted) { /* no progress possible (rounding): keep the last weights */
            E->w = E->wold;
            bnot_build(E);
            E->ok = 0;
            return;
        }
    }
}

extern "C" void bnot_deltas(bnot_engine *E, double *dmin, double *davg)
{
    const int rc = E->dens ? cfpo_dens_nn(E->dens, E->xy.data(), (size_t)E->n, nullptr, dmin, davg)
                           : cfpo_nn_stats(E->xy.data(), (size_t)E->n, nullptr, dmin, davg);
    if (rc != 0) *dmin = *davg = NAN;
}
