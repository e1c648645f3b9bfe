/* pointfile.h - layer 2 (its code uses safefile.h, layer 0): the one module
 * that reads and writes point files.
 *
 * Owns: the four formats (text "x y" lines with '#' comments, CSV (a header
 * line "x,y", then "x,y" a line), NumPy .npy
 * n x 2 float64 (read also: float32 and big-endian, versions 1.0-3.0, the
 * header read strictly by npy.c), raw little-endian float64 pairs), the choice of format by
 * file extension, atomic writing (temporary file in the same folder, renamed
 * on success, removed on failure) and strict validation on reading.
 * Does not own: what the points mean, or how tools report errors (every
 * function returns -1 and fills a one-line message naming the file). */
#ifndef CFPO_POINTFILE_H
#define CFPO_POINTFILE_H

#include <stddef.h>
#include <stdio.h>

typedef enum { PF_UNKNOWN = 0, PF_TEXT, PF_NPY, PF_RAW, PF_CSV } pf_format;

/* Format from the file name: .txt .dat .pts .xy -> text, .csv -> CSV,
 * .npy -> NumPy, .bin .raw .f64 -> raw float64. PF_UNKNOWN otherwise. */
pf_format pf_format_of(const char *path);
const char *pf_format_name(pf_format f);
/* 1 for the formats written line by line (text, CSV): one writer holds the
 * whole set, no point has a fixed byte offset. */
int pf_format_is_text(pf_format f);
/* The accepted extensions, for messages and --help. */
#define PF_EXTENSIONS ".txt/.dat/.pts/.xy (text), .csv (CSV), .npy (NumPy), .bin/.raw/.f64 (raw float64)"

/* Streaming writer: points are appended in order; nothing appears under the
 * final name until pf_writer_commit succeeds. */
typedef struct pf_writer pf_writer;

/* Opens a temporary file beside `path` (so an unwritable folder fails at
 * once, before any long computation). n is the number of points that will
 * be written. Returns NULL with a message in err. */
pf_writer *pf_writer_open(const char *path, size_t n, char *err, size_t errlen);
/* Appends `count` points (xy interleaved: x0 y0 x1 y1 ...). */
int pf_writer_put(pf_writer *w, const double *xy, size_t count, char *err, size_t errlen);
/* Flushes, checks that exactly n points were written, renames into place,
 * frees w. On failure the temporary file is removed. */
int pf_writer_commit(pf_writer *w, char *err, size_t errlen);
/* pf_writer_commit in two halves, for a run that replaces none of its
 * files unless all were written whole: finish (flush, check the count,
 * close; on failure the temporary is removed and w must still go to
 * pf_writer_abort), then publish (rename into place; frees w). */
int pf_writer_finish(pf_writer *w, char *err, size_t errlen);
int pf_writer_publish(pf_writer *w, char *err, size_t errlen);
/* Removes the temporary file and frees w. Safe on NULL. */
void pf_writer_abort(pf_writer *w);
/* The temporary file's name (for a signal handler that must unlink it). */
const char *pf_writer_tmpname(const pf_writer *w);

/* The bytes before the first point: the .npy header (a multiple of 64
 * bytes), or nothing for raw files. Returns its length (0 for raw, text or CSV,
 * or when cap is too small). For writers that place points themselves
 * (MPI-IO): point k then lies at offset len + 16 k. */
#define PF_HEADER_MAX 256
size_t pf_header(pf_format fmt, size_t n, unsigned char *buf, size_t cap);

/* Whole-array helpers. */
int pf_write(const char *path, const double *xy, size_t n, char *err, size_t errlen);
/* Reads a whole file; *xy is malloc'ed (2n doubles) and owned by the caller.
 * Rejects: missing/unreadable files, unknown extensions, empty sets,
 * truncated or corrupt data, bad .npy headers, wrong shapes, NaN/inf and
 * coordinates outside [0,1). */
int pf_read(const char *path, double **xy, size_t *n, char *err, size_t errlen);

/* The same checks on bytes already in memory (buf is not changed); name
 * stands for the file in messages. For tests and the fuzzing harnesses. */
int pf_read_buffer(pf_format fmt, const char *name, const unsigned char *buf, size_t len, double **xy,
                   size_t *n, char *err, size_t errlen);

#endif
