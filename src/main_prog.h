/* main_prog.h - layer 5: the `cfpo --progressive` and `cfpo --classes K`
 * path of the cfpo command (main.c parses the command line and refuses the
 * options this path does not take): the run of progressive.h, its files
 * (the points in prefix order; a trace with the level, the prefix and the
 * worst prefix so far, and one row per sweep of the joint move, level =
 * the level count), the LEVEL lines, a JOINT line per sweep of the joint
 * move (every prefix's delta_min and delta_avg) and the SUMMARY with the
 * worst prefix.
 * May include: progressive.h and the layers below, cli.h. */
#ifndef CFPO_MAIN_PROG_H
#define CFPO_MAIN_PROG_H

#include "progressive.h"

typedef struct {
    int on;              /* --progressive or --classes given */
    int base_given, level_min_given, relax_given, joint_given, polish_given, level_iter_given, balance_given, colour_given;
    cfpo_prog_options p; /* base, classes, level_min */
} prog_cli;

/* Option codes of main.c's getopt table. */
enum { PROG_OPT_PROGRESSIVE = 1101, PROG_OPT_BASE, PROG_OPT_CLASSES, PROG_OPT_LEVEL_MIN, PROG_OPT_RELAX, PROG_OPT_JOINT,
       PROG_OPT_JOINT_PREFIX, PROG_OPT_JOINT_FULL, PROG_OPT_JOINT_HOLD, PROG_OPT_JOINT_LAST,
       PROG_OPT_JOINT_CANDIDATES,
       PROG_OPT_JOINT_SOLVE, PROG_OPT_JOINT_AVG, PROG_OPT_JOINT_SOFT, PROG_OPT_JOINT_CIRCUM, PROG_OPT_JOINT_PAIRS,
       PROG_OPT_POLISH, PROG_OPT_POLISH_FLOOR, PROG_OPT_LEVEL_ITER,
       PROG_OPT_CLASSES_LEVELS, PROG_OPT_CLASS_UNION_FLOOR, PROG_OPT_CLASS_REACH,
       PROG_OPT_CLASS_SWAPS, PROG_OPT_LEVEL_BALANCE, PROG_OPT_LEVEL_BALANCE_ORDER };

/* One option of this path: 1 when ch is one (a bad value is a usage
 * error), 0 otherwise. */
int prog_cli_option(prog_cli *pc, const char *prog, int ch, const char *arg);

/* The options' checks against n (usage errors: one line, exit 2). */
void prog_cli_settle(prog_cli *pc, const char *prog, int64_t n, int variant);

/* Runs, writes out and trace (either may be NULL), prints LEVEL and
 * SUMMARY lines; with checkpoint, the level under way's checkpoint every
 * `every` iterations, at each level's end and on SIGTERM / SIGUSR1 (then
 * exit status 3, no output); resume: go on from such a checkpoint.
 * Returns the exit status; a failure leaves no file. */
int prog_cli_main(prog_cli *pc, const char *prog, int64_t n, cfpo_options *o, const char *out, const char *trace,
                  int quiet, const char *checkpoint, int every, const char *resume);

#endif
