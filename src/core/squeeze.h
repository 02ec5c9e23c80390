/* squeeze.h: what a held object pushes, and where it must stop (hold.h; the
 * issue of objects squeezed through walls).
 *
 * A held object has infinite mass: what it strikes gives way, or it stops.  An
 * object it pushes against anything that cannot give way (a static object, or the
 * held object itself) cannot give way either, and neither can a chain of them.
 * So a collision with a held object is answered with every object within the
 * squeeze gap (squeeze_gap) of what it strikes, and of those in turn: their gaps
 * become rows that only push, with no rebound, as lasting contacts' are.  Where
 * those rows have no solution the chain is jammed: the held object stops where it
 * touches (its hand catches up later, hold.h), and what it pressed is answered
 * again against a still hand, with no rebound anywhere (squeeze_settle), so that
 * the squeezed objects stop too, and nothing passes through anything.
 *
 * The gap is small (a contact's thickness): a ball a finger's breadth from a wall
 * is thrown at it and bounces back as ever, and each time it comes back the paddle
 * has gained on the wall, until the gap is smaller than this.  With e < 1, or at
 * the speed limits, the gap closes geometrically: some tens of collisions.
 */
#ifndef VROC_SQUEEZE_H
#define VROC_SQUEEZE_H

#include <stdbool.h>

#include "body.h"
#include "impulse.h"
#include "tolerance.h"

typedef struct world world;

/* The squeeze gap of a and b: objects this close to each other are answered
 * together when a held object strikes one of them. */
static inline double squeeze_gap(const body *a, const body *b) { return tol_contact(a, b); }

/* Adds to list (n objects, synced to time t, marked nowhere) every dynamic
 * object that is not held and lies within the squeeze gap of one of them, and of
 * those in turn; each added is brought to time t (step_sync).  Returns the new
 * count. */
int squeeze_reach(world *w, int *list, int n, double t);

/* Held body i stops where it is at time t, until the hand sets its motion again
 * (hold.h): it met what cannot give way. */
void squeeze_hold_stop(world *w, int i, double t);

/* After the held object stopped: the nr rows (their objects synced to the same
 * instant; mobile marks the objects of list) are answered again with no rebound
 * at all, so that nothing approaches anything.  Where even that has no solution
 * (rounding), the n objects of list stop.  Returns true when it solved. */
bool squeeze_settle(world *w, impulse_row *rows, int nr, const int *list, int n, const bool *mobile);

#endif
