/* bl_method.h - the one description of each baseline method, read by the
 * commands (bl_cli.c) and by the Python binding (python/src) alike.
 *
 * Owns: what a method is as data: its names, its own options with their
 * type, range, default, the command's spelling and wording and the Python
 * keyword; its trace columns after the common ones; and, for the
 * iterative methods, its engine behind function pointers (bl_loop.h runs
 * it). The list of methods is bl_list.c; each method's row sits beside
 * its command-independent glue in bl_<method>.c.
 * Does not own: parsing argv (bl_cli.c), the run loop and its stop rules
 * (bl_loop.c), the Poisson-disk radius check (pd_check.c), any method's
 * algorithm (fpo.cpp, ccvt.c, ...). */
#ifndef CFPO_BASELINES_BL_METHOD_H
#define CFPO_BASELINES_BL_METHOD_H

#include <stddef.h>
#include <stdint.h>

#include "cfpo_types.h"
#include "density.h"
#include "tracecols.h"

typedef enum { BL_INT, BL_REAL, BL_FLAG, BL_CHOICE } bl_type;

#define BL_MAX_OPTIONS 8
#define BL_MAX_CHOICES 4
#define BL_MAX_COLUMNS 8

/* One option of a method. The command spells it --cli (short -letter when
 * letter is set), Python py; "" where it is not offered. A flag is set to 1
 * by --cli and to 0 by --cli_off. */
typedef struct {
    const char *cli;
    const char *py;
    char letter;
    bl_type type;
    int64_t lo, hi;       /* BL_INT: the range */
    double min, max;      /* BL_REAL: the range */
    int open_min;         /* BL_REAL: min itself excluded */
    double def;           /* the default; it may lie outside the range: 0 or
                           * -1, decided by the method (e.g. from n) or not
                           * given; BL_CHOICE: the index of the default */
    const char *bad;      /* the command's wording after "'VALUE' " for a bad
                           * value, e.g. "is not a whole number in 1..1e6" */
    const char *choices[BL_MAX_CHOICES]; /* BL_CHOICE: the words, NULL-ended */
    const char *cli_off;  /* BL_FLAG: the command's option that clears it */
    const char *help;     /* the iterative command's help lines, a printf
                           * format that may show the default (%g); the
                           * Poisson-disk command writes its own (pd_main.c) */
} bl_option;

/* An option's value, by the option's type: BL_REAL in d, else in i (a
 * choice's index, a flag's 0/1). */
typedef union {
    int64_t i;
    double d;
} bl_value;

/* A trace column after the common ones (src/common/tracecols.h). */
typedef cfpo_trace_column bl_column;

typedef enum { BL_POISSON, BL_ITERATIVE } bl_kind;

typedef struct bl_method bl_method;
struct bl_method {
    const char *name;        /* the SUMMARY line's method= and Python's function */
    const char *prog;        /* the command, e.g. "cfpo-ccvt" */
    bl_kind kind;
    const char *about;       /* the help's description lines */
    const bl_option *options;/* the method's own options */
    int noptions;
    const bl_column *columns;/* the trace columns after the common ones */
    int ncolumns;

    /* BL_POISSON: which sampler (pd_check.h) and its default relative
     * radius r / Delta(n) */
    int pd_kind;
    double pd_rel;

    /* BL_ITERATIVE. The options' values are v[0..noptions-1]. */
    /* SUMMARY method= when the options decide it; NULL: name */
    const char *(*method_name)(const bl_value *v);
    /* checks n before any work: 0 ok, -1 bad argument, -2 too large for
     * memory, with a message */
    int (*check_n)(const bl_value *v, int64_t n, double tol, char *err, size_t errlen);
    /* the engine for n points, seed and tol; NULL with a message */
    void *(*create)(const bl_value *v, int64_t n, uint64_t seed, double tol, char *err, size_t errlen);
    /* the same under a density (`--density SPEC`, read during the run);
     * NULL: the method has no density option. With rho = 1 it must give
     * create's run, byte for byte; its deltas are then in the symmetric
     * measure (src/density/dens_measure.h). */
    void *(*create_density)(const bl_value *v, int64_t n, uint64_t seed, double tol, const cfpo_density *d,
                            char *err, size_t errlen);
    /* NULL: a direct sampler (its start is its set, converged at once) */
    void (*iterate)(void *E, cfpo_iter_stats *s);
    void (*deltas)(void *E, double *dmin, double *davg);
    /* the values of the columns (ncolumns of them) */
    void (*column_values)(void *E, double *out);
    const double *(*points)(void *E);
    const char *density_help; /* --density's help: what the method does under it */
    /* NULL, or the message when options v do not go with a density */
    const char *(*density_refuses)(const bl_value *v);
    void (*destroy)(void *E);
};

/* A row's pieces: the options' table, the trace columns' table, and the
 * engine's functions under their usual names in a bl_<method>.c. */
#define BL_OPTIONS(opts) .options = (opts), .noptions = (int)(sizeof(opts) / sizeof(opts)[0])
#define BL_COLUMNS(cols) .columns = (cols), .ncolumns = (int)(sizeof(cols) / sizeof(cols)[0])
#define BL_ENGINE                                                                                                \
    .check_n = check_n, .create = create, .iterate = iterate, .deltas = deltas, .points = points,                \
    .destroy = destroy

/* The methods, in the order of scripts/methods.tsv; NULL-ended. */
extern const bl_method *const bl_methods[];

/* The method named name, or NULL. */
const bl_method *bl_method_find(const char *name);

/* v[i] = the default of option i, for every option. */
void bl_defaults(const bl_method *m, bl_value *v);

/* The options' index by the command's spelling (cli or cli_off), or -1. */
int bl_option_index(const bl_method *m, const char *cli);

/* Parses the command's argument for option i into v[i] (a flag: off says
 * whether --cli_off was given). 0, or -1 with the command's message
 * ("--name: 'arg' is not ..."). */
int bl_option_parse(const bl_method *m, int i, const char *arg, int off, bl_value *v, char *err,
                    size_t errlen);

/* The common checks of n for an iterative method: cfpo's smallest n (its
 * cell side scales tol), then `bytes` against the machine's memory. 0, -1
 * (too small) or -2 (too large for memory) with a message. */
int bl_check_n_memory(const char *method, int64_t n, double tol, double bytes, char *err, size_t errlen);

#endif
