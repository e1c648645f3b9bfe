/* runfiles.c - see runfiles.h. */
#include "runfiles.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "comm.h"
#include "pointfile.h"
#include "tmpguard.h"
#include "tracecols.h"

struct cfpo_runfiles {
    int64_t n;
    const char *out; /* the output's name (the caller's string), or NULL */
    const char *trace_path;
    pf_format fmt;
    pf_writer *w;   /* text output, one rank */
    comm_file *cf;  /* .npy and raw output, every rank */
    int traced;     /* a trace was asked for */
    cli_atomic tr;  /* the trace's file, rank 0, opened at the end */
    FILE *mem;      /* the trace's rows as the run makes them, rank 0 */
    char *membuf;
    size_t memlen;
};

/* Do paths a and b name the same file? The same device and inode when
 * both exist; else the same name in the same folder (folders compared by
 * device and inode too). */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    const char *ba = strrchr(a, '/'), *bb = strrchr(b, '/');
    const char *na = ba ? ba + 1 : a, *nb = bb ? bb + 1 : b;
    if (strcmp(na, nb) != 0) return 0;
    char da[4096], db[4096];
    snprintf(da, sizeof da, "%.*s", ba ? (int)(ba - a) + 1 : 1, ba ? a : ".");
    snprintf(db, sizeof db, "%.*s", bb ? (int)(bb - b) + 1 : 1, bb ? b : ".");
    if (stat(da, &sa) != 0 || stat(db, &sb) != 0) return strcmp(da, db) == 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int cfpo_runfiles_check(const char *out, const char *trace, const char *checkpoint, int ranks, char *err,
                        size_t errlen)
{
    const char *name[3] = {out, trace, checkpoint}, *opt[3] = {"-o", "--trace", "--checkpoint"};
    for (int i = 0; i < 3; i++) {
        if (name[i] && !name[i][0]) {
            snprintf(err, errlen, "%s: the file name is empty", opt[i]);
            return -1;
        }
        for (int j = 0; j < i; j++)
            if (name[i] && name[j] && same_file(name[i], name[j])) {
                snprintf(err, errlen, "%s %s and %s %s are the same file", opt[j], name[j], opt[i], name[i]);
                return -1;
            }
    }
    if (!out) return 0;
    const pf_format fmt = pf_format_of(out);
    if (fmt == PF_UNKNOWN) {
        snprintf(err, errlen, "%s: unknown output format (use %s)", out, PF_EXTENSIONS);
        return -1;
    }
    if (pf_format_is_text(fmt) && ranks > 1) {
        snprintf(err, errlen, "%s: text output needs one rank (no rank holds the whole set); use .npy or .bin",
                 out);
        return -1;
    }
    return 0;
}

/* Opens the points' temporary (at the end of the run); 0 on every rank
 * or -1 on every rank. */
static int open_points(cfpo_runfiles *f, char *err, size_t errlen)
{
    if (!f->out) return 0;
    f->fmt = pf_format_of(f->out);
    if (pf_format_is_text(f->fmt)) {
        f->w = pf_writer_open(f->out, (size_t)f->n, err, errlen);
        if (!f->w) return -1;
        tmpguard_file(pf_writer_tmpname(f->w));
        return 0;
    }
    f->cf = comm_file_create(f->out, err, errlen);
    if (!f->cf) return -1;
    if (comm_rank() == 0) tmpguard_file(comm_file_tmpname(f->cf));
    return 0;
}

/* Rank 0 creates and removes a temporary beside a file's name, so a bad
 * path fails before the work. */
static int probe(const char *path, const char *what, char *err, size_t errlen)
{
    int ok = 1;
    if (comm_rank() == 0) {
        char *tmp = NULL;
        const int fd = safefile_create(path, &tmp, err, errlen);
        ok = fd >= 0;
        if (ok) {
            close(fd);
            unlink(tmp);
            free(tmp);
        }
    }
    if (comm_all(ok)) return 0;
    if (ok) snprintf(err, errlen, "%s: cannot create the %s", path, what);
    return -1;
}

cfpo_runfiles *cfpo_runfiles_open(const char *out, const char *trace, const char *checkpoint, int64_t n,
                                  char *err, size_t errlen)
{
    cfpo_runfiles *f = calloc(1, sizeof *f);
    if (!comm_all(f != NULL)) {
        free(f);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    tmpguard_install();
    f->n = n;
    f->out = out;
    f->trace_path = trace;
    if ((out && probe(out, "output", err, errlen) != 0) || (trace && probe(trace, "trace", err, errlen) != 0) ||
        (checkpoint && probe(checkpoint, "checkpoint", err, errlen) != 0)) {
        free(f);
        return NULL;
    }
    if (trace) {
        f->traced = 1;
        int ok = 1;
        if (comm_rank() == 0) {
            f->mem = open_memstream(&f->membuf, &f->memlen);
            ok = f->mem != NULL;
            if (ok) {
                cfpo_trace_write_names(f->mem, cfpo_trace_columns, CFPO_TRACE_COLUMNS, 1);
                fputc('\n', f->mem);
            }
        }
        if (!comm_all(ok)) {
            snprintf(err, errlen, "out of memory for the trace");
            cfpo_runfiles_abort(f);
            return NULL;
        }
    }
    return f;
}

FILE *cfpo_runfiles_trace(const cfpo_runfiles *f)
{
    return f && f->traced && comm_rank() == 0 ? f->mem : NULL;
}

static void drop_trace(cfpo_runfiles *f)
{
    if (f->mem) fclose(f->mem);
    free(f->membuf);
    f->mem = NULL;
    f->membuf = NULL;
}

void cfpo_runfiles_abort(cfpo_runfiles *f)
{
    if (!f) return;
    char ignored[256];
    pf_writer_abort(f->w);
    if (f->cf) comm_file_commit(f->cf, 0, ignored, sizeof ignored);
    if (f->tr.f && comm_rank() == 0) cli_atomic_abort(&f->tr);
    drop_trace(f);
    free(f);
}

/* The points into the text writer (one rank), finished but not in place. */
static int finish_text(cfpo_runfiles *f, const cfpo_run_engine *R, char *err, size_t errlen)
{
    if (R->ops->put_text(R->E, f->w, err, errlen) != 0) return -1;
    if (pf_writer_finish(f->w, err, errlen) != 0) return -1;
    return 0;
}

/* The points into the shared file: rank 0 writes the header, every rank
 * its points (collective); finished but not in place. */
static int finish_shared(cfpo_runfiles *f, const cfpo_run_engine *R, char *err, size_t errlen)
{
    unsigned char hdr[PF_HEADER_MAX];
    const size_t hl = pf_header(f->fmt, (size_t)f->n, hdr, sizeof hdr);
    int ok = 1;
    if (comm_rank() == 0 && hl) ok = comm_file_write_at(f->cf, 0, hdr, hl) == 0;
    if (R->ops->put_points(R->E, f->cf, hl, err, errlen) != 0) ok = 0;
    comm_file *cf = f->cf;
    f->cf = NULL;
    if (comm_file_finish(cf, ok, err, errlen) != 0) return -1; /* removed and freed */
    f->cf = cf;
    return 0;
}

/* Every file finished (written whole and closed), on every rank? */
static int finish_all(cfpo_runfiles *f, const cfpo_run_engine *R, char *err, size_t errlen)
{
    int rc = 0;
    if (f->w) rc = finish_text(f, R, err, errlen);
    else if (f->cf) rc = finish_shared(f, R, err, errlen);
    if (rc == 0 && f->traced && comm_rank() == 0 && safefile_finish(&f->tr, err, errlen) != 0) {
        f->traced = 0; /* removed */
        rc = -1;
    }
    if (!comm_all(rc == 0)) {
        if (rc == 0) snprintf(err, errlen, "another rank failed to write its files");
        return -1;
    }
    return 0;
}

/* The trace's rows into its temporary (rank 0). 0 or -1. */
static int open_trace(cfpo_runfiles *f, char *err, size_t errlen)
{
    if (!f->traced || comm_rank() != 0) return 0;
    if (fflush(f->mem) != 0) {
        snprintf(err, errlen, "out of memory for the trace");
        return -1;
    }
    if (cli_atomic_open(&f->tr, f->trace_path, err, errlen) != 0) return -1;
    if (fwrite(f->membuf, 1, f->memlen, f->tr.f) != f->memlen) {
        snprintf(err, errlen, "%s: write failed", f->trace_path);
        return -1;
    }
    drop_trace(f);
    return 0;
}

int cfpo_runfiles_commit(cfpo_runfiles *f, const cfpo_run_engine *R, char *err, size_t errlen)
{
    int opened = open_trace(f, err, errlen) == 0;
    if (!comm_all(opened)) {
        if (opened) snprintf(err, errlen, "cannot write the trace file");
        cfpo_runfiles_abort(f);
        return -1;
    }
    if (open_points(f, err, errlen) != 0) {
        cfpo_runfiles_abort(f);
        return -1;
    }
    char ptmp[4096] = "";
    if (f->w) snprintf(ptmp, sizeof ptmp, "%s", pf_writer_tmpname(f->w));
    if (f->cf) snprintf(ptmp, sizeof ptmp, "%s", comm_file_tmpname(f->cf));
    if (finish_all(f, R, err, errlen) != 0) {
        if (f->cf) comm_file_discard(f->cf);
        f->cf = NULL;
        cfpo_runfiles_abort(f);
        return -1;
    }
    /* Every file is whole: now put them in place. */
    int rc = 0;
    if (f->w) rc = pf_writer_publish(f->w, err, errlen);
    else if (f->cf) rc = comm_file_publish(f->cf, err, errlen);
    f->w = NULL;
    f->cf = NULL;
    if (ptmp[0]) tmpguard_forget(ptmp);
    if (f->traced && comm_rank() == 0) {
        char ttmp[4096];
        snprintf(ttmp, sizeof ttmp, "%s", f->tr.tmp);
        if (safefile_publish(&f->tr, err, errlen) != 0) rc = -1;
        tmpguard_forget(ttmp);
    }
    free(f);
    return rc;
}
