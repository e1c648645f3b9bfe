/* test_d3_sched.c - the 3-D schedule's block in a checkpoint (sched3.h):
 * a run stopped inside round 1 writes a version-3 checkpoint whose block
 * passes the check and resumes to the uninterrupted run's set and
 * statistics; the block with one field out of range, a best-set
 * coordinate outside [0,1) or a length one off fails the check, and a
 * resume from such a file (its checksum made right) is refused with one
 * line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine3.h"
#include "sched3.h"
#include "testutil.h"

static int passed_, failed_;

/* The schedule (W = 3 with a gain no iteration reaches, so each round is
 * exactly 3 iterations; 2 shakes) from the jittered start or resumed. */
static int run(cfpo3_engine *e, int max_iter, const char *ck, cfpo3_sched_result *r, char *err, size_t el)
{
    cfpo3_sched_args a;
    memset(&a, 0, sizeof a);
    a.so = (cfpo3_sched_opts){.rounds = 2, .amp = 0.15, .flat = 3, .flat_gain = 1.0};
    a.max_iter = max_iter;
    cfpo_stop_rules_init(&a.stop);
    a.ckpt = ck;
    a.every = 1;
    return cfpo3_sched_run(e, &a, r, err, el);
}

static unsigned char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *len = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc(*len);
    if (b && fread(b, 1, *len, f) != *len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

/* buf with its checksum made right, parsed and resumed: 0 when the resume ran */
static int resume_bytes(unsigned char *buf, size_t len, char *err, size_t el)
{
    const uint32_t crc = cfpo3_checkpoint_crc(buf, len);
    memcpy(buf + 60, &crc, 4);
    cfpo3_engine *e = cfpo3_checkpoint_parse(buf, len, "x.ck", 1, err, el);
    if (!e) return -1;
    cfpo3_sched_result r;
    const int rc = run(e, 1000, NULL, &r, err, el);
    cfpo3_free(r.e);
    if (rc == 0) free(r.best);
    return rc;
}

int main(void)
{
    const int64_t n = 324;
    char err[512], path[] = "/tmp/cfpo3-sched-XXXXXX";
    const int fd = mkstemp(path);
    if (fd >= 0) close(fd);
    cfpo3_options o;
    cfpo3_options_default(&o);
    o.threads = 1;
    cfpo3_sched_result u, p, q;
    CHECK(run(cfpo3_create(n, &o, err, sizeof err), 1000, NULL, &u, err, sizeof err) == 0, "whole run: %s", err);
    CHECK(u.iterations == 9 && u.converged && u.rounds_done == 2 && u.best, "whole run: %d iterations", u.iterations);
    /* stopped at iteration 5 (round 1's second), then resumed */
    CHECK(run(cfpo3_create(n, &o, err, sizeof err), 5, path, &p, err, sizeof err) == 0 && p.stop == CFPO_STOP_MAX_ITER &&
              p.rounds_done == 1,
          "the run to 5: %s", err);
    cfpo3_free(p.e), free(p.best);
    size_t len;
    unsigned char *buf = slurp(path, &len);
    CHECK(buf && len > 64 + 24 * (size_t)n && buf[8] == 3, "a version-3 checkpoint");
    cfpo3_engine *e = buf ? cfpo3_checkpoint_parse(buf, len, "x.ck", 2, err, sizeof err) : NULL;
    size_t tl = 0;
    const unsigned char *t0 = e ? cfpo3_checkpoint_tail(e, &tl) : NULL;
    unsigned char *tail = t0 ? malloc(tl) : NULL; /* (the engine goes to the schedule) */
    if (tail) memcpy(tail, t0, tl);
    CHECK(tail && cfpo3_sched_block_check(tail, tl, n, err, sizeof err) == 0, "the block passes: %s", err);
    CHECK(e && run(e, 1000, NULL, &q, err, sizeof err) == 0, "resume: %s", err);
    if (e) { /* (e is the schedule's now: q.e holds the last round's engine) */
        CHECK(q.iterations == u.iterations && q.dmin == u.dmin && q.davg == u.davg && q.best_round == u.best_round &&
                  memcmp(q.best, u.best, 24 * (size_t)n) == 0,
              "the resume differs from the whole run");
        cfpo3_free(q.e), free(q.best);
    }
    /* the block's fields, one at a time (offsets of sched3.c), and its length */
    if (buf && tail) {
        const size_t at = len - tl; /* the block's place in the file */
        struct {
            size_t off;
            int bytes;
            double v;
        } bad[] = {{8, 4, 3}, {12, 4, 1001}, {16, 8, 0}, {16, 8, NAN}, {24, 4, 10001}, {28, 4, 2}, {32, 8, 2},
                   {68, 4, 3}, {72, 4, 2}, {76, 4, 1}, {tl - 8, 8, 1.0}, {tl - 8, 8, -0.5}};
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            unsigned char *b = malloc(len);
            memcpy(b, buf, len);
            if (bad[i].bytes == 4) {
                const uint32_t v = (uint32_t)bad[i].v;
                memcpy(b + at + bad[i].off, &v, 4);
            } else {
                memcpy(b + at + bad[i].off, &bad[i].v, 8);
            }
            CHECK(cfpo3_sched_block_check(b + at, tl, n, err, sizeof err) != 0, "field at %zu accepted", bad[i].off);
            err[0] = 0;
            CHECK(resume_bytes(b, len, err, sizeof err) != 0 && strncmp(err, "the checkpoint's schedule: ", 27) == 0 &&
                      !strchr(err, '\n'),
                  "resume with the field at %zu: '%s'", bad[i].off, err);
            free(b);
        }
        CHECK(cfpo3_sched_block_check(tail, tl - 1, n, err, sizeof err) != 0 &&
                  cfpo3_sched_block_check(tail, tl, n + 1, err, sizeof err) != 0,
              "a block of the wrong length accepted");
    }
    free(buf), free(u.best), free(tail);
    cfpo3_free(u.e);
    unlink(path);
    return test_report(passed_, failed_);
}
