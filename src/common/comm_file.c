/* comm_file.c - see comm.h ("Files"): files written and read by every
 * rank at once (MPI-IO under several ranks, plain calls on one), under a
 * temporary name until every rank succeeded. */
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
    if (comm_rank() == 0) {
        char *tmp = NULL;
        const int fd = safefile_create(path, &tmp, err, errlen);
        if (fd < 0) e = 1;
        else {
            snprintf(f->tmp, len, "%s", tmp);
            free(tmp);
            if (comm_size() > 1 && comm_mpi_active()) close(fd);
            else f->fd = fd;
        }
    }
    int64_t ev = e;
    comm_bcast(&ev, sizeof ev, 0);
    if (ev) { /* rank 0 has the reason in err */
        if (comm_rank() != 0) snprintf(err, errlen, "%s: cannot create file", path);
        free_file(f);
        return NULL;
    }
#ifdef CFPO_HAVE_MPI
    if (comm_mpi_active() && comm_size() > 1) {
        comm_bcast(f->tmp, len, 0);
        int rc = MPI_File_open(MPI_COMM_WORLD, f->tmp, MPI_MODE_WRONLY, MPI_INFO_NULL, &f->fh);
        if (!comm_all(rc == MPI_SUCCESS)) {
            if (rc == MPI_SUCCESS) MPI_File_close(&f->fh);
            if (comm_rank() == 0) unlink(f->tmp);
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
        for (size_t off = 0; off < bytes; off += COMM_PIECE) {
            size_t b = bytes - off < COMM_PIECE ? bytes - off : COMM_PIECE;
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
 * runs and COMM_PIECE bytes, starting at element *done of run *k. Fills the
 * block lengths and displacements (when bl is not NULL); returns the count. */
static int next_piece(const uint64_t *first, const uint64_t *len, int64_t nruns, size_t elem,
                      int64_t maxruns, int64_t *k, uint64_t *done, int *bl, MPI_Aint *dp, size_t *bytes_out)
{
    size_t bytes = 0;
    int cnt = 0;
    while (*k < nruns && cnt < maxruns && bytes < COMM_PIECE) {
        uint64_t take = len[*k] - *done;
        if (bytes + take * elem > COMM_PIECE) take = (COMM_PIECE - bytes) / elem;
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
        /* Pieces of at most 2^26 runs and COMM_PIECE bytes, each one collective
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
    if (comm_rank() == 0 && safefile_replace(f->tmp, f->path) != 0) e = errno;
    comm_bcast(&e, sizeof e, 0);
    if (e) snprintf(err, errlen, "%s: cannot rename into place: %s", f->path, strerror((int)e));
    free_file(f);
    return e ? -1 : 0;
}

void comm_file_discard(comm_file *f)
{
    if (comm_rank() == 0) unlink(f->tmp);
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
