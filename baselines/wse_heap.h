/* wse_heap.h - layer 1 of the baselines: the max-heap of weights that
 * weighted sample elimination (Yuksel 2015) pops from, shared by the 2-D
 * (wse.c) and 3-D (wse3.c) eliminations: the point of largest weight
 * first (ties: the larger tie key, the point's index when tie is NULL),
 * with each point's place kept so that a lowered weight sifts down. */
#ifndef CFPO_WSE_HEAP_H
#define CFPO_WSE_HEAP_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

typedef struct {
    int64_t *w;        /* the weights, by point */
    size_t *heap, *pos; /* heap[i]: a point; pos[point]: its place */
    size_t len;        /* live points in the heap */
    const size_t *tie; /* the ties' keys by point, or NULL: the point itself */
} wse_heap;

/* The arrays for c points (weights 0); 0, or -1 when out of memory. */
static inline int wse_heap_alloc(wse_heap *H, size_t c, const size_t *tie)
{
    H->w = calloc(c ? c : 1, sizeof *H->w);
    H->heap = malloc((c ? c : 1) * sizeof *H->heap);
    H->pos = malloc((c ? c : 1) * sizeof *H->pos);
    H->len = 0;
    H->tie = tie;
    return H->w && H->heap && H->pos ? 0 : -1;
}

static inline void wse_heap_free(wse_heap *H)
{
    free(H->w), free(H->heap), free(H->pos);
    H->w = NULL, H->heap = H->pos = NULL;
}

static inline int wse_heap_above(const wse_heap *H, size_t a, size_t b)
{
    if (H->w[a] != H->w[b]) return H->w[a] > H->w[b];
    return H->tie ? H->tie[a] > H->tie[b] : a > b;
}

static inline void wse_heap_swap(wse_heap *H, size_t i, size_t j)
{
    const size_t a = H->heap[i], b = H->heap[j];
    H->heap[i] = b, H->heap[j] = a;
    H->pos[b] = i, H->pos[a] = j;
}

static inline void wse_heap_sift_down(wse_heap *H, size_t i)
{
    for (;;) {
        const size_t l = 2 * i + 1;
        size_t best = i;
        if (l < H->len && wse_heap_above(H, H->heap[l], H->heap[best])) best = l;
        if (l + 1 < H->len && wse_heap_above(H, H->heap[l + 1], H->heap[best])) best = l + 1;
        if (best == i) return;
        wse_heap_swap(H, i, best);
        i = best;
    }
}

/* Heap order over points 0..c-1 with their weights as they stand. */
static inline void wse_heap_build(wse_heap *H, size_t c)
{
    for (size_t a = 0; a < c; a++) H->heap[a] = a, H->pos[a] = a;
    H->len = c;
    for (size_t i = c / 2; i-- > 0;) wse_heap_sift_down(H, i);
}

/* Removes and returns the point of largest weight (len > 0). */
static inline size_t wse_heap_pop(wse_heap *H)
{
    const size_t a = H->heap[0];
    wse_heap_swap(H, 0, H->len - 1);
    H->len--;
    wse_heap_sift_down(H, 0);
    return a;
}

/* Lowers point b's weight by dw (>= 0) and restores the order. */
static inline void wse_heap_lower(wse_heap *H, size_t b, int64_t dw)
{
    H->w[b] -= dw;
    wse_heap_sift_down(H, H->pos[b]);
}

#endif
