/* tolerance.h: the simulation's tolerances and thresholds, each named once.
 *
 * Lengths are metres, times seconds, speeds m/s.  "Relative" tolerances multiply
 * the size of what they compare (the sum of two objects' outer radii, say).  The
 * thresholds of rest follow the thesis's contact state (3.3.3); the others are
 * rounding margins, chosen far above double precision's and far below anything a
 * scene can show.
 */
#ifndef VROC_TOLERANCE_H
#define VROC_TOLERANCE_H

#include "body.h"
#include "vmath.h"

/* Most internal steps one frame may take; more is an error asking for fewer. */
#define SIM_MAX_SUBFRAMES 1000000L

/* Two objects this close (m) or closer touch: neither apart nor interpenetrating.
 * A search stops at this distance (toi.h), and objects placed within it of each
 * other are in contact. */
#define SIM_TOUCH 1e-9
/* Relative: distances between objects are known to this fraction of their size
 * (the contact distance grows with it for very large objects). */
#define SIM_ROUND_REL 1e-13

/* The contact distance of objects a and b: SIM_TOUCH, or more for objects so
 * large that their distances round to more than it. */
static inline double tol_touch(const body *a, const body *b)
{
    return d_max(SIM_TOUCH, SIM_ROUND_REL * (a->shape.r_out + b->shape.r_out));
}

/* An impact whose rebound would be slower than this (m/s: e times the closing
 * speed) is perfectly inelastic, when e < 1: the objects stay in contact, and the
 * ever smaller bounces a dropped ball makes before its Zeno time are summed at
 * once. */
#define SIM_BOUNCE_SPEED 0.02
/* Below this speed (m/s: |v| + |w| times the outer radius) an object held by its
 * supports, sliding or pressed on them, comes to rest at the end of a frame (the
 * thesis's contact state): it stays put, costs nothing, and feels no force until
 * something moves it.  Only where the contacts lose energy (e < 1), or the object
 * is still. */
#define SIM_REST_SPEED 0.05

/* Relative: a speed (m/s) below this fraction of the objects' size is rounding
 * (a normal speed of zero, a spin about the normal only). */
#define SIM_SPEED_ROUND 1e-12
/* Relative: an acceleration (m/s^2) below this fraction of the objects' size is
 * rounding (the objects do not press together, an object is balanced). */
#define SIM_ACCEL_ROUND 1e-9
/* Relative: features within this fraction of a pair's size (the sum of the two
 * outer radii) of the contact plane are in contact (the contact region). */
#define SIM_CONTACT_TOL 1e-6

/* The thickness of the contact region of objects a and b (SIM_CONTACT_TOL of their
 * size). */
static inline double tol_contact(const body *a, const body *b)
{
    return SIM_CONTACT_TOL * (a->shape.r_out + b->shape.r_out);
}

/* The gap (relative to the sizes, as SIM_CONTACT_TOL) at which lasting contacts
 * are kept, by a cluster's kicks and a slide's start: a little way apart, so
 * that their queries find them apart (cheap) rather than in (a depth to
 * estimate), far inside a contact's thickness and far above rounding. */
#define SIM_HOVER 1e-8
/* Two unit normals n, m are the same direction when n . m > 1 - SIM_PARALLEL. */
#define SIM_PARALLEL 1e-6

/* A cluster of objects pressed together (cluster.h) moves in steps of at most
 * this long (s), and short enough that none of its points moves more than
 * SIM_CLUSTER_MOVE (m) in one. */
#define SIM_CLUSTER_STEP 2e-3
#define SIM_CLUSTER_MOVE 1e-3
/* Rows of contact one cluster may hold (the corners of its contact regions). */
#define SIM_CLUSTER_ROWS 64

/* Events one internal step may answer before it gives up and lets the step end
 * (a guard against a fault; counted in stats as an overflow). */
#define SIM_MAX_EVENTS_PER_STEP 100000

#endif
