/* edit.h: what a command changes in the world, and what each change does to rest,
 * slides and the schedule.
 *
 * The shell changes bodies only through these functions (and the world's add and
 * delete), so that a change always wakes what it disturbs and leaves the
 * simulation's own state consistent: a body given a velocity wakes and slides no
 * more, the objects resting on it wake, a new mass makes the pairs again.  A
 * property is named by its offset in body, as the command table gives it
 * (offsetof(body, v) for linear_vel, offsetof(body, sp.radius) for radius).
 */
#ifndef VROC_EDIT_H
#define VROC_EDIT_H

#include <stdbool.h>
#include <stddef.h>

#include "world.h"

/* The values must lie within core/limits.h's limits (the shell's command table
 * checks them); every computation that follows then stays finite.
 *
 * Sets the property of body i at offset off in body from num (one number, three
 * for a vector or a colour, four for an axis and an angle), as a command does:
 *   v (linear_vel), w (angular_vel, in world axes as typed; each limited to
 *   max_linear or max_angular, scaled down whatever its size), x (translate),
 *   rot_axis (rotate: num[3] the angle), mass (non-zero; negative: static),
 *   elasticity, volume, color, and the shape's parameters sp.radius, sp.size,
 *   sp.exp1, sp.exp2, sp.a1, sp.a2, sp.a3, sp.ures, sp.vres, sp.scale (the shape
 *   is built again).
 * Anything but the colour or the loudness wakes the body and everything pressed
 * together with it, whose modes are found anew when time runs; placing, turning,
 * reshaping or a new mass also end its lasting contacts, which are found anew
 * (objects placed within SIM_TOUCH of each other touch).  Returns 0, or -1 with a message in err when the
 * shape cannot be built (the body keeps its old shape) or off names no property. */
int edit_property(world *w, int i, size_t off, const double *num, char *err, size_t errlen);

/* Gives polyhedron i (SHAPE_POLYHEDRON) the geometry src, as `file` does, taking
 * ownership of src: the shape is built again, and what the property statements
 * above wake is woken.  Returns 0 (the old source is freed), or -1 with a message
 * in err when the shape cannot be built (src is freed; the body keeps its old
 * shape). */
int edit_source(world *w, int i, shape_source *src, char *err, size_t errlen);

/* Sets the global force (a direction and a magnitude) and wakes every resting
 * object: rest depends on the force. */
void edit_force(world *w, dir_amount force);

/* ---- exact state (language.md, "Exact state"), as save writes it ----
 * Each sets what it names exactly, with no limit applied.  A new orientation,
 * velocity or angular momentum wakes the object and what presses on it, as
 * edit_property does; a saved world's contact state, which follows its objects,
 * puts them back as they were.  The contact state (edit_exact_contact,
 * edit_exact_touching) takes object i's contacts and mode as given: they are not
 * found anew when time runs, and i is not checked for overlaps (the state is the
 * simulation's own). */

/* Orientation q (a unit quaternion, scalar first; used as given when its length
 * is within Q_UNIT_TOL of 1, else normalised: q_as_unit).  The angular velocity stays and
 * the angular momentum follows the new axes, as with rotate; the orientation the
 * object already has, to the bit, changes nothing. */
void edit_exact_orientation(world *w, int i, quat q);

/* Linear velocity v, not limited. */
void edit_exact_velocity(world *w, int i, vec3 v);

/* Angular momentum L (world axes), not limited; w is found from it, unless the
 * angular velocity the object has gives exactly L (one typed, saved and read
 * back keeps its last digit). */
void edit_exact_momentum(world *w, int i, vec3 L);

/* The static object (support, an index) and its face that a slide is on; the
 * mode statement that follows checks them. */
void edit_exact_support(world *w, int i, int support, int face);

/* The mode (for MODE_SLIDE, on the support and face given before), and resting or
 * not.  Returns 0, or -1 with a message in err (a static object; a slide whose
 * support is not static or has no such face). */
int edit_exact_contact(world *w, int i, body_mode mode, bool resting, char *err, size_t errlen);

/* Objects i and j are in lasting contact.  Returns 0, or -1 with a message in err
 * (the same object, two static objects, out of memory). */
int edit_exact_touching(world *w, int i, int j, char *err, size_t errlen);

/* The clock: time = base + frames * time_step, as frames add it up (exactly so). */
void edit_clock(world *w, double base, long frames);

/* Object i's lasting contacts end, and it and every dynamic object pressed
 * together with it move again, their modes found anew when the simulation starts
 * over (for a body the hand takes: hold.h). */
void edit_unpress(world *w, int i);

/* ---- the limits of a state (limits.h), which every state the simulation makes
 * keeps, so that what save writes reads back ---- */

/* True when dynamic object i's state is beyond what a statement may set: a
 * coordinate of its origin (translate) beyond LIM_POSITION_MAX, a component of
 * its velocity beyond LIM_SPEED_MAX or of its angular momentum beyond
 * LIM_MOMENTUM_MAX (a fall that went on for minutes, a force of a thousand g). */
bool edit_beyond_limits(const world *w, int i);

/* Puts object i (dynamic, not held), beyond the limits, to rest where it left
 * them: each coordinate of its origin brought back to LIM_POSITION_MAX, its
 * velocities 0, its lasting contacts ended (what pressed on it moves again); it
 * rests, feeling no force, until something moves it. */
void edit_rest_at_limits(world *w, int i);

/* Removes object i; what pressed on it moves again. */
void edit_delete(world *w, int i);

/* Something was changed from outside the simulation (a statement ran): the schedule
 * starts afresh, every pair due, and the simulation copies its bodies again. */
void edit_done(world *w);

#endif
