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

/* The pairs in lasting contact, by their objects (stable across a rebuild). */
typedef struct {
    const body *a, *b;
} kept;

int pairs_update(world *w)
{
    if (!w->pairs.dirty) return 0;
    long d = 0, st = 0; /* dynamic and static objects */
    for (int i = 0; i < w->n; i++) {
        if (body_is_static(w->bodies[i])) st++;
        else d++;
    }
    long n = d * (d - 1) / 2 + d * st, nkeep = 0;
    for (long i = 0; i < w->pairs.n; i++) nkeep += w->pairs.p[i].touching;
    kept *keep = malloc((size_t)(nkeep ? nkeep : 1) * sizeof *keep);
    if (!keep) return -1;
    nkeep = 0;
    for (long i = 0; i < w->pairs.n; i++) {
        const pair *p = &w->pairs.p[i];
        /* (a deleted object's pairs are gone: world_delete ended them) */
        if (p->touching && p->a < w->n && p->b < w->n)
            keep[nkeep++] = (kept){w->bodies[p->a], w->bodies[p->b]};
    }
    if (n > w->pairs.cap) {
        pair *np = realloc(w->pairs.p, (size_t)n * sizeof *np);
        if (np) w->pairs.p = np;
        pair_hit *nh = realloc(w->pairs.hits, (size_t)n * sizeof *nh);
        if (nh) w->pairs.hits = nh;
        if (!np || !nh) {
            free(keep);
            return -1;
        }
        w->pairs.cap = n;
    }
    long k = 0;
    for (int i = 0; i < w->n; i++) {
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            w->pairs.p[k++] = (pair){.a = i, .b = j, .toi_fa = -1, .toi_fb = -1, .toi = HUGE_VAL};
        }
    }
    assert(k == n); /* every dynamic-dynamic and dynamic-static pair, once */
    w->pairs.n = k;
    w->pairs.dirty = false;
    w->sched_dirty = true; /* the heap holds the old pairs */
    /* the lasting contacts, found again among the new pairs */
    for (long i = 0; i < nkeep; i++) {
        int a = -1, b = -1;
        for (int j = 0; j < w->n; j++) {
            if (w->bodies[j] == keep[i].a) a = j;
            if (w->bodies[j] == keep[i].b) b = j;
        }
        long at = a >= 0 && b >= 0 ? pair_index(w, a, b) : -1;
        if (at >= 0) w->pairs.p[at].touching = true;
    }
    free(keep);
    return 0;
}

closest_result pair_query(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = body_distance(a, b, &p->cache);
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
