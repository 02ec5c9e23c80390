/* tolerance.h: the simulation's tolerances and thresholds, each named once, and
 * the rule by which a pair's tolerances follow its objects.
 *
 * Lengths are metres, times seconds, speeds m/s.  The thresholds of rest follow
 * the thesis's contact state (3.3.3); the others are rounding margins, chosen far
 * above double precision's and far below anything a scene can show.
 *
 * The rule.  A pair's tolerances come from the object that moves, never from a
 * static object's size: a cube is answered on a 10 km floor as on a 5 m one.
 *  - Its size S (tol_size): twice the outer radius of the pair's moving object,
 *    of the smaller one when both move (for two equal objects, the sum of their
 *    radii).  "Relative" tolerances multiply S (the thickness of a contact, and
 *    the areas of its region S^2) or 1 + S (the hover gap, the margins, the
 *    rounding of speeds and accelerations: objects under a metre keep a metre's).
 *  - Its speed: a relative speed is known no better than the rounding of the
 *    speeds it is a difference of (tol_speed).
 *  - Rounding: every tolerance stays above the rounding of the coordinates the
 *    pair's distances are computed from (tol_round): SIM_DIST_ULPS roundings of
 *    the farthest coordinate either object's points reach, 1e-11 m at 5 km from
 *    the origin, 2e-9 m at 1e6 m (limits.h).  Near the origin the size decides;
 *    far from it, the contact distance, the hover gap and the margins grow with
 *    the coordinates.
 */
#ifndef VROC_TOLERANCE_H
#define VROC_TOLERANCE_H

#include <float.h>
#include <math.h>

#include "body.h"
#include "vmath.h"

/* Most internal steps one frame may take; more is an error asking for fewer. */
#define SIM_MAX_SUBFRAMES 1000000L

/* Two objects this close (m) or closer touch: neither apart nor interpenetrating
 * (near the origin: tol_touch).  A search stops at this distance (toi.h), and
 * objects placed within it of each other are in contact. */
#define SIM_TOUCH 1e-9
/* Relative (1 + S): distances a query found are known to this fraction of the
 * pair's size (the margins the searches and bounds keep: tol_margin). */
#define SIM_ROUND_REL 1e-13
/* A distance between two objects is known to this many roundings (DBL_EPSILON
 * each) of the farthest coordinate either object's points reach: a query takes
 * a few differences and products of them. */
#define SIM_DIST_ULPS 8

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

/* Relative (1 + S): a speed (m/s) below this fraction of the pair's size is
 * rounding (a normal speed of zero, a spin about the normal only), and so is one
 * below SIM_DIST_ULPS roundings of the speeds it is a difference of. */
#define SIM_SPEED_ROUND 1e-12
/* Relative (1 + S): an acceleration (m/s^2) below this fraction of the size is
 * rounding (the objects do not press together, an object is balanced). */
#define SIM_ACCEL_ROUND 1e-9
/* Relative (S): features within this fraction of a pair's size of the contact
 * plane are in contact (the thickness of the contact region; 1 + S for a lasting
 * contact that holds, or a slide that starts). */
#define SIM_CONTACT_TOL 1e-6
/* Relative (1 + S): the gap at which lasting contacts are kept, by a cluster's
 * kicks and a slide's start: a little way apart, so that their queries find them
 * apart (cheap) rather than in (a depth to estimate), far inside a contact's
 * thickness and far above rounding. */
#define SIM_HOVER 1e-8

/* ---- the rule (see the top) ---- */

/* The farthest any coordinate of b's points reaches from the origin (m). */
static inline double tol_reach(const body *b)
{
    return d_max(fabs(b->x.x), d_max(fabs(b->x.y), fabs(b->x.z))) + b->shape.r_out;
}

/* The size S of pair a, b (m): twice the outer radius of its moving object, of
 * the smaller one when both move; never a static object's. */
static inline double tol_size(const body *a, const body *b)
{
    bool sa = body_is_static(a), sb = body_is_static(b);
    double r = sa && !sb ? b->shape.r_out : sb && !sa ? a->shape.r_out : d_min(a->shape.r_out, b->shape.r_out);
    return 2 * r;
}

/* The rounding of a distance between a and b (m): SIM_DIST_ULPS roundings of the
 * farthest coordinate either reaches. */
static inline double tol_round(const body *a, const body *b)
{
    return SIM_DIST_ULPS * DBL_EPSILON * d_max(tol_reach(a), tol_reach(b));
}

/* The contact distance of a and b: SIM_TOUCH, or four roundings of their
 * distance far from the origin. */
static inline double tol_touch(const body *a, const body *b)
{
    return d_max(SIM_TOUCH, 4 * tol_round(a, b));
}

/* The margin a search or a bound keeps below a distance a query found. */
static inline double tol_margin(const body *a, const body *b)
{
    return d_max(SIM_ROUND_REL * (1 + tol_size(a, b)), tol_round(a, b));
}

/* The thickness of the contact region of a and b: the features within it of the
 * contact plane are in contact. */
static inline double tol_contact(const body *a, const body *b)
{
    return d_max(SIM_CONTACT_TOL * tol_size(a, b), 64 * tol_round(a, b));
}

/* The thickness of the contact region of a and b when their distance is d (<= 0
 * in): tol_contact, deeper by as much as they are in, so that every point that
 * is in is one of its points.  A contact is met (toi.c) and answered (instant.c)
 * at the same points. */
static inline double tol_region(const body *a, const body *b, double d)
{
    return tol_contact(a, b) + (d < 0 ? -d : 0);
}

/* The gap at which a lasting contact of a and b is kept (SIM_HOVER), at least
 * four contact distances far from the origin. */
static inline double tol_hover(const body *a, const body *b)
{
    return d_max(SIM_HOVER * (1 + tol_size(a, b)), 16 * tol_round(a, b));
}

/* The speed of b's fastest point (m/s), near enough: |v| + |w| r_out (0 for a
 * static object). */
static inline double tol_body_speed(const body *b)
{
    return body_is_static(b) ? 0 : v3_len(b->v) + v3_len(b->w) * b->shape.r_out;
}

/* The rounding of a relative speed of a's and b's points (m/s). */
static inline double tol_speed(const body *a, const body *b)
{
    return SIM_SPEED_ROUND * (1 + tol_size(a, b)) +
           SIM_DIST_ULPS * DBL_EPSILON * (tol_body_speed(a) + tol_body_speed(b));
}

/* The rounding of a relative acceleration of a's and b's points (m/s^2). */
static inline double tol_accel(const body *a, const body *b)
{
    return SIM_ACCEL_ROUND * (1 + tol_size(a, b));
}

/* Two unit normals n, m are the same direction when n . m > 1 - SIM_PARALLEL. */
#define SIM_PARALLEL 1e-6

/* A cluster of objects pressed together (cluster.h) moves in steps of at most
 * this long (s), and short enough that none of its points moves more than
 * SIM_CLUSTER_MOVE (m) in one. */
#define SIM_CLUSTER_STEP 2e-3
#define SIM_CLUSTER_MOVE 1e-3
/* Rows of contact (the corners of its contact regions) a cluster's scratch has
 * room for from the start; a larger cluster grows it (rows.h). */
#define SIM_CLUSTER_ROWS 64

/* Events one internal step may answer before the event guard's last resort stops
 * the objects whose events ran away (guard.h; counted in stats as guards). */
#define SIM_MAX_EVENTS_PER_STEP 100000

#endif
