/* comm.c - see comm.h: starting MPI, the ranks working alone,
 * reductions and exchanges. With comm_file.c (the shared files) the only
 * files of the project that call MPI. */
#define _GNU_SOURCE
#include "comm.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef CFPO_HAVE_MPI
#include <mpi.h>
#endif

static int active, rank, size = 1;

void comm_init(int *argc, char ***argv)
{
#ifdef CFPO_HAVE_MPI
    if (active) return;
    if (!getenv("OMPI_COMM_WORLD_SIZE") && !getenv("PMI_SIZE") && !getenv("PMIX_RANK")) return;
    int provided;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    active = 1;
#else
    (void)argc;
    (void)argv;
#endif
}

void comm_finalize(void)
{
#ifdef CFPO_HAVE_MPI
    if (active) {
        active = 0;
        MPI_Finalize();
    }
#endif
}

int comm_rank(void) { return rank; }
int comm_size(void) { return size; }

/* The job's rank and size while every rank works alone (comm_solo_begin). */
static int solo, world_rank, world_size;

void comm_solo_begin(void)
{
    if (solo) return;
    solo = 1;
    world_rank = rank;
    world_size = size;
    rank = 0;
    size = 1;
}

void comm_solo_end(void)
{
    if (!solo) return;
    solo = 0;
    rank = world_rank;
    size = world_size;
}

int comm_solo(void) { return solo; }

/* The ranks of the whole job, also while each works alone. */
static int job_size(void) { return solo ? world_size : size; }

void comm_abort(int code)
{
#ifdef CFPO_HAVE_MPI
    if (active && job_size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
    comm_finalize();
#endif
    exit(code);
}

int comm_local_size(void)
{
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        MPI_Comm local;
        int n = 1;
        MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
        MPI_Comm_size(local, &n);
        MPI_Comm_free(&local);
        return n;
    }
#endif
    return 1;
}

int comm_mpi_active(void) { return active; }

void comm_barrier(void)
{
#ifdef CFPO_HAVE_MPI
    if (active) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

/* An all-reduce in place over `ranks` ranks (this rank alone: nothing):
 * size for the reductions below, job_size() for comm_world_max_i64. */
#ifdef CFPO_HAVE_MPI
#define REDUCE_OVER(ranks, v, count, type, op)                                       \
    do {                                                                             \
        if (active && (ranks) > 1) MPI_Allreduce(MPI_IN_PLACE, v, count, type, op, MPI_COMM_WORLD); \
    } while (0)
#else
#define REDUCE_OVER(ranks, v, count, type, op) ((void)(ranks), (void)(v), (void)(count))
#endif
#define REDUCE(v, count, type, op) REDUCE_OVER(size, v, count, type, op)

void comm_sum_i64(int64_t *v, int count) { REDUCE(v, count, MPI_INT64_T, MPI_SUM); }
void comm_max_i64(int64_t *v, int count) { REDUCE(v, count, MPI_INT64_T, MPI_MAX); }
void comm_world_max_i64(int64_t *v, int count) { REDUCE_OVER(job_size(), v, count, MPI_INT64_T, MPI_MAX); }
void comm_min_d(double *v, int count) { REDUCE(v, count, MPI_DOUBLE, MPI_MIN); }
void comm_max_d(double *v, int count) { REDUCE(v, count, MPI_DOUBLE, MPI_MAX); }
void comm_sum_d(double *v, int count) { REDUCE(v, count, MPI_DOUBLE, MPI_SUM); }

int comm_all(int ok)
{
    int64_t bad = ok ? 0 : 1;
    comm_max_i64(&bad, 1);
    return bad == 0;
}

void comm_allgather_i64(int64_t v, int64_t *all)
{
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        MPI_Allgather(&v, 1, MPI_INT64_T, all, 1, MPI_INT64_T, MPI_COMM_WORLD);
        return;
    }
#endif
    all[0] = v;
}

void comm_bcast(void *buf, size_t bytes, int root)
{
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        for (size_t off = 0; off < bytes; off += COMM_PIECE) {
            size_t b = bytes - off < COMM_PIECE ? bytes - off : COMM_PIECE;
            MPI_Bcast((char *)buf + off, (int)b, MPI_BYTE, root, MPI_COMM_WORLD);
        }
    }
#else
    (void)buf;
    (void)bytes;
    (void)root;
#endif
}

#ifdef CFPO_HAVE_MPI
/* Posts the pieces of one payload; *nr counts requests. */
static void post(MPI_Request *r, int *nr, int send, void *buf, size_t bytes, int peer, int tag)
{
    for (size_t off = 0; off < bytes; off += COMM_PIECE) {
        size_t b = bytes - off < COMM_PIECE ? bytes - off : COMM_PIECE;
        if (send) MPI_Isend((char *)buf + off, (int)b, MPI_BYTE, peer, tag, MPI_COMM_WORLD, &r[(*nr)++]);
        else MPI_Irecv((char *)buf + off, (int)b, MPI_BYTE, peer, tag, MPI_COMM_WORLD, &r[(*nr)++]);
    }
}
static size_t pieces(size_t bytes) { return bytes / COMM_PIECE + 1; }
#endif

int comm_allgatherv(const void *buf, size_t bytes, void **all, size_t *total)
{
    *all = NULL;
    *total = 0;
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        int64_t *sz = malloc((size_t)size * sizeof *sz);
        if (!sz) comm_abort(1);
        comm_allgather_i64((int64_t)bytes, sz);
        size_t t = 0;
        for (int r = 0; r < size; r++) t += (size_t)sz[r];
        char *out = t ? malloc(t) : NULL;
        if (!comm_all(t == 0 || out)) {
            free(out);
            free(sz);
            return -1;
        }
        size_t nreq = 0;
        for (int r = 0; r < size; r++) nreq += 2 * pieces((size_t)sz[r]);
        MPI_Request *req = malloc(nreq * sizeof *req);
        if (!req) comm_abort(1);
        int nr = 0;
        size_t off = 0;
        for (int r = 0; r < size; r++) {
            if (sz[r]) post(req, &nr, 0, out + off, (size_t)sz[r], r, 7);
            off += (size_t)sz[r];
        }
        if (bytes)
            for (int r = 0; r < size; r++) post(req, &nr, 1, (void *)buf, bytes, r, 7);
        MPI_Waitall(nr, req, MPI_STATUSES_IGNORE);
        free(req);
        free(sz);
        *all = out;
        *total = t;
        return 0;
    }
#endif
    if (bytes) {
        *all = malloc(bytes);
        if (!*all) return -1;
        memcpy(*all, buf, bytes);
    }
    *total = bytes;
    return 0;
}

static int grow(comm_msg *m, size_t bytes)
{
    if (bytes > m->recvcap) {
        size_t cap = bytes + bytes / 2 + 64;
        void *p = realloc(m->recv, cap);
        if (!p) return -1;
        m->recv = p;
        m->recvcap = cap;
    }
    m->recvbytes = bytes;
    return 0;
}

int comm_exchange(comm_msg *m, int count)
{
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        int64_t *sz = malloc(2 * (size_t)(count + 1) * sizeof *sz);
        MPI_Request *req = malloc(2 * (size_t)(count + 1) * sizeof *req);
        if (!sz || !req) comm_abort(1);
        int nr = 0;
        for (int i = 0; i < count; i++) {
            sz[count + i] = (int64_t)m[i].sendbytes;
            MPI_Irecv(&sz[i], 1, MPI_INT64_T, m[i].rank, 11, MPI_COMM_WORLD, &req[nr++]);
            MPI_Isend(&sz[count + i], 1, MPI_INT64_T, m[i].rank, 11, MPI_COMM_WORLD, &req[nr++]);
        }
        MPI_Waitall(nr, req, MPI_STATUSES_IGNORE);
        size_t nreq = 0;
        for (int i = 0; i < count; i++) {
            if (grow(&m[i], (size_t)sz[i]) != 0) comm_abort(1);
            nreq += pieces((size_t)sz[i]) + pieces(m[i].sendbytes);
        }
        free(req);
        req = malloc(nreq * sizeof *req);
        if (!req) comm_abort(1);
        nr = 0;
        for (int i = 0; i < count; i++)
            if (m[i].recvbytes) post(req, &nr, 0, m[i].recv, m[i].recvbytes, m[i].rank, 12);
        for (int i = 0; i < count; i++)
            if (m[i].sendbytes) post(req, &nr, 1, (void *)m[i].send, m[i].sendbytes, m[i].rank, 12);
        MPI_Waitall(nr, req, MPI_STATUSES_IGNORE);
        free(req);
        free(sz);
        return 0;
    }
#endif
    /* One rank: only messages to itself. */
    for (int i = 0; i < count; i++) {
        if (grow(&m[i], m[i].sendbytes) != 0) return -1;
        if (m[i].sendbytes) memcpy(m[i].recv, m[i].send, m[i].sendbytes);
    }
    return 0;
}

int comm_alltoallv(void *const *send, const size_t *sendbytes, void **recv, size_t *recvbytes)
{
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        int64_t *so = malloc(2 * (size_t)size * sizeof *so);
        if (!so) comm_abort(1);
        int64_t *si = so + size;
        for (int r = 0; r < size; r++) so[r] = (int64_t)sendbytes[r];
        MPI_Alltoall(so, 1, MPI_INT64_T, si, 1, MPI_INT64_T, MPI_COMM_WORLD);
        int bad = 0;
        size_t nreq = 0;
        for (int r = 0; r < size; r++) {
            recvbytes[r] = (size_t)si[r];
            recv[r] = si[r] ? malloc((size_t)si[r]) : NULL;
            if (si[r] && !recv[r]) bad = 1;
            nreq += pieces((size_t)si[r]) + pieces(sendbytes[r]);
        }
        if (!comm_all(!bad)) {
            for (int r = 0; r < size; r++) free(recv[r]);
            free(so);
            return -1;
        }
        MPI_Request *req = malloc(nreq * sizeof *req);
        if (!req) comm_abort(1);
        int nr = 0;
        for (int r = 0; r < size; r++)
            if (recvbytes[r]) post(req, &nr, 0, recv[r], recvbytes[r], r, 13);
        for (int r = 0; r < size; r++)
            if (sendbytes[r]) post(req, &nr, 1, send[r], sendbytes[r], r, 13);
        MPI_Waitall(nr, req, MPI_STATUSES_IGNORE);
        free(req);
        free(so);
        return 0;
    }
#endif
    recvbytes[0] = sendbytes[0];
    recv[0] = NULL;
    if (sendbytes[0]) {
        recv[0] = malloc(sendbytes[0]);
        if (!recv[0]) return -1;
        memcpy(recv[0], send[0], sendbytes[0]);
    }
    return 0;
}
