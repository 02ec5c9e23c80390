/* sim.h: advancing simulated time with collisions (thesis 3.2.3, 3.3.3, 3.4.2).
 *
 * A frame of time_step is cut into world_subframes() equal internal steps.  Within
 * an internal step every dynamic body flies freely under the global acceleration:
 * linear motion exactly (x += v h + a h^2/2, v += a h), rotation by a symmetric
 * splitting about the principal axes that keeps the angular momentum L exactly and
 * the energy to O(h^2) (Dullweber, Leimkuhler and McLachlan 1997), then the speed
 * limits max_linear and max_angular.  At the end of the step the pairs are checked;
 * a pair found touching or penetrating is traced back in time to its first contact
 * (Newton steps on its closing speed and acceleration, bisection after an
 * overshoot), the earliest such collision is answered (contact.h) with the objects
 * it concerns at that instant (the others fly on unchanged), and the
 * rest of the step goes on from there.  Objects whose motion dies down on a support
 * come to rest or settle (thesis 3.3.3).
 */
#ifndef VROC_SIM_H
#define VROC_SIM_H

#include <stddef.h>

#include "world.h"

/* Most internal steps one frame may take; more is an error asking for fewer. */
#define SIM_MAX_SUBFRAMES 1000000L

/* Time of impact: the search stops when its bracket is this short (s). */
#define SIM_TOI_TIME 1e-10
/* After a collision the pair is set apart to at least this distance (m). */
#define SIM_SEPARATION 1e-7
/* A pair that collides slowly while a force presses them together (gravity, for
 * an object on a support) leaves at least as fast as it must to rise this far (m)
 * against that force: the collision envelope, which keeps an object that pivots or
 * rocks on a support from colliding every few microseconds. */
#define SIM_HOP 1e-4
/* Below this speed (m/s: |v| + |w| times the outer radius) an object on a support
 * underneath, against the global force, comes to rest (the thesis's contact state):
 * at once when it collides with the support, or at the end of a frame when it
 * slides on it.  Above it, an object that no longer bounces off such a support
 * slides on it: the part of the force that presses it onto the support is taken
 * away while it stays there. */
#define SIM_REST_SPEED 0.05
/* Settling (the limit of rocking, sim.c settle): an object with restitution below 1
 * barely bouncing on a support under it, whose rocking could not tip it more than
 * SIM_SETTLE_ANGLE (radians), is laid on the face it can stand on nearest to the
 * support, if that face is within the angle and nothing is in the way. */
#define SIM_SETTLE_ANGLE 0.35
/* A sandwich: an object that struck a still object less than SIM_PINNED_TIME (s)
 * ago, one of the last two it struck, and is still within SIM_PINNED_GAP (m) of
 * it, passes the part of a blow within 45 degrees of pressing it back against it
 * on to it, as a stack passes blows to its support. */
#define SIM_PINNED_TIME 0.01
#define SIM_PINNED_GAP 1e-5
/* Collisions one internal step may answer before the step gives up and lets the
 * objects through (a guard against endless micro-collisions; counted in stats). */
#define SIM_MAX_COLLISIONS_PER_STEP 1000

/* Advances the world by one frame.  Returns 0, or -1 with a message in err when the
 * settings ask for more than SIM_MAX_SUBFRAMES internal steps (nothing moves then).
 * With time_step 0 nothing moves and the frame still counts. */
int sim_frame(world *w, char *err, size_t errlen);

/* Makes ready what the frames need: the pairs, the schedule, the copies of the
 * objects that may move and the scratch of the internal steps, each allocated
 * and written once, so that frames allocate nothing and touch no fresh memory
 * (the shell calls it when time is about to run; sim_frame calls it too, for
 * what a command changed since).  Returns 0, or -1 when out of memory. */
int sim_prepare(world *w);

/* Free flight of one dynamic body over h seconds under acceleration a, then the
 * speed limits. */
void sim_flight(body *b, double h, vec3 a, double max_linear, double max_angular);

/* Rebuilds the pair list when objects were added, deleted or changed mass. */
int sim_update_pairs(world *w);

/* Calls report for every pair that interpenetrates now (deeper than the contact
 * tolerance), with the depth estimate; returns how many.  -1 when out of memory. */
typedef void (*sim_report)(void *ctx, const body *a, const body *b, double depth);
long sim_penetrations(world *w, sim_report report, void *ctx);

/* Wakes every resting object (after a change of the global force), and those
 * resting on object i (after a command moved it; i = -1 for none). */
void sim_wake_all(world *w);
void sim_wake_on(world *w, int i);

#endif
