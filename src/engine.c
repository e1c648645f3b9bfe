/* engine.c - see engine.h.
 *
 * Why a phase is race-free (written once, here): cells of one colour are
 * `period` cells apart in both directions. A point of cell C may move only
 * inside S(x), C grown by L - Delta(n) < L, so it stays in C's 3x3 block,
 * and solving C reads only C's 3x3 block. With period 3 the blocks of two
 * same-colour cells are disjoint, so no cell is written by one thread and
 * read by another (Parallelization Theorem). The simplified variant keeps
 * points in their own cell, so period 2 suffices: blocks overlap only in
 * cells nobody writes. Inside a cell, points are solved in id order, each
 * seeing the moves of the ones before it; buckets are rebuilt between
 * phases, and only when some point crossed into another cell.
 *
 * Skipping: a cell is solved again only if some cell of its 3x3 block
 * changed (a point moved in it, left it or arrived) since its last solve.
 * An unchanged block means the same inputs (same Y in the same order, same
 * x), hence the same answer, which last time was "do not move", so the
 * output is byte-identical to recomputing everything. */
#include "engine.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "omp_compat.h"

struct cfpo_engine {
    cfpo_grid G;
    cfpo_options o;
    int64_t n, cells;
    double *px, *py;  /* positions, cell by cell */
    uint32_t *pid;    /* ids, ascending inside a cell (n < 2^32 per process) */
    double *tx, *ty;  /* spare buffers for rebuilding and output */
    uint32_t *tid;
    uint32_t *start;  /* CSR: cell c holds [start[c], start[c+1]) */
    uint32_t *start2; /* the next CSR offsets, while relocating */
    uint8_t *need;    /* cell must be solved (its block changed) */
    uint16_t *mask;   /* this phase: bit (dy+1)*3+(dx+1) set if a point of
                         the cell moved into the cell at offset (dx,dy) */
    float *disp;      /* 2 per id: net displacement this iteration */
    double *rowsum, *rowmin;
    int nthreads;
    int maxcell;
    double **scratch; /* per thread */
    size_t scratch_m; /* points the scratch is sized for */
};

static double now(void) { return omp_get_wtime(); }

const cfpo_grid *cfpo_engine_grid(const cfpo_engine *E) { return &E->G; }

static size_t thread_scratch_doubles(size_t m) { return 2 * m + cfpo_solver_scratch(m); }

uint64_t cfpo_engine_bytes(int64_t n, int variant, int threads)
{
    cfpo_grid G;
    char err[8];
    if (cfpo_grid_init(&G, n, variant, 0, err, sizeof err) != 0) return 0;
    uint64_t cells = (uint64_t)(G.g * G.g);
    return (uint64_t)n * (2 * (16 + 4) + 8) + cells * (4 + 4 + 1 + 2) + 8 + (uint64_t)G.g * 16 +
           (uint64_t)(threads > 0 ? threads : 1) * thread_scratch_doubles(64) * 8;
}

void cfpo_engine_free(cfpo_engine *E)
{
    if (!E) return;
    free(E->px); free(E->py); free(E->pid);
    free(E->tx); free(E->ty); free(E->tid);
    free(E->start); free(E->start2); free(E->need); free(E->mask); free(E->disp);
    free(E->rowsum); free(E->rowmin);
    if (E->scratch)
        for (int t = 0; t < E->nthreads; t++) free(E->scratch[t]);
    free(E->scratch);
    free(E);
}

static int ensure_scratch(cfpo_engine *E)
{
    size_t m = (size_t)9 * (size_t)E->maxcell + 1;
    if (m <= E->scratch_m) return 0;
    m = m < 64 ? 64 : m + m / 2;
    for (int t = 0; t < E->nthreads; t++) {
        double *b = realloc(E->scratch[t], thread_scratch_doubles(m) * sizeof(double));
        if (!b) return -1;
        E->scratch[t] = b;
    }
    E->scratch_m = m;
    return 0;
}

static inline int64_t cell_of(const cfpo_engine *E, double x, double y)
{
    return cfpo_grid_coord(&E->G, y) * E->G.g + cfpo_grid_coord(&E->G, x);
}

/* Is cell e's mask bit for the neighbour at offset (dx, dy) set? */
static inline int sends_to(unsigned mk, int dx, int dy) { return mk >> ((dy + 1) * 3 + (dx + 1)) & 1u; }
#define CENTRE_BIT (1u << 4)

/* Moves points that changed cell in the last phase into their new cells.
 * Only the cells of that phase's colour can have sent points (their masks
 * say where to), so each cell gathers its own new content: the points of
 * its old slice that stayed, then arrivals from the neighbours whose mask
 * points at it, then id order. Parallel over cells, deterministic, O(n)
 * copying and O(points of sending cells) cell computations. */
static int relocate(cfpo_engine *E)
{
    const int64_t g = E->G.g, cells = E->cells;
    const uint32_t *st = E->start;
    uint32_t *ns = E->start2;
    const uint16_t *mask = E->mask;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t c = 0; c < cells; c++) {
        const int64_t cx = c % g, cy = c / g;
        uint32_t cnt = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int64_t e = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                const unsigned mk = mask[e];
                if (dx == 0 && dy == 0) {
                    if (!(mk & ~CENTRE_BIT)) { cnt += st[c + 1] - st[c]; continue; }
                } else if (!sends_to(mk, -dx, -dy)) continue;
                for (uint32_t k = st[e]; k < st[e + 1]; k++) cnt += cell_of(E, E->px[k], E->py[k]) == c;
            }
        ns[c + 1] = cnt;
    }
    ns[0] = 0;
    for (int64_t c = 0; c < cells; c++) ns[c + 1] += ns[c];
    int maxcell = 0;
#pragma omp parallel for schedule(static) reduction(max : maxcell) num_threads(E->nthreads)
    for (int64_t c = 0; c < cells; c++) {
        const int64_t cx = c % g, cy = c / g;
        uint32_t w = ns[c];
        int arrivals = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int64_t e = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                const unsigned mk = mask[e];
                int check;
                if (dx == 0 && dy == 0) check = (mk & ~CENTRE_BIT) != 0;
                else if (sends_to(mk, -dx, -dy)) check = 1, arrivals = 1;
                else continue;
                for (uint32_t k = st[e]; k < st[e + 1]; k++) {
                    if (check && cell_of(E, E->px[k], E->py[k]) != c) continue;
                    E->tx[w] = E->px[k];
                    E->ty[w] = E->py[k];
                    E->tid[w] = E->pid[k];
                    w++;
                }
            }
        if (arrivals) /* insertion sort by id; cells hold a handful of points */
            for (uint32_t k = ns[c] + 1; k < w; k++) {
                const uint32_t id = E->tid[k];
                const double x = E->tx[k], y = E->ty[k];
                uint32_t j = k;
                while (j > ns[c] && E->tid[j - 1] > id) {
                    E->tid[j] = E->tid[j - 1];
                    E->tx[j] = E->tx[j - 1];
                    E->ty[j] = E->ty[j - 1];
                    j--;
                }
                E->tid[j] = id;
                E->tx[j] = x;
                E->ty[j] = y;
            }
        if ((int)(w - ns[c]) > maxcell) maxcell = (int)(w - ns[c]);
    }
    double *t;
    t = E->px; E->px = E->tx; E->tx = t;
    t = E->py; E->py = E->ty; E->ty = t;
    uint32_t *u;
    u = E->pid; E->pid = E->tid; E->tid = u;
    u = E->start; E->start = E->start2; E->start2 = u;
    E->maxcell = maxcell;
    return ensure_scratch(E);
}

cfpo_engine *cfpo_engine_create(int64_t n, const cfpo_options *o, char *err, size_t errlen)
{
    if (cfpo_validate(n, o, err, errlen) != 0) return NULL;
    cfpo_engine *E = calloc(1, sizeof *E);
    if (!E) { snprintf(err, errlen, "out of memory"); return NULL; }
    E->o = *o;
    E->n = n;
    cfpo_grid_init(&E->G, n, o->variant, o->seed, err, errlen);
    E->cells = E->G.g * E->G.g;
    E->nthreads = o->threads > 0 ? o->threads : omp_get_num_procs();
    size_t nn = (size_t)n, nc = (size_t)E->cells;
    E->px = malloc(nn * sizeof(double));
    E->py = malloc(nn * sizeof(double));
    E->pid = malloc(nn * sizeof(uint32_t));
    E->tx = malloc(nn * sizeof(double));
    E->ty = malloc(nn * sizeof(double));
    E->tid = malloc(nn * sizeof(uint32_t));
    E->disp = calloc(2 * nn, sizeof(float));
    E->start = malloc((nc + 1) * sizeof(uint32_t));
    E->start2 = malloc((nc + 1) * sizeof(uint32_t));
    E->need = malloc(nc);
    E->mask = calloc(nc, sizeof(uint16_t));
    E->rowsum = malloc((size_t)E->G.g * sizeof(double));
    E->rowmin = malloc((size_t)E->G.g * sizeof(double));
    E->scratch = calloc((size_t)E->nthreads, sizeof(double *));
    if (!E->px || !E->py || !E->pid || !E->tx || !E->ty || !E->tid || !E->disp || !E->start || !E->start2 ||
        !E->need || !E->mask || !E->rowsum || !E->rowmin || !E->scratch) {
        snprintf(err, errlen, "out of memory for n = %lld (%.1f GB needed)", (long long)n,
                 (double)cfpo_engine_bytes(n, o->variant, E->nthreads) / 1e9);
        cfpo_engine_free(E);
        return NULL;
    }
    memset(E->need, 1, nc);
    /* Initial set, straight into the buckets: cell by cell, ids in order,
     * every point inside its cell (grid.c guarantees it). */
    int64_t k = 0;
    const int64_t g = E->G.g;
    int maxcell = 0;
    for (int64_t c = 0; c < E->cells; c++) {
        E->start[c] = (uint32_t)k;
        uint64_t cnt = cfpo_grid_cell_count(&E->G, (uint64_t)c);
        if ((int)cnt > maxcell) maxcell = (int)cnt;
        for (uint64_t j = 0; j < cnt; j++, k++) {
            cfpo_grid_cell_point(&E->G, c % g, c / g, j, &E->px[k], &E->py[k]);
            E->pid[k] = (uint32_t)k;
        }
    }
    E->start[E->cells] = (uint32_t)k;
    E->maxcell = maxcell;
    if (ensure_scratch(E) != 0) {
        snprintf(err, errlen, "out of memory");
        cfpo_engine_free(E);
        return NULL;
    }
    return E;
}

/* Copies the 3x3 block around (cx, cy) into local coordinates (origin at
 * the cell's lower-left corner), cells in row-major order, ids ascending
 * inside each: the canonical order of Y. Returns the count; *centre is the
 * index of the centre cell's first point. */
static int gather(const cfpo_engine *E, int64_t cx, int64_t cy, double *lx, double *ly,
                  int *centre)
{
    const int64_t g = E->G.g;
    const double ox = (double)cx * E->G.L, oy = (double)cy * E->G.L;
    int m = 0;
    for (int dy = -1; dy <= 1; dy++) {
        int64_t ny = cy + dy;
        double sy = 0;
        if (ny < 0) { ny += g; sy = -1; } else if (ny >= g) { ny -= g; sy = 1; }
        for (int dx = -1; dx <= 1; dx++) {
            int64_t nx = cx + dx;
            double sx = 0;
            if (nx < 0) { nx += g; sx = -1; } else if (nx >= g) { nx -= g; sx = 1; }
            if (dx == 0 && dy == 0) *centre = m;
            int64_t c = ny * g + nx;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++, m++) {
                lx[m] = (E->px[k] + sx) - ox;
                ly[m] = (E->py[k] + sy) - oy;
            }
        }
    }
    return m;
}

static inline int wrap_offset(int64_t d, int64_t g)
{
    if (d > 1) d -= g;
    if (d < -1) d += g;
    return (int)d;
}

/* Solves every point of cell (cx, cy) in id order. Returns moves. */
static int64_t solve_cell(cfpo_engine *E, int64_t cx, int64_t cy, double *buf, int64_t *solved)
{
    const int64_t g = E->G.g, c = cy * g + cx;
    const uint32_t s = E->start[c], e = E->start[c + 1];
    if (s == e) return 0;
    if (E->o.skip && !E->need[c]) return 0;
    E->need[c] = 0;
    const size_t mcap = E->scratch_m;
    double *lx = buf, *ly = buf + mcap, *sol = buf + 2 * mcap;
    int off = 0;
    const int m = gather(E, cx, cy, lx, ly, &off);
    const cfpo_square S = cfpo_grid_square(&E->G);
    const double tolL = E->o.tol * E->G.L;
    const double ox = (double)cx * E->G.L, oy = (double)cy * E->G.L;
    int64_t moves = 0;
    unsigned mask = 0;
    for (uint32_t k = 0; k < e - s; k++) {
        const int gi = off + (int)k;
        const double x = lx[gi], y = ly[gi];
        const double r02 = cfpo_min_dist2(x, y, lx, ly, m, gi);
        if (isinf(r02)) continue;
        const double thr = sqrt(r02) + tolL, floor2 = thr * thr;
        double nx, ny;
        const double v = cfpo_local_solve(lx, ly, m, gi, S, x, y, floor2, &nx, &ny, sol);
        (*solved)++;
        if (!(v > floor2)) continue;
        lx[gi] = nx;
        ly[gi] = ny;
        const double gx = cfpo_wrap01(nx + ox), gy = cfpo_wrap01(ny + oy);
        E->px[s + k] = gx;
        E->py[s + k] = gy;
        const uint32_t id = E->pid[s + k];
        E->disp[2 * id] += (float)(nx - x);
        E->disp[2 * id + 1] += (float)(ny - y);
        int ddx = wrap_offset(cfpo_grid_coord(&E->G, gx) - cx, g);
        int ddy = wrap_offset(cfpo_grid_coord(&E->G, gy) - cy, g);
        mask |= 1u << ((ddy + 1) * 3 + (ddx + 1));
        moves++;
    }
    E->mask[c] = (uint16_t)mask;
    return moves;
}

static void mark_block(cfpo_engine *E, int64_t cx, int64_t cy)
{
    const int64_t g = E->G.g;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            E->need[((cy + dy + g) % g) * g + (cx + dx + g) % g] = 1;
}

int64_t cfpo_engine_phase(cfpo_engine *E, int colour, int64_t *solved)
{
    const int p = E->G.period;
    const int64_t g = E->G.g, per = g / p, T = per * per;
    const int64_t a = colour / p, b = colour % p;
    int64_t moves = 0, solv = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : moves, solv) num_threads(E->nthreads)
    for (int64_t t = 0; t < T; t++) {
        const int64_t cy = a + p * (t / per), cx = b + p * (t % per);
        moves += solve_cell(E, cx, cy, E->scratch[omp_get_thread_num()], &solv);
    }
    *solved = solv;
    if (moves == 0) return 0;
    /* Mark the blocks that changed; move points that changed cell; then
     * clear the masks. */
    int crossed = 0;
    for (int64_t t = 0; t < T; t++) {
        const int64_t cy = a + p * (t / per), cx = b + p * (t % per), c = cy * g + cx;
        const unsigned mk = E->mask[c];
        if (!mk) continue;
        mark_block(E, cx, cy);
        for (int bit = 0; bit < 9; bit++)
            if (bit != 4 && (mk >> bit & 1u)) {
                crossed = 1;
                mark_block(E, cx + bit % 3 - 1, cy + bit / 3 - 1);
            }
    }
    if (crossed && relocate(E) != 0) {
        fprintf(stderr, "cfpo: out of memory while moving points between cells\n");
        exit(1);
    }
    for (int64_t t = 0; t < T; t++)
        E->mask[(a + p * (t / per)) * g + b + p * (t % per)] = 0;
    return moves;
}

/* Nearest-neighbour distance^2 of point k (global index) in cell (cx, cy):
 * rings of cells outward until no unvisited cell can be closer. */
static double nn2(const cfpo_engine *E, int64_t cx, int64_t cy, uint32_t k)
{
    const int64_t g = E->G.g;
    const double L = E->G.L, x = E->px[k], y = E->py[k];
    const double lx = x - (double)cx * L, ly = y - (double)cy * L;
    double edge = fmin(fmin(lx, L - lx), fmin(ly, L - ly));
    if (edge < 0) edge = 0;
    double best = INFINITY;
    for (int64_t r = 0;; r++) {
        if (2 * r + 1 > g) { /* the rings would wrap onto themselves: all */
            for (int64_t j = 0; j < E->n; j++)
                if ((uint32_t)j != k) {
                    double d2 = cfpo_torus_dist2(x, y, E->px[j], E->py[j]);
                    if (d2 < best) best = d2;
                }
            return best;
        }
        for (int64_t dy = -r; dy <= r; dy++)
            for (int64_t dx = -r; dx <= r; dx++) {
                if (dy != -r && dy != r && dx != -r && dx != r) continue;
                int64_t c = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                for (uint32_t j = E->start[c]; j < E->start[c + 1]; j++) {
                    if (j == k) continue;
                    double d2 = cfpo_torus_dist2(x, y, E->px[j], E->py[j]);
                    if (d2 < best) best = d2;
                }
            }
        double reach = (double)r * L + edge; /* distance to any unvisited cell */
        if (best <= reach * reach) return best;
    }
}

void cfpo_engine_deltas(cfpo_engine *E, double *dmin, double *davg)
{
    const int64_t g = E->G.g;
#pragma omp parallel for schedule(static) num_threads(E->nthreads)
    for (int64_t cy = 0; cy < g; cy++) {
        double sum = 0, mn = INFINITY;
        for (int64_t cx = 0; cx < g; cx++) {
            int64_t c = cy * g + cx;
            for (uint32_t k = E->start[c]; k < E->start[c + 1]; k++) {
                double d = sqrt(nn2(E, cx, cy, k));
                sum += d;
                if (d < mn) mn = d;
            }
        }
        E->rowsum[cy] = sum;
        E->rowmin[cy] = mn;
    }
    double sum = 0, mn = INFINITY;
    for (int64_t cy = 0; cy < g; cy++) { /* fixed order: same sum for any thread count */
        sum += E->rowsum[cy];
        if (E->rowmin[cy] < mn) mn = E->rowmin[cy];
    }
    *dmin = mn / E->G.delta;
    *davg = sum / (double)E->n / E->G.delta;
}

void cfpo_engine_iterate(cfpo_engine *E, cfpo_iter_stats *s)
{
    double t0 = now();
    memset(E->disp, 0, 2 * (size_t)E->n * sizeof(float));
    int64_t moved = 0, solved = 0;
    const int ncol = E->G.period * E->G.period;
    for (int colour = 0; colour < ncol; colour++) {
        int64_t sv = 0;
        moved += cfpo_engine_phase(E, colour, &sv);
        solved += sv;
    }
    double maxd2 = 0;
    if (moved) {
#pragma omp parallel for schedule(static) reduction(max : maxd2) num_threads(E->nthreads)
        for (int64_t i = 0; i < E->n; i++) {
            double dx = E->disp[2 * i], dy = E->disp[2 * i + 1];
            double d2 = dx * dx + dy * dy;
            if (d2 > maxd2) maxd2 = d2;
        }
    }
    s->moved = moved;
    s->solved = solved;
    s->max_disp = sqrt(maxd2) / E->G.L;
    s->converged = moved == 0 || s->max_disp < E->o.tol;
    cfpo_engine_deltas(E, &s->delta_min, &s->delta_avg);
    s->seconds = now() - t0;
}

void cfpo_engine_run(cfpo_engine *E, cfpo_result *res)
{
    double t0 = now();
    cfpo_iter_stats s = {0};
    cfpo_engine_deltas(E, &s.delta_min, &s.delta_avg);
    s.seconds = now() - t0;
    int stop = E->o.progress ? E->o.progress(&s, E->o.user) : 0;
    int it = 0;
    while (!stop && !s.converged && it < E->o.max_iter) {
        cfpo_engine_iterate(E, &s);
        s.iteration = ++it;
        if (E->o.progress) stop = E->o.progress(&s, E->o.user);
    }
    res->iterations = it;
    res->converged = s.converged;
    res->seconds = now() - t0;
    res->delta_min = s.delta_min;
    res->delta_avg = s.delta_avg;
    res->cells_per_side = E->G.g;
}

void cfpo_engine_points(const cfpo_engine *E, double *xy)
{
    for (int64_t i = 0; i < E->n; i++) {
        xy[2 * E->pid[i]] = E->px[i];
        xy[2 * E->pid[i] + 1] = E->py[i];
    }
}

int cfpo_engine_write(cfpo_engine *E, pf_writer *w, char *err, size_t errlen)
{
    for (int64_t i = 0; i < E->n; i++) {
        E->tx[E->pid[i]] = E->px[i];
        E->ty[E->pid[i]] = E->py[i];
    }
    enum { CHUNK = 4096 };
    double buf[2 * CHUNK];
    for (int64_t i = 0; i < E->n; i += CHUNK) {
        int64_t cnt = E->n - i < CHUNK ? E->n - i : CHUNK;
        for (int64_t j = 0; j < cnt; j++) {
            buf[2 * j] = E->tx[i + j];
            buf[2 * j + 1] = E->ty[i + j];
        }
        if (pf_writer_put(w, buf, (size_t)cnt, err, errlen) != 0) return -1;
    }
    return 0;
}
