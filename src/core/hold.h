/* hold.h: a body held by the hand (thesis 1.3 and Appendix A.1.2; language.md,
 * "The hand and the tool panel").
 *
 * A held body is moved by the hand, not by forces.  From the instant its motion is
 * set (hold_set) it moves as a rigid body fixed to the hand: the hand's point, the
 * pivot, goes at constant velocity v, and the body turns about it at constant
 * angular velocity w, until its motion is set again.  So a hand that moves and
 * turns at constant rates between two tracker rows carries it exactly.  The hand
 * sets its motion at every tracker row and every frame.
 *
 * What the simulation does with it (sim.c):
 *  - it feels no force; its centre of mass accelerates only by turning about the
 *    pivot (hold_accel, which force_on gives for it);
 *  - in a collision with a dynamic object it has infinite mass and keeps its
 *    motion: the other object is answered as if struck by a moving wall, with the
 *    held body's velocity at the contact point;
 *  - against a static object, another held one, or an object that cannot give way
 *    (held by what it stands on, or pinned against a still object it just struck)
 *    it stops where it touches, and stays there until its motion is set again;
 *  - its pairs are checked at the end of every internal step, whatever the
 *    schedule predicts, and its broad-phase box holds everything: no prediction
 *    assumes how fast the hand will move it;
 *  - nothing rests or slides on it, and it neither rests nor slides.
 * Speeds are held to the limits: the centre of mass goes no faster than
 * |v| + |w| |c - pivot| <= max_linear, and |w| <= max_angular (hold_set scales
 * a faster motion down; a hand that goes faster leaves the body behind).
 *
 * Outside a frame (a statement) these calls only change the body: the shell then
 * makes the schedule anew (edit_done).  Within a frame (sim_hook's at) they also
 * make the body's pairs due at once.
 */
#ifndef VROC_HOLD_H
#define VROC_HOLD_H

#include "body.h"
#include "vmath.h"

typedef struct world world;

/* How a held body moves until its motion is set again. */
typedef struct {
    vec3 pivot; /* the point it turns about (the hand), world, now */
    vec3 v;     /* that point's velocity */
    vec3 w;     /* angular velocity, world axes */
} hold_motion;

/* Body i, dynamic or resting, is held from now (world.time) and moves as m says
 * (scaled down to the speed limits); called on a held body, sets its motion anew.
 * It wakes and slides no more; objects resting or sliding on it wake when the
 * simulation next looks (rest_wake_unsupported).  Returns 0, or -1 for a static
 * body (nothing changes). */
int hold_set(world *w, int i, hold_motion m);

/* Body i is held no more: from now it flies freely with velocity v (of its centre
 * of mass) and angular velocity wv (world axes), under the force as any dynamic
 * body.  Nothing happens to a body that is not held. */
void hold_release(world *w, int i, vec3 v, vec3 wv);

/* Puts body i at once at origin x with orientation q (unit): for a held body whose
 * hand jumped while time stood still.  Its velocities stay. */
void hold_place(world *w, int i, vec3 x, quat q);

/* Held body b's flight over h seconds (flight_fly calls it): its pivot moves by
 * hold_v h and it turns by w h about the pivot; v and L follow. */
void hold_fly(body *b, double h);

/* The acceleration of a held body's centre of mass: it turns about the pivot,
 * w x (w x (c - pivot)). */
static inline vec3 hold_accel(const body *b)
{
    return v3_cross(b->w, v3_cross(b->w, v3_sub(body_com(b), b->hold_pivot)));
}

#endif
