/* toi.h: the first contact of a pair within an internal step (the time of impact).
 *
 * Given two objects that are apart at time lo and touch or penetrate at hi, each
 * flying from its flight's start in the step (step.h), the search finds the
 * latest time it can show them apart: less than SIM_SEPARATION / 2 apart, or
 * within SIM_TOI_TIME of a time they are not (toi.c says how).  Input and output
 * are structs, as Box2D's b2TOIInput and b2TOIOutput.
 */
#ifndef VROC_TOI_H
#define VROC_TOI_H

#include "closest.h"

typedef struct world world;

typedef struct {
    int a, b;             /* the two objects (body indices, a < b) */
    closest_cache cache;  /* the features to start from */
    double lo, hi;        /* the bracket: absolute times, touching at hi */
} toi_input;

typedef enum {
    TOI_OVERLAPPED, /* touching or penetrating already at lo: t = lo */
    TOI_HIT         /* apart at t, at their first contact */
} toi_state;

typedef struct {
    toi_state state;
    double t;             /* the time found */
    closest_result r;     /* TOI_HIT: the pair there (the answer starts from it) */
    closest_cache cache;  /*   and the features the search ended on */
    long queries;         /* closest-feature queries made */
} toi_output;

toi_output toi_find(world *w, const toi_input *in);

#endif
