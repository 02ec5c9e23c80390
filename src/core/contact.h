/* contact.h: the answer to one collision (thesis 3.2.2).
 *
 * A single-point, frictionless impulse from the conservation of linear and angular
 * momentum with full inertia tensors (Hahn 1988; Moore and Wilhelms 1988), the
 * restitution min(e1, e2), static objects with infinite mass.  The contact point is
 * the centre of the contact region: where the two objects' supporting features
 * (vertex, edge or face) overlap, so that a box landing flat stays flat.
 */
#ifndef VROC_CONTACT_H
#define VROC_CONTACT_H

#include "body.h"
#include "closest.h"

typedef struct {
    vec3 point;    /* contact point, world */
    vec3 normal;   /* unit, from b towards a */
    double speed;  /* closing speed before the impulse (> 0: approaching) */
    double impulse;/* magnitude of the impulse applied (along normal to a) */
} contact;

/* The centre of the contact region of a and b, touching or nearly touching with
 * closest result r: the centroid of the overlap of a's and b's features that lie
 * within tol of the contact plane, projected onto that plane. */
vec3 contact_point(const body *a, const body *b, const closest_result *r, double tol);

/* Of the corners of that contact region (the ends of a segment, the vertices of a
 * polygon), the one where a and b close fastest along r->normal; p when none
 * closes.  For a region whose centre moves apart while a corner of it closes: a
 * box turning as it lands on an edge strikes with the edge's lower end. */
vec3 contact_closing_corner(const body *a, const body *b, const closest_result *r, double tol,
                            vec3 p);

/* True when m can stand on a support below it, n pointing from the support to m:
 * m is a sphere, or its features facing the support form a polygon (tolerance tol)
 * that holds the projection of m's centre of mass. */
bool contact_stable(const body *m, vec3 n, double tol);

/* How far across n the features of m facing along -n (within tol of the furthest)
 * reach from its centre of mass: the radius of the circle about it that holds
 * what m stands on, however it turns about n (0 for a ball). */
double contact_footprint(const body *m, vec3 n, double tol);

/* The pose in which m, a polyhedron touching a support below it (n from the support
 * to m), would come to lie on one of its faces: the face that m can stand on (its
 * centre of mass over the face) whose outward normal is nearest -n, within
 * max_angle radians.  Writes the orientation that turns that face flat onto the
 * support, rotated the shortest way, and the height of m's centre of mass above the
 * face's plane; false when no face qualifies (or m is a sphere). */
bool contact_settle_pose(const body *m, vec3 n, double max_angle, quat *q, double *height);

/* Velocity of the material point of b at world point p. */
vec3 contact_point_velocity(const body *b, vec3 p);

/* Closing speed of a and b at p along n (from b to a): > 0 when approaching. */
double contact_closing_speed(const body *a, const body *b, vec3 p, vec3 n);

/* Applies the impulse that answers the collision of a and b at p with normal n
 * (from b to a) and restitution e, when they approach.  held = 1 holds a, 2 holds
 * b (0 neither): the held object does not turn and has infinite mass along the unit
 * vector s, the normal of what holds it, so that it moves across s only; with s
 * zero it does not move at all.  Returns what was done (impulse 0 when they do not
 * approach). */
contact contact_respond(body *a, body *b, vec3 p, vec3 n, double e, int held, vec3 s);

#endif
