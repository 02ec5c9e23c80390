/* pairs.c: the pairs of objects that may collide, made and ended as the broad
 * phase finds objects near and apart, and the counted queries of a pair (thesis
 * 3.3.2). */
#include "pairs.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "broad.h"
#include "grow.h"
#include "schedule.h"
#include "world.h"

void pairs_init(pair_list *pl)
{
    memset(pl, 0, sizeof *pl);
}

void pairs_free(pair_list *pl)
{
    free(pl->p);
    free(pl->hits);
    for (long k = 0; pl->pieces && k < pl->cap; k++) free(pl->pieces[k].e);
    free(pl->pieces);
    free(pl->free_slots);
    for (int i = 0; i < pl->nadj; i++) free(pl->adj[i].l);
    free(pl->adj);
    free(pl->fresh);
    pairs_init(pl);
}

/* ---- each object's pairs, by the other object ---- */

/* The place of other in adj: where it is, or where it would go. */
static int adj_place(const pair_adj *adj, int other)
{
    int lo = 0, hi = adj->n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (adj->l[mid].other < other) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

static int adj_insert(pair_adj *adj, int other, long slot)
{
    pair_link *l = grow_for_one(adj->l, adj->n, &adj->cap, sizeof *l, 4);
    if (!l) return -1;
    adj->l = l;
    int at = adj_place(adj, other);
    memmove(&adj->l[at + 1], &adj->l[at], (size_t)(adj->n - at) * sizeof *adj->l);
    adj->l[at] = (pair_link){other, slot};
    adj->n++;
    return 0;
}

static void adj_erase(pair_adj *adj, int other)
{
    int at = adj_place(adj, other);
    assert(at < adj->n && adj->l[at].other == other);
    memmove(&adj->l[at], &adj->l[at + 1], (size_t)(adj->n - at - 1) * sizeof *adj->l);
    adj->n--;
}

long pair_index(const world *w, int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    if (a < 0 || a >= w->pairs.nadj) return -1;
    const pair_adj *adj = &w->pairs.adj[a];
    int at = adj_place(adj, b);
    return at < adj->n && adj->l[at].other == b ? adj->l[at].slot : -1;
}

/* ---- slots ---- */

/* True when the schedule is built for the pairs of the moment, and is to be kept
 * in step with them (otherwise it is built again before it is used). */
static bool scheduled(const world *w)
{
    return w->sched.heap != NULL && !w->sched_dirty && w->sched.nobj == w->n;
}

/* A pair of a and b with no memory, in slot k of pl. */
static pair fresh_pair(pair_list *pl, long k, int a, int b, bool near)
{
    return (pair){.a = a, .b = b, .near = near, .toi_fa = -1, .toi_fb = -1, .toi = HUGE_VAL,
                  .pieces = &pl->pieces[k]};
}

/* Slot k's piece pairs: every pair of its objects' pieces (none when neither
 * has several).  Returns 0 or -1. */
static int list_all(world *w, long k)
{
    const pair *p = &w->pairs.p[k];
    piece_pairs *pp = &w->pairs.pieces[k];
    const body *a = w->bodies[p->a], *b = w->bodies[p->b];
    pp->n = 0;
    if (!body_compound(a) && !body_compound(b)) return 0;
    return pieces_list(pp, a, b, NULL, 0);
}

/* A new pair of a < b in a free slot, in the lists of both: its slot, or -1 when
 * out of memory. */
static long pair_new(world *w, int a, int b, bool near)
{
    pair_list *pl = &w->pairs;
    long k;
    if (pl->nfree > 0) {
        k = pl->free_slots[--pl->nfree];
    } else {
        if (pl->n == pl->cap) {
            long cap = pl->cap ? 2 * pl->cap : 64;
            pair *np = realloc(pl->p, (size_t)cap * sizeof *np);
            if (np) pl->p = np;
            pair_hit *nh = realloc(pl->hits, (size_t)cap * sizeof *nh);
            if (nh) pl->hits = nh;
            long *nf = realloc(pl->free_slots, (size_t)cap * sizeof *nf);
            if (nf) pl->free_slots = nf;
            piece_pairs *npp = realloc(pl->pieces, (size_t)cap * sizeof *npp);
            if (npp) {
                memset(npp + pl->cap, 0, (size_t)(cap - pl->cap) * sizeof *npp);
                pl->pieces = npp;
                for (long j = 0; j < pl->n; j++) pl->p[j].pieces = &npp[j]; /* (moved) */
            }
            if (!np || !nh || !nf || !npp) return -1;
            pl->cap = cap;
        }
        k = pl->n++;
    }
    pl->p[k] = fresh_pair(pl, k, a, b, near);
    if (list_all(w, k) != 0 || adj_insert(&pl->adj[a], b, k) != 0) {
        pl->p[k].a = -1;
        pl->free_slots[pl->nfree++] = k;
        return -1;
    }
    if (adj_insert(&pl->adj[b], a, k) != 0) {
        adj_erase(&pl->adj[a], b);
        pl->p[k].a = -1;
        pl->free_slots[pl->nfree++] = k;
        return -1;
    }
    pl->live++;
    /* due at once until the caller, taking it from the fresh list, bounds it */
    if (scheduled(w) && sched_add(w, k, -HUGE_VAL) != 0) {
        pair_far(w, k);
        return -1;
    }
    return k;
}

/* Notes slot k as made (or made near) since the caller last looked. */
static int note_fresh(pair_list *pl, long k)
{
    if (pl->nfresh == pl->capfresh) {
        long cap = pl->capfresh ? 2 * pl->capfresh : 64;
        long *f = realloc(pl->fresh, (size_t)cap * sizeof *f);
        if (!f) return -1;
        pl->fresh = f;
        pl->capfresh = cap;
    }
    pl->fresh[pl->nfresh++] = k;
    return 0;
}

int pair_near(world *w, int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    pair_list *pl = &w->pairs;
    long k = pair_index(w, a, b);
    if (k >= 0) {
        if (pl->p[k].near) return 0;
        /* (heap off) near again: afresh, as the pair the heap would make now */
        pl->p[k] = fresh_pair(pl, k, a, b, true);
        if (list_all(w, k) != 0) return -1;
        if (scheduled(w)) sched_set(w, sched_pair_id(&w->sched, k), -HUGE_VAL);
    } else if ((k = pair_new(w, a, b, true)) < 0) {
        return -1;
    }
    return note_fresh(pl, k);
}

void pair_far(world *w, long k)
{
    pair_list *pl = &w->pairs;
    pair *p = &pl->p[k];
    if (p->touching) return;
    pl->pieces[k].n = 0; /* (every pair of pieces while it is far: heap off) */
    if (pl->every) {
        p->near = false;
        return;
    }
    adj_erase(&pl->adj[p->a], p->b);
    adj_erase(&pl->adj[p->b], p->a);
    if (scheduled(w)) sched_remove(w, k);
    p->a = p->b = -1;
    p->near = false;
    pl->free_slots[pl->nfree++] = k;
    pl->live--;
}

const long *pairs_take_fresh(world *w, long *n)
{
    *n = w->pairs.nfresh;
    w->pairs.nfresh = 0;
    return w->pairs.fresh;
}

/* ---- making them again ---- */

/* The pairs in lasting contact, by their objects (stable across a rebuild). */
typedef struct {
    const body *a, *b;
} kept;

/* An object's address and index, sorted by address: the objects found again. */
typedef struct {
    uintptr_t at;
    int i;
} by_address;

static int cmp_address(const void *x, const void *y)
{
    uintptr_t a = ((const by_address *)x)->at, b = ((const by_address *)y)->at;
    return (a > b) - (a < b);
}

static int find_address(const by_address *s, int n, const body *b)
{
    uintptr_t at = (uintptr_t)b;
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (s[mid].at < at) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && s[lo].at == at ? s[lo].i : -1;
}

/* Empties the slots and gives every object an empty list.  Returns 0 or -1. */
static int clear(world *w)
{
    pair_list *pl = &w->pairs;
    if (w->n > pl->nadj) {
        pair_adj *adj = realloc(pl->adj, (size_t)w->n * sizeof *adj);
        if (!adj) return -1;
        memset(adj + pl->nadj, 0, (size_t)(w->n - pl->nadj) * sizeof *adj);
        pl->adj = adj;
        pl->nadj = w->n;
    }
    for (int i = 0; i < pl->nadj; i++) pl->adj[i].n = 0;
    pl->n = pl->live = pl->nfree = pl->nfresh = 0;
    return 0;
}

/* Heap off: every pair, in the order of a then b, far until the broad phase says
 * otherwise.  Returns 0 or -1. */
static int make_every(world *w)
{
    for (int i = 0; i < w->n; i++)
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            if (pair_index(w, i, j) < 0 && pair_new(w, i, j, false) < 0) return -1;
        }
    return 0;
}

/* The collision heap turned on or off since the pairs were made: the far pairs
 * are ended, or every missing one is made, far. */
static int switch_mode(world *w, bool every)
{
    pair_list *pl = &w->pairs;
    pl->every = every;
    w->sched_dirty = true;
    if (every) return make_every(w);
    for (long k = 0; k < pl->n; k++)
        if (pl->p[k].a >= 0 && !pl->p[k].near) pair_far(w, k);
    return 0;
}

int pairs_update(world *w)
{
    pair_list *pl = &w->pairs;
    bool every = !w->set.collision_heap;
    if (!pl->dirty) return every == pl->every ? 0 : switch_mode(w, every);
    long nkeep = 0;
    for (long i = 0; i < pl->n; i++) nkeep += pl->p[i].a >= 0 && pl->p[i].touching;
    kept *keep = malloc((size_t)(nkeep ? nkeep : 1) * sizeof *keep);
    by_address *addr = malloc((size_t)(w->n ? w->n : 1) * sizeof *addr);
    if (!keep || !addr) {
        free(keep);
        free(addr);
        return -1;
    }
    nkeep = 0;
    for (long i = 0; i < pl->n; i++) {
        const pair *p = &pl->p[i];
        /* (a deleted object's pairs are gone: world_delete ended them) */
        if (p->a >= 0 && p->touching && p->a < w->n && p->b < w->n)
            keep[nkeep++] = (kept){w->bodies[p->a], w->bodies[p->b]};
    }
    for (int i = 0; i < w->n; i++) addr[i] = (by_address){(uintptr_t)w->bodies[i], i};
    qsort(addr, (size_t)w->n, sizeof *addr, cmp_address);
    w->sched_dirty = true; /* the heap holds the old pairs */
    int rc = clear(w);
    pl->every = every;
    if (rc == 0 && every) rc = make_every(w);
    if (rc == 0) rc = broad_rebuild(w);
    /* the lasting contacts, found again (and kept, near or not) */
    for (long i = 0; i < nkeep && rc == 0; i++) {
        int a = find_address(addr, w->n, keep[i].a), b = find_address(addr, w->n, keep[i].b);
        if (a < 0 || b < 0) continue;
        rc = pair_near(w, a, b);
        long at = pair_index(w, a, b);
        if (at >= 0) pl->p[at].touching = true;
    }
    free(keep);
    free(addr);
    pl->nfresh = 0; /* (the schedule is made anew) */
    if (rc == 0) pl->dirty = false;
    return rc;
}

closest_result pair_query(world *w, pair *p, const body *a, const body *b)
{
    piece_pairs *pp = pair_pieces(w, p);
    closest_result r = pp->n > 0 ? pieces_distance(a, b, pp, PIECES_QUERY, true)
                                 : body_distance(a, b, &p->cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

closest_result pair_query_apart(world *w, pair *p, const body *a, const body *b)
{
    piece_pairs *pp = pair_pieces(w, p);
    closest_result r = pp->n > 0 ? pieces_distance(a, b, pp, PIECES_QUERY, false)
                                 : body_distance_apart(a, b, &p->cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

closest_result pair_query_peek(world *w, pair *p, const body *a, const body *b, bool depth)
{
    piece_pairs *pp = pair_pieces(w, p);
    closest_cache cache = p->cache;
    closest_result r = pp->n > 0 ? pieces_distance(a, b, pp, PIECES_PEEK, depth)
                       : depth   ? body_distance(a, b, &cache)
                                 : body_distance_apart(a, b, &cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

piece_pairs *pair_pieces(world *w, const pair *p)
{
    (void)w;
    return p->pieces;
}

int pair_near_pieces(world *w, int i, int j, const int *jk, int n)
{
    pair_list *pl = &w->pairs;
    long k = pair_index(w, i, j);
    if ((k < 0 || !pl->p[k].near) && pair_near(w, i, j) != 0) return -1;
    k = pair_index(w, i, j);
    const pair *p = &pl->p[k];
    const body *a = w->bodies[p->a], *b = w->bodies[p->b];
    piece_pairs *now = &pl->pieces[k];
    if (pieces_listed(now, a, b, j == p->b, jk, n)) return 0;
    /* the new list, with no memory: the pair is searched anew */
    int rc = j == p->b ? pieces_list(now, a, b, jk, n) : pieces_list_first(now, a, b, jk, n);
    if (rc != 0) return -1;
    pl->p[k].toi_fa = pl->p[k].toi_fb = -1;
    if (scheduled(w)) sched_set(w, sched_pair_id(&w->sched, k), -HUGE_VAL);
    return note_fresh(pl, k);
}

void pair_hit_from_query(world *w, pair *p)
{
    p->hit = p->cache;
    pieces_hit_from_query(pair_pieces(w, p));
}

void pair_forget(world *w, pair *p)
{
    p->cache.valid = p->hit.valid = false;
    pieces_forget(pair_pieces(w, p));
}
