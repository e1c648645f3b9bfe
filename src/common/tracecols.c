/* tracecols.c - see tracecols.h. */
#include "tracecols.h"

#include <string.h>

const cfpo_trace_column cfpo_trace_columns[CFPO_TRACE_COLUMNS] = {
    {"iteration", "%lld"}, {"delta_min", "%.9f"}, {"delta_avg", "%.9f"}, {"moved", "%lld"},
    {"solved", "%lld"},    {"max_disp", "%.6g"},  {"seconds", "%.6f"},   {"elapsed", "%.6f"},
    {"max_move", "%.6g"},  {"near", "%lld"}};

void cfpo_trace_values(const cfpo_iter_stats *s, double elapsed, double row[CFPO_TRACE_COLUMNS])
{
    row[0] = s->iteration;
    row[1] = s->delta_min;
    row[2] = s->delta_avg;
    row[3] = (double)s->moved;
    row[4] = (double)s->solved;
    row[5] = s->max_disp;
    row[6] = s->seconds;
    row[7] = elapsed;
    row[8] = s->max_move;
    row[9] = s->near;
}

int cfpo_trace_is_whole(const cfpo_trace_column *c) { return strcmp(c->fmt, "%lld") == 0; }

void cfpo_trace_write_names(FILE *f, const cfpo_trace_column *cols, int n, int first)
{
    for (int c = 0; c < n; c++) fprintf(f, "%s%s", c == 0 && first ? "" : "\t", cols[c].name);
}

void cfpo_trace_write_values(FILE *f, const cfpo_trace_column *cols, const double *v, int n, int first)
{
    for (int c = 0; c < n; c++) {
        if (c > 0 || !first) fputc('\t', f);
        if (cfpo_trace_is_whole(&cols[c])) fprintf(f, "%lld", (long long)v[c]);
        else fprintf(f, cols[c].fmt, v[c]);
    }
}
