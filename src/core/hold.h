/* hold.h: a body held by the hand (thesis 1.3 and Appendix A.1.2; language.md,
 * "The hand and the tool panel").
 *
 * A held body is moved by the hand, not by forces.  From the instant its motion is
 * set (hold_set) it flies FLIGHT_HELD (flight.h): fixed to the hand's point, the
 * pivot, which goes at a constant velocity, it turns about it at a constant
 * angular velocity, until its motion is set again.  So a hand that moves and
 * turns at constant rates between two tracker rows carries it exactly.  The hand
 * sets its motion at every tracker row and every frame.
 *
 * What the simulation does with it (sim.c):
 *  - no force moves it, and it neither rests nor slides; it is in lasting contact
 *    with nothing (every contact with it is a collision), so nothing rests or
 *    slides on it;
 *  - in a collision it has infinite mass and keeps its motion: the objects it
 *    strikes are answered, with their lasting contacts, as if struck by a moving
 *    wall, with the held body's velocity at each contact point; a contact too
 *    slow to bounce parts at SIM_BOUNCE_SPEED;
 *  - against a static object, another held one, or objects that cannot give way
 *    (pressed against a static one: the contact's impulses have no solution) it
 *    stops where it touches, and stays there until its motion is set again;
 *  - its pairs are searched from the instant its motion is set, by conservative
 *    advancement about its pivot (schedule.h, sched_move: its reach about the
 *    pivot, its spin): no bound assumes how the hand will move it next.
 * Speeds are held to the limits: the centre of mass goes no faster than
 * |v| + |w| |c - pivot| <= max_linear, and |w| <= max_angular (hold_set scales
 * a faster motion down; a hand that goes faster leaves the body behind).
 *
 * Each call says the world changed (edit_done): between frames the next frame
 * starts over from it; within a frame (sim_hook's at) the simulation starts over
 * at once, from the hook's instant.
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
 * When it was not held: it wakes and slides no more, its lasting contacts end,
 * and the objects pressed together with it wake.  Returns 0, or -1 for a static
 * body (nothing changes). */
int hold_set(world *w, int i, hold_motion m);

/* Body i is held no more: from now it flies freely with velocity v (of its centre
 * of mass) and angular velocity wv (world axes), under the force as any dynamic
 * body; each is scaled down to max_linear or max_angular when longer, a cut
 * counted as a collision's is (st.speed_cuts, st.first_cut).  Nothing happens to
 * a body that is not held. */
void hold_release(world *w, int i, vec3 v, vec3 wv);

/* Held body i's pivot and that point's velocity, exactly (save writes them): its
 * own velocity and angular velocity stay as they are.  Returns 0, or -1 when it
 * is not held (nothing changes). */
int hold_exact(world *w, int i, vec3 pivot, vec3 v);

/* Puts body i at once at origin x with orientation q (unit): for a held body whose
 * hand jumped while time stood still (the caller has checked the place is free).
 * Its velocities stay; a held body's pivot keeps its place relative to it. */
void hold_place(world *w, int i, vec3 x, quat q);

/* Held body i jumps with a hand that jumped while time stood still: it sweeps
 * along the straight path from its pose towards origin x1 with orientation q1 (its
 * centre of mass in a line, turning the short way, both evenly) and stops at the
 * first thing it touches, a hover gap (tolerance.h) short of it, there placed as
 * hold_place places it.  It pushes nothing: no time passes.  Where it starts in
 * something, it stays.  Returns the fraction of the way it went, 0 to 1. */
double hold_sweep(world *w, int i, vec3 x1, quat q1);

#endif
