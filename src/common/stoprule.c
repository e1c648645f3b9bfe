/* stoprule.c - see stoprule.h. */
#include "stoprule.h"

#include <string.h>

#include "cli.h"

void cfpo_stop_rules_init(cfpo_stop_rules *r)
{
    r->target_min = 0;
    r->target_avg = 0;
    r->time_limit = 0;
}

const cfpo_stop_option cfpo_stop_options[3] = {{"target-min", 0, 1}, {"target-avg", 0, 1.1}, {"time-limit", 0, 1e9}};

int cli_stop_option(const char *prog, const char *name, const char *arg, cfpo_stop_rules *r)
{
    double *const dsts[3] = {&r->target_min, &r->target_avg, &r->time_limit};
    int i = 0;
    while (i < 3 && strcmp(name, cfpo_stop_options[i].name) != 0) i++;
    if (i == 3) return 0;
    double *dst = dsts[i];
    const double lo = cfpo_stop_options[i].lo, hi = cfpo_stop_options[i].hi;
    double v;
    if (cli_parse_double(arg, lo, hi, &v) != 0 || !(v > 0))
        cli_usage_error(prog, "--%s: '%s' is not a number in (%g, %g]", name, arg, lo, hi);
    *dst = v;
    return 1;
}

int cfpo_stop_targets_met(const cfpo_stop_rules *r, double dmin, double davg)
{
    if (!(r->target_min > 0) && !(r->target_avg > 0)) return 0;
    if (r->target_min > 0 && !(dmin >= r->target_min)) return 0;
    if (r->target_avg > 0 && !(davg >= r->target_avg)) return 0;
    return 1;
}

int cfpo_stop_check(const cfpo_stop_rules *r, const cfpo_iter_stats *s, double elapsed, int max_iter)
{
    if (s->converged) return CFPO_STOP_CONVERGED;
    if (cfpo_stop_targets_met(r, s->delta_min, s->delta_avg)) return CFPO_STOP_TARGET;
    if (r->time_limit > 0 && elapsed >= r->time_limit) return CFPO_STOP_TIME;
    if (s->iteration >= max_iter) return CFPO_STOP_MAX_ITER;
    return CFPO_STOP_NONE;
}

const char *cfpo_stop_name(int why)
{
    switch (why) {
    case CFPO_STOP_CONVERGED: return "converged";
    case CFPO_STOP_TARGET: return "target";
    case CFPO_STOP_TIME: return "time";
    case CFPO_STOP_MAX_ITER: return "max-iter";
    case CFPO_STOP_CALLER: return "caller";
    case CFPO_STOP_SIGNAL: return "signal";
    case CFPO_STOP_FLAT: return "flat";
    case CFPO_STOP_LEVEL_ITER: return "level-iter";
    default: return "-";
    }
}
