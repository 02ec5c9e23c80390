/* step.h: the state of the simulation between its events: each object's flight,
 * the times of the objects' own events, and the copies the searches fly.
 *
 * Every moving object flies from its flight's start (flight.h): the start of the
 * internal step, or the last event that changed it.  Its state at any time of the
 * step is one evaluation of its flight from there, so a search for a pair's first
 * contact depends on the two flights alone.  Flights are numbered (flight.id), so
 * that what was found from a flight is known to hold while it does.  An object's
 * own event (a slide leaving its face, the end of a cluster's step) is kept in
 * `event`.
 */
#ifndef VROC_STEP_H
#define VROC_STEP_H

#include <stdbool.h>

#include "body.h"
#include "flight.h"
#include "schedule.h"

typedef struct world world;

/* step_flown's copies of each object (it remembers what it flew each to): body
 * i's are flown[STEP_FLOWN_COPIES i + k], k = 0, 1.  (The copies that answering
 * works on are its own: answer.h.) */
#define STEP_FLOWN_COPIES 2

typedef struct {
    flight *fl;           /* each object's flight (a static object's: still) */
    long flight_count;
    double *event;        /* each object's own next event, or +inf */
    body *flown;          /* step_flown's copies of each object, */
    long *flown_id;       /*   the flight each was flown on, */
    double *flown_t;      /*   and to when (-1: none) */
    int cap;              /* objects the arrays above have room for */
    double t_end;         /* the end of the internal step under way */
    long *due;            /* the entries checked in a step, and their new times */
    double *due_next;
    long capdue;
} step_state;

void step_init(step_state *s);
void step_free(step_state *s);

/* Makes room for the world's objects and pairs and, when changed (a command
 * changed something), copies the objects into the scratch, so that within a frame
 * only their states need copying.  Returns 0, or -1 when out of memory. */
int step_prepare(world *w, bool changed);

/* Makes room for due entries in the schedule's due list.  Returns 0 or -1. */
int step_reserve_due(world *w, long due);

/* Body i's state at time t (t at or after its flight's start) in out, a copy of
 * body i. */
void step_fly(const world *w, int i, double t, body *out);

/* Body i at time t: itself when it does not move, else its scratch copy number k
 * (0 or 1), flown there (unless it is there already). */
const body *step_flown(const world *w, int i, double t, int k);

/* Brings body i's state to time t (its flight's), in place. */
void step_sync(world *w, int i, double t);

/* True when body i moves: dynamic and not resting. */
bool step_moves(const world *w, int i);

/* Body i's motion at its state o (at some time of its flight), as the bounds see
 * it (schedule.h): still, flying about its centre of mass, or held (about the
 * hand's pivot). */
sched_move step_move(const world *w, int i, const body *o);

/* Starts body i's flight at time t from its state, as its mode says (the caller
 * has set mode and state). */
void step_start(world *w, int i, double t);

#endif
