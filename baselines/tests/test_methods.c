/* test_methods.c - the method table (bl_method.h, bl_list.c) against what
 * it describes:
 *  - scripts/methods.tsv (argv[1]): every pd and iter row has a method of
 *    that name, command and kind, and every method a row;
 *  - every option: a name for the command or Python, help lines (the
 *    iterative commands print them; pd_main.c writes its own), a wording for a bad
 *    value, a default inside its range or one of the out-of-range markers
 *    (0, -1) that mean "the method decides"; a choice's default is one of
 *    its words; the command's spellings are unique within a method;
 *  - the command's parse takes the default's text back to the default, and
 *    refuses a value past the range with "--name: 'value' <bad>";
 *  - the defaults are the library's own: bnot_rule_init's schedule,
 *    ccvt_options_init's choices, fpo_options_init's start;
 *  - the trace columns: the common ones are cfpo's first eight, each
 *    column of a method has a name and a format. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bl_method.h"
#include "bnot.h"
#include "ccvt.h"
#include "fpo.h"
#include "testutil.h"

static int passed_ = 0, failed_ = 0;

static void check_tsv(const char *path)
{
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return;
    char line[1024];
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || strncmp(line, "key\t", 4) == 0) continue;
        char *field[8] = {0};
        int k = 0;
        for (char *p = strtok(line, "\t\n"); p && k < 8; p = strtok(NULL, "\t\n")) field[k++] = p;
        /* the baselines' rows: Poisson-disk (pd), direct and iterative (iter);
         * the direct samplers run through the iterative command line */
        if (k < 8 || (strcmp(field[4], "pd") != 0 && strcmp(field[4], "direct") != 0 && strcmp(field[4], "iter") != 0))
            continue;
        rows++;
        const bl_method *m = bl_method_find(field[0]);
        CHECK(m != NULL, "methods.tsv row %s has no method in bl_list.c", field[0]);
        if (!m) continue;
        const size_t w = strcspn(field[7], " "); /* the program, before any fixed arguments */
        CHECK(strlen(m->prog) == w && strncmp(m->prog, field[7], w) == 0, "%s: command %s, methods.tsv says %s",
              m->name, m->prog, field[7]);
        CHECK(m->kind == (strcmp(field[4], "pd") == 0 ? BL_POISSON : BL_ITERATIVE), "%s: kind", m->name);
        CHECK(strcmp(field[5], m->name) == 0, "%s: SUMMARY method %s", m->name, field[5]);
    }
    fclose(f);
    int n = 0;
    while (bl_methods[n]) n++;
    CHECK(rows == n, "methods.tsv has %d pd/direct/iter rows, bl_list.c %d methods", rows, n);
}

static void check_option(const bl_method *m, int i)
{
    const bl_option *o = &m->options[i];
    CHECK(o->cli[0] || o->py[0] || o->cli_off, "%s option %d: no name", m->name, i);
    CHECK(o->type == BL_FLAG || (o->bad && o->bad[0]), "%s --%s: no wording for a bad value", m->name, o->cli);
    CHECK(m->kind != BL_ITERATIVE || o->help != NULL, "%s --%s: no help", m->name, o->cli);
    for (int j = 0; j < i; j++) {
        const bl_option *p = &m->options[j];
        CHECK(!o->cli[0] || strcmp(o->cli, p->cli) != 0, "%s: --%s twice", m->name, o->cli);
        CHECK(!o->py[0] || strcmp(o->py, p->py) != 0, "%s: %s twice", m->name, o->py);
    }
    bl_value v[BL_MAX_OPTIONS];
    char arg[64], err[256];
    const int marker = o->def == 0 || o->def == -1;
    switch (o->type) {
    case BL_INT:
        CHECK(o->lo <= o->hi, "%s --%s: empty range", m->name, o->cli);
        CHECK((o->def >= (double)o->lo && o->def <= (double)o->hi) || marker, "%s --%s: default %g", m->name, o->cli,
              o->def);
        if (o->def >= (double)o->lo && o->def <= (double)o->hi) {
            snprintf(arg, sizeof arg, "%.0f", o->def);
            CHECK(bl_option_parse(m, i, arg, 0, v, err, sizeof err) == 0 && v[i].i == (int64_t)o->def,
                  "%s --%s %s: not taken back", m->name, o->cli, arg);
        }
        if (o->lo > INT64_MIN) {
            snprintf(arg, sizeof arg, "%lld", (long long)o->lo - 1);
            char want[256];
            snprintf(want, sizeof want, "--%s: '%s' %s", o->cli, arg, o->bad);
            CHECK(bl_option_parse(m, i, arg, 0, v, err, sizeof err) == -1 && strcmp(err, want) == 0,
                  "%s --%s %s: '%s'", m->name, o->cli, arg, err);
        }
        break;
    case BL_REAL:
        CHECK((o->def >= o->min && o->def <= o->max && !(o->open_min && o->def == o->min)) || marker,
              "%s --%s: default %g", m->name, o->cli, o->def);
        if (!marker || o->def > o->min) {
            snprintf(arg, sizeof arg, "%.17g", o->def);
            CHECK(bl_option_parse(m, i, arg, 0, v, err, sizeof err) == 0 && v[i].d == o->def,
                  "%s --%s %s: not taken back", m->name, o->cli, arg);
        }
        snprintf(arg, sizeof arg, "%.17g", o->max * 2 + 1);
        CHECK(bl_option_parse(m, i, arg, 0, v, err, sizeof err) == -1 && strstr(err, o->bad) != NULL,
              "%s --%s %s: '%s'", m->name, o->cli, arg, err);
        if (o->open_min) {
            snprintf(arg, sizeof arg, "%.17g", o->min);
            CHECK(bl_option_parse(m, i, arg, 0, v, err, sizeof err) == -1, "%s --%s: takes its open end", m->name,
                  o->cli);
        }
        break;
    case BL_CHOICE: {
        int nc = 0;
        while (nc < BL_MAX_CHOICES && o->choices[nc]) nc++;
        CHECK(nc >= 2 && o->def >= 0 && o->def < nc, "%s --%s: default %g of %d words", m->name, o->cli, o->def, nc);
        for (int c = 0; c < nc; c++)
            CHECK(bl_option_parse(m, i, o->choices[c], 0, v, err, sizeof err) == 0 && v[i].i == c,
                  "%s --%s %s", m->name, o->cli, o->choices[c]);
        CHECK(bl_option_parse(m, i, "no-such-word", 0, v, err, sizeof err) == -1, "%s --%s: took a bad word",
              m->name, o->cli);
        break;
    }
    case BL_FLAG:
        CHECK(o->def == 0 || o->def == 1, "%s %s: default %g", m->name, o->py, o->def);
        CHECK(bl_option_parse(m, i, NULL, 1, v, err, sizeof err) == 0 && v[i].i == 0, "%s: off", m->name);
        CHECK(bl_option_parse(m, i, NULL, 0, v, err, sizeof err) == 0 && v[i].i == 1, "%s: on", m->name);
        break;
    }
}

static double def_of(const char *method, const char *cli)
{
    const bl_method *m = bl_method_find(method);
    const int i = m ? bl_option_index(m, cli) : -1;
    CHECK(i >= 0, "%s has no --%s", method, cli);
    return i >= 0 ? m->options[i].def : -99;
}

int main(int argc, char **argv)
{
    if (argc > 1) check_tsv(argv[1]);
    for (int k = 0; bl_methods[k]; k++) {
        const bl_method *m = bl_methods[k];
        char prog[64];
        snprintf(prog, sizeof prog, "cfpo-%s", m->name);
        CHECK(strcmp(prog, m->prog) == 0, "%s: command %s", m->name, m->prog);
        CHECK(m->noptions <= BL_MAX_OPTIONS && m->ncolumns <= BL_MAX_COLUMNS, "%s: too many", m->name);
        for (int i = 0; i < m->noptions; i++) check_option(m, i);
        for (int c = 0; c < m->ncolumns; c++)
            CHECK(m->columns[c].name && m->columns[c].fmt && m->columns[c].fmt[0] == '%', "%s column %d", m->name, c);
        if (m->kind == BL_ITERATIVE)
            CHECK(m->check_n && m->create && m->deltas && m->points && m->destroy &&
                      (m->ncolumns == 0 || m->column_values),
                  "%s: an engine function is missing", m->name);
        else CHECK(m->pd_rel > 0 && m->pd_rel <= 2, "%s: relative radius %g", m->name, m->pd_rel);
    }
    CHECK(strcmp(cfpo_trace_columns[0].name, "iteration") == 0 && CFPO_TRACE_COMMON == 8 &&
              strcmp(cfpo_trace_columns[CFPO_TRACE_COMMON - 1].name, "elapsed") == 0,
          "the common trace columns");
    bnot_rule r;
    bnot_rule_init(&r);
    CHECK(def_of("bnot", "epsilon") == r.epsilon && def_of("bnot", "max-rounds") == r.max_rounds &&
              def_of("bnot", "round-iters") == r.round_iters && def_of("bnot", "no-breaker") == r.breaker,
          "bnot's defaults are not bnot_rule_init's");
    ccvt_options co;
    ccvt_options_init(&co);
    CHECK(def_of("ccvt", "point-set") == co.points && def_of("ccvt", "update") == co.update &&
              def_of("ccvt", "assign") == co.assign && def_of("ccvt", "points-per-site") == (double)co.m,
          "ccvt's defaults are not ccvt_options_init's");
    fpo_options fo;
    fpo_options_init(&fo);
    CHECK(def_of("fpo", "start") == fo.start && def_of("fpo", "local") == 0 && def_of("lfpo", "local") == 1,
          "fpo's defaults");
    return test_report(passed_, failed_);
}
