/* sim.h: advancing simulated time with collisions (thesis 3.2.3, 3.3.3, 3.4.2).
 *
 * A frame of time_step is cut into world_subframes() equal internal steps, the
 * thesis's subframes.  Within a step the objects fly exactly (flight.h), and its
 * events are answered in the order they happen, each at its own instant: a pair's
 * first contact, found by conservative advancement (toi.h) for the pairs the
 * schedule says could touch (schedule.h); a slide leaving its face; the end of a
 * cluster's step (rest.h, cluster.h).  Collisions are answered together with
 * every lasting contact of the objects they touch (impulse.h).  At the end of a
 * frame, objects held still by their supports rest.  The collisions of a frame
 * are left in world.events.
 */
#ifndef VROC_SIM_H
#define VROC_SIM_H

#include <stddef.h>

#include "tolerance.h"
#include "world.h"

/* How far below the lowest static object an object has left the room (m). */
#define SIM_FALL_DEPTH 100

/* Advances the world by one frame.  Returns 0, or -1 with a message in err when the
 * settings ask for more than SIM_MAX_SUBFRAMES internal steps (nothing moves then).
 * With time_step 0 nothing moves and the frame still counts.  A collision whose
 * result max_linear or max_angular cut is counted in st.speed_cuts, the world's
 * first described in st.first_cut (its object's index valid until the objects
 * change): the caller may say so, since each loses energy.  So may it where a
 * contact with friction had no consistent answer (st.painleve, st.first_painleve),
 * and where an object has left the room: one that falls more than SIM_FALL_DEPTH
 * below the lowest point of every static object has its fell set to 1, once, and
 * is counted in st.fallen; it falls on. */
int sim_frame(world *w, char *err, size_t errlen);

/* A caller's say within a frame: the hand, whose trigger and tracker rows act at
 * their exact times (hold.h).  next gives the earliest instant (simulated time)
 * at which it wants to act, or HUGE_VAL; it is asked when the frame starts and
 * after each at.  If that instant falls within the frame, the internal step under
 * way is cut there, every object is brought to that instant, and at is called
 * with world.time exactly it.  at may hold, release and place bodies (hold.h);
 * it must not add or delete objects or change settings.  What it changed starts
 * over from there as after a statement (every flight, every pair's bound, the
 * contacts and modes of the objects it woke), and the step goes on to its end.
 * After at, next must give a later instant.  An instant at the frame's very end
 * is not the frame's: the caller acts there after it. */
typedef struct {
    double (*next)(void *ctx, const world *w);
    void (*at)(void *ctx, world *w);
    void *ctx;
} sim_hook;

/* The simulated time at which the next frame will end (world.time after it), to
 * the bit, as long as time_step does not change before it. */
double sim_frame_end(const world *w);

/* sim_frame with hook (NULL: none, which is sim_frame). */
int sim_frame_hooked(world *w, const sim_hook *hook, char *err, size_t errlen);

/* Makes ready what the frames need: the pairs, the schedule, the copies of the
 * objects that may move and the scratch of the internal steps, each allocated
 * and written once, so that frames allocate nothing and touch no fresh memory
 * (the shell calls it when time is about to run; sim_frame calls it too, for
 * what a command changed since).  Returns 0, or -1 when out of memory. */
int sim_prepare(world *w);

/* Calls report for every pair that a command placed (one of its objects was
 * placed, turned, reshaped or added since time last ran) and that interpenetrates
 * now, deeper than the contact tolerance, with the depth estimate; returns how
 * many.  States the simulation made itself are never reported: a run can be
 * split anywhere.  -1 when out of memory. */
typedef void (*sim_report)(void *ctx, const body *a, const body *b, double depth);
long sim_penetrations(world *w, sim_report report, void *ctx);

#endif
