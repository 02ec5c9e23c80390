/* closest.h: distance, closest points and closest features between two convex
 * shapes placed in the world (thesis 3.2.1).
 *
 * Polyhedra (cubes, superquadrics) are tracked with closest features as in Lin and
 * Canny, in the robust form of Mirtich's V-Clip (ACM TOG 17(3), 1998): each pair
 * keeps its last closest features (closest_cache) and the next query walks from them
 * to neighbouring features until each closest point lies in the other feature's
 * Voronoi region, so a coherent query costs about the same whatever the size of the
 * polyhedra.  Sphere-sphere and sphere-box are closed-form; sphere-polyhedron is the
 * distance from the centre to the polyhedron (tracked the same way) minus the radius.
 *
 * The Voronoi regions of a polyhedron's features are computed once per shape by
 * closest_hull_new and hung on the shape (shape.feat).  A query sees only proxies:
 * a hull (or a sphere's radius) and a pose; it knows nothing of bodies or the world.
 *
 * Conventions of a result:
 *  - distance > 0: separated, exact; pa on A and pb on B are the closest points
 *    (world), normal = (pa - pb) / distance.
 *  - distance <= 0: touching (0, within 1e-12 of the objects' size) or penetrating.
 *    Then -distance estimates the penetration depth: exact for sphere-sphere,
 *    sphere-box and sphere-polyhedron; for two polyhedra the smallest overlap of
 *    their projections onto the face normals of both and onto the cross products of
 *    the edges at the closest features found (an upper bound of the true depth:
 *    other edge-edge directions are not tried).  normal is that direction: moving
 *    A by -distance along it clears B.  The points are the deepest vertex of one
 *    and its projection onto the other's face plane (or the two extreme vertices
 *    along an edge-edge direction), so again distance = normal . (pa - pb).
 *  - normal is a unit vector from B towards A in every case.
 * (body_distance, body.h, puts each pair in a canonical order first, so that
 * swapping two bodies mirrors the result exactly.)
 */
#ifndef VROC_CLOSEST_H
#define VROC_CLOSEST_H

#include <stdbool.h>

#include "poly.h"
#include "vmath.h"

typedef enum {
    CLOSEST_NONE,   /* no feature (an invalid result, an empty cache) */
    CLOSEST_VERTEX, /* index into poly.v */
    CLOSEST_EDGE,   /* index into poly.e */
    CLOSEST_FACE,   /* index into poly.f */
    CLOSEST_SPHERE  /* the whole sphere; index 0 */
} closest_kind;

typedef struct {
    closest_kind kind;
    int index;
} closest_feature;

/* The closest features of one pair, kept with the pair between queries: fa on the
 * first object passed, fb on the second.  Zero-initialised (valid false) means none
 * yet.  A cache that does not fit the objects (another shape, out-of-range index) is
 * ignored, never trusted. */
typedef struct {
    closest_feature fa, fb;
    bool valid;
} closest_cache;

typedef enum {
    CLOSEST_SEPARATED,   /* distance > 0 */
    CLOSEST_PENETRATING, /* distance <= 0: touching or overlapping */
    CLOSEST_INVALID      /* a shape not built, or a position or orientation not finite */
} closest_status;

typedef struct {
    closest_status status;
    double distance;    /* > 0 separated; <= 0 minus the penetration estimate; NAN invalid */
    vec3 pa, pb;        /* points on A and on B, world coordinates */
    vec3 normal;        /* unit, from B towards A */
    closest_feature fa, fb; /* the features pa and pb lie on */
    int ka, kb;         /* the pieces of A and B they are on, for bodies of several
                           (pieces.h); 0 otherwise */
    int steps;          /* feature-walk steps taken (0 for closed forms) */
    bool restarted;     /* the walk exceeded its step bound and was redone from scratch;
                           never expected: callers count these so that a fault shows */
} closest_result;

/* Voronoi-region data of one polyhedron (body frame), opaque. */
struct closest_hull;
typedef struct closest_hull closest_hull;

/* A shape placed in the world, as a query sees it: a convex polyhedron (hull, with
 * its Voronoi data feat, which may be NULL: it is then built for the call, at
 * O(size) cost), or, when hull is NULL, a sphere of radius radius about the body
 * origin.  com is the centre of mass in the body frame (where a walk without a
 * cache starts looking).  Body frame to world is p -> q p q* + x. */
typedef struct {
    const poly *hull;
    const closest_hull *feat;
    double radius;
    vec3 com;
    vec3 x;
    quat q; /* need not be exactly unit */
} closest_proxy;

/* Builds the feature and Voronoi-region data of p (which must outlive it).  NULL on
 * allocation failure. */
closest_hull *closest_hull_new(const poly *p);
void closest_hull_free(closest_hull *h);

/* The vertex of h's hull furthest along d (body frame): in time that grows with the
 * log of its vertices on a large hull (support.h), by a climb on a small one. */
int closest_hull_support(const closest_hull *h, vec3 d);

/* Distance between a and b, computed in the order given (so swapping a and b
 * mirrors the result up to the choice among equally close features).  cache (may be
 * NULL) gives the features to start from and receives the new ones.  A proxy with a
 * non-finite x or q, or a sphere of negative radius, gives status CLOSEST_INVALID,
 * distance NAN, and leaves the cache alone. */
closest_result closest_distance(const closest_proxy *a, const closest_proxy *b,
                                closest_cache *cache);

/* closest_distance for callers that need to know only whether the pair is apart,
 * and how far: the status and, when separated, everything are the same as
 * closest_distance's; when touching or penetrating, distance is 0 and the points
 * and normal are unspecified (no penetration estimate is made, which is most of the
 * cost of an overlapping query). */
closest_result closest_distance_apart(const closest_proxy *a, const closest_proxy *b,
                                      closest_cache *cache);

/* r as the query of the swapped pair gives it: points, features and pieces
 * swapped, normal negated. */
void closest_mirror(closest_result *r);

/* An invalid result: status CLOSEST_INVALID, distance NAN, the rest zero. */
void closest_invalid(closest_result *r);

/* "vertex", "edge", "face", "sphere" or "none". */
const char *closest_kind_name(closest_kind k);

#endif
