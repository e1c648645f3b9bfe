/* runfiles.c - see runfiles.h. */
#include "runfiles.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "comm.h"
#include "pointfile.h"

struct cfpo_runfiles {
    int64_t n;
    pf_format fmt;
    pf_writer *w;   /* text output, one rank */
    comm_file *cf;  /* .npy and raw output, every rank */
    int traced;     /* a trace was asked for */
    cli_atomic tr;  /* the trace, rank 0 */
};

int cfpo_runfiles_check(const char *out, const char *checkpoint, int ranks, char *err, size_t errlen)
{
    if (!out) return 0;
    const pf_format fmt = pf_format_of(out);
    if (fmt == PF_UNKNOWN) {
        snprintf(err, errlen, "%s: unknown output format (use %s)", out, PF_EXTENSIONS);
        return -1;
    }
    if (fmt == PF_TEXT && ranks > 1) {
        snprintf(err, errlen, "%s: text output needs one rank (no rank holds the whole set); use .npy or .bin",
                 out);
        return -1;
    }
    if (checkpoint && strcmp(checkpoint, out) == 0) {
        snprintf(err, errlen, "--checkpoint and -o name the same file");
        return -1;
    }
    return 0;
}

/* Opens the points' temporary; 0 on every rank or -1 on every rank. */
static int open_points(cfpo_runfiles *f, const char *out, char *err, size_t errlen)
{
    cli_guard_tmp(NULL);
    if (!out) return 0;
    f->fmt = pf_format_of(out);
    if (f->fmt == PF_TEXT) {
        f->w = pf_writer_open(out, (size_t)f->n, err, errlen);
        if (!f->w) return -1;
        cli_guard_tmp(pf_writer_tmpname(f->w));
        return 0;
    }
    f->cf = comm_file_create(out, err, errlen);
    if (!f->cf) return -1;
    if (comm_rank() == 0) cli_guard_tmp(comm_file_tmpname(f->cf));
    return 0;
}

cfpo_runfiles *cfpo_runfiles_open(const char *out, const char *trace, int64_t n, char *err, size_t errlen)
{
    cfpo_runfiles *f = calloc(1, sizeof *f);
    if (!comm_all(f != NULL)) {
        free(f);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    f->n = n;
    if (open_points(f, out, err, errlen) != 0) {
        free(f);
        return NULL;
    }
    if (trace) {
        f->traced = 1;
        const int ok = comm_rank() != 0 || cli_atomic_open(&f->tr, trace, err, errlen) == 0;
        if (!comm_all(ok)) {
            if (ok) snprintf(err, errlen, "cannot open the trace file");
            f->traced = 0;
            cfpo_runfiles_abort(f);
            return NULL;
        }
        if (comm_rank() == 0)
            fprintf(f->tr.f, "iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed\tmax_move\n");
    }
    return f;
}

FILE *cfpo_runfiles_trace(const cfpo_runfiles *f)
{
    return f && f->traced && comm_rank() == 0 ? f->tr.f : NULL;
}

void cfpo_runfiles_abort(cfpo_runfiles *f)
{
    if (!f) return;
    char ignored[256];
    pf_writer_abort(f->w);
    if (f->cf) comm_file_commit(f->cf, 0, ignored, sizeof ignored);
    if (f->traced && comm_rank() == 0) cli_atomic_abort(&f->tr);
    free(f);
}

/* The points into the text writer (one rank). */
static int commit_text(cfpo_runfiles *f, cfpo_engine *E, char *err, size_t errlen)
{
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s", pf_writer_tmpname(f->w));
    if (cfpo_engine_write(E, f->w, err, errlen) != 0) return -1;
    pf_writer *w = f->w;
    f->w = NULL;
    if (pf_writer_commit(w, err, errlen) != 0) return -1;
    cli_unguard_tmp(tmp);
    return 0;
}

/* The points into the shared file: rank 0 writes the header, every rank
 * its points (collective). */
static int commit_shared(cfpo_runfiles *f, cfpo_engine *E, char *err, size_t errlen)
{
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s", comm_file_tmpname(f->cf));
    unsigned char hdr[PF_HEADER_MAX];
    const size_t hl = pf_header(f->fmt, (size_t)f->n, hdr, sizeof hdr);
    int ok = 1;
    if (comm_rank() == 0 && hl) ok = comm_file_write_at(f->cf, 0, hdr, hl) == 0;
    if (cfpo_engine_write_points(E, f->cf, hl, err, errlen) != 0) ok = 0;
    comm_file *cf = f->cf;
    f->cf = NULL;
    if (comm_file_commit(cf, ok, err, errlen) != 0) return -1;
    cli_unguard_tmp(tmp);
    return 0;
}

int cfpo_runfiles_commit(cfpo_runfiles *f, cfpo_engine *E, char *err, size_t errlen)
{
    int rc = 0;
    if (f->w) rc = commit_text(f, E, err, errlen);
    else if (f->cf) rc = commit_shared(f, E, err, errlen);
    if (rc == 0 && f->traced && comm_rank() == 0) {
        f->traced = 0;
        rc = cli_atomic_commit(&f->tr, err, errlen);
    }
    if (rc != 0) {
        cfpo_runfiles_abort(f);
        return -1;
    }
    free(f);
    return 0;
}
