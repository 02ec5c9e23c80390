/* pairs.h: the pairs of objects that may collide, and the queries made of them.
 *
 * A pair is dynamic-dynamic or dynamic-static (resting objects count as
 * dynamic), never static-static (thesis 3.3.2).  Each keeps the closest features
 * of its last query, those its collision searches start from, whether its objects
 * are in lasting contact (pressed together: rest.h), and the schedule's lower
 * bound on when it could next touch.  The pairs are made again, in the order of a,
 * then b, whenever objects come, go or change mass (pairs_update); lasting
 * contacts are kept across that.  Every query of a pair goes through pair_query
 * and its kin, which count it in the world's pair_checks.
 */
#ifndef VROC_PAIRS_H
#define VROC_PAIRS_H

#include <stdbool.h>

#include "body.h"
#include "closest.h"

typedef struct world world;

typedef struct pair {
    int a, b;             /* body indices, a < b */
    bool touching;        /* in lasting contact: the contact forces keep them
                           * together (rest.h, cluster.h); not searched for
                           * collisions */
    closest_cache cache;  /* closest features of the last query */
    closest_cache hit;    /* those of its last contact: where a search for the next
                           * starts, so that what it finds does not depend on which
                           * checks the schedule made (toi.h) */
    double next;          /* the schedule's: it cannot touch before this time */
    long toi_fa, toi_fb;  /* the flights of a and b its last search was made for
                           * (a search's answer holds while they fly them), */
    double toi;           /*   when it found them touching (+inf: apart through the
                           *   step's end, until next) */
} pair;

/* A pair's last search's contact (toi.h): the pair there and the features the
 * search ended on. */
typedef struct {
    closest_result r;
    closest_cache cache;
} pair_hit;

typedef struct {
    pair *p;              /* n pairs, in the order of a, then b */
    pair_hit *hits;       /* each pair's last contact found */
    long n, cap;
    bool dirty;           /* objects were added, deleted or changed mass */
} pair_list;

void pairs_init(pair_list *pl);
void pairs_free(pair_list *pl);

/* Makes the pairs again when they are dirty, and the schedule with them
 * (world.sched_dirty); the pairs in lasting contact stay so.  Returns 0, or -1
 * when out of memory. */
int pairs_update(world *w);

/* The index of the pair of objects a and b (either order), or -1 when they have
 * none. */
long pair_index(const world *w, int a, int b);

/* The query of pair p with its objects in the states a and b (body_distance),
 * from and into the pair's cache; counted in the world's pair_checks. */
closest_result pair_query(world *w, pair *p, const body *a, const body *b);

/* The same for a check that needs only whether the pair is apart, and how far
 * (body_distance_apart). */
closest_result pair_query_apart(world *w, pair *p, const body *a, const body *b);

#endif
