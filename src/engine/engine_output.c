/* engine_output.c - the engine's points out: to a shared file (every rank
 * writes its own points at their ids' places, collectively), to a point-file
 * writer on one rank, or to memory. All in id order. */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void eng_sort3(uint64_t *id, double *x, double *y, int64_t lo, int64_t hi)
{
    while (hi - lo > 16) {
        int64_t mid = lo + (hi - lo) / 2;
        uint64_t a = id[lo], b = id[mid], c = id[hi - 1];
        uint64_t piv = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
        int64_t i = lo, j = hi - 1;
        while (i <= j) {
            while (id[i] < piv) i++;
            while (id[j] > piv) j--;
            if (i <= j) {
                uint64_t t = id[i]; id[i] = id[j]; id[j] = t;
                double u = x[i]; x[i] = x[j]; x[j] = u;
                u = y[i]; y[i] = y[j]; y[j] = u;
                i++;
                j--;
            }
        }
        if (j + 1 - lo < hi - i) { eng_sort3(id, x, y, lo, j + 1); lo = i; }
        else { eng_sort3(id, x, y, i, hi); hi = j + 1; }
    }
    for (int64_t k = lo + 1; k < hi; k++) {
        uint64_t t = id[k];
        double u = x[k], v = y[k];
        int64_t j = k;
        while (j > lo && id[j - 1] > t) { id[j] = id[j - 1]; x[j] = x[j - 1]; y[j] = y[j - 1]; j--; }
        id[j] = t; x[j] = u; y[j] = v;
    }
}

int cfpo_engine_write_points(cfpo_engine *E, comm_file *f, uint64_t base, char *err, size_t errlen)
{
    /* Own points in id order, in the spare buffers. */
    memcpy(E->tid, E->pid, (size_t)E->nloc * sizeof(uint64_t));
    memcpy(E->tx, E->px, (size_t)E->nloc * sizeof(double));
    memcpy(E->ty, E->py, (size_t)E->nloc * sizeof(double));
    eng_sort3(E->tid, E->tx, E->ty, 0, E->nloc);
    /* In pieces of CH points: each piece is one collective write of its
     * runs of consecutive ids. */
    const int64_t CH = (int64_t)1 << 20;
    int64_t rounds = (E->nloc + CH - 1) / CH;
    comm_max_i64(&rounds, 1);
    double *buf = malloc((size_t)CH * 16);
    uint64_t *first = malloc((size_t)CH * sizeof *first), *len = malloc((size_t)CH * sizeof *len);
    int ok = buf && first && len;
    if (!comm_all(ok)) {
        free(buf); free(first); free(len);
        snprintf(err, errlen, "out of memory while writing");
        return -1;
    }
    for (int64_t r = 0; r < rounds; r++) {
        int64_t a = r * CH, b = a + CH < E->nloc ? a + CH : E->nloc;
        if (a > b) a = b;
        int64_t nr = 0;
        for (int64_t i = a; i < b; i++) {
            buf[2 * (i - a)] = E->tx[i];
            buf[2 * (i - a) + 1] = E->ty[i];
            if (nr > 0 && first[nr - 1] + len[nr - 1] == E->tid[i]) len[nr - 1]++;
            else { first[nr] = E->tid[i]; len[nr] = 1; nr++; }
        }
        if (comm_file_write_runs(f, base, 16, buf, nr, first, len) != 0) ok = 0;
    }
    free(buf); free(first); free(len);
    if (!comm_all(ok)) {
        snprintf(err, errlen, "write failed (disk full or file system error)");
        return -1;
    }
    return 0;
}

int cfpo_engine_write(cfpo_engine *E, pf_writer *w, char *err, size_t errlen)
{
    for (int64_t i = 0; i < E->nloc; i++) {
        E->tx[E->pid[i]] = E->px[i];
        E->ty[E->pid[i]] = E->py[i];
    }
    enum { CHUNK = 4096 };
    double buf[2 * CHUNK];
    for (int64_t i = 0; i < E->n; i += CHUNK) {
        int64_t cnt = E->n - i < CHUNK ? E->n - i : CHUNK;
        for (int64_t j = 0; j < cnt; j++) {
            buf[2 * j] = E->tx[i + j];
            buf[2 * j + 1] = E->ty[i + j];
        }
        if (pf_writer_put(w, buf, (size_t)cnt, err, errlen) != 0) return -1;
    }
    return 0;
}

void cfpo_engine_points(const cfpo_engine *E, double *xy)
{
    for (int64_t i = 0; i < E->nloc; i++) {
        xy[2 * E->pid[i]] = E->px[i];
        xy[2 * E->pid[i] + 1] = E->py[i];
    }
}
