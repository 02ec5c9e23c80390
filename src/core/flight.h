/* flight.h: free flight of one body, and how its points move (the integrator).
 *
 * A body flies under a constant acceleration (the global force as it feels it):
 * its centre of mass exactly, x += v h + a h^2 / 2, v += a h, with the step held
 * to max_linear; its rotation keeps its angular momentum L exactly (flight.c says
 * how), then the speed limits.  A body that slides on a support turning about the
 * support's normal only (as settling leaves it) keeps turning so.  Nothing here
 * knows the world: the caller gives the acceleration.
 */
#ifndef VROC_FLIGHT_H
#define VROC_FLIGHT_H

#include <stdbool.h>

#include "body.h"
#include "vmath.h"

/* Free flight of dynamic body b over h seconds under acceleration a, then the
 * speed limits; a held body (hold.h) moves as the hand set it instead. */
void flight_fly(body *b, double h, vec3 a, double max_linear, double max_angular);

/* True when b slides on a support turning about the support's normal only (or
 * not at all off it): then its flight keeps it so. */
bool flight_spins_on_support(const body *b);

/* How a body moves at one instant of free flight, for the velocity and the
 * acceleration of its points. */
typedef struct {
    vec3 c, v, w, a, dw; /* centre of mass, its velocity, spin, acceleration; dw/dt */
} flight_motion;

/* Body b's motion now, a the acceleration it flies under: nothing for a static
 * or resting body; velocity and spin only for one that does not fly; a held body
 * (hold.h) turns at a constant rate. */
static inline flight_motion flight_motion_of(const body *b, vec3 a)
{
    flight_motion m = {body_com(b), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)};
    if (body_is_static(b) || b->state == STATE_RESTING) return m;
    m.v = b->v;
    m.w = b->w;
    if (b->state != STATE_DYNAMIC) return m;
    m.a = a;
    if (v3_len2(b->w) != 0 && !b->held) m.dw = v3_neg(body_inertia_inv_mulv(b, v3_cross(b->w, b->L)));
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
