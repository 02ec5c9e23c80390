/* contact.h: where two touching objects meet: their contact region and the points
 * at which they press (thesis 3.2.2).
 *
 * The contact region is found from the objects' supporting features along the
 * normal (the vertices within a tolerance of the furthest), projected onto the
 * contact plane: a vertex, a segment or a convex polygon each; their overlap is
 * the region, and its corners are where the contact forces of a frictionless
 * contact act (impulse.h), so that a box landing flat stays flat and one
 * standing over an edge tips.
 */
#ifndef VROC_CONTACT_H
#define VROC_CONTACT_H

#include "body.h"
#include "closest.h"
#include "pieces.h"
#include "region.h"

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

/* A point at which two touching objects press on each other, fixed in them so
 * that it can be followed as they move: a point of object p (a vertex, a corner of
 * the contact region, or a sphere's centre with its radius r) against a feature of
 * object q: a plane (a face's), a line (an edge's) or a point (a vertex, a
 * sphere's centre); or an edge of p against an edge of q, whose gap is the
 * distance between their lines along their common normal (crossing edges, as a
 * drum's rim rolling over a box's edge: a point of either would leave the contact
 * as they turn).  p and q are 0 (a) or 1 (b) as contact_cpoints writes them;
 * callers may renumber them. */
typedef enum { CPT_PLANE, CPT_LINE, CPT_POINT, CPT_EDGES } cpt_kind;

typedef struct {
    int p, q;
    cpt_kind kind;
    vec3 sp;   /* the point, in p's body frame */
    double r;  /* the radius about it (a sphere's, or two spheres' together) */
    vec3 f0;   /* q's feature in q's frame: PLANE its unit normal (towards p); */
    vec3 f1;   /*   LINE and EDGES a point f0 and unit direction f1; POINT f0;
                *   PLANE's offset is f1.x (f0 . y = f1.x on the plane) */
    vec3 sd;   /* EDGES: p's edge's unit direction in p's frame (sp a point of it), */
    double sgn; /*   and the sign that turns sd x f1 from q towards p */
} cpoint;

/* The most points one contact is followed by: of a region with more corners,
 * this many spread around it are kept (two quadrilaterals overlap in eight at
 * most; a cup's round base has more). */
#define CONTACT_MAX_POINTS 16

/* The points at which touching (or nearly touching) polyhedra or spheres a and b
 * press (closest result r of a against b, tol the thickness of the contact
 * region): a sphere's one point; the corners of a contact region (a segment's two
 * ends, a polygon's corners), each against the plane of the face side; or the one
 * closest pair.  At most max written (CONTACT_MAX_POINTS is enough for every
 * caller); returns the count (0 when out of memory).  Bodies of several pieces:
 * the points of each pair of their pieces that touches, among those of pp (their
 * pair's: pieces.h), or of every pair of pieces when pp is NULL or empty. */
int contact_cpoints(const body *a, const body *b, const piece_pairs *pp, const closest_result *r,
                    double tol, cpoint *out, int max);

/* contact_cpoints at the pair of pieces r names alone (pieces.h): for bodies of
 * one piece, the same. */
int contact_cpoints_of_pieces(const body *a, const body *b, const closest_result *r, double tol,
                              cpoint *out, int max);

/* The gap of point cp with its objects in the states P and Q (> 0 apart), the
 * unit normal there (from Q towards P) and the world point where they press (on
 * P's surface). */
double cpoint_eval(const cpoint *cp, const body *P, const body *Q, vec3 *n, vec3 *at);

/* True when m, touching support s (r the closest result of m against s, normal
 * from s to m), stands on a face of s with its centre of mass, projected along the
 * normal, strictly inside the region they touch on (for a ball: the face): a
 * frictionless face can then hold it without turning it.  *face is s's face (-1
 * when s touches with no face). */
bool contact_holds(const body *m, const body *s, const closest_result *r, double tol, int *face);

/* The same for the point shift (along the face) from m's centre of mass: where
 * friction moves the centre of pressure (friction_face). */
bool contact_holds_at(const body *m, const body *s, const closest_result *r, double tol, vec3 shift,
                      int *face);

/* Turns m about its centre of mass so that its face nearest s's face `face` lies
 * flat on it, and moves it along that face's normal to `gap` from its plane:
 * false (and m unchanged) when that face is more than max_tilt radians off.  w
 * is recomputed from L. */
bool contact_level(body *m, const body *s, int face, double max_tilt, double gap);

/* The mean distance from the foot of m's centre of mass over m's face that lies
 * flat against a face of normal n (the integral of the distance over its area,
 * exact): what a uniform pressure's friction turns against as m spins about n.
 * -1 when that face is not flat against n, or not centrally symmetric about
 * that foot (a spin alone would then push it sideways). */
double contact_face_arm(const body *m, vec3 n);

/* m's face that lies flat against a face of normal n (within SIM_PARALLEL):
 * its corners from m's centre of mass, in the plane's axes e1, e2 (e1 x e2 =
 * n), counterclockwise about n, into out (room for max); *height the centre of
 * mass's height over it.  Returns the corner count, or -1 when there is no
 * such face (or more corners than max). */
int contact_face_outline(const body *m, vec3 n, vec3 e1, vec3 e2, region_pt *out, int max, double *height);

/* The face of polyhedron o whose outward normal is nearest world direction d, or
 * -1 for a sphere. */
int contact_facing(const body *o, vec3 d);

/* Velocity of the material point of b at world point p. */
vec3 contact_point_velocity(const body *b, vec3 p);

/* Closing speed of a and b at p along n (from b to a): > 0 when approaching. */
double contact_closing_speed(const body *a, const body *b, vec3 p, vec3 n);

#endif
