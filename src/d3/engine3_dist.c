/* engine3_dist.c - see engine3_dist.h. */
#include "engine3_dist.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "nn3.h"
#include "omp_compat.h"

/* A migrating point: its new cell and position. */
typedef struct {
    int64_t id, cell;
    double x[3];
} mig_rec;

static void coords(int64_t c, int g, int *i, int *j, int *k)
{
    *i = (int)(c % g);
    *j = (int)((c / g) % g);
    *k = (int)(c / ((int64_t)g * g));
}

static int in_region_cell(const cfpo3_bricks *B, const int r[3], int64_t c)
{
    int i, j, k;
    coords(c, B->g, &i, &j, &k);
    return cfpo3_bricks_in_region(B, r, i, j, k);
}

static int mine_cell(const cfpo3_bricks *B, int64_t c)
{
    int i, j, k;
    coords(c, B->g, &i, &j, &k);
    return cfpo3_bricks_mine(B, i, j, k);
}

int cfpo3_dist_init(cfpo3_engine *e, char *err, size_t errlen)
{
    if (cfpo3_bricks_init(&e->B, e->G.g, comm_size(), comm_rank(), err, errlen) != 0) return -1;
    e->dist = e->B.P > 1;
    if (e->B.nnb > 0) {
        e->msg = calloc((size_t)e->B.nnb, sizeof *e->msg);
        if (!e->msg) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        for (int k = 0; k < e->B.nnb; k++) e->msg[k].rank = e->B.nb[k];
    }
    return 0;
}

void cfpo3_dist_free(cfpo3_engine *e)
{
    cfpo3_bricks_free(&e->B);
    free(e->mv.v);
    if (e->msg)
        for (int k = 0; k < e->B.nnb; k++) free(e->msg[k].recv);
    free(e->msg);
    for (int k = 0; k < 26; k++) free(e->sendbuf[k]);
}

static int put(cfpo3_engine *e, int k, size_t *len, const void *rec, size_t bytes)
{
    if (len[k] + bytes > e->sendcap[k]) {
        const size_t cap = 2 * (len[k] + bytes) + 4096;
        void *nb = realloc(e->sendbuf[k], cap);
        if (!nb) return -1;
        e->sendbuf[k] = nb;
        e->sendcap[k] = cap;
    }
    memcpy((char *)e->sendbuf[k] + len[k], rec, bytes);
    len[k] += bytes;
    return 0;
}

/* Sends sendbuf[k] (len[k] bytes) to neighbour k, receives theirs into
 * msg[k].recv; counts the bytes. */
static int exchange(cfpo3_engine *e, const size_t *len, double *bytes)
{
    for (int k = 0; k < e->B.nnb; k++) {
        e->msg[k].send = e->sendbuf[k];
        e->msg[k].sendbytes = len[k];
        *bytes += (double)len[k];
    }
    return comm_exchange(e->msg, e->B.nnb);
}

void cfpo3_dist_cells(cfpo3_engine *e)
{
    const int g = e->G.g;
    const cfpo3_bricks *B = &e->B;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < e->n; i++) {
        if (e->cellof[i] < 0) continue;
        const double *x = e->pos + 3 * i;
        const int a = cfpo3_cell1(cfpo3_u(x[0], e->shift[0]), g);
        const int b = cfpo3_cell1(cfpo3_u(x[1], e->shift[1]), g);
        const int c = cfpo3_cell1(cfpo3_u(x[2], e->shift[2]), g);
        e->cellof[i] = cfpo3_bricks_in_region(B, B->me, a, b, c) ? (int32_t)((c * g + b) * g + a) : -1;
    }
}

int cfpo3_dist_migrate(cfpo3_engine *e)
{
    const double t0 = omp_get_wtime();
    const int g = e->G.g, nnb = e->B.nnb;
    const cfpo3_bricks *B = &e->B;
    int32_t *nw = malloc(sizeof(int32_t) * (size_t)e->n);
    int fail = nw == NULL;
    if (comm_all(!fail) == 0) {
        free(nw);
        return -1;
    }
    /* the new cell of each point of this brick (under the old shift) */
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < e->n; i++) {
        nw[i] = -1;
        if (e->cellof[i] < 0 || !mine_cell(B, e->cellof[i])) continue;
        const double *x = e->pos + 3 * i;
        const int a = cfpo3_cell1(cfpo3_u(x[0], e->shift[0]), g);
        const int b = cfpo3_cell1(cfpo3_u(x[1], e->shift[1]), g);
        const int c = cfpo3_cell1(cfpo3_u(x[2], e->shift[2]), g);
        nw[i] = (int32_t)((c * g + b) * g + a);
    }
    size_t len[26] = {0};
    int runs[26][3];
    for (int k = 0; k < nnb; k++) cfpo3_bricks_runs(B, B->nb[k], runs[k]);
    for (int64_t i = 0; i < e->n && !fail; i++) {
        if (nw[i] < 0) continue;
        const mig_rec r = {i, nw[i], {e->pos[3 * i], e->pos[3 * i + 1], e->pos[3 * i + 2]}};
        for (int k = 0; k < nnb; k++)
            if (in_region_cell(B, runs[k], nw[i]) && put(e, k, len, &r, sizeof r) != 0) fail = 1;
    }
    if (comm_all(!fail) == 0) {
        free(nw);
        return -1;
    }
    /* what stays here, then what came in */
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < e->n; i++) e->cellof[i] = nw[i] >= 0 && in_region_cell(B, B->me, nw[i]) ? nw[i] : -1;
    free(nw);
    if (exchange(e, len, &e->b_migrate) != 0) return -1;
    for (int k = 0; k < nnb; k++) {
        const size_t cnt = e->msg[k].recvbytes / sizeof(mig_rec);
        for (size_t q = 0; q < cnt; q++) {
            mig_rec r;
            memcpy(&r, (const char *)e->msg[k].recv + q * sizeof r, sizeof r);
            e->cellof[r.id] = (int32_t)r.cell;
            memcpy(e->pos + 3 * r.id, r.x, sizeof r.x);
        }
    }
    e->t_migrate += omp_get_wtime() - t0;
    return 0;
}

int cfpo3_dist_note(cfpo3_move_list *l, int64_t id, int32_t from, int32_t to, const double *x, const double *p0)
{
    if (l->len == l->cap) {
        const int64_t cap = 2 * l->cap + 64;
        cfpo3_move *v = realloc(l->v, sizeof *v * (size_t)cap);
        if (!v) return -1;
        l->v = v;
        l->cap = cap;
    }
    cfpo3_move *m = &l->v[l->len++];
    m->id = id, m->from = from, m->to = to;
    memcpy(m->x, x, sizeof m->x);
    memcpy(m->p0, p0, sizeof m->p0);
    return 0;
}

int cfpo3_dist_halo(cfpo3_engine *e, uint64_t ph, int *crossed)
{
    const double t0 = omp_get_wtime();
    const int nnb = e->B.nnb;
    const cfpo3_bricks *B = &e->B;
    size_t len[26] = {0};
    int runs[26][3], fail = 0;
    for (int k = 0; k < nnb; k++) cfpo3_bricks_runs(B, B->nb[k], runs[k]);
    for (int64_t q = 0; q < e->mv.len && !fail; q++) {
        const cfpo3_move *m = &e->mv.v[q];
        for (int k = 0; k < nnb; k++)
            if ((in_region_cell(B, runs[k], m->from) || in_region_cell(B, runs[k], m->to)) &&
                put(e, k, len, m, sizeof *m) != 0)
                fail = 1;
    }
    e->mv.len = 0;
    if (comm_all(!fail) == 0) return -1;
    if (exchange(e, len, &e->b_halo) != 0) return -1;
    for (int k = 0; k < nnb; k++) {
        const size_t cnt = e->msg[k].recvbytes / sizeof(cfpo3_move);
        for (size_t q = 0; q < cnt; q++) {
            cfpo3_move m;
            memcpy(&m, (const char *)e->msg[k].recv + q * sizeof m, sizeof m);
            e->changed[m.from] = ph;
            e->changed[m.to] = ph;
            const int32_t now = in_region_cell(B, B->me, m.to) ? m.to : -1;
            if (e->cellof[m.id] != now) *crossed = 1;
            e->cellof[m.id] = now;
            if (now >= 0) {
                memcpy(e->pos + 3 * m.id, m.x, sizeof m.x);
                memcpy(e->prev + 3 * m.id, m.p0, sizeof m.p0);
            }
        }
    }
    e->t_halo += omp_get_wtime() - t0;
    return 0;
}

/* The squared distance from point i to its nearest other in i's 3x3x3
 * block (the same arithmetic as nn3.c's), INFINITY when none. */
static double block_nn2(const cfpo3_engine *e, int64_t i)
{
    const int g = e->G.g;
    int ci, cj, ck;
    coords(e->cellof[i], g, &ci, &cj, &ck);
    const double *p = e->pos;
    double best = INFINITY;
    for (int dz = -1; dz <= 1; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int64_t cc = ((int64_t)((ck + dz + g) % g) * g + (cj + dy + g) % g) * g + (ci + dx + g) % g;
                for (int64_t s = e->cstart[cc]; s < e->cstart[cc + 1]; s++) {
                    const int64_t j = e->cids[s];
                    if (j == i) continue;
                    const double ex = cfpo3_pdiff(p[3 * j], p[3 * i]);
                    const double ey = cfpo3_pdiff(p[3 * j + 1], p[3 * i + 1]);
                    const double ez = cfpo3_pdiff(p[3 * j + 2], p[3 * i + 2]);
                    const double d = ex * ex + ey * ey + ez * ez;
                    if (d < best) best = d;
                }
            }
    return best;
}

int cfpo3_dist_measure(cfpo3_engine *e)
{
    const double t0 = omp_get_wtime();
    const cfpo3_bricks *B = &e->B;
    const int g = e->G.g;
    const int lo[3] = {B->lo[0][B->me[0]], B->lo[1][B->me[1]], B->lo[2][B->me[2]]};
    const int w[3] = {B->lo[0][B->me[0] + 1] - lo[0], B->lo[1][B->me[1] + 1] - lo[1], B->lo[2][B->me[2] + 1] - lo[2]};
    const int64_t ncell = (int64_t)w[0] * w[1] * w[2];
    const double L2 = e->G.L * e->G.L;
    double *d2 = malloc(sizeof(double) * (size_t)(e->n > 0 ? e->n : 1)); /* by id, own points */
    if (comm_all(d2 != NULL) == 0) {
        free(d2);
        return -1;
    }
    int64_t unsure = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : unsure)
    for (int64_t q = 0; q < ncell; q++) {
        const int i = lo[0] + (int)(q % w[0]), j = lo[1] + (int)((q / w[0]) % w[1]), k = lo[2] + (int)(q / ((int64_t)w[0] * w[1]));
        const int64_t c = ((int64_t)k * g + j) * g + i;
        for (int64_t s = e->cstart[c]; s < e->cstart[c + 1]; s++) {
            const int64_t id = e->cids[s];
            d2[id] = block_nn2(e, id);
            if (!(d2[id] <= L2)) unsure++;
        }
    }
    comm_sum_i64(&unsure, 1);
    if (unsure > 0) { /* a nearest neighbour may lie beyond the block: the whole set */
        double *all = malloc(sizeof(double) * 3 * (size_t)e->n), *all2 = malloc(sizeof(double) * (size_t)e->n);
        int ok = all && all2;
        if (comm_all(ok) == 0 || cfpo3_dist_gather(e, all) != 0 || comm_all(cfpo3_knn(all, (size_t)e->n, 1, NULL, all2) == 0) == 0) {
            free(all), free(all2), free(d2);
            return -1;
        }
        free(all);
        free(d2);
        d2 = all2;
    }
    double mn = INFINITY;
    int64_t sum[2] = {0, 0};
    const double two31 = 2147483648.0;
#pragma omp parallel for schedule(static) reduction(min : mn) reduction(+ : sum[:2])
    for (int64_t q = 0; q < ncell; q++) {
        const int i = lo[0] + (int)(q % w[0]), j = lo[1] + (int)((q / w[0]) % w[1]), k = lo[2] + (int)(q / ((int64_t)w[0] * w[1]));
        const int64_t c = ((int64_t)k * g + j) * g + i;
        for (int64_t s = e->cstart[c]; s < e->cstart[c + 1]; s++) {
            const double d = sqrt(d2[e->cids[s]]);
            if (d < mn) mn = d;
            const double hi = floor(d * two31);
            sum[0] += (int64_t)hi;
            sum[1] += (int64_t)floor((d * two31 - hi) * two31);
        }
    }
    free(d2);
    comm_min_d(&mn, 1);
    comm_sum_i64(sum, 2);
    const double D = cfpo3_delta_bound((double)e->n);
    const double total = (double)sum[0] / two31 + (double)sum[1] / (two31 * two31);
    e->dmin = mn / D;
    e->davg = total / (double)e->n / D;
    e->t_compute += omp_get_wtime() - t0;
    return 0;
}

int cfpo3_dist_gather(const cfpo3_engine *e, double *all)
{
    if (!e->dist) {
        memcpy(all, e->pos, sizeof(double) * 3 * (size_t)e->n);
        return 0;
    }
    const int64_t own = cfpo3_dist_own(e);
    double *buf = malloc(sizeof(double) * 4 * (size_t)(own > 0 ? own : 1));
    if (comm_all(buf != NULL) == 0) {
        free(buf);
        return -1;
    }
    int64_t k = 0;
    for (int64_t i = 0; i < e->n; i++)
        if (e->cellof[i] >= 0 && mine_cell(&e->B, e->cellof[i])) {
            buf[4 * k] = (double)i; /* ids below 2^53 are exact */
            memcpy(buf + 4 * k + 1, e->pos + 3 * i, sizeof(double) * 3);
            k++;
        }
    void *got = NULL;
    size_t total = 0;
    const int rc = comm_allgatherv(buf, sizeof(double) * 4 * (size_t)own, &got, &total);
    free(buf);
    if (rc != 0) return -1;
    const double *r = got;
    const size_t cnt = total / (4 * sizeof(double));
    for (size_t q = 0; q < cnt; q++) memcpy(all + 3 * (int64_t)r[4 * q], r + 4 * q + 1, sizeof(double) * 3);
    free(got);
    return cnt == (size_t)e->n ? 0 : -1;
}

int64_t cfpo3_dist_own(const cfpo3_engine *e)
{
    int64_t k = 0;
    for (int64_t i = 0; i < e->n; i++)
        if (e->cellof[i] >= 0 && mine_cell(&e->B, e->cellof[i])) k++;
    return k;
}
