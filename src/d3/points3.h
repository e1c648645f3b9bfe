/* points3.h - layer 2 of the 3-D engine (uses safefile.h, readall.h,
 * npy.h, cli.h): 3-D point files.
 *
 * Owns: writing n x 3 sets in six formats, chosen by extension, each
 * written whole or not at all (a temporary beside the file, renamed on
 * success, removed on failure or a signal): .npy (n x 3 float64), text
 * (.txt .dat .pts: "x y z" lines), CSV (.csv: header "x,y,z"), raw
 * little-endian float64 triples (.bin .raw .f64), extended XYZ (.xyz
 * .extxyz: the periodic cell as Lattice, species X), LAMMPS data files
 * (.data .lmp: atom style atomic, one atom type) and GROMACS .gro files
 * (box side in nm; GROMACS's fixed layout, which every .gro reader takes:
 * coordinates in 8 columns with 3 decimals, so rounded to 0.001 nm; the
 * box line "L L L"). The first four hold
 * the unit torus; XYZ, LAMMPS and .gro hold the box of side `box`
 * (coordinates times box). Reading (--init): .npy (n x 3, float64 or float32, either
 * byte order, C or Fortran order), text, CSV and raw, strictly (every
 * coordinate finite and in [0,1), at least one point). */
#ifndef CFPO_POINTS3_H
#define CFPO_POINTS3_H

#include <stddef.h>

typedef enum { P3F_UNKNOWN = 0, P3F_TEXT, P3F_CSV, P3F_NPY, P3F_RAW, P3F_XYZ, P3F_LAMMPS, P3F_GRO } p3_format;

#define P3_EXTENSIONS ".npy, .txt/.dat/.pts, .csv, .bin/.raw/.f64, .xyz/.extxyz, .data/.lmp, .gro"

p3_format p3_format_of(const char *path);
/* 1 for the formats --init reads. */
int p3_format_readable(p3_format f);

/* The .gro layout's room: coordinates below 10^4 nm (box < 10^4), as
 * every box a format takes must be positive and finite. 0, or -1 with one
 * line naming path. */
int p3_check_box(const char *path, double box, char *err, size_t errlen);

/* Checks that path can be written (its temporary can be made; removed at
 * once) before a long run. 0, or -1 with one line. */
int p3_probe(const char *path, char *err, size_t errlen);

/* Writes n points (xyz interleaved, in [0,1)). box > 0 (XYZ, LAMMPS).
 * 0, or -1 with one line naming the file (nothing left under path). */
int p3_write(const char *path, const double *xyz, size_t n, double box, char *err, size_t errlen);

/* Reads a whole file; *xyz malloc'ed (3n doubles). 0 or -1 with one line. */
int p3_read(const char *path, double **xyz, size_t *n, char *err, size_t errlen);
/* The same on bytes in memory (buf not changed; tests, fuzzing). */
int p3_read_buffer(p3_format fmt, const char *name, const unsigned char *buf, size_t len, double **xyz,
                   size_t *n, char *err, size_t errlen);

#endif
