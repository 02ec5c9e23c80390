/* shape.h: the three primitives of the thesis (Tables A.2 to A.4), and polyhedra
 * given as point sets (read from mesh files: src/mesh/), turned into geometry.
 *
 * A shape is built from its parameters once (and again when a parameter changes):
 * a triangle mesh for drawing (spheres and superquadrics at ures x vres, smooth
 * normals; cubes flat; a polyhedron's as its source gives it), the convex polyhedron
 * used by collision detection (cubes, superquadrics and polyhedra; spheres stay
 * exact), and the mass properties at unit density with the inner and outer radius
 * about the centre of mass, all in the body frame.
 *
 * Superquadric (Barr's superellipsoid), eta in [-pi/2, pi/2], omega in [-pi, pi):
 *   x = a1 c(eta,e1) c(omega,e2), y = a2 c(eta,e1) s(omega,e2), z = a3 s(eta,e1),
 *   c(t,e) = sign(cos t) |cos t|^e, s(t,e) = sign(sin t) |sin t|^e.
 * ures divides omega (around the z axis), vres divides eta (pole to pole).
 */
#ifndef VROC_SHAPE_H
#define VROC_SHAPE_H

#include <stdbool.h>
#include <stddef.h>

#include "closest.h"
#include "poly.h"
#include "vmath.h"

typedef enum { SHAPE_SPHERE, SHAPE_CUBE, SHAPE_SUPERQUADRIC, SHAPE_POLYHEDRON } shape_kind;

/* Triangle mesh for drawing: per-vertex positions and unit normals. */
typedef struct {
    int nv, nt;
    vec3 *pos;
    vec3 *nrm;
    int (*tri)[3]; /* counter-clockwise seen from outside (a polyhedron's: as its
                    * source's faces run, which may be either way) */
} mesh;

/* A polyhedron's geometry as its maker gives it (a mesh file: src/mesh/), in the
 * maker's units, before the shape's scale: the points, the mesh drawn (no
 * triangles: the hull is drawn), and the maker's faces (polygons, corners into
 * pts) in runs, one run per convex piece.  Each piece collides as the hull of its
 * faces' points; a source without faces is one piece, the hull of all its points.  The points are distinct
 * and in a canonical order (the maker sorts them), so that the same points give
 * the same hull to the bit whatever order or format they came in.  It never
 * changes once made.  A body owns the one of its parameters (body.h); shapes
 * built from it borrow it.  release frees it (shape_source_release). */
typedef struct shape_source {
    int np;
    vec3 *pts;
    mesh draw;
    int nf;               /* faces: face f's corners are corner[face_first[f] ..
                           * face_first[f + 1] - 1]; 0: none */
    int *face_first;      /* nf + 1 offsets */
    int *corner;          /* each corner's point (into pts) */
    int npieces;          /* runs of faces: piece k's are piece_first[k] ..
                           * piece_first[k + 1] - 1; 0 or 1: one piece */
    int *piece_first;     /* npieces + 1 offsets */
    void (*release)(struct shape_source *src);
} shape_source;

/* Frees src through its release function (nothing for NULL). */
static inline void shape_source_release(shape_source *src)
{
    if (src) src->release(src);
}

typedef struct {
    shape_kind kind;
    double radius;           /* sphere */
    vec3 size;               /* cube half-extents */
    double exp1, exp2;       /* superquadric exponents */
    double a1, a2, a3;       /* superquadric radii */
    int ures, vres;          /* sphere and superquadric resolutions */
    vec3 scale;              /* polyhedron: its source's units into metres (each > 0) */
    shape_source *src;       /* polyhedron: its geometry; NULL: the box a new cube
                              * is, scaled */
    double thickness;        /* polyhedron: a static open piece's slabs, m (> 0) */
    bool fixed;              /* polyhedron: static, so that a piece whose faces do
                              * not close a volume becomes one slab per face */
} shape_params;

/* One convex piece of a shape of several (a rigid union: shape.pieces > 1), in
 * the body frame. */
typedef struct {
    poly *hull;
    closest_hull *feat;
    vec3 box_lo, box_hi; /* its box, in body axes */
    vec3 c;              /* the centre of that box, and the radius about it that */
    double r;            /*   holds the piece */
    int face0;           /* its first face in the shape's numbering of faces (the
                          * pieces' faces one after another) */
} shape_piece;

/* How a polyhedron's mass properties were found (shape.mass_from). */
typedef enum {
    MASS_HULL,   /* its one convex piece's hull (a primitive's: its own) */
    MASS_MESH,   /* the closed, consistently oriented mesh: signed tetrahedra */
    MASS_PIECES  /* the union of its pieces' hulls: overlaps counted twice */
} mass_source;

typedef struct {
    shape_params p;
    poly *hull;          /* collision polyhedron; NULL for a sphere */
    mesh draw;           /* what the renderer draws */
    bool draw_borrowed;  /* draw is the source's own (a polyhedron at scale 1) */
    int pieces;          /* convex pieces it collides as */
    shape_piece *piece;  /* pieces > 1: each piece; hull and feat are then the
                          * hull of them all (a bound, never used with the
                          * features of a query: those name their piece) */
    int nfaces;          /* faces of its pieces together (shape_face) */
    mass_source mass_from;
    int slabs;           /* pieces that are slabs of a static open piece's faces */
    mass_props mass;     /* unit density, body frame */
    double r_in, r_out;  /* inscribed and circumscribed radius about mass.com */
    vec3 box_lo, box_hi; /* the box, in body axes, that holds the shape */
    closest_hull *feat;  /* closest_hull_new(hull), NULL for a sphere */
} shape;

/* The thesis's defaults for a primitive of the given kind: radius 1, size (1,1,1),
 * exponents 1, a1..a3 1, resolutions 10; scale (1,1,1), no source, thickness
 * 0.02 m. */
shape_params shape_defaults(shape_kind kind);

/* Builds s from p (s need not be initialised).  Returns 0, or -1 with a message in
 * err (then s holds nothing to free).  Parameters are assumed validated: positive
 * sizes, exponents > 0, resolutions >= 3, scale components within core/limits.h's
 * lengths.  A polyhedron's points, scaled, must lie within LIM_LENGTH_MAX of its
 * origin on each axis.  Each of its pieces collides as the exact convex hull of
 * its points (poly_hull_merge at angle 0), which must not lie in one plane; but a
 * fixed (static) piece whose faces do not close a volume becomes one slab per
 * face instead, `thickness` deep behind it (opposite its normal).  Mass
 * properties: one convex piece's are its hull's; else the signed tetrahedra sum
 * of the source's faces when they close consistently oriented volumes (every
 * edge run once each way), else the sum over the pieces' hulls (mass_from). */
int shape_build(shape *s, const shape_params *p, char *err, size_t errlen);

void shape_free(shape *s);

/* The drawn triangles of s that do not lie on its collision hull's surface (their
 * plane, either way round, is not a supporting plane of the hull within 1e-6 of
 * r_out): none for a convex mesh, some for a concave one, which collides as its
 * hull.  0 for a sphere. */
long shape_off_hull(const shape *s);

/* The hull of piece k of s (its own hull when it has one piece). */
static inline const poly *shape_piece_hull(const shape *s, int k)
{
    return s->pieces > 1 ? s->piece[k].hull : s->hull;
}

/* Face `face` of s in its numbering of faces (the pieces' one after another):
 * the piece's hull, and the face's index in it in *local; NULL when there is no
 * such face. */
const poly *shape_face(const shape *s, int face, int *local);

/* The piece face `face` of s is on (its index in that piece in *local), or -1
 * when there is no such face. */
int shape_face_piece(const shape *s, int face, int *local);

/* The number, in s's numbering, of face `local` of piece k. */
static inline int shape_face_number(const shape *s, int k, int local)
{
    return s->pieces > 1 ? s->piece[k].face0 + local : local;
}

/* s placed with body frame to world p -> q p q* + x, as closest-feature queries
 * take it. */
static inline closest_proxy shape_proxy(const shape *s, vec3 x, quat q)
{
    return (closest_proxy){s->hull, s->feat, s->p.radius, s->mass.com, x, q};
}

/* Points of the superquadric's ures x vres tessellation (the two poles once each,
 * (vres - 1) rings of ures points): writes at most max points, returns the count. */
int superquadric_points(const shape_params *p, vec3 *out, int max);

#endif
