/* backend_cpu.c - the OpenMP backend (see backend.h): the cells of one
 * colour solved in parallel by the engine's threads, one cell a task, on
 * the host arrays; relocation by eng_relocate (engine_move.c). What to do
 * with each point (its square, which solver, over-relaxation) is the
 * iteration's policy, E->pol (policy.h): this file holds no decision and
 * no constant of the variants' schedules. */
#include "backend.h"

#include <math.h>
#include <string.h>

#include "geom.h"
#include "omp_compat.h"

/* Copies the 3x3 block around own cell (lx, ly) into local coordinates
 * (origin at the cell's lower-left corner), cells in row-major order, ids
 * ascending inside each: the canonical order of Y. Returns the count;
 * *centre is the index of the centre cell's first point. */
static int gather_shifted(const cfpo_engine *E, int64_t lx, int64_t ly, double *ox_, double *oy_, int *centre)
{
    const int64_t cx = E->x0 + lx, cy = E->y0 + ly;
    const double L = E->G.L, shx = E->G.shift_x, shy = E->G.shift_y;
    const double ox = (double)cx * L + shx, oy = (double)cy * L + shy;
    int m = 0;
    /* The last cell wraps, so unwrap point by point (to the copy nearest
     * the neighbour cell's centre). */
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            if (dx == 0 && dy == 0) *centre = m;
            const double mx = ((double)(cx + dx) + 0.5) * L + shx, my = ((double)(cy + dy) + 0.5) * L + shy;
            const int64_t e = locate(E, lx + dx, ly + dy);
            const double *X, *Y;
            uint32_t a, b;
            cell_slice(E, e, &X, &Y, &a, &b);
            for (uint32_t k = a; k < b; k++, m++) {
                ox_[m] = (X[k] + nearbyint(mx - X[k])) - ox;
                oy_[m] = (Y[k] + nearbyint(my - Y[k])) - oy;
            }
        }
    return m;
}

/* The same points as the general gathers, in the same order, with the same
 * arithmetic (v + 0 - o is v - o exactly), from three runs of slots. */
__attribute__((optimize("no-tree-vectorize"))) /* runs of 3-4 points: a vector loop's set-up costs more */
static int gather_plain(const cfpo_engine *E, int64_t lx, int64_t ly, double *ox_, double *oy_, int *centre)
{
    const double L = E->G.L;
    const double ox = (double)(E->x0 + lx) * L + E->G.shift_x, oy = (double)(E->y0 + ly) * L + E->G.shift_y;
    const int64_t c = ly * E->w + lx;
    const uint32_t *st = E->start;
    const double *X = E->px, *Y = E->py;
    int m = 0;
    for (int dy = -1; dy <= 1; dy++) {
        const int64_t r = c + dy * E->w;
        if (dy == 0) *centre = m + (int)(st[c] - st[c - 1]);
        const uint32_t a = st[r - 1], b = st[r + 2];
        for (uint32_t k = a; k < b; k++, m++) {
            ox_[m] = X[k] - ox;
            oy_[m] = Y[k] - oy;
        }
    }
    return m;
}

/* The points of the 3x3 block around own cell (lx, ly) in the cell's frame
 * (origin at its lower-left corner), cells row by row, ids ascending in
 * each: the canonical order of Y. Returns the count; *centre is the index
 * of the centre cell's first point. */
static int eng_gather_block(const cfpo_engine *E, int64_t lx, int64_t ly, double *ox_, double *oy_, int *centre)
{
    if (eng_plain_block(E, lx, ly)) return gather_plain(E, lx, ly, ox_, oy_, centre);
    if (E->G.shift_x != 0 || E->G.shift_y != 0) return gather_shifted(E, lx, ly, ox_, oy_, centre);
    const int64_t g = E->G.g, cx = E->x0 + lx, cy = E->y0 + ly;
    const double ox = (double)cx * E->G.L, oy = (double)cy * E->G.L;
    int m = 0;
    for (int dy = -1; dy <= 1; dy++) {
        const int64_t ny = cy + dy;
        const double sy = ny < 0 ? -1.0 : (ny >= g ? 1.0 : 0.0);
        for (int dx = -1; dx <= 1; dx++) {
            const int64_t nx = cx + dx;
            const double sx = nx < 0 ? -1.0 : (nx >= g ? 1.0 : 0.0);
            if (dx == 0 && dy == 0) *centre = m;
            const int64_t e = locate(E, lx + dx, ly + dy);
            const double *X, *Y;
            uint32_t a, b;
            cell_slice(E, e, &X, &Y, &a, &b);
            for (uint32_t k = a; k < b; k++, m++) {
                ox_[m] = (X[k] + sx) - ox;
                oy_[m] = (Y[k] + sy) - oy;
            }
        }
    }
    return m;
}

/* Point slot k moved by (ddx, ddy) in the frame of the cell at global
 * (cx, cy), to local (nx, ny): stores it, adds to its net displacement and
 * returns the mask bit of the cell that now holds it. */
static unsigned store_move(cfpo_engine *E, uint32_t k, int64_t cx, int64_t cy, double nx, double ny, double ddx,
                           double ddy)
{
    const double ox = (double)cx * E->G.L + E->G.shift_x, oy = (double)cy * E->G.L + E->G.shift_y;
    const double gx = cfpo_wrap01(nx + ox), gy = cfpo_wrap01(ny + oy);
    E->px[k] = gx;
    E->py[k] = gy;
    E->dq[2 * k] += (float)ddx;
    E->dq[2 * k + 1] += (float)ddy;
    const int dx = wrap_offset(cfpo_grid_cx(&E->G, gx) - cx, E->G.g);
    const int dy = wrap_offset(cfpo_grid_cy(&E->G, gy) - cy, E->G.g);
    return 1u << ((dy + 1) * 3 + (dx + 1));
}

/* The transport sweep's move of point gi of the block (transport.h): along
 * the band's field or the grid's print's (gridmodes.h), shortened to
 * P->vmax, keeping min(r0, P->cap) from every point (the square keeps it
 * from those beyond the block). */
static int transport_move(const cfpo_engine *E, const double *lxs, const double *lys, int m, int gi, double ox,
                          double oy, double *nx, double *ny)
{
    const cfpo_policy *P = &E->pol;
    const double x = lxs[gi], y = lys[gi], r02 = cfpo_min_dist2(x, y, lxs, lys, m, gi);
    if (isinf(r02)) return 0;
    const double floor2 = fmin(r02, P->cap * P->cap);
    cfpo_square Sx;
    if (!cfpo_policy_square(P, sqrt(floor2), &Sx)) return 0;
    double ux, uy;
    const double gx = cfpo_wrap01(x + ox), gy = cfpo_wrap01(y + oy);
    if (P->transport == CFPO_TRANSPORT_PRINT) cfpo_gridmodes_field(&E->gm, gx, gy, &ux, &uy);
    else cfpo_transport_field(&E->lf, gx, gy, &ux, &uy);
    const double u = sqrt(ux * ux + uy * uy);
    if (u > P->vmax) ux *= P->vmax / u, uy *= P->vmax / u;
    return cfpo_transport_move(x, y, ux, uy, lxs, lys, m, gi, r02, floor2, &Sx, nx, ny);
}

/* Solves every point of own cell (lx, ly) in id order. Returns moves. */
static int64_t solve_cell(cfpo_engine *E, int64_t lx, int64_t ly, double *buf, int64_t *solved, double *maxmove)
{
    const int64_t c = ly * E->w + lx;
    const uint32_t s = E->start[c], e = E->start[c + 1];
    if (s == e) return 0;
    if (E->o.skip && !(E->mask[c] & NEED_BIT)) return 0;
    const size_t mcap = E->scratch_m;
    double *lxs = buf, *lys = buf + mcap, *sol = buf + 2 * mcap;
    int off = 0;
    const int m = eng_gather_block(E, lx, ly, lxs, lys, &off);
    const double tolL = E->o.tol * E->G.L;
    const cfpo_policy *P = &E->pol;
    int64_t moves = 0;
    unsigned mask = 0;
    const double ox = (double)(E->x0 + lx) * E->G.L + E->G.shift_x, oy = (double)(E->y0 + ly) * E->G.L + E->G.shift_y;
    /* Held points (id < cfg.fixed) are neighbours only; ids ascend inside
     * a cell, so they are the cell's first slots. */
    uint32_t k0 = 0;
    if (E->cfg.fixed)
        while (k0 < e - s && E->pid[s + k0] < (uint64_t)E->cfg.fixed) k0++;
    for (uint32_t k = k0; k < e - s; k++) {
        const int gi = off + (int)k;
        const double x = lxs[gi], y = lys[gi];
        if (P->transport) {
            double nx, ny;
            (*solved)++;
            if (!transport_move(E, lxs, lys, m, gi, ox, oy, &nx, &ny)) continue;
            lxs[gi] = nx;
            lys[gi] = ny;
            const double ddx = nx - x, ddy = ny - y, mv = ddx * ddx + ddy * ddy;
            if (mv > *maxmove) *maxmove = mv;
            mask |= store_move(E, s + k, E->x0 + lx, E->y0 + ly, nx, ny, ddx, ddy);
            moves++;
            continue;
        }
        const double r02 = cfpo_min_dist2(x, y, lxs, lys, m, gi);
        if (isinf(r02)) continue;
        const double thr = sqrt(r02) + tolL, floor2 = thr * thr;
        cfpo_square Sx;
        if (!cfpo_policy_square(P, thr, &Sx)) continue;
        double nx, ny;
        const double v = P->near ? cfpo_near_solve(lxs, lys, m, gi, Sx, x, y, floor2, &nx, &ny, sol, P->near_cells)
                                 : cfpo_local_solve(lxs, lys, m, gi, Sx, x, y, floor2, &nx, &ny, sol);
        (*solved)++;
        if (!(v > floor2)) continue;
        if (P->relax) cfpo_policy_relax(P, &Sx, lxs, lys, m, gi, x, y, floor2, &nx, &ny);
        lxs[gi] = nx;
        lys[gi] = ny;
        const double ddx = nx - x, ddy = ny - y, mv = ddx * ddx + ddy * ddy;
        if (mv > *maxmove) *maxmove = mv;
        mask |= store_move(E, s + k, E->x0 + lx, E->y0 + ly, nx, ny, ddx, ddy);
        moves++;
    }
    E->mask[c] = (uint16_t)mask; /* and no longer NEED_BIT */
    return moves;
}

static int64_t cpu_solve(cfpo_engine *E, const eng_colour *C, int64_t *solved)
{
    const int64_t T = C->nxc * C->nyc;
    int64_t moves = 0, solv = 0;
    double mm = E->max_move;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : moves, solv) reduction(max : mm) num_threads(E->nthreads)
    for (int64_t t = 0; t < T; t++) {
        int64_t lx, ly;
        if (!eng_colour_cell(C, t, &lx, &ly)) continue;
        moves += solve_cell(E, lx, ly, E->scratch[omp_get_thread_num()], &solv, &mm);
    }
    E->max_move = mm;
    *solved += solv;
    return moves;
}

static void cpu_regrid(cfpo_engine *E, const eng_colour *C)
{
    const int64_t g = E->G.g, T = C->nxc * C->nyc;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t t = 0; t < T; t++) {
        int64_t lx, ly;
        if (!eng_colour_cell(C, t, &lx, &ly)) continue;
        const int64_t c = ly * E->w + lx, cx = E->x0 + lx, cy = E->y0 + ly;
        unsigned mask = 0;
        for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
            const int dx = wrap_offset(cfpo_grid_cx(&E->G, E->px[k]) - cx, g);
            const int dy = wrap_offset(cfpo_grid_cy(&E->G, E->py[k]) - cy, g);
            mask |= 1u << ((dy + 1) * 3 + (dx + 1));
        }
        E->mask[c] = (uint16_t)((E->mask[c] & NEED_BIT) | mask);
    }
}

static int cpu_mark(cfpo_engine *E, const eng_colour *C)
{
    int crossed = 0;
    for (int64_t t = 0; t < C->nxc * C->nyc; t++) {
        int64_t lx, ly;
        if (!eng_colour_cell(C, t, &lx, &ly)) continue;
        const unsigned mk = E->mask[ly * E->w + lx] & 0x1ffu;
        if (!mk) continue;
        eng_mark_block(E, lx, ly);
        for (int bit = 0; bit < 9; bit++)
            if (bit != 4 && (mk >> bit & 1u)) {
                crossed = 1;
                eng_mark_block(E, lx + bit % 3 - 1, ly + bit / 3 - 1);
            }
    }
    return crossed;
}

static void cpu_unmark(cfpo_engine *E, const eng_colour *C)
{
    for (int64_t t = 0; t < C->nxc * C->nyc; t++) {
        int64_t lx, ly;
        if (eng_colour_cell(C, t, &lx, &ly)) E->mask[ly * E->w + lx] &= NEED_BIT;
    }
}

static void cpu_begin(cfpo_engine *E)
{
    memset(E->dq, 0, 2 * (size_t)E->nloc * sizeof(float));
    E->max_move = 0;
}

static double cpu_max_disp2(const cfpo_engine *E)
{
    double maxd2 = 0;
#pragma omp parallel for schedule(static) reduction(max : maxd2) num_threads(E->nthreads)
    for (int64_t i = 0; i < E->nloc; i++) {
        const double dx = E->dq[2 * i], dy = E->dq[2 * i + 1];
        const double d2 = dx * dx + dy * dy;
        if (d2 > maxd2) maxd2 = d2;
    }
    return maxd2;
}

const cfpo_backend eng_backend_cpu = {
    .name = "cpu",
    .begin = cpu_begin,
    .solve = cpu_solve,
    .regrid = cpu_regrid,
    .mark = cpu_mark,
    .unmark = cpu_unmark,
    .relocate = eng_relocate,
    .max_disp2 = cpu_max_disp2,
    .sync_host = NULL,
    .sync_device = NULL,
};
