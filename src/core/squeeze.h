/* squeeze.h: what a held object pushes, and where it must stop (hold.h; the
 * issue of objects squeezed through walls).
 *
 * A held object has infinite mass: what it strikes gives way, or it stops.  An
 * object it pushes against anything that cannot give way (a static object, or the
 * held object itself) cannot give way either, and neither can a chain of them.
 * So an instant with a held object (instant.h) takes in every pair within the
 * squeeze gap (squeeze_gap) of each object it sets moving, not only those within
 * the contact distance: their gaps become rows that only push, as the rest of
 * the instant's.  Where the rows have no solution the chain is jammed: the held
 * object stops where it touches (squeeze_hold_stop; its hand catches up later,
 * hold.h), and every contact is answered again against the still hand with no
 * rebound anywhere, so that the squeezed objects stop too, and nothing passes
 * through anything; where even that has no solution (rounding), they stop.
 *
 * The gap is small (a contact's thickness): a ball a finger's breadth from a wall
 * is thrown at it and bounces back as ever, and each time it comes back the paddle
 * has gained on the wall, until the gap is smaller than this.  With e < 1, or at
 * the speed limits, the gap closes geometrically: some tens of collisions.
 */
#ifndef VROC_SQUEEZE_H
#define VROC_SQUEEZE_H

#include "body.h"
#include "tolerance.h"

typedef struct world world;

/* The squeeze gap of a and b: objects this close to each other are answered
 * together when a held object strikes one of them. */
static inline double squeeze_gap(const body *a, const body *b) { return tol_contact(a, b); }

/* Held body i stops where it is at time t, until the hand sets its motion again
 * (hold.h): it met what cannot give way. */
void squeeze_hold_stop(world *w, int i, double t);

#endif
