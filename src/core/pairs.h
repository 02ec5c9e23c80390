/* pairs.h: the pairs of objects that may collide, and the queries made of them.
 *
 * A pair is dynamic-dynamic or dynamic-static (resting objects count as
 * dynamic), never static-static (thesis 3.3.2).  Each keeps the closest features
 * of its last check and of its last collision, and what the schedule found for it.
 * The pairs are made again, in the order of a, then b, whenever objects come, go
 * or change mass (pairs_update).  Every query of a pair goes through pair_query
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
    closest_cache cache;  /* closest features of the last check */
    closest_cache hit;    /* those of its last collision: where the time of impact
                           * and the answer start, so that they do not depend on
                           * which checks the schedule made (sim.c) */
    double next;          /* earliest time the pair could collide (the schedule) */
    double checked;       /* when next was found from its objects' speeds, or +inf
                           * when it holds only while their motions do (sim.c) */
    double toi;           /* its first contact found in this internal step, valid */
    long toi_a, toi_b;    /*   while its objects fly from flights numbered so (sim.c) */
    bool along;           /* next came from sched_predict_along: it holds only while
                           * both objects fly as they flew when it was found */
    bool far;             /* next came from sched_predict_far, when its objects had */
    double jumped_a, jumped_b; /* been moved at once so far (body.jumped), */
    bool far_slide_a, far_slide_b; /* counting that object's slide's lesser
                           * acceleration (only a steady slide's: body.slide_steady) */
    double speed_a, speed_b; /* the speeds next was found from (slack included) */
} pair;

/* A pair's first contact as its time of impact found it (toi.h): the pair at
 * time t, apart, and the features the search ended on; t is NAN when there is
 * none to reuse. */
typedef struct {
    closest_result r;
    closest_cache cache;
    double t;
} pair_hit;

typedef struct {
    pair *p;              /* n pairs, in the order of a, then b */
    pair_hit *hits;       /* each pair's last first contact found */
    long n, cap;
    bool dirty;           /* objects were added, deleted or changed mass */
} pair_list;

void pairs_init(pair_list *pl);
void pairs_free(pair_list *pl);

/* Makes the pairs again when they are dirty, and the schedule with them
 * (world.sched_dirty).  A slide on a still support keeps its pair (found again);
 * others end.  Returns 0, or -1 when out of memory. */
int pairs_update(world *w);

/* The index of the pair of objects a and b (either order), or -1 when they have
 * none. */
long pair_index(const world *w, int a, int b);

/* The query of pair p with its objects in the states a and b (body_distance),
 * from and into the pair's cache; counted in the world's pair_checks. */
closest_result pair_query(world *w, pair *p, const body *a, const body *b);

/* The same from and into the features of the pair's last collision (pair.hit),
 * for the answer to a collision. */
closest_result pair_query_hit(world *w, pair *p, const body *a, const body *b);

/* The same for a check that needs only whether the pair is apart, and how far
 * (body_distance_apart). */
closest_result pair_query_apart(world *w, pair *p, const body *a, const body *b);

#endif
