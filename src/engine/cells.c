/* cells.c - see cells.h: the engine's storage, grown on demand, its
 * memory model, the change marks that drive skipping and the cached
 * statistics, the brick colourings' table of row (column) shifts, and
 * eng_fatal, the way out when the storage cannot grow mid-run (every
 * engine file above may call it; it calls only comm). */
#include "cells.h"

#include <stdio.h>
#include <stdlib.h>

#include "geom.h"

static size_t thread_scratch_doubles(size_t m) { return 2 * m + cfpo_solver_scratch(m); }

/* Per point: positions 16 + spare 16, ids 8 + spare 8, displacement 8
 * (relocation rotates five 8-byte buffers, so it needs no spare). Per
 * cell: two offsets and the mask. Per halo cell: two offsets and two
 * copies of about 1.25 points. */
uint64_t cfpo_engine_bytes_local(int64_t nlocal, int64_t cells, int64_t ring, int threads)
{
    return (uint64_t)nlocal * (16 + 16 + 8 + 8 + 8) + (uint64_t)cells * (4 + 4 + 2) +
           (uint64_t)ring * (2 * 4 + 4 + 2 * 2 * 16 * 5 / 4) +
           (uint64_t)(threads > 0 ? threads : 1) * thread_scratch_doubles(64) * 8;
}

int eng_ensure_scratch(cfpo_engine *E)
{
    size_t m = (size_t)9 * (size_t)E->maxcell + 1;
    if (m <= E->scratch_m) return 0;
    m = m < 64 ? 64 : m + m / 2;
    for (int t = 0; t < E->nthreads; t++) {
        double *b = realloc(E->scratch[t], thread_scratch_doubles(m) * sizeof(double));
        if (!b) return -1;
        E->scratch[t] = b;
    }
    E->scratch_m = m;
    return 0;
}

/* Grows the point arrays to hold at least `need` points. */
int eng_ensure_cap(cfpo_engine *E, size_t need)
{
    if (need <= E->cap) return 0;
    size_t cap = need + need / 16 + 1024;
    /* Five buffers of 8 bytes a slot swap roles in eng_relocate(), so they
     * all have the same capacity. */
#define GROW(p, T, per)                                       \
    do {                                                      \
        T *q_ = realloc(E->p, cap * (per) * sizeof(T));       \
        if (!q_) return -1;                                   \
        E->p = q_;                                            \
    } while (0)
    GROW(px, double, 1); GROW(py, double, 1); GROW(tx, double, 1); GROW(ty, double, 1);
    GROW(pid, uint64_t, 1); GROW(tid, uint64_t, 1); GROW(dq, float, 2);
#undef GROW
    E->cap = cap;
    return 0;
}

/* The brick shifts of the iteration's key (cells.h). */
int eng_brick_table(cfpo_engine *E)
{
    if (!E->pol.brick || (E->brick_sh && E->brick_sh_key == E->pol.brick_key)) return 0;
    if (!E->brick_sh && !(E->brick_sh = malloc((size_t)E->G.g))) return -1;
    for (int64_t i = 0; i < E->G.g; i++) E->brick_sh[i] = (uint8_t)cfpo_policy_brick_shift(E->pol.brick_key, i);
    E->brick_sh_key = E->pol.brick_key;
    return 0;
}

/* Out of memory mid-run: back to cfpo_engine_run's setjmp (one rank), or
 * the whole job ends (several ranks: every rank must stop). */
void eng_fatal(cfpo_engine *E, const char *what)
{
    if (E->fail) {
        snprintf(E->fail_msg, sizeof E->fail_msg, "out of memory while %s", what);
        longjmp(*E->fail, 1);
    }
    fprintf(stderr, "cfpo: rank %d: out of memory while %s\n", E->rank, what);
    comm_abort(1);
}

static inline void mark_cell(cfpo_engine *E, int64_t x, int64_t y)
{
    E->mask[y * E->w + x] |= NEED_BIT;
    E->bdirty[(y / SB) * E->nbx + x / SB] = 1;
}

/* Marks the own cells of the 3x3 block around (lx, ly) (an own cell or a
 * halo cell) to be solved again, and their statistics blocks stale. */
void eng_mark_block(cfpo_engine *E, int64_t lx, int64_t ly)
{
    if (lx >= 1 && lx < E->w - 1 && ly >= 1 && ly < E->h - 1) { /* inside: no wrap, no halo */
        const int64_t b0 = (lx - 1) / SB, b1 = (lx + 1) / SB; /* the block columns it touches */
        for (int64_t y = ly - 1; y <= ly + 1; y++) {
            uint16_t *mk = E->mask + y * E->w + lx;
            mk[-1] |= NEED_BIT;
            mk[0] |= NEED_BIT;
            mk[1] |= NEED_BIT;
            uint8_t *bd = E->bdirty + (y / SB) * E->nbx;
            bd[b0] = 1;
            bd[b1] = 1;
        }
        return;
    }
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int64_t x = lx + dx, y = ly + dy;
            if (E->wrapx) x = (x % E->w + E->w) % E->w;
            else if (x < 0 || x >= E->w) continue;
            if (E->wrapy) y = (y % E->h + E->h) % E->h;
            else if (y < 0 || y >= E->h) continue;
            mark_cell(E, x, y);
        }
}
