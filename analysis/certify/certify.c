/* certify.c - see certify.h.
 *
 * Why the neighbourhoods are large enough (rho = largest empty circle of X,
 * d(x) = d(x, X \ {x}); every set below is taken with all periodic images,
 * so small n needs no special case):
 *
 * Farthest point test. R(x) = max_p d(p, X\{x}) over the torus. Outside
 * the Voronoi cell V(x) of x, d(p, X\{x}) = d(p, X) <= rho; inside it,
 * d(p, X\{x}) >= d(p, x) = d(p, X). So R(x) = max(rho, T), T = the largest
 * d(p, X\{x}) over p in V(x). V(x) lies in the disk of radius rho around
 * x, so in the square S_x of half-side s = rho (or the torus, s = 1/2),
 * and is S_x clipped by the bisectors of x and every image within
 * (Chebyshev) s + rho of x (a Voronoi neighbour y has a point c of V(x)
 * with |c - y| = |c - x| <= rho). For p in V(x), let y be its nearest image
 * of X\{x}: shrinking the disk around p through y towards y, the first copy
 * of x met lies on its boundary with y, empty disk: y is a Voronoi neighbour
 * of that copy, so a translate of y is one of x and its bisector touches
 * V(x). So T is the maximum over V(x) of the distance to the images of the
 * points whose bisector touches V(x) (every image of them within s + rho +
 * d(x), where p's nearest lies): a handful of points even when V(x) is a
 * strip across the torus (collinear points) or a wide wedge (a cluster),
 * where one LocalCFPO over S_x with every image costs O(n^2). Coincident
 * points count once (they give the same distances).
 *
 * A cell's radius is LocalCFPO on the cell with the points of a square
 * around it, grown until the answer is no larger than the margin between
 * the cell and the square's edge (no point outside can then be nearer).
 *
 * Local Characterization Theorem. D(x), S(x) as in certify.h; both
 * properties are one LocalCFPO each on S(x): with all points of D(x)
 * (property 1) and without x (property 2). */
#include "certify.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cellradius.h"
#include "certwork.h"
#include "farthest.h"
#include "lct.h"
#include "geom.h"
#include "nnhist.h"
#include "ptree.h"
#include "stats.h"
#include "vmax.h"

typedef an_cert_ctx ctx;
typedef an_cert_work work;


typedef struct {
    double fp, p1, p2; /* violations, absolute */
    double tx, ty;     /* a farthest point of X \ {x} on the torus */
} point_result;

static int check_point(const ctx *C, size_t i, work *w, point_result *res)
{
    const double x = C->xy[2 * i], y = C->xy[2 * i + 1], di = C->nn[i];
    double s = C->rho * (1 + 1e-9) + 1e-12;
    if (s >= 0.5) s = 0.5;
    const double H1 = (s + C->rho + di) * (1 + 1e-9) + 1e-12;
    const double h = fmax(fmax(3 * C->delta, C->delta + di), C->Dn) * (1 + 1e-9);

    /* Farthest point test: R(x) = max(rho, T). */
    double T, tx = 0, ty = 0;
    if (an_cert_reserve(w, 64) != 0) return -1;
    const int st = an_vmax(C, i, w, x, y, s, fmax(H1, h), &T, &tx, &ty);
    if (st != 0) return st;
    const size_t top = C->top;
    res->fp = fmax(T, C->rho) - di;
    res->tx = T >= C->rho ? tx : C->arg_cell[2 * top];
    res->ty = T >= C->rho ? ty : C->arg_cell[2 * top + 1];

    /* Local Characterization Theorem (lct.c). */
    return an_lct(C, i, w, h, &res->p1, &res->p2);
}

typedef int (*item_fn)(const ctx *C, size_t t, work *w, void *out);

static int cell_item(const ctx *C, size_t t, work *w, void *out)
{
    (void)out;
    const size_t c = C->order[t];
    return an_cell_radius(C, c, C->cell_ub[c], C->n, w, C->rho_cell + c, C->arg_cell + 2 * c);
}

static int point_item(const ctx *C, size_t t, work *w, void *out)
{
    return check_point(C, t, w, (point_result *)out + t);
}

/* fn over 0..count-1 in parallel, each thread with its own buffers.
 * 0, or the first failure seen (-1 memory, -2 solver). */
static int parallel_over(const ctx *C, size_t count, item_fn fn, void *out)
{
    int status = 0;
#pragma omp parallel
    {
        work w = {0};
        int mine = 0;
#pragma omp for schedule(dynamic, 64)
        for (size_t t = 0; t < count; t++)
            if (mine == 0) mine = fn(C, t, &w, out);
#pragma omp critical(an_certify_status)
        if (mine < 0 && status == 0) status = mine;
        an_cert_work_free(&w);
    }
    return status;
}

static void summarise(const point_result *pr, size_t n, double tol, double Dn, an_certificate *c,
                      double *viol, double *target, unsigned char *pass)
{
    for (size_t i = 0; i < n && viol; i++) viol[i] = pr[i].fp / Dn;
    for (size_t i = 0; i < n && pass; i++)
        pass[i] = (unsigned char)((pr[i].fp <= tol ? AN_PASS_FP : 0) | (pr[i].p1 <= tol ? AN_PASS_P1 : 0) |
                                  (pr[i].p2 <= tol ? AN_PASS_P2 : 0));
    for (size_t i = 0; i < n && target; i++) {
        target[2 * i] = pr[i].tx;
        target[2 * i + 1] = pr[i].ty;
    }
    c->fp_max_violation = c->p1_max_violation = c->p2_max_violation = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        c->fp_pass += pr[i].fp <= tol;
        c->p1_pass += pr[i].p1 <= tol;
        c->p2_pass += pr[i].p2 <= tol;
        c->lct_pass += pr[i].p1 <= tol && pr[i].p2 <= tol;
        if (pr[i].fp / Dn > c->fp_max_violation) {
            c->fp_max_violation = pr[i].fp / Dn;
            c->fp_worst = i;
        }
        c->p1_max_violation = fmax(c->p1_max_violation, pr[i].p1 / Dn);
        c->p2_max_violation = fmax(c->p2_max_violation, pr[i].p2 / Dn);
    }
    c->fpd = c->fp_pass == n && c->lct_pass == n;
}

/* rho, the largest empty circle of X, and the cell where it is reached
 * (the largest radius, the lowest index among equal ones). A cell's radius
 * lies within its centre's distance to X plus its half-diagonal (ub), so
 * the cells are solved exactly by decreasing ub, a batch at a time, until
 * the next ub is below the largest radius found: no cell left can reach
 * it. rho_cell and arg_cell are filled for the cells solved. */
static int covering(ctx *C, size_t *order, double *ub)
{
    const size_t cells = C->G.g * C->G.g;
    int status = 0;
#pragma omp parallel for schedule(dynamic, 64)
    for (size_t t = 0; t < cells; t++) ub[t] = an_cell_bound(C, t, C->n);
    an_cell_key *keys = malloc(cells * sizeof *keys);
    if (!keys) return -1;
    for (size_t t = 0; t < cells; t++) keys[t] = (an_cell_key){ub[t], t};
    qsort(keys, cells, sizeof *keys, an_cell_key_desc);
    for (size_t t = 0; t < cells; t++) order[t] = keys[t].c;
    free(keys);
    C->cell_ub = ub;
    C->rho = -1;
    C->top = cells;
    /* Small batches first: the first radii found usually end it. */
    size_t batch = 2 * (size_t)omp_get_max_threads();
    for (size_t a = 0; a < cells && !(ub[order[a]] < C->rho); batch = batch < 256 ? 2 * batch : batch) {
        const size_t b = a + batch < cells ? a + batch : cells;
        C->order = order + a;
        status = parallel_over(C, b - a, cell_item, NULL);
        if (status < 0) return status;
        for (size_t t = a; t < b; t++) {
            const size_t c = order[t];
            if (C->rho_cell[c] > C->rho || (C->rho_cell[c] == C->rho && c < C->top)) {
                C->rho = C->rho_cell[c];
                C->top = c;
            }
        }
        a = b;
    }
    return 0;
}

int an_certify(const double *xy, size_t n, double tol_rel, an_certificate *c, double *viol,
               double *target, char *err, size_t errlen)
{
    return an_certify_points(xy, n, tol_rel, c, viol, target, NULL, err, errlen);
}

int an_certify_points(const double *xy, size_t n, double tol_rel, an_certificate *c, double *viol,
                      double *target, unsigned char *pass, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->n = n;
    c->tol_rel = tol_rel;
    if (n < 2) {
        snprintf(err, errlen, "the certificate needs at least 2 points");
        return -1;
    }
    an_ptree tree;
    ctx C = {.xy = xy, .n = n, .Dn = cfpo_delta_bound((double)n), .tree = &tree};
    double *nn = malloc(n * sizeof *nn);
    point_result *pr = malloc(n * sizeof *pr);
    double *rho_cell = NULL, *arg_cell = NULL, *ub = NULL;
    size_t *order = NULL;
    int status = 0;
    double dmin, davg;
    if (an_ptree_build(&tree, xy, n) != 0 || !nn || !pr || an_cellgrid_build(xy, n, &C.G) != 0 ||
        an_nn_stats(xy, n, &tree, nn, &dmin, &davg) != 0) {
        status = -1;
        goto done;
    }
    const size_t cells = C.G.g * C.G.g;
    rho_cell = malloc(cells * sizeof *rho_cell);
    arg_cell = malloc(2 * cells * sizeof *arg_cell);
    order = malloc(cells * sizeof *order);
    ub = malloc(cells * sizeof *ub);
    if (!rho_cell || !arg_cell || !order || !ub) { status = -1; goto done; }
    C.rho_cell = rho_cell;
    C.arg_cell = arg_cell;
    C.nn = nn;
    C.delta = dmin * C.Dn;
    status = covering(&C, order, ub);
    if (status < 0) goto done;
    status = parallel_over(&C, n, point_item, pr);
    if (status < 0) goto done;
    c->delta = dmin;
    c->covering = C.rho / C.Dn;
    summarise(pr, n, tol_rel * C.Dn, C.Dn, c, viol, target, pass);
done:
    if (status == -1) snprintf(err, errlen, "certificate: out of memory");
    if (status == -2) snprintf(err, errlen, "certificate: the local solver found no candidate");
    free(nn); free(pr); free(rho_cell); free(arg_cell); free(order); free(ub);
    an_cellgrid_free(&C.G);
    an_ptree_free(&tree);
    return status < 0 ? -1 : 0;
}

void an_certificate_merge(an_certificate *a, const an_certificate *b)
{
    if (a->n == 0) { *a = *b; return; }
    if (b->fp_max_violation > a->fp_max_violation) {
        a->fp_max_violation = b->fp_max_violation;
        a->fp_worst = b->fp_worst;
    }
    a->n += b->n;
    a->delta = fmin(a->delta, b->delta);
    a->covering = fmax(a->covering, b->covering);
    a->fp_pass += b->fp_pass;
    a->p1_pass += b->p1_pass;
    a->p2_pass += b->p2_pass;
    a->lct_pass += b->lct_pass;
    a->p1_max_violation = fmax(a->p1_max_violation, b->p1_max_violation);
    a->p2_max_violation = fmax(a->p2_max_violation, b->p2_max_violation);
    a->fpd = a->fpd && b->fpd;
}
