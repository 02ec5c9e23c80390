/* poly.h: convex polyhedra with full adjacency, built by qhull, and their mass properties.
 *
 * A poly is the collision shape of every non-sphere object (design.md, "Geometry"):
 * vertices, edges and faces in the body frame, each face planar with coplanar
 * neighbours merged, and every incidence a closest-feature walk needs (thesis 3.2.1,
 * Lin and Canny; Mirtich's V-Clip).  It is built once from a point cloud by
 * libqhull_r and never changes afterwards.
 *
 * Conventions:
 *  - face f has an outward unit normal f.n and offset f.d: a point p is on or inside
 *    the face's plane when dot(f.n, p) <= f.d;
 *  - the vertices of face f are face_vert[f.first .. f.first + f.count - 1], in
 *    counter-clockwise order seen from outside; face_edge[f.first + k] is the edge
 *    joining face_vert[f.first + k] to face_vert[f.first + (k + 1) % f.count];
 *  - edge e runs from vertex e.v[0] to e.v[1]; e.f[0] is the face on its left seen
 *    from outside (the face whose ccw boundary traverses v[0] -> v[1]), e.f[1] the face
 *    on its right (traversing v[1] -> v[0]);
 *  - the edges at vertex v are vert_edge[vert_first[v] .. vert_first[v + 1] - 1].
 */
#ifndef VROC_POLY_H
#define VROC_POLY_H

#include <stddef.h>

#include "vmath.h"

typedef struct {
    int v[2]; /* tail, head */
    int f[2]; /* left face (v0 -> v1 ccw), right face */
} poly_edge;

typedef struct {
    vec3 n;    /* outward unit normal */
    double d;  /* plane offset: dot(n, p) = d on the face */
    int first; /* index into face_vert / face_edge */
    int count; /* number of vertices (= number of edges) of the face */
} poly_face;

typedef struct {
    int nv, ne, nf;
    vec3 *v;          /* nv vertices, body frame */
    poly_edge *e;     /* ne edges */
    poly_face *f;     /* nf faces */
    int *face_vert;   /* sum of face counts */
    int *face_edge;   /* same length as face_vert */
    int *vert_first;  /* nv + 1 offsets into vert_edge */
    int *vert_edge;   /* 2 * ne entries */
} poly;

/* Mass properties of a solid at unit density, in the frame the solid is given in. */
typedef struct {
    double volume;
    vec3 com;     /* centre of mass */
    mat3 inertia; /* inertia tensor about the centre of mass, unit density */
} mass_props;

/* The convex hull of n points (n >= 4, not all coplanar), coplanar facets merged into
 * convex polygons.  Returns NULL and writes a message to err when qhull fails or the
 * points are degenerate (flat, collinear, too few). */
poly *poly_hull(const vec3 *pts, int n, char *err, size_t errlen);

/* poly_hull's flatness angle in radians (about 1.7 degrees): see poly_hull_merge. */
#define POLY_FLAT_ANGLE 0.03

/* poly_hull with the flatness angle given.  The exact hull is built first; then each
 * connected region of faces whose normals lie within angle / 2 of the normal of its
 * largest face becomes one face, on the plane with the region's area-weighted normal
 * moved out to touch the hull, and the result is the intersection of those
 * half-spaces.  So it contains every point, is larger than the exact hull by about
 * angle times a region's width at most, and is not exactly symmetric when the points
 * are; surfaces whose faces turn by more than angle / 2 do not merge.  angle = 0
 * gives the exact hull, with only facets coplanar to roundoff merged; it is also what
 * poly_hull falls back to should merging fail. */
poly *poly_hull_merge(const vec3 *pts, int n, double angle, char *err, size_t errlen);

/* poly_hull_merge(pts, n, angle) for points whose hull the caller knows: the nf
 * face cycles (count[f] vertex indices each, one after another in fvert, ccw seen
 * from outside) that close a surface over all n points.  Where that surface is
 * checked to be their exact hull (every face planar to roundoff, every point on
 * or below every face, every edge folded by far more than roundoff) it is taken as
 * is, with no qhull run, and its nearly flat regions merged as poly_hull_merge
 * merges them (which goes by the faces' geometry, not their numbering); else (and
 * for more than a few thousand points, where the check would cost more than
 * qhull) it is poly_hull_merge's.  The same solid either way, to the bit (where
 * nothing merged, its vertices are in pts' order, not qhull's). */
poly *poly_hull_surface(const vec3 *pts, int n, int nf, const int *count, const int *fvert,
                        double angle, char *err, size_t errlen);

/* The box of half-extents h (each > 0) about the origin, built directly: the
 * same vertices, edges and faces, in the same order, as poly_hull gives for its
 * eight corners (tests/test_geometry.c checks it to the bit), at no qhull run.
 * NULL with err when out of memory. */
poly *poly_box(vec3 h, char *err, size_t errlen);

/* A deep copy (NULL on allocation failure). */
poly *poly_copy(const poly *p);

/* The vertex of p furthest along d, by strict ascent over the vertex graph from
 * vertex j (on a convex polyhedron a local maximum is global). */
int poly_climb(const poly *p, vec3 d, int j);

void poly_free(poly *p);

/* Volume, centre of mass and inertia tensor of the solid polyhedron at unit density
 * (exact polyhedral volume integrals: divergence theorem over the faces). */
mass_props poly_mass(const poly *p);

/* Largest distance from c to a vertex (the circumscribed radius about c). */
double poly_outer_radius(const poly *p, vec3 c);

/* Smallest distance from c to a face plane (the inscribed radius about c, c inside). */
double poly_inner_radius(const poly *p, vec3 c);

/* Index of the vertex furthest along direction d (support mapping). */
int poly_support(const poly *p, vec3 d);

/* Checks every invariant above (Euler's formula, planarity to tol, ccw order, edge
 * to face incidences, convexity).  Returns 0 when all hold, or writes the first
 * broken one to err and returns -1.  For tests and debugging. */
int poly_check(const poly *p, double tol, char *err, size_t errlen);

#endif
