/* support.h: the vertex of a large hull furthest along a direction, in time that
 * grows with the log of its vertices (a Dobkin-Kirkpatrick hierarchy).
 *
 * A hill climb over a hull's vertex graph from a fixed vertex takes about sqrt(n)
 * steps on a tessellation of n vertices (a 160 x 160 superquadric: about 80).  The
 * hierarchy (Dobkin and Kirkpatrick 1990, "Determining the separation of
 * preprocessed polyhedra: a unified approach"; O'Rourke, "Computational Geometry in
 * C", 7.10) keeps coarser and coarser hulls: each level is the convex hull of the
 * level below less an independent set of its vertices of low degree, down to a few
 * vertices.  The furthest vertex of the top is found by looking at all of them;
 * going down, the furthest vertex of the level below is the one found or one of its
 * removed neighbours (any neighbour further on was removed, so its own neighbours
 * were all kept, and it is a local, so global, maximum).  Each level's step is a
 * climb from the vertex found above (poly_climb), which is that lemma when the
 * levels are exact hulls and stays right (a climb on a convex hull ends at its
 * furthest vertex) wherever qhull left a coplanar vertex out of a level.  Built
 * once per shape, for hulls of more than SUPPORT_MIN_VERTICES vertices.
 */
#ifndef VROC_SUPPORT_H
#define VROC_SUPPORT_H

#include "poly.h"
#include "vmath.h"

/* Hulls of at most this many vertices get no hierarchy: a climb is as short. */
#define SUPPORT_MIN_VERTICES 512

typedef struct support_tree support_tree;

/* The hierarchy of p (which must outlive it), or NULL when p has at most
 * SUPPORT_MIN_VERTICES vertices or memory or qhull failed: support_vertex then
 * climbs from vertex 0. */
support_tree *support_tree_new(const poly *p);
void support_tree_free(support_tree *t);

/* The vertex of p furthest along d: a vertex no other is further along d than (on
 * ties, the one the descent reaches).  t is p's hierarchy, or NULL. */
int support_vertex(const support_tree *t, const poly *p, vec3 d);

#endif
