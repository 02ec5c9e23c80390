/* flight.h: how one body moves between events: its flight, evaluated at any time.
 *
 * A flight starts at time t0 from a body's state and gives the state at any later
 * time exactly, with nothing accumulated in between (design.md, "Dynamics"):
 *  - FLIGHT_FREE: the centre of mass flies its parabola under the force, x = c0 +
 *    v0 t + a t^2 / 2, and the body turns freely with its angular momentum L kept,
 *    by the exact torque-free motion (spin.h); energy and L are kept to rounding.
 *  - FLIGHT_SLIDE: on a face of a still support with normal n, the centre flies
 *    a parabola along the face, and the body turns about a fixed axis by
 *    w0 h + dw h^2 / 2.  On a frictionless face: under the force less its part
 *    along -n, turning about n only at a constant rate (what such a face leaves
 *    free).  With friction (friction_face): under the force and a constant
 *    Coulomb force against its slip, a box not turning (or spinning in place
 *    about n, slowed by friction's couple), a ball turning about n x slip,
 *    spun up by friction's couple, until its slip reaches zero at t_stop (an
 *    event: it then sticks, rolls or slides on anew), where it stays.
 *  - FLIGHT_ROLL: a ball rolling on a face of a still support with normal n,
 *    along a line u of the face (its velocity's, or its acceleration's from
 *    rest), at the constant acceleration a along u that gravity and its rolling
 *    resistance give (friction_face), until its speed reaches zero at t_stop
 *    (an event), where it stays; it turns about n x u by the distance gone over
 *    its radius, at w = n x v / r (no slip).
 *  - FLIGHT_SPIN: a flat body sliding and spinning on a face (level or not) with
 *    friction over its face (facespin.h): one step of the integration of its
 *    slide and spin, read from its dense output, until t_stop, the step's end
 *    (an event: the next step starts there, or it stops, or on a steep slope
 *    it slides on down in closed form).
 *  - FLIGHT_STILL: the body stays where it is (resting, static).
 *  - FLIGHT_HELD: held by the hand (hold.h), the body is fixed to a point, the
 *    pivot, that moves at a constant velocity, and turns about it at a constant
 *    angular velocity w: pivot(t) = p0 + v t, R the turn by w t, c = pivot + R r0,
 *    q = R q0, v = v + w x (R r0), L = I_world w.  No force moves it.
 * No speed is limited in flight: max_linear and max_angular apply where a command
 * or a collision sets a speed (edit.c, sim.c).
 */
#ifndef VROC_FLIGHT_H
#define VROC_FLIGHT_H

#include <stdbool.h>

#include "body.h"
#include "spin.h"
#include "vmath.h"

typedef enum { FLIGHT_STILL, FLIGHT_FREE, FLIGHT_SLIDE, FLIGHT_HELD, FLIGHT_ROLL, FLIGHT_SPIN } flight_kind;

/* One step of a flat body sliding and spinning on a level face (facespin.h),
 * h long: in the face's axes (e1, e2 = friction_basis of its normal), the
 * displacement of its centre of mass, its turn about the normal, its velocity
 * and its spin, y = (x, y, turn, vx, vy, w), at s in [0, 1] of the step r0 + s
 * (r1 + (1 - s) (r2 + s (r3 + (1 - s) r4))) (Dormand and Prince's dense
 * output).  more: it goes on after the step; else its slip and spin stop there
 * together (|v| + |w| R < 1e-9 m/s), or (slides: on a slope steeper than
 * friction holds) its spin and drift across the slope are gone there, and it
 * slides on down.  tips: no step could be taken (h 0: the pressure that
 * balances it gives out at once), it tips. */
typedef struct {
    double h, r[5][6];
    bool more, tips, slides;
} face_step;

typedef struct {
    flight_kind kind;
    double t0;        /* when it starts */
    vec3 c0, v0, a;   /* the centre of mass then, its velocity, its acceleration */
    quat q0;          /* the orientation then (body to world) */
    vec3 L;           /* the angular momentum (world axes): constant in FREE */
    bool spins;       /* FREE: L is not zero, spin holds the motion */
    free_spin spin;
    vec3 n;           /* SLIDE, ROLL: the support's normal, towards the body; */
    vec3 axis;        /* SLIDE: the axis it turns about, its rate then */
    double w0, dw;    /*   and the rate's constant change */
    vec3 p0, r0, w;   /* HELD: the pivot then (v0 its velocity), the centre of
                       *   mass from it, and the constant spin */
    double t_stop;    /* SLIDE, ROLL: how long after t0 it stops (HUGE_VAL: never), */
    bool closed;      /* SLIDE, ROLL with friction: t_stop ends its closed form
                       *   (else its state asked for none, and t_stop is 0) */
    vec3 u;           /* ROLL: the line it rolls along, */
    double radius;    /*   and its radius */
    face_step step;   /* SPIN: its step (t_stop its length), in the axes e1, e2 */
    vec3 e1, e2;
    double rate;      /* no point of the body turns faster than rate (rad/s) */
    long id;          /* a number no other flight of this world has */
} flight;

/* Starts flight f of kind at time t0 from body b's state (x, q, v, L; b's w is
 * taken as consistent with L): a the acceleration of the centre of mass (FREE,
 * SLIDE, ROLL), n the support's normal (SLIDE: b turns about n only, at w . n,
 * as on a frictionless face; with friction, and for ROLL, flight_start_face
 * sets the rest).  HELD takes the pivot, its velocity and w from b
 * (hold_pivot, hold_v, w). */
void flight_start(flight *f, const body *b, flight_kind kind, double t0, vec3 a, vec3 n, long id);

/* How a body moves on a still face with friction (friction_face writes it):
 * its mode there (MODE_SLIDE, MODE_STICK, MODE_ROLL; MODE_GENERAL where no
 * closed form holds), the acceleration of its centre of mass, the fixed axis
 * it turns about and the constant rate of change of its spin about it
 * (SLIDE), and how long until its slip (SLIDE) or speed (ROLL) reaches zero
 * (HUGE_VAL: never); or (spins) a step of its slide and spin, t_stop its
 * length. */
typedef struct {
    body_mode mode;
    vec3 a, axis;
    double dw, t_stop;
    bool spins;     /* sliding and spinning at once: step holds its motion */
    face_step step;
} face_motion;

/* Starts b's flight f of kind FLIGHT_SLIDE or FLIGHT_ROLL on a face of normal
 * n with friction, as m says, at t0 (b's state as friction_face found it:
 * along the face, a ball's spin about m->axis); rate covers it up to time
 * until (the end of its step: it is started again there). */
void flight_start_face(flight *f, const body *b, flight_kind kind, double t0, const face_motion *m,
                       vec3 n, double until, long id);

/* Writes the state at time t (t >= t0) into out, a copy of the flight's body:
 * x, q, v, L and w (and a held body's pivot). */
void flight_at(const flight *f, const body *shape_of, double t, body *out);

/* How body b moves at one instant, for the velocity and the acceleration of its
 * points. */
typedef struct {
    vec3 c, v, w, a, dw; /* centre of mass, its velocity, spin, acceleration; dw/dt */
} flight_motion;

/* Body b's motion at the state given (b as flight_at wrote it), a its centre's
 * acceleration: nothing for a still body.  A held body (pivot not NULL: where the
 * pivot is) turns at a constant w about its pivot: its centre accelerates by
 * w x (w x (c - pivot)), and w does not change. */
static inline flight_motion flight_motion_of(const body *b, bool moving, vec3 a, const vec3 *pivot)
{
    flight_motion m = {body_com(b), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)};
    if (!moving) return m;
    m.v = b->v;
    m.w = b->w;
    m.a = a;
    if (pivot) m.a = v3_cross(b->w, v3_cross(b->w, v3_sub(m.c, *pivot)));
    else if (v3_len2(b->w) != 0) m.dw = v3_neg(body_inertia_inv_mulv(b, v3_cross(b->w, b->L)));
    return m;
}

/* The velocity of the body's point p. */
static inline vec3 flight_point_velocity(const flight_motion *m, vec3 p)
{
    return v3_add(m->v, v3_cross(m->w, v3_sub(p, m->c)));
}

/* The acceleration of the body's point p: the centre's, plus the centripetal part
 * w x (w x r) and the torque-free turn dw/dt x r, dw/dt = -I^-1 (w x L) (Euler's
 * equations). */
static inline vec3 flight_point_accel(const flight_motion *m, vec3 p)
{
    vec3 r = v3_sub(p, m->c);
    return v3_add(m->a, v3_add(v3_cross(m->w, v3_cross(m->w, r)), v3_cross(m->dw, r)));
}

#endif
