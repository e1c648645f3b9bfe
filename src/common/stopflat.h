/* stopflat.h - layer 2: the flatness stop rule.
 *
 * Owns: the rule that ends a run whose quality has stopped rising: after
 * an iteration k >= W (W iterations of this process's run, so a resumed
 * run counts from its resume), it holds when delta_min and delta_avg
 * each rose by less than G over the last W iterations
 * (delta(k) - delta(k - W) < G). It sees only the statistics every rank
 * shares, so every rank stops at the same iteration; the 3-D command's
 * --flat W and --flat-gain G (docs/method.md, "Three dimensions").
 * May include: nothing of the project. */
#ifndef CFPO_STOPFLAT_H
#define CFPO_STOPFLAT_H

/* The largest window. */
#define CFPO_FLAT_MAXW 10000

typedef struct {
    int window;  /* W; 0: the rule is off */
    double gain; /* G */
    int count;   /* iterations pushed */
    double *dmin, *davg; /* the last W + 1 values, a ring */
} cfpo_flat_rule;

/* The rule with window W (0: off, nothing allocated) and gain G. 0, or -1
 * when memory runs out. */
int cfpo_flat_init(cfpo_flat_rule *r, int window, double gain);
void cfpo_flat_free(cfpo_flat_rule *r);

/* Records one iteration's statistics; 1 when the rule holds after it. */
int cfpo_flat_push(cfpo_flat_rule *r, double dmin, double davg);
/* 1 when the rule holds after the last push (what that push answered). */
int cfpo_flat_holds(const cfpo_flat_rule *r);

#endif
