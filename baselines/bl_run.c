/* bl_run.c - see bl_run.h. */
#include "bl_run.h"

#include <string.h>

#include "tmpguard.h"

void bl_check_output_name(const char *prog, const char *out)
{
    if (out && pf_format_of(out) == PF_UNKNOWN)
        cli_usage_error(prog, "%s: unknown output format (use %s)", out, PF_EXTENSIONS);
}

void bl_run_open(bl_run *r, const char *prog, const char *out, const char *trace, size_t n,
                 const char *trace_header, int quiet)
{
    char err[512];
    memset(r, 0, sizeof *r);
    r->prog = prog;
    r->out = out;
    r->trace = trace;
    r->n = n;
    tmpguard_install();
    if (out) {
        /* n == 0: probe that the folder takes a file now, write at the end. */
        pf_writer *w = pf_writer_open(out, n, err, sizeof err);
        if (!w) cli_fail(prog, "%s", err);
        if (n == 0) pf_writer_abort(w);
        else {
            r->w = w;
            tmpguard_file(pf_writer_tmpname(w));
        }
    }
    if (trace) {
        if (cli_atomic_open(&r->tr, trace, err, sizeof err) != 0) {
            pf_writer_abort(r->w);
            r->w = NULL;
            cli_fail(prog, "%s", err);
        }
        r->tf = r->tr.f;
        fprintf(r->tf, "%s\n", trace_header);
    }
    cli_progress_init(&r->pg, quiet);
    r->t0 = cli_now();
}

void bl_run_finish(bl_run *r, const double *xy, size_t n)
{
    char err[512];
    cli_progress_end(&r->pg);
    if (r->out) {
        if (r->w) {
            char tmp[4096];
            snprintf(tmp, sizeof tmp, "%s", pf_writer_tmpname(r->w));
            if (pf_writer_put(r->w, xy, n, err, sizeof err) != 0 ||
                pf_writer_commit(r->w, err, sizeof err) != 0)
                cli_fail(r->prog, "%s", err);
            tmpguard_forget(tmp);
            r->w = NULL;
        } else if (pf_write(r->out, xy, n, err, sizeof err) != 0) {
            cli_fail(r->prog, "%s", err);
        }
    }
    if (r->trace && cli_atomic_commit(&r->tr, err, sizeof err) != 0) cli_fail(r->prog, "%s", err);
    r->tf = NULL;
}
