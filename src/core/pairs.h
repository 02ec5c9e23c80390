/* pairs.h: the pairs of objects that may collide, and the queries made of them.
 *
 * A pair is dynamic-dynamic or dynamic-static (resting objects count as
 * dynamic), never static-static (thesis 3.3.2).  Each keeps the closest features
 * of its last query, those its collision searches start from, whether its objects
 * are in lasting contact (pressed together: rest.h), and the schedule's lower
 * bound on when it could next touch.
 *
 * Which pairs exist (broad.h): with the collision heap on, only the near ones,
 * those whose objects' boxes meet, made and ended as the objects come near and
 * move apart, so that their number and memory grow with what is near, not with
 * n^2.  With it off, every pair exists (the thesis's comparison), and the near
 * ones are marked so.  A pair that becomes near starts afresh, with no memory of
 * its objects' earlier meetings, in both modes, so that the two give the same
 * answers to the bit.  A pair in lasting contact is never ended.
 *
 * The pairs live in slots (an index that stays while the pair lives; a slot freed
 * is used again), and each object lists its pairs by the other object's index
 * (pair_adj): every walk over an object's pairs meets them in that order, which
 * is what makes the answers independent of the order the pairs were made in.  The
 * pairs are made again, near ones only, whenever objects come, go or change mass
 * (pairs_update); lasting contacts are kept across that.  Every query of a pair
 * goes through pair_query and its kin, which count it in the world's pair_checks.
 */
#ifndef VROC_PAIRS_H
#define VROC_PAIRS_H

#include <stdbool.h>

#include "body.h"
#include "closest.h"
#include "pieces.h"

typedef struct world world;

typedef struct pair {
    int a, b;             /* body indices, a < b; a = -1: a free slot */
    bool touching;        /* in lasting contact: the contact forces keep them
                           * together (rest.h, cluster.h); not searched for
                           * collisions */
    bool near;            /* the broad phase holds it (always, with the heap on) */
    closest_cache cache;  /* closest features of the last query */
    closest_cache hit;    /* those of its last contact: where a search for the next
                           * starts, so that what it finds does not depend on which
                           * checks the schedule made (toi.h) */
    double next;          /* the schedule's: it cannot touch before this time */
    long toi_fa, toi_fb;  /* the flights of a and b its last search was made for
                           * (a search's answer holds while they fly them), */
    double toi;           /*   when it found them touching (+inf: apart through the
                           *   step's end, until next) */
    piece_pairs *pieces;  /* its piece pairs (pair_list's pieces[slot]) */
} pair;

/* A pair's last search's contact (toi.h): the pair there and the features the
 * search ended on. */
typedef struct {
    closest_result r;
    closest_cache cache;
} pair_hit;

/* One of an object's pairs: the other object, and the pair's slot. */
typedef struct {
    int other;
    long slot;
} pair_link;

/* An object's pairs, by the other object's index. */
typedef struct {
    pair_link *l;
    int n, cap;
} pair_adj;

typedef struct {
    pair *p;              /* slots 0 .. n - 1 (free ones have a = -1) */
    pair_hit *hits;       /* each slot's pair's last contact found */
    piece_pairs *pieces;  /* each slot's pair's piece pairs, for bodies of several
                           * pieces (pieces.h; empty otherwise): kept with the slot
                           * when it is freed, to be used again */
    long n, cap;          /* slots used and allocated */
    long live;            /* pairs that exist */
    long *free_slots;     /* freed slots, to use again (the last first) */
    long nfree;
    pair_adj *adj;        /* per object: its pairs */
    int nadj;             /* objects adj has lists for */
    long *fresh;          /* the slots made since pairs_take_fresh last emptied it */
    long nfresh, capfresh;
    bool dirty;           /* objects were added, deleted or changed mass */
    bool every;           /* every pair exists (the heap off) */
} pair_list;

void pairs_init(pair_list *pl);
void pairs_free(pair_list *pl);

/* Makes the pairs again when they are dirty (with the broad phase, broad.h) or
 * when the collision heap was turned on or off since, and the schedule with them
 * (world.sched_dirty); the pairs in lasting contact stay so.  Returns 0, or -1
 * when out of memory. */
int pairs_update(world *w);

/* The slot of the pair of objects a and b (either order), or -1 when they have
 * none. */
long pair_index(const world *w, int a, int b);

/* The broad phase's word that objects a and b are near (pair_near) or no more
 * (pair_far).  pair_near makes their pair (heap on) or marks it near (heap off),
 * in either case with no memory, and notes its slot in the fresh list; it does
 * nothing to a pair already near.  pair_far ends it (heap on) or marks it far,
 * unless it is in lasting contact.  The schedule is kept in step (schedule.h).
 * pair_near returns 0, or -1 when out of memory. */
int pair_near(world *w, int a, int b);
void pair_far(world *w, long slot);

/* The slots made since the last call (n of them), for the caller to schedule;
 * the list is emptied. */
const long *pairs_take_fresh(world *w, long *n);

/* The query of pair p with its objects in the states a and b (body_distance),
 * from and into the pair's cache (its piece pairs' for bodies of several
 * pieces); counted in the world's pair_checks. */
closest_result pair_query(world *w, pair *p, const body *a, const body *b);

/* The same for a check that needs only whether the pair is apart, and how far
 * (body_distance_apart). */
closest_result pair_query_apart(world *w, pair *p, const body *a, const body *b);

/* The same from the pair's cache, which it leaves as it was: pair_query's answer
 * when depth, else pair_query_apart's. */
closest_result pair_query_peek(world *w, pair *p, const body *a, const body *b, bool depth);

/* Pair p's piece pairs (empty unless one of its objects has several pieces). */
piece_pairs *pair_pieces(world *w, const pair *p);

/* The broad phase's word that the pair of moving object i and static object j
 * of several pieces meets those pieces listed in jk (n of them, in order, n >= 1):
 * the pair is made near as by pair_near when it is not, and lists those pieces
 * (with no memory of them: the pair is searched anew, as a fresh one, when the
 * list changed).  Returns 0, or -1 when out of memory. */
int pair_near_pieces(world *w, int i, int j, const int *jk, int n);

/* What a query that found p touching leaves as its hit (p->hit = p->cache, its
 * piece pairs' too); and forgets every feature (a frame's start). */
void pair_hit_from_query(world *w, pair *p);
void pair_forget(world *w, pair *p);

/* Walks object i's pairs, in the order of the other object: link the pair_link,
 * pr its pair.  (An object with no pairs may have no list at all, NULL, to which
 * not even 0 may be added: its end is then its start.) */
#define FOR_PAIRS_OF(w, i, link, pr)                                                        \
    for (const pair_link *link = (w)->pairs.adj[i].l,                                      \
                         *link##_end_ = link ? link + (w)->pairs.adj[i].n : link;           \
         link != link##_end_; link++)                                                       \
        for (pair *pr = &(w)->pairs.p[link->slot]; pr; pr = NULL)

#endif
