/* apart.h: no overlap left at a frame's end (the issue of piles that rest inside
 * each other), and, in the validation build, the watch that no pair overlaps
 * after any event.
 *
 * Searches stop short of contact and collisions part what meets, so overlap
 * should not arise; where rounding, a cluster's step or a contact problem that
 * could not be solved leaves some, it would stay, since objects at rest are not
 * searched.  So at the end of every frame each pair that overlaps by more than
 * APART_SLOP is moved apart, along its contact normal, until it touches: the
 * objects' positions are moved in inverse proportion to their masses (a static or
 * held object does not move), and no velocity changes, so no kinetic energy is
 * made.  (Raising an object against gravity raises its potential energy by m g
 * times the depth, at most a micrometre's worth for what the searches leave.)
 */
#ifndef VROC_APART_H
#define VROC_APART_H

#include <stdbool.h>

typedef struct world world;

/* Overlap (m) a frame's end leaves as it is: a contact's rounding, far inside the
 * micrometre the issue allows. */
#define APART_SLOP 1e-7

/* Passes over the overlapping pairs at a frame's end: each moves objects, which
 * may press others (an object pressed between two others halves its overlap
 * each pass: a centimetre comes to APART_SLOP in 17); what is left after these
 * stays. */
#define APART_PASSES 64

/* Moves apart the pairs that overlap by more than APART_SLOP at w->time (every
 * object there: the frame's end), and starts the flights of the moved afresh.
 * Returns how many times pairs were moved apart (st.separations counts them). */
int apart_frame_end(world *w);

/* (Validation build) The deepest overlap (m, > 0) of any pair with every object
 * flown to time t, recorded in st.deepest when deeper than what it holds. */
void apart_watch(world *w, double t);

#endif
