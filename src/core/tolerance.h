/* tolerance.h: the simulation's tolerances and thresholds, each named once.
 *
 * Lengths are metres, times seconds, speeds m/s.  "Relative" tolerances multiply
 * the size of what they compare (the sum of two objects' outer radii, say).  The
 * thresholds of rest and sliding follow the thesis's contact state (3.3.3); the
 * others are rounding margins, chosen far above double precision's and far below
 * anything a scene can show.
 */
#ifndef VROC_TOLERANCE_H
#define VROC_TOLERANCE_H

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
/* Settling (the limit of rocking, rest.c): an object with restitution below 1
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
 * objects through (a guard against endless micro-collisions). */
#define SIM_MAX_COLLISIONS_PER_STEP 1000
/* A polyhedron of at most this many vertices is tried vertex by vertex by the
 * time of impact's search after a strike (toi.c). */
#define SIM_PLANE_VERTICES 32

/* Relative: features within this fraction of a pair's size (the sum of the two
 * outer radii) of the contact plane are in contact (the contact region, standing,
 * footprints). */
#define SIM_CONTACT_TOL 1e-6
/* Two unit normals n, m are the same direction when n . m > 1 - SIM_PARALLEL. */
#define SIM_PARALLEL 1e-6
/* A normal n holds against a direction u (a support under a body, a blow pressing
 * it back) when n . u > SIM_SUPPORT_COS: within 45 degrees. */
#define SIM_SUPPORT_COS 0.7
/* A speed (m/s) along a support's normal below this is rounding (1e-7 m in a
 * day). */
#define SIM_SPEED_ROUND 1e-12

#endif
