/* pairs.c: the pairs of objects that may collide, made again as objects come and
 * go, and the counted queries of a pair (thesis 3.3.2). */
#include "pairs.h"

#include <assert.h>

#include <math.h>
#include <stdlib.h>

#include "world.h"

void pairs_init(pair_list *pl)
{
    pl->p = NULL;
    pl->hits = NULL;
    pl->n = pl->cap = 0;
    pl->dirty = false;
}

void pairs_free(pair_list *pl)
{
    free(pl->p);
    free(pl->hits);
    pairs_init(pl);
}

long pair_index(const world *w, int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    long lo = 0, hi = w->pairs.n;
    while (lo < hi) {
        long mid = lo + (hi - lo) / 2;
        const pair *p = &w->pairs.p[mid];
        if (p->a < a || (p->a == a && p->b < b)) lo = mid + 1;
        else hi = mid;
    }
    return lo < w->pairs.n && w->pairs.p[lo].a == a && w->pairs.p[lo].b == b ? lo : -1;
}

int pairs_update(world *w)
{
    if (!w->pairs.dirty) return 0;
    long d = 0, st = 0; /* dynamic and static objects */
    for (int i = 0; i < w->n; i++) {
        if (body_is_static(w->bodies[i])) st++;
        else d++;
    }
    long n = d * (d - 1) / 2 + d * st;
    if (n > w->pairs.cap) {
        pair *np = realloc(w->pairs.p, (size_t)n * sizeof *np);
        if (np) w->pairs.p = np;
        pair_hit *nh = realloc(w->pairs.hits, (size_t)n * sizeof *nh);
        if (nh) w->pairs.hits = nh;
        if (!np || !nh) return -1;
        w->pairs.cap = n;
    }
    long k = 0;
    for (int i = 0; i < w->n; i++) {
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            w->pairs.hits[k].t = NAN;
            w->pairs.p[k++] = (pair){.a = i, .b = j, .toi_a = -1, .toi_b = -1};
        }
    }
    assert(k == n); /* every dynamic-dynamic and dynamic-static pair, once */
    w->pairs.n = k;
    w->pairs.dirty = false;
    w->sched_dirty = true; /* the heap holds the old pairs */
    /* an object added or deleted elsewhere leaves a slide on a still support as
     * it was: its pair is found again (the pairs are in the order of a, then b).
     * A slide on a support that moves itself ends, as the schedule starts afresh. */
    for (int i = 0; i < w->n; i++) {
        body *m = w->bodies[i];
        if (m->slide < 0) continue;
        long at = -1;
        if (m->state == STATE_DYNAMIC && w->bodies[m->slide]->state != STATE_DYNAMIC)
            at = pair_index(w, i, m->slide);
        m->slide = at >= 0 ? m->slide : -1;
        m->slide_pair = at;
    }
    return 0;
}

closest_result pair_query(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = body_distance(a, b, &p->cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

closest_result pair_query_hit(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = body_distance(a, b, &p->hit);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

closest_result pair_query_apart(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = body_distance_apart(a, b, &p->cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}
