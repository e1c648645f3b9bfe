/* comm.c - see comm.h. The only file of the project that calls MPI. */
#define _GNU_SOURCE
#include "comm.h"

#include "safefile.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef CFPO_HAVE_MPI
#include <mpi.h>
#endif

static int active, rank, size = 1;

/* Payloads are sent in pieces of at most this many bytes (MPI counts are
 * ints). */
#define PIECE ((size_t)1 << 30)

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

void comm_world_max_i64(int64_t *v, int count)
{
#ifdef CFPO_HAVE_MPI
    if (active && (solo ? world_size : size) > 1)
        MPI_Allreduce(MPI_IN_PLACE, v, count, MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
#else
    (void)v;
    (void)count;
#endif
}

void comm_abort(int code)
{
#ifdef CFPO_HAVE_MPI
    if (active && (solo ? world_size : size) > 1) MPI_Abort(MPI_COMM_WORLD, code);
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

#ifdef CFPO_HAVE_MPI
static void comm_barrier(void)
{
    if (active) MPI_Barrier(MPI_COMM_WORLD);
}
#endif

#ifdef CFPO_HAVE_MPI
#define REDUCE(v, count, type, op)                                                   \
    do {                                                                             \
        if (active && size > 1) MPI_Allreduce(MPI_IN_PLACE, v, count, type, op, MPI_COMM_WORLD); \
    } while (0)
#else
#define REDUCE(v, count, type, op) ((void)(v), (void)(count))
#endif

void comm_sum_i64(int64_t *v, int count) { REDUCE(v, count, MPI_INT64_T, MPI_SUM); }
void comm_max_i64(int64_t *v, int count) { REDUCE(v, count, MPI_INT64_T, MPI_MAX); }
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
        for (size_t off = 0; off < bytes; off += PIECE) {
            size_t b = bytes - off < PIECE ? bytes - off : PIECE;
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
    for (size_t off = 0; off < bytes; off += PIECE) {
        size_t b = bytes - off < PIECE ? bytes - off : PIECE;
        if (send) MPI_Isend((char *)buf + off, (int)b, MPI_BYTE, peer, tag, MPI_COMM_WORLD, &r[(*nr)++]);
        else MPI_Irecv((char *)buf + off, (int)b, MPI_BYTE, peer, tag, MPI_COMM_WORLD, &r[(*nr)++]);
    }
}
static size_t pieces(size_t bytes) { return bytes / PIECE + 1; }
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

/* ---- files ---- */

struct comm_file {
    char *path, *tmp;
    int fd; /* one rank */
    int failed;
#ifdef CFPO_HAVE_MPI
    MPI_File fh;
    int mpi;
#endif
};

const char *comm_file_tmpname(const comm_file *f) { return f->tmp; }

static void free_file(comm_file *f)
{
    if (!f) return;
    free(f->path);
    free(f->tmp);
    free(f);
}

comm_file *comm_file_create(const char *path, char *err, size_t errlen)
{
    comm_file *f = calloc(1, sizeof *f);
    const size_t len = strlen(path) + 16; /* the temporary's name, as safefile_create makes it */
    if (!f || !(f->path = strdup(path)) || !(f->tmp = calloc(1, len))) {
        free_file(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    f->fd = -1;
    /* Rank 0 makes the temporary file (a unique name in the same folder),
     * every rank then opens it. */
    int e = 0;
    if (rank == 0) {
        char *tmp = NULL;
        const int fd = safefile_create(path, &tmp, err, errlen);
        if (fd < 0) e = 1;
        else {
            snprintf(f->tmp, len, "%s", tmp);
            free(tmp);
            if (size > 1 && active) close(fd);
            else f->fd = fd;
        }
    }
    int64_t ev = e;
    comm_bcast(&ev, sizeof ev, 0);
    if (ev) { /* rank 0 has the reason in err */
        if (rank != 0) snprintf(err, errlen, "%s: cannot create file", path);
        free_file(f);
        return NULL;
    }
#ifdef CFPO_HAVE_MPI
    if (active && size > 1) {
        comm_bcast(f->tmp, len, 0);
        int rc = MPI_File_open(MPI_COMM_WORLD, f->tmp, MPI_MODE_WRONLY, MPI_INFO_NULL, &f->fh);
        if (!comm_all(rc == MPI_SUCCESS)) {
            if (rc == MPI_SUCCESS) MPI_File_close(&f->fh);
            if (rank == 0) unlink(f->tmp);
            snprintf(err, errlen, "%s: cannot open for MPI-IO", path);
            free_file(f);
            return NULL;
        }
        f->mpi = 1;
    }
#endif
    return f;
}

static int pwrite_all(int fd, const void *buf, size_t bytes, uint64_t off)
{
    const char *p = buf;
    while (bytes) {
        ssize_t w = pwrite(fd, p, bytes, (off_t)off);
        if (w < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        p += w;
        bytes -= (size_t)w;
        off += (uint64_t)w;
    }
    return 0;
}

int comm_file_write_at(comm_file *f, uint64_t offset, const void *buf, size_t bytes)
{
#ifdef CFPO_HAVE_MPI
    if (f->mpi) {
        for (size_t off = 0; off < bytes; off += PIECE) {
            size_t b = bytes - off < PIECE ? bytes - off : PIECE;
            if (MPI_File_write_at(f->fh, (MPI_Offset)(offset + off), (const char *)buf + off, (int)b,
                                  MPI_BYTE, MPI_STATUS_IGNORE) != MPI_SUCCESS) {
                f->failed = 1;
                return -1;
            }
        }
        return 0;
    }
#endif
    if (pwrite_all(f->fd, buf, bytes, offset) != 0) {
        f->failed = 1;
        return -1;
    }
    return 0;
}

#ifdef CFPO_HAVE_MPI
/* The next piece of a run list for one collective write: at most maxruns
 * runs and PIECE bytes, starting at element *done of run *k. Fills the
 * block lengths and displacements (when bl is not NULL); returns the count. */
static int next_piece(const uint64_t *first, const uint64_t *len, int64_t nruns, size_t elem,
                      int64_t maxruns, int64_t *k, uint64_t *done, int *bl, MPI_Aint *dp, size_t *bytes_out)
{
    size_t bytes = 0;
    int cnt = 0;
    while (*k < nruns && cnt < maxruns && bytes < PIECE) {
        uint64_t take = len[*k] - *done;
        if (bytes + take * elem > PIECE) take = (PIECE - bytes) / elem;
        if (take == 0) break;
        if (bl) {
            bl[cnt] = (int)(take * elem);
            dp[cnt] = (MPI_Aint)((first[*k] + *done) * elem);
        }
        cnt++;
        bytes += take * elem;
        *done += take;
        if (*done == len[*k]) { (*k)++; *done = 0; }
    }
    if (bytes_out) *bytes_out = bytes;
    return cnt;
}
#endif

int comm_file_write_runs(comm_file *f, uint64_t base, size_t elem, const void *buf, int64_t nruns,
                         const uint64_t *first, const uint64_t *len)
{
#ifdef CFPO_HAVE_MPI
    if (f->mpi) {
        /* Pieces of at most 2^26 runs and PIECE bytes, each one collective
         * write through an hindexed file view; every rank takes part in the
         * same number of them. */
        const int64_t maxruns = (int64_t)1 << 26;
        int64_t k = 0, rounds = 0;
        uint64_t done = 0; /* elements of run k already written */
        const char *p = buf;
        {
            int64_t kk = 0;
            uint64_t dd = 0;
            while (kk < nruns) {
                next_piece(first, len, nruns, elem, maxruns, &kk, &dd, NULL, NULL, NULL);
                rounds++;
            }
        }
        int64_t all_rounds = rounds;
        comm_max_i64(&all_rounds, 1);
        int *bl = malloc((size_t)(nruns < maxruns ? nruns + 1 : maxruns) * sizeof *bl);
        MPI_Aint *dp = malloc((size_t)(nruns < maxruns ? nruns + 1 : maxruns) * sizeof *dp);
        if (!bl || !dp) comm_abort(1);
        int ok = 1;
        for (int64_t r = 0; r < all_rounds; r++) {
            size_t bytes;
            int cnt = next_piece(first, len, nruns, elem, maxruns, &k, &done, bl, dp, &bytes);
            MPI_Datatype t;
            MPI_Type_create_hindexed(cnt, bl, dp, MPI_BYTE, &t);
            MPI_Type_commit(&t);
            if (MPI_File_set_view(f->fh, (MPI_Offset)base, MPI_BYTE, t, "native", MPI_INFO_NULL) !=
                MPI_SUCCESS)
                ok = 0;
            if (MPI_File_write_all(f->fh, p, (int)bytes, MPI_BYTE, MPI_STATUS_IGNORE) != MPI_SUCCESS)
                ok = 0;
            MPI_Type_free(&t);
            p += bytes;
        }
        free(bl);
        free(dp);
        MPI_File_set_view(f->fh, 0, MPI_BYTE, MPI_BYTE, "native", MPI_INFO_NULL);
        if (!ok) f->failed = 1;
        return ok ? 0 : -1;
    }
#endif
    const char *p = buf;
    for (int64_t k = 0; k < nruns; k++) {
        if (pwrite_all(f->fd, p, len[k] * elem, base + first[k] * elem) != 0) {
            f->failed = 1;
            return -1;
        }
        p += len[k] * elem;
    }
    return 0;
}

int comm_file_sync(comm_file *f)
{
    int ok = !f->failed;
#ifdef CFPO_HAVE_MPI
    if (f->mpi) {
        if (MPI_File_sync(f->fh) != MPI_SUCCESS) ok = 0;
        comm_barrier(); /* sync, barrier: other ranks' writes are visible */
        return comm_all(ok) ? 0 : -1;
    }
#endif
    return comm_all(ok) ? 0 : -1; /* one rank: pwrite is visible to every reader at once */
}

int comm_file_finish(comm_file *f, int ok, char *err, size_t errlen)
{
    int good = comm_all(ok && !f->failed);
#ifdef CFPO_HAVE_MPI
    if (f->mpi) {
        if (good && MPI_File_sync(f->fh) != MPI_SUCCESS) good = 0;
        good = comm_all(good);
        if (MPI_File_close(&f->fh) != MPI_SUCCESS) good = 0;
        good = comm_all(good);
    } else
#endif
    {
        if (good && fsync(f->fd) != 0 && errno != EINVAL) good = 0;
        if (close(f->fd) != 0) good = 0;
    }
    f->fd = -1;
    if (good) return 0;
    snprintf(err, errlen, "%s: write failed (disk full or file system error)", f->path);
    comm_file_discard(f);
    return -1;
}

int comm_file_publish(comm_file *f, char *err, size_t errlen)
{
    int64_t e = 0;
    if (rank == 0 && safefile_replace(f->tmp, f->path) != 0) e = errno;
    comm_bcast(&e, sizeof e, 0);
    if (e) snprintf(err, errlen, "%s: cannot rename into place: %s", f->path, strerror((int)e));
    free_file(f);
    return e ? -1 : 0;
}

void comm_file_discard(comm_file *f)
{
    if (rank == 0) unlink(f->tmp);
    free_file(f);
}

int comm_file_commit(comm_file *f, int ok, char *err, size_t errlen)
{
    if (comm_file_finish(f, ok, err, errlen) != 0) return -1;
    return comm_file_publish(f, err, errlen);
}

comm_file *comm_file_open_read(const char *path, uint64_t *size_out, char *err, size_t errlen)
{
    comm_file *f = calloc(1, sizeof *f);
    if (!f || !(f->path = strdup(path))) {
        free_file(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    f->fd = open(path, O_RDONLY);
    int64_t e = f->fd < 0 ? errno : 0;
    comm_max_i64(&e, 1);
    if (e) {
        if (f->fd >= 0) close(f->fd);
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror((int)e));
        free_file(f);
        return NULL;
    }
    off_t end = lseek(f->fd, 0, SEEK_END);
    int64_t sz = end < 0 ? 0 : (int64_t)end;
    comm_bcast(&sz, sizeof sz, 0);
    *size_out = (uint64_t)sz;
    return f;
}

int comm_file_read_at(comm_file *f, uint64_t offset, void *buf, size_t bytes)
{
    char *p = buf;
    while (bytes) {
        ssize_t r = pread(f->fd, p, bytes, (off_t)offset);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return -1;
        p += r;
        bytes -= (size_t)r;
        offset += (uint64_t)r;
    }
    return 0;
}

void comm_file_close(comm_file *f)
{
    if (!f) return;
    if (f->fd >= 0) close(f->fd);
    free_file(f);
}
