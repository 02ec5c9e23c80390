/* retime.h: what follows when an object's flight changes within an internal step
 * (sim.c, answer.c): everything timed from the old flight is timed again.
 *
 * An object's flight (step.h) changes where an event answers it, or where a step
 * starts it afresh.  Then its own next event (a slide leaving its face, or none)
 * is set anew; its box is checked to cover it until the step's end, or made again
 * (broad.h, broad_cover), which may make new pairs; and what was found of its
 * pairs no longer holds: each gets the schedule's cheap bound from that time
 * (schedule.h, sched_sphere_time), and is searched again when it falls due.
 */
#ifndef VROC_RETIME_H
#define VROC_RETIME_H

#include <stdbool.h>

#include "pairs.h"
#include "schedule.h"
#include "step.h"
#include "world.h"

/* True when pair p needs searching: one of its objects moves, and they are not
 * pressed together. */
static inline bool retime_searched(const world *w, const pair *p)
{
    /* (a pair of bodies of several pieces in lasting contact is searched for
     * its other pieces: toi.h) */
    return (!p->touching || p->pieces->n > 0) &&
           (step_moves(w, p->a) || step_moves(w, p->b));
}

/* Pair k's cheap bound from time t, as its objects fly now (t itself for a held
 * object's: no bound foresees the hand; +inf for a pair not searched). */
double retime_bound(world *w, long k, double t);

/* The pairs the broad phase made since the last call get their cheap bounds from
 * time t. */
void retime_fresh(world *w, double t);

/* Object i's own next event is at time t (+inf: none).  (Inline: every internal
 * step sets every moving object's.) */
static inline void retime_event(world *w, int i, double t)
{
    w->step.event[i] = t;
    sched_set(w, sched_obj_id(i), t);
}

/* Moving object i's box covers it, flying from time t, until the end of the step
 * (broad_cover); same: on the motion of its last flight.  Running out of memory
 * sets w->out_of_memory. */
void retime_box(world *w, int i, double t, bool same);

/* Object i flies on from time t as it is now: its flight starts afresh (a slide's
 * until it leaves its face, its own event), its box covers it, and each of its
 * pairs gets its cheap bound. */
void retime_object(world *w, int i, double t);

#endif
