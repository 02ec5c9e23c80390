/* step.h: the internal step's state: where each object's flight starts, and the
 * copies and lists a step works on.
 *
 * Within an internal step each moving object flies from its own starting state:
 * snap[i] at time snap_t[i], the start of the step, or the instant of the last
 * collision that changed it.  An object's place at time t is always one flight
 * from there, so a collision that sends the world back to an earlier instant
 * leaves every other object's flight, and so its pairs' predictions, exactly as
 * they were.  Each start is numbered (snap_id, from flight_count), so that what
 * was found from a flight (a pair's first contact) is known to hold while it does.
 */
#ifndef VROC_STEP_H
#define VROC_STEP_H

#include <stdbool.h>

#include "body.h"
#include "pairs.h"

typedef struct world world;

/* Copies of each object a time of impact or a settling works on: body i's are
 * scratch[STEP_COPIES i] to scratch[STEP_COPIES i + STEP_COPIES - 1]. */
#define STEP_COPIES 4

typedef struct {
    body *snap;           /* each object's state where its flight starts, */
    double *snap_t;       /*   at that time, */
    long *snap_id;        /*   numbered from flight_count */
    long flight_count;
    body *pre;            /* the colliding pair's states before the answer */
    bool *touched;        /* the other objects a collision's answer changed */
    long *end_id;         /* the flight each moving object was last flown to the
                           * end of the internal step from */
    body *scratch;        /* STEP_COPIES copies of each object */
    int *movers, nmovers; /* the objects that are not static, in order */
    int cap;              /* objects the arrays above have room for */
    long *due;            /* the pairs checked in a step, and their new times */
    double *due_next;
    long capdue;
} step_state;

void step_init(step_state *s);
void step_free(step_state *s);

/* Makes the copies of the objects that may move, so that within a frame only their
 * states need copying (nothing else changes while time runs; static objects are
 * read where they are), and room for the due pairs.  The copies are made again
 * only when changed (a command changed something): between frames nothing else
 * changes a body but its state, which every step copies before it reads it.
 * Returns 0, or -1 when out of memory. */
int step_prepare(world *w, bool changed);

/* Every moving object's flight starts where it is, at time t (the step's start). */
void step_save(world *w, double t);

/* Flies out, a copy of moving body i where its flight starts, on to time t. */
void step_fly_on(const world *w, int i, double t, body *out);

/* Puts moving body i's state at time t in out, a copy of body i. */
void step_fly_into(const world *w, int i, double t, body *out);

/* Puts body i's state at time t in out, a copy of body i (what does not move is
 * there already). */
void step_fly_at(const world *w, int i, double t, body *out);

/* Body i at time t: itself when it does not move, else its scratch copy number
 * k, flown there. */
const body *step_flown(const world *w, int i, double t, int k);

/* The copies of body i a search works on, the first at time t: body i itself
 * when it does not move (nothing then changes them), else its scratch copies
 * (only the first flown: the others are written before they are read). */
void step_search_copies(world *w, int i, double t, body *out[STEP_COPIES]);

/* Body i where its flight starts (at snap_t[i]). */
const body *step_at_start(const world *w, int i);

/* The earlier start of the flights of pair p's moving objects. */
double step_flights_start(const world *w, const pair *p);

/* Every moving object to the end of the step, t_end: an object whose flight did
 * not change since it was last flown there is there already. */
void step_fly_to_end(world *w, double t_end);

/* Object i flies on from time t as it is now (a new flight number). */
void step_renew(world *w, int i, double t);

#endif
