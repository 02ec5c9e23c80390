/* grow.h: room for one more item in an array that doubles as it grows (the core's
 * pairs and broad phase, and the shell's tokens, statements and tracker rows), and
 * arrays sized for a count (the step's and the answering's scratch). */
#ifndef VROC_GROW_H
#define VROC_GROW_H

#include <stdbool.h>
#include <stdlib.h>

/* items (n of them, room for *cap, each elem bytes) with room for one more: items
 * itself when there is room, else the array moved to twice the room (first when
 * there was none), *cap updated.  NULL when out of memory: items is left as it
 * was. */
static inline void *grow_for_one(void *items, int n, int *cap, size_t elem, int first)
{
    if (n < *cap) return items;
    int c = *cap ? 2 * *cap : first;
    void *moved = realloc(items, (size_t)c * elem);
    if (moved) *cap = c;
    return moved;
}

/* The room to grow an array of room cap to, for need items (need > cap): twice
 * cap at least, so that what grows an item at a time (a crowd's contact points)
 * moves its arrays few times. */
static inline long grow_doubled(long need, long cap)
{
    return need > 2 * cap ? need : 2 * cap;
}

/* The array p resized to n elements (at least one) of elem bytes: the moved
 * array, or p itself with *ok set false when that fails. */
static inline void *grow_resized(void *p, size_t elem, long n, bool *ok)
{
    void *q = realloc(p, (size_t)(n > 0 ? n : 1) * elem);
    if (!q) *ok = false;
    return q ? q : p;
}

#endif
