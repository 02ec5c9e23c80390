/* energy.h: the mechanical energy and the momenta of the world or of one body
 * (language.md, `energy`; the trace's ke column; plot's figures).
 *
 * Kinetic energy is m |v|^2 / 2 (v of the centre of mass) plus w . L / 2 (L the
 * angular momentum about the centre of mass, w = I^-1 L).  Potential energy is
 * that of the uniform global force (force.h): -m a . c, zero at the origin, with a
 * the global acceleration and c the centre of mass; a body sliding on a face feels
 * less of the force (force_on), but its energy is the field's all the same.
 * Momentum is m v; angular momentum is taken about the origin, c x m v + L, so
 * that the bodies' sum is the world's.  Static bodies (infinite mass, never
 * moving) hold none; a held body counts as the body it is.  Without a force and
 * with elasticity 1 the total is what Newton keeps: energy_test in
 * tests/test_physics.c checks it against the textbook. */
#ifndef VROC_ENERGY_H
#define VROC_ENERGY_H

#include "body.h"
#include "world.h"

typedef struct {
    double linear, rotational; /* kinetic energy, J */
    double potential;          /* J, under the global force, zero at the origin */
    vec3 momentum;             /* kg m/s */
    vec3 angular_momentum;     /* about the origin, kg m^2/s */
} energy_sum;

/* Body b's share (zero for a static body) under w's force. */
energy_sum energy_of_body(const world *w, const body *b);

/* The sum over every body of w. */
energy_sum energy_of_world(const world *w);

static inline double energy_kinetic(energy_sum e) { return e.linear + e.rotational; }
static inline double energy_total(energy_sum e) { return e.linear + e.rotational + e.potential; }

#endif
