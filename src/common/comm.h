/* comm.h - layer 2 (includes nothing of the project; its code uses safefile.h): the only door to
 * MPI; comm.c and comm_file.c (the shared files) are the files that call it.
 *
 * Owns: starting and ending MPI (only when the program was started by a
 * launcher such as mpirun; a plain start is one rank and never touches
 * MPI), reductions, exchanges between neighbouring ranks (sizes first,
 * then payloads), all-to-all of bytes, and files written and read by all
 * ranks at once (MPI-IO), created under a temporary name and renamed into
 * place only when every rank succeeded.
 * Does not own: what is sent (the engine packs and unpacks), tiling, or
 * error messages beyond "which call failed".
 *
 * Every function works on one rank without MPI, as the identity or as plain
 * stdio, so the layers above run the same code with or without mpirun. */
#ifndef CFPO_COMM_H
#define CFPO_COMM_H

#include <stddef.h>
#include <stdint.h>

/* Starts MPI when a launcher started us (OpenMPI, MPICH or PMIx variables
 * in the environment); otherwise one rank. Idempotent. */
void comm_init(int *argc, char ***argv);
void comm_finalize(void);
int comm_rank(void);
int comm_size(void);
/* From comm_solo_begin to comm_solo_end every rank works alone: comm_rank
 * is 0 and comm_size 1 on each, every reduction and exchange is the
 * identity and files are each rank's own, as on one rank without MPI (a
 * piece of work too small to cut across the ranks, done by each of them
 * the same way; they must not wait on one another inside it). */
void comm_solo_begin(void);
void comm_solo_end(void);
/* Whether the ranks work alone now (between comm_solo_begin and _end). */
int comm_solo(void);
/* The maximum over every rank of the job, also while they work alone: the
 * one reduction allowed there, for what must agree across the job though
 * each rank works alone (a signal that reached some ranks only). Every
 * rank must call it the same number of times. */
void comm_world_max_i64(int64_t *v, int count);
/* Whether MPI was started (comm_init under a launcher). */
int comm_mpi_active(void);
/* Collective: waits for every rank (nothing on one). */
void comm_barrier(void);
/* Payloads and file writes go in pieces of at most this many bytes (MPI
 * counts are ints). */
#define COMM_PIECE ((size_t)1 << 30)
/* Ends every rank of the job at once (MPI_Abort), or exits on one rank. */
void comm_abort(int code) __attribute__((noreturn));
/* Ranks on this machine (sharing its memory). */
int comm_local_size(void);

/* In-place reductions over all ranks. */
void comm_sum_i64(int64_t *v, int count);
void comm_max_i64(int64_t *v, int count);
void comm_min_d(double *v, int count);
void comm_max_d(double *v, int count);
void comm_sum_d(double *v, int count);
/* all[r] = v of rank r. */
void comm_allgather_i64(int64_t v, int64_t *all);
void comm_bcast(void *buf, size_t bytes, int root);
/* Every rank's bytes, concatenated in rank order; malloc'ed (NULL when the
 * total is 0), *total its size. -1 when out of memory (on any rank). */
int comm_allgatherv(const void *buf, size_t bytes, void **all, size_t *total);

/* One message each way with a neighbouring rank. The caller fills rank,
 * send and sendbytes; comm_exchange sends the sizes first, then the
 * payloads, and fills recv (grown with realloc; keep it between calls)
 * and recvbytes. A rank appears at most once in the list. Returns -1 when
 * out of memory. */
typedef struct {
    int rank;
    const void *send;
    size_t sendbytes;
    void *recv;
    size_t recvcap, recvbytes;
} comm_msg;
int comm_exchange(comm_msg *m, int count);

/* All-to-all of bytes: send[r] goes to rank r; recv[r] (malloc'ed) comes
 * from rank r. Sizes first, then payloads. -1 when out of memory. */
int comm_alltoallv(void *const *send, const size_t *sendbytes, void **recv, size_t *recvbytes);

/* Files. comm_file_create makes a temporary file beside path (same name on
 * every rank); writes go to it; comm_file_commit renames it into place
 * when every rank wrote successfully, and removes it otherwise. All of
 * them are collective. err gets one line naming the file. */
typedef struct comm_file comm_file;
comm_file *comm_file_create(const char *path, char *err, size_t errlen);
/* Independent write at a byte offset (used by one rank for headers). */
int comm_file_write_at(comm_file *f, uint64_t offset, const void *buf, size_t bytes);
/* Collective write: nruns runs of elements, run k of len[k] elements of
 * elem bytes goes to offset base + first[k] * elem; buf holds them all in
 * order. */
int comm_file_write_runs(comm_file *f, uint64_t base, size_t elem, const void *buf, int64_t nruns,
                         const uint64_t *first, const uint64_t *len);
/* Collective: agrees on success (ok = this rank's verdict), then closes and
 * renames or removes. Returns 0 when every rank succeeded. */
int comm_file_commit(comm_file *f, int ok, char *err, size_t errlen);
/* comm_file_commit in two halves, for a run that replaces none of its
 * files unless all were written whole: finish (agree, sync, close; on
 * failure the temporary is removed and f freed), then either publish
 * (rename into place) or discard (remove the temporary); both free f. */
int comm_file_finish(comm_file *f, int ok, char *err, size_t errlen);
int comm_file_publish(comm_file *f, char *err, size_t errlen);
void comm_file_discard(comm_file *f);
const char *comm_file_tmpname(const comm_file *f);
/* Collective: everything written so far is on disk and visible to reads of
 * the temporary file (comm_file_open_read of comm_file_tmpname) on every
 * rank. 0 when every rank succeeded. */
int comm_file_sync(comm_file *f);

/* Reading: opened by all ranks; reads are independent. */
comm_file *comm_file_open_read(const char *path, uint64_t *size, char *err, size_t errlen);
int comm_file_read_at(comm_file *f, uint64_t offset, void *buf, size_t bytes);
void comm_file_close(comm_file *f);

/* 1 when every rank passes ok != 0. */
int comm_all(int ok);

#endif
