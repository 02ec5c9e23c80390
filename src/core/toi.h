/* toi.h: the first contact of a pair within an internal step, by conservative
 * advancement (thesis 3.4.2, step 4; design.md, "Dynamics").
 *
 * From the later of the two flights' starts (or the step's start), the pair is
 * queried, advanced by the schedule's bound to the earliest time its gap could
 * close to half the contact distance (schedule.h, sched_ca_time), and queried
 * again, until it is within the contact distance and its objects approach or
 * press together there (a contact), or the step ends.  The bound is never late,
 * so no contact is passed, whatever the objects' spin, speed or thinness, and the
 * first is found to within the contact distance.  The search depends on the two
 * flights and the features it starts from alone, so whoever asks (the heap, or a
 * check of every pair) gets the same answer.  Input and output are structs, as
 * Box2D's b2TOIInput and b2TOIOutput.
 */
#ifndef VROC_TOI_H
#define VROC_TOI_H

#include "body.h"
#include "closest.h"
#include "pieces.h"

typedef struct world world;

typedef struct {
    int a, b;             /* the two objects (body indices, a < b) */
    closest_cache cache;  /* the features to start from */
    double lo, hi;        /* search [lo, hi]: absolute times */
    piece_pairs *pieces;  /* the pair's piece pairs (pieces.h), whose hit features
                           * it starts from, and whose found ones it ends on, when
                           * it has any; else cache alone */
} toi_input;

typedef enum {
    TOI_NONE, /* apart through hi; t is when it must be searched again (> hi) */
    TOI_HIT   /* in contact at t: they approach or press together there */
} toi_state;

typedef struct {
    toi_state state;
    double t;
    closest_result r;     /* TOI_HIT: the pair there (with its depth when touching) */
    closest_cache cache;  /*   and the features the search ended on */
    long queries;         /* closest-feature queries made */
} toi_output;

toi_output toi_find(world *w, const toi_input *in);

#endif
