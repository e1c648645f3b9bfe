/* npy.h - layer 0 (includes nothing of the project): the .npy header,
 * read strictly (used by pointfile.c and density.c).
 *
 * Accepts exactly the files numpy's format specification describes that
 * hold an (n, 2) array of float64 or float32: versions 1.0, 2.0 and 3.0;
 * a header that is a Python dict literal with the three keys 'descr',
 * 'fortran_order' and 'shape', each once; descr '<f8', '>f8', '<f4', '>f4'
 * (also written '=f8', 'f8', '<d', 'd', 'f4', 'f', ...; '=' and no prefix
 * mean this machine's order, as numpy reads them); fortran_order True or
 * False; shape a tuple of two non-negative decimal ints, the second 2;
 * nothing but spaces, tabs and line ends around the tokens and after the
 * closing brace. Refused, among others: duplicate or missing or extra
 * keys, 'TrueX', junk after the brace, leading zeros (Python refuses
 * them), escapes and concatenated strings, headers over 10,000 bytes (numpy
 * refuses them too), minor versions other than 0.
 * npy_parse_header_2d reads the same grammar for any 2-D shape (rows,
 * cols) of float64 or float32: the density arrays of density.c.
 * Owns: the header grammar. Does not own: the data (pointfile.c). */
#ifndef CFPO_NPY_H
#define CFPO_NPY_H

#include <stddef.h>

typedef struct {
    size_t n;        /* rows */
    size_t cols;     /* columns: 2 for point files */
    size_t data;     /* offset of the first data byte */
    int itemsize;    /* 8 (float64) or 4 (float32) */
    int big_endian;  /* the data's byte order */
    int fortran;     /* column-major: all x, then all y */
} npy_info;

/* 0, or -1 with one line naming the file (path) in err. Checks the header
 * only; the data's length is the caller's. */
int npy_parse_header(const char *path, const unsigned char *buf, size_t len, npy_info *info, char *err,
                     size_t errlen);

/* The same for a 2-D array of any shape: info->n rows, info->cols columns. */
int npy_parse_header_2d(const char *path, const unsigned char *buf, size_t len, npy_info *info, char *err,
                        size_t errlen);

#endif
