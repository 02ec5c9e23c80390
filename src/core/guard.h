/* guard.h: steps whose events run away (issue 35: a ball pinched in a crowd,
 * a pile that chatters), and the last resort that keeps every contact answered.
 *
 * sim.c counts each event of an internal step against the objects it touches
 * (a pair's two, an object's own event its one).
 *  - An object that has taken part in SIM_CROWD_EVENTS events in one step is
 *    crowded for the rest of it: every contact it is in is answered with no
 *    restitution (instant.c), together with every other contact that begins with
 *    it, as an instant always is.  A contact that no longer bounces stays closed,
 *    so the crowd presses together and moves as a cluster (cluster.h) instead of
 *    colliding for ever.  Counted in sim_stats.crowds.
 *  - Where a step still reaches SIM_MAX_EVENTS_PER_STEP events, the last resort:
 *    every crowded object, and the objects of the event at hand, stop where they
 *    are (no velocity: nothing they touch approaches, so every contact of theirs
 *    is answered and nothing passes through anything), and the step goes on.
 *    Counted in sim_stats.guards, the first described in sim_stats.first_guard
 *    (the shell warns once, naming the objects).
 *  - A step that reaches twice that many events is cut short (sim_stats.overflows;
 *    never expected).
 * The limits are in the world (guard_limits), from those constants, so that a test
 * can make a runaway cheap.
 */
#ifndef VROC_GUARD_H
#define VROC_GUARD_H

#include <stdbool.h>

typedef struct world world;

/* Events of one object in one internal step after which its contacts are answered
 * with no restitution for the rest of the step. */
#define SIM_CROWD_EVENTS 1000

/* What the guard keeps: the limits, and per object the events of the step under
 * way (those counted listed, so that the step's end clears only them). */
typedef struct {
    long crowd_events;    /* SIM_CROWD_EVENTS */
    long max_events;      /* SIM_MAX_EVENTS_PER_STEP */
    int *events;          /* per object: its events this step */
    bool *crowded;        /* per object: crowded this step */
    int *counted, ncounted; /* the objects counted this step */
    int cap;
} guard_work;

void guard_init(guard_work *g);
void guard_free(guard_work *g);

/* Makes room for the world's objects: 0, or -1 when out of memory. */
int guard_prepare(world *w);

/* Counts the event of objects a and b (b -1: an object's own) that is the n-th
 * of the step, at time t, and acts as above.  False when the step is to be cut
 * short. */
bool guard_event(world *w, int a, int b, long n, double t);

/* True when object i is crowded (its contacts have no restitution). */
static inline bool guard_crowded(const guard_work *g, int i) { return g->ncounted > 0 && g->crowded[i]; }

/* The step is over: every count starts again from nothing. */
void guard_step_end(world *w);

#endif
