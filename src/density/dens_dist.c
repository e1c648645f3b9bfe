/* dens_dist.c - layer 3: the density engine's cut, store, migration and
 * halos on several ranks (dens_dist.h).
 * Messages: a point travels as {id, x, y, q} (32 bytes) on migration and
 * halo fetch, as {x, y, q} (24 bytes) on a phase's refresh, where both
 * sides walk the same cells in the same order (the lists are made once:
 * for each colour and neighbour, this rank's cells next to the neighbour's,
 * and the neighbour's next to this rank's). */
#include "dens_dist.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"

typedef struct {
    int64_t *v;
    int64_t n, cap;
} ivec;

typedef struct {
    int64_t gid;
    double x, y, q;
} wire;

struct cfpo_dens_dist {
    int64_t g;
    int P, me, nnb;
    int *owner;   /* g g: the rank of each cell */
    int *nb;      /* nnb neighbour ranks, increasing */
    int *nb_of;   /* P: index in nb, or -1 */
    ivec mine[9]; /* this rank's cells of each colour */
    ivec *snd, *rcv; /* [colour * P + a]: cells sent to / received from nb[a] after that colour's phase */
    comm_msg *msg;   /* [a], for nb[a]; the receive buffers kept */
    char **sbuf;
    size_t *scap;
    double sx, sy; /* the offset of the last cut */
    int placed;    /* a cut was made */
};

static int push(ivec *v, int64_t x)
{
    if (v->n == v->cap) {
        int64_t cap = v->cap ? 2 * v->cap : 16;
        int64_t *p = realloc(v->v, (size_t)cap * sizeof *p);
        if (!p) return -1;
        v->v = p;
        v->cap = cap;
    }
    v->v[v->n++] = x;
    return 0;
}

int cfpo_dens_store_reserve(cfpo_dens_store *s, int64_t cap, int with_gid)
{
    if (cap < 1) cap = 1;
    if (cap <= s->cap && (!with_gid || s->gid)) return 0;
    if (cap < s->cap) cap = s->cap;
    double *xy = realloc(s->xy, (size_t)cap * 2 * sizeof *xy);
    if (xy) s->xy = xy;
    double *q = realloc(s->q, (size_t)cap * sizeof *q);
    if (q) s->q = q;
    int64_t *gid = with_gid ? realloc(s->gid, (size_t)cap * sizeof *gid) : s->gid;
    if (gid) s->gid = gid;
    if (!xy || !q || (with_gid && !gid)) return -1;
    s->cap = cap;
    return 0;
}

void cfpo_dens_store_free(cfpo_dens_store *s)
{
    free(s->xy);
    free(s->q);
    free(s->gid);
    memset(s, 0, sizeof *s);
}

int64_t cfpo_dens_dist_max_ranks(int64_t g) { return (g / 3) * (g / 3); }

/* The points of each cell under the shift (sx, sy) (g g doubles,
 * row-major): of the store's own points, summed over the ranks when `all`
 * (on one rank's whole set, before the first cut, not). Collective. */
static double *cell_points(const cfpo_dens_dist *T, const cfpo_dens_store *s, double sx, double sy, int all)
{
    const int64_t g = T->g;
    double *M = calloc((size_t)(g * g), sizeof *M);
    if (M)
        for (int64_t i = 0; i < s->own; i++) M[cfpo_dens_cell_of(g, sx, sy, s->xy[2 * i], s->xy[2 * i + 1])] += 1;
    if (!comm_all(M != NULL)) {
        free(M);
        return NULL;
    }
    if (all) comm_sum_d(M, (int)(g * g));
    return M;
}

static int near_rank(const cfpo_dens_dist *T, int64_t c, int r)
{
    const int64_t g = T->g, cx = c % g, cy = c / g;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (T->owner[((cy + dy + g) % g) * g + (cx + dx + g) % g] == r) return 1;
    return 0;
}

static int colour_of(int64_t g, int64_t c) { return (int)((c % g) % 3 + 3 * ((c / g) % 3)); }

/* The cut for the shift (sx, sy): owners, this rank's cells, neighbours
 * and the refresh lists. 0, or -1 when out of memory. */
static int recut(cfpo_dens_dist *T, const cfpo_dens_store *s, double sx, double sy, int all)
{
    const int64_t g = T->g;
    const int P = T->P;
    double *M = cell_points(T, s, sx, sy, all);
    if (!M) return -1;
    T->sx = sx;
    T->sy = sy;
    T->placed = 1;
    double total = 0, acc = 0;
    for (int64_t c = 0; c < g * g; c++) total += M[c];
    for (int64_t k = 0; k < g * g; k++) { /* up the even columns, down the odd ones */
        const int64_t ix = k / g, r = k % g, iy = (ix & 1) ? g - 1 - r : r, c = iy * g + ix;
        int o = (int)floor((double)P * (acc + 0.5 * M[c]) / total);
        T->owner[c] = o < 0 ? 0 : o >= P ? P - 1 : o;
        acc += M[c];
    }
    free(M);
    for (int k = 0; k < 9; k++) T->mine[k].n = 0;
    for (int k = 0; k < 9 * P; k++) T->snd[k].n = T->rcv[k].n = 0;
    for (int r = 0; r < P; r++) T->nb_of[r] = -1;
    T->nnb = 0;
    for (int64_t c = 0; c < g * g; c++)
        if (T->owner[c] == T->me) {
            if (push(&T->mine[colour_of(g, c)], c) != 0) return -1;
            const int64_t cx = c % g, cy = c / g;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    const int r = T->owner[((cy + dy + g) % g) * g + (cx + dx + g) % g];
                    if (r != T->me) T->nb_of[r] = 0;
                }
        }
    for (int r = 0; r < P; r++)
        if (T->nb_of[r] == 0) { T->nb_of[r] = T->nnb; T->nb[T->nnb++] = r; }
    for (int64_t c = 0; c < g * g; c++) {
        const int o = T->owner[c], k = colour_of(g, c);
        if (o != T->me && T->nb_of[o] < 0) continue;
        for (int a = 0; a < T->nnb; a++) {
            if (o == T->me && near_rank(T, c, T->nb[a]) && push(&T->snd[k * P + a], c) != 0) return -1;
            if (o == T->nb[a] && near_rank(T, c, T->me) && push(&T->rcv[k * P + a], c) != 0) return -1;
        }
    }
    for (int a = 0; a < T->nnb; a++) T->msg[a].rank = T->nb[a];
    return 0;
}

cfpo_dens_dist *cfpo_dens_dist_create(int64_t g, char *err, size_t errlen)
{
    const int P = comm_size();
    if ((int64_t)P > cfpo_dens_dist_max_ranks(g)) {
        const int64_t m = cfpo_dens_dist_max_ranks(g);
        snprintf(err, errlen, "the grid has %lld x %lld cells, enough for at most %lld rank%s (this run has %d): "
                 "use fewer ranks or more points", (long long)g, (long long)g, (long long)m, m == 1 ? "" : "s", P);
        return NULL;
    }
    cfpo_dens_dist *T = calloc(1, sizeof *T);
    if (!T) goto oom;
    T->g = g;
    T->P = P;
    T->me = comm_rank();
    T->owner = malloc((size_t)(g * g) * sizeof *T->owner);
    T->nb_of = malloc((size_t)P * sizeof *T->nb_of);
    T->nb = malloc((size_t)P * sizeof *T->nb);
    T->snd = calloc(9 * (size_t)P, sizeof *T->snd);
    T->rcv = calloc(9 * (size_t)P, sizeof *T->rcv);
    T->msg = calloc((size_t)P, sizeof *T->msg);
    T->sbuf = calloc((size_t)P, sizeof *T->sbuf);
    T->scap = calloc((size_t)P, sizeof *T->scap);
    if (!T->owner || !T->nb_of || !T->nb || !T->snd || !T->rcv || !T->msg || !T->sbuf || !T->scap) goto oom;
    return T;
oom:
    cfpo_dens_dist_free(T);
    snprintf(err, errlen, "out of memory for the cut of %lld x %lld cells", (long long)g, (long long)g);
    return NULL;
}

const int64_t *cfpo_dens_dist_cells(const cfpo_dens_dist *T, int colour, int64_t *count)
{
    *count = T->mine[colour].n;
    return T->mine[colour].v;
}

int cfpo_dens_dist_keep(cfpo_dens_dist *T, cfpo_dens_store *s, double sx, double sy)
{
    if (recut(T, s, sx, sy, 0) != 0 || !comm_all(cfpo_dens_store_reserve(s, s->cap, 1) == 0)) return -1;
    int64_t k = 0;
    for (int64_t i = 0; i < s->own; i++)
        if (T->owner[cfpo_dens_cell_of(T->g, sx, sy, s->xy[2 * i], s->xy[2 * i + 1])] == T->me) {
            s->xy[2 * k] = s->xy[2 * i];
            s->xy[2 * k + 1] = s->xy[2 * i + 1];
            s->q[k] = s->q[i];
            s->gid[k++] = i;
        }
    s->own = s->loc = k;
    return 0;
}

static int grow_buf(char **b, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    size_t c = need + need / 2 + 64;
    char *p = realloc(*b, c);
    if (!p) return -1;
    *b = p;
    *cap = c;
    return 0;
}

static void put(cfpo_dens_store *s, int64_t k, const wire *w)
{
    s->gid[k] = w->gid;
    s->xy[2 * k] = w->x;
    s->xy[2 * k + 1] = w->y;
    s->q[k] = w->q;
}

/* Appends the halo: every own point of a cell next to a neighbour's cells
 * goes to that neighbour, in id order. */
static int fetch_halo(cfpo_dens_dist *T, cfpo_dens_store *s, double sx, double sy)
{
    const int64_t g = T->g;
    size_t *len = calloc((size_t)(T->nnb ? T->nnb : 1), sizeof *len);
    int ok = len != NULL;
    for (int64_t i = 0; ok && i < s->own; i++) {
        const int64_t c = cfpo_dens_cell_of(g, sx, sy, s->xy[2 * i], s->xy[2 * i + 1]), cx = c % g, cy = c / g;
        int seen[9], ns = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int r = T->owner[((cy + dy + g) % g) * g + (cx + dx + g) % g];
                int dup = r == T->me;
                for (int t = 0; t < ns && !dup; t++) dup = seen[t] == r;
                if (dup) continue;
                seen[ns++] = r;
                const int a = T->nb_of[r];
                if (grow_buf(&T->sbuf[a], &T->scap[a], len[a] + sizeof(wire)) != 0) { ok = 0; break; }
                const wire w = {s->gid[i], s->xy[2 * i], s->xy[2 * i + 1], s->q[i]};
                memcpy(T->sbuf[a] + len[a], &w, sizeof w);
                len[a] += sizeof w;
            }
    }
    for (int a = 0; ok && a < T->nnb; a++) {
        T->msg[a].send = T->sbuf[a];
        T->msg[a].sendbytes = len[a];
    }
    free(len);
    if (!comm_all(ok) || comm_exchange(T->msg, T->nnb) != 0) return -1;
    int64_t more = 0;
    for (int a = 0; a < T->nnb; a++) more += (int64_t)(T->msg[a].recvbytes / sizeof(wire));
    if (!comm_all(cfpo_dens_store_reserve(s, s->loc + more, 1) == 0)) return -1;
    for (int a = 0; a < T->nnb; a++)
        for (size_t b = 0; b < T->msg[a].recvbytes; b += sizeof(wire)) {
            wire w;
            memcpy(&w, (char *)T->msg[a].recv + b, sizeof w);
            put(s, s->loc++, &w);
        }
    return 0;
}

int cfpo_dens_dist_migrate(cfpo_dens_dist *T, cfpo_dens_store *s, double sx, double sy)
{
    const int P = T->P;
    /* The same offset: no point left its cell (moves stay in their cells)
     * and every halo copy is current (refreshed after each colour). */
    if (T->placed && sx == T->sx && sy == T->sy) return 0;
    s->loc = s->own;
    if (recut(T, s, sx, sy, 1) != 0) return -1;
    void **send = calloc((size_t)P, sizeof *send), **recv = calloc((size_t)P, sizeof *recv);
    size_t *sbytes = calloc((size_t)P, sizeof *sbytes), *rbytes = calloc((size_t)P, sizeof *rbytes),
           *scap = calloc((size_t)P, sizeof *scap);
    int ok = send && recv && sbytes && rbytes && scap;
    int64_t kept = 0;
    for (int64_t i = 0; ok && i < s->own; i++) {
        const int o = T->owner[cfpo_dens_cell_of(T->g, sx, sy, s->xy[2 * i], s->xy[2 * i + 1])];
        if (o == T->me) {
            s->xy[2 * kept] = s->xy[2 * i];
            s->xy[2 * kept + 1] = s->xy[2 * i + 1];
            s->q[kept] = s->q[i];
            s->gid[kept++] = s->gid[i];
            continue;
        }
        if (grow_buf((char **)&send[o], &scap[o], sbytes[o] + sizeof(wire)) != 0) { ok = 0; break; }
        const wire w = {s->gid[i], s->xy[2 * i], s->xy[2 * i + 1], s->q[i]};
        memcpy((char *)send[o] + sbytes[o], &w, sizeof w);
        sbytes[o] += sizeof w;
    }
    int rc = -1;
    if (!comm_all(ok) || comm_alltoallv(send, sbytes, recv, rbytes) != 0) goto done;
    /* merge by id: what stayed (ids increasing) and each rank's part (the same) */
    int64_t total = kept;
    for (int r = 0; r < P; r++) total += (int64_t)(rbytes[r] / sizeof(wire));
    cfpo_dens_store m = {0};
    size_t *at = calloc((size_t)P, sizeof *at);
    ok = at && cfpo_dens_store_reserve(&m, total + total / 4 + 16, 1) == 0;
    if (!comm_all(ok)) { free(at); cfpo_dens_store_free(&m); goto done; }
    int64_t i = 0;
    for (int64_t k = 0; k < total; k++) {
        int best = -1; /* -1: the kept points */
        int64_t bid = i < kept ? s->gid[i] : INT64_MAX;
        for (int r = 0; r < P; r++)
            if (at[r] < rbytes[r]) {
                int64_t id;
                memcpy(&id, (char *)recv[r] + at[r], sizeof id);
                if (id < bid) { bid = id; best = r; }
            }
        if (best < 0) {
            m.gid[k] = s->gid[i];
            m.xy[2 * k] = s->xy[2 * i];
            m.xy[2 * k + 1] = s->xy[2 * i + 1];
            m.q[k] = s->q[i++];
        } else {
            wire w;
            memcpy(&w, (char *)recv[best] + at[best], sizeof w);
            at[best] += sizeof w;
            put(&m, k, &w);
        }
    }
    free(at);
    cfpo_dens_store_free(s);
    *s = m;
    s->own = s->loc = total;
    rc = fetch_halo(T, s, sx, sy);
done:
    for (int r = 0; r < P; r++) {
        if (send) free(send[r]);
        if (recv) free(recv[r]);
    }
    free(send); free(recv); free(sbytes); free(rbytes); free(scap);
    return rc;
}

int cfpo_dens_dist_refresh(cfpo_dens_dist *T, cfpo_dens_store *s, const int64_t *cstart, const int64_t *cidx,
                           double *cxyq, int colour, unsigned char *dirty, int64_t g)
{
    const int k0 = colour < 0 ? 0 : colour, k1 = colour < 0 ? 9 : colour + 1;
    int ok = 1;
    for (int a = 0; a < T->nnb; a++) {
        size_t len = 0;
        for (int k = k0; k < k1; k++) {
            const ivec *L = &T->snd[k * T->P + a];
            for (int64_t t = 0; t < L->n; t++) len += (size_t)(cstart[L->v[t] + 1] - cstart[L->v[t]]) * 3 * sizeof(double);
        }
        if (grow_buf(&T->sbuf[a], &T->scap[a], len) != 0) { ok = 0; break; }
        double *p = (double *)(void *)T->sbuf[a];
        for (int k = k0; k < k1; k++) {
            const ivec *L = &T->snd[k * T->P + a];
            for (int64_t t = 0; t < L->n; t++)
                for (int64_t e = cstart[L->v[t]]; e < cstart[L->v[t] + 1]; e++) {
                    const int64_t j = cidx[e];
                    *p++ = s->xy[2 * j];
                    *p++ = s->xy[2 * j + 1];
                    *p++ = s->q[j];
                }
        }
        T->msg[a].send = T->sbuf[a];
        T->msg[a].sendbytes = len;
    }
    if (!comm_all(ok) || comm_exchange(T->msg, T->nnb) != 0) return -1;
    for (int a = 0; a < T->nnb; a++) {
        size_t len = 0;
        for (int k = k0; k < k1; k++) {
            const ivec *L = &T->rcv[k * T->P + a];
            for (int64_t t = 0; t < L->n; t++) len += (size_t)(cstart[L->v[t] + 1] - cstart[L->v[t]]) * 3 * sizeof(double);
        }
        if (len != T->msg[a].recvbytes) { ok = 0; continue; }
        const double *p = (const double *)T->msg[a].recv;
        for (int k = k0; k < k1; k++) {
            const ivec *L = &T->rcv[k * T->P + a];
            for (int64_t t = 0; t < L->n; t++) {
                int changed = 0;
                for (int64_t e = cstart[L->v[t]]; e < cstart[L->v[t] + 1]; e++, p += 3) {
                    const int64_t j = cidx[e];
                    changed |= s->xy[2 * j] != p[0] || s->xy[2 * j + 1] != p[1] || s->q[j] != p[2];
                    s->xy[2 * j] = p[0];
                    s->xy[2 * j + 1] = p[1];
                    s->q[j] = p[2];
                    if (cxyq) {
                        cxyq[3 * e] = p[0];
                        cxyq[3 * e + 1] = p[1];
                        cxyq[3 * e + 2] = p[2];
                    }
                }
                if (changed && dirty) cfpo_dens_mark_block(dirty, g, L->v[t]);
            }
        }
    }
    return comm_all(ok) ? 0 : -1;
}

int cfpo_dens_dist_gather_values(const cfpo_dens_dist *T, const cfpo_dens_store *s, int64_t n, const double *v, int k,
                                 double *all)
{
    (void)T;
    const size_t rec = (size_t)(k + 1) * sizeof(double); /* id, then the k values */
    char *buf = malloc((size_t)(s->own ? s->own : 1) * rec);
    if (!comm_all(buf != NULL)) { free(buf); return -1; }
    for (int64_t i = 0; i < s->own; i++) {
        memcpy(buf + (size_t)i * rec, &s->gid[i], sizeof(int64_t));
        memcpy(buf + (size_t)i * rec + sizeof(int64_t), v + (size_t)k * (size_t)i, (size_t)k * sizeof(double));
    }
    void *got;
    size_t bytes;
    const int rc = comm_allgatherv(buf, (size_t)s->own * rec, &got, &bytes);
    free(buf);
    if (rc != 0) return -1;
    const size_t m = bytes / rec;
    int ok = (int64_t)m == n;
    for (size_t t = 0; ok && t < m; t++) {
        int64_t id;
        memcpy(&id, (char *)got + t * rec, sizeof id);
        if (id < 0 || id >= n) { ok = 0; break; }
        memcpy(&all[(size_t)k * (size_t)id], (char *)got + t * rec + sizeof id, (size_t)k * sizeof(double));
    }
    free(got);
    return ok ? 0 : -1;
}

void cfpo_dens_dist_free(cfpo_dens_dist *T)
{
    if (!T) return;
    for (int k = 0; k < 9; k++) free(T->mine[k].v);
    for (int k = 0; k < 9 * T->P; k++) {
        if (T->snd) free(T->snd[k].v);
        if (T->rcv) free(T->rcv[k].v);
    }
    for (int a = 0; a < T->P; a++) {
        if (T->msg) free(T->msg[a].recv);
        if (T->sbuf) free(T->sbuf[a]);
    }
    free(T->snd); free(T->rcv); free(T->msg); free(T->sbuf); free(T->scap);
    free(T->owner); free(T->nb); free(T->nb_of);
    free(T);
}
