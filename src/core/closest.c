/* closest.c: closest features, distance and penetration between two convex objects
 * (thesis 3.2.1; Lin and Canny 1991; Mirtich, "V-Clip: fast and robust polyhedral
 * collision detection", ACM TOG 17(3), 1998).
 *
 * Voronoi regions.  Every feature X of a convex polyhedron owns the region of space
 * whose closest point on the polyhedron lies on X, bounded by planes each with a
 * neighbouring feature on its far side:
 *   vertex v: for each edge e at v, the plane through v perpendicular to e (nb e);
 *   edge e:   the planes perpendicular to e at its tail and head (nb the vertices),
 *             and for each of its two faces the plane through e perpendicular to the
 *             face (nb the face);
 *   face f:   for each edge of f the plane through it perpendicular to f (nb the
 *             edge); the region also lies above f's plane (tested separately).
 * Each plane is stored once per edge (closest_hull) and shared with opposite signs by
 * the two regions it separates, so no point is left in a gap by rounding.
 *
 * The walk (V-Clip).  A state is a pair of features (V,V), (V,E), (E,E), (V,F) or
 * (E,F) and its mirror images.  Each state either proves the pair closest (every
 * closest point of one lies in the other's region; (E,F) never does), finds the
 * objects penetrating, or moves one feature to a neighbour so that the distance
 * between the features drops, or stays equal while a feature's dimension drops; so
 * the walk cannot cycle.  An edge is tested against a region by clipping it against
 * the region's planes and, where it leaves through a plane, by the sign of the
 * derivative of its distance to the feature there ("derivative checks").  A vertex
 * under a face with no edge leading up to it is a local minimum: all faces are
 * scanned, and either the vertex is inside the other polyhedron (penetration) or the
 * walk jumps to the face it is furthest above.  Two choices differ from the paper's
 * pseudocode, both keeping the distance-or-dimension descent: an edge that misses a
 * face's region makes the face's nearest boundary edge the new feature (found over
 * the face's edges), and an edge that misses an edge's region through two planes
 * moves to the neighbour beyond which the edges' closest point lies.
 *
 * Tests use a small tolerance (1e-12 of the scene's size) so that decisions on
 * exactly degenerate input (parallel faces, a vertex on a region boundary) are taken
 * the same way in both frames; the distance errors this allows are second order, or
 * 1e-12 relative.  A walk longer than its step bound is a fault (rounding beating the
 * theory): the query is redone from scratch, then by brute force, and flagged in the
 * result.  Without a cache the walk starts from the vertices furthest towards each
 * other along the line between the centres, found by hill climbing (on a large
 * hull, down a Dobkin-Kirkpatrick hierarchy: support.h).
 *
 * Touching and penetration.  When the walk ends at distance 0, or finds an edge
 * through a face or a vertex inside, the objects are touching if some direction
 * separates them: the face normals of both and the cross products of the edges at
 * the final features (support points by hill climbing, faces in depth-first order
 * so that each climb is short); else the smallest overlap along those directions is
 * the penetration estimate.  Spheres: sphere-sphere and sphere-box are closed
 * forms; a sphere and any other polyhedron is the walk with the sphere's centre as a
 * point (a vertex without edges), then minus the radius; a centre inside gives the
 * exact depth from the nearest face.
 *
 * Geometry is computed in the body frames: to test a feature of B against a region of
 * A, B's points are carried into A's frame (m[0] x + t[0]), and back (m[1], t[1]).
 */
#include "closest.h"

#include <stdlib.h>
#include <string.h>

#include "support.h"

#define EPS_REL 1e-12 /* length tolerance, relative to the scene's size */
#define EPS_DIR 1e-12 /* tolerance on cosines between unit vectors */

/* ---- per-polyhedron data ---- */

struct closest_hull {
    const poly *p;
    vec3 *eu;         /* unit direction of edge e, tail to head */
    double *elen;     /* its length */
    double (*eud)[2]; /* eu . tail, eu . head */
    vec3 (*ew)[2];    /* ew[e][s]: unit, in the plane of face e.f[s], perpendicular to e,
                         pointing into the face */
    double (*ewd)[2]; /* ew[e][s] . tail */
    int *face_order;  /* the faces in depth-first order over shared edges, so that
                         consecutive faces are mostly neighbours (support climbs) */
    support_tree *top; /* large hulls: the furthest vertex along a direction in log
                          time (a scratch walk's start), else NULL */
    double size;      /* largest |vertex| */
    double r_in;      /* a ball of this radius about the origin lies inside (-HUGE_VAL
                         when the origin is not inside) */
    /* an axis-aligned box (a cube's hull): sphere-box is then closed-form */
    bool box;
    vec3 lo, hi;
    int box_face[3][2]; /* face with outward normal -e_i (0) or +e_i (1) */
    int box_vert[8];    /* vertex with coordinate i high when bit i is set */
    int box_edge[3][4]; /* edge along axis i; bit 0: axis i+1 high, bit 1: axis i+2 high */
};

/* Recognises an axis-aligned box and fills its lookup tables. */
static void hull_find_box(closest_hull *h)
{
    const poly *p = h->p;
    h->box = false;
    if (p->nv != 8 || p->ne != 12 || p->nf != 6) return;
    h->lo = h->hi = p->v[0];
    for (int v = 1; v < 8; v++) {
        h->lo = v3_min(h->lo, p->v[v]);
        h->hi = v3_max(h->hi, p->v[v]);
    }
    for (int i = 0; i < 3; i++)
        if (!(v3_comp(h->hi, i) > v3_comp(h->lo, i))) return;
    for (int v = 0; v < 8; v++) {
        int bits = 0;
        for (int i = 0; i < 3; i++) {
            double c = v3_comp(p->v[v], i);
            if (c == v3_comp(h->hi, i)) bits |= 1 << i;
            else if (c != v3_comp(h->lo, i)) return;
        }
        h->box_vert[bits] = v;
    }
    for (int f = 0; f < 6; f++) {
        vec3 n = p->f[f].n;
        int i = fabs(n.x) > 0.5 ? 0 : fabs(n.y) > 0.5 ? 1 : 2;
        if (fabs(fabs(v3_comp(n, i)) - 1) > 1e-12) return;
        h->box_face[i][v3_comp(n, i) > 0] = f;
    }
    for (int e = 0; e < 12; e++) {
        vec3 a = p->v[p->e[e].v[0]], b = p->v[p->e[e].v[1]];
        int i = a.x != b.x ? 0 : a.y != b.y ? 1 : 2;
        int j = (i + 1) % 3, k = (i + 2) % 3;
        int bits = (v3_comp(a, j) == v3_comp(h->hi, j)) | (v3_comp(a, k) == v3_comp(h->hi, k)) << 1;
        h->box_edge[i][bits] = e;
    }
    h->box = true;
}

/* Depth-first order of the faces over shared edges (order has nf entries). */
static int hull_face_order(const poly *p, int *order)
{
    char *seen = calloc((size_t)p->nf, 1);
    int *stack = malloc((size_t)(p->nf + 2 * p->ne + 1) * sizeof *stack);
    if (!seen || !stack) {
        free(seen);
        free(stack);
        return -1;
    }
    int n = 0, top = 0;
    stack[top++] = 0;
    while (top > 0) {
        int f = stack[--top];
        if (seen[f]) continue;
        seen[f] = 1;
        order[n++] = f;
        for (int j = p->f[f].count - 1; j >= 0; j--) {
            const poly_edge *e = &p->e[p->face_edge[p->f[f].first + j]];
            int g = e->f[0] == f ? e->f[1] : e->f[0];
            if (!seen[g]) stack[top++] = g;
        }
    }
    for (int f = 0; f < p->nf; f++) /* (a valid polyhedron is connected) */
        if (!seen[f]) order[n++] = f;
    free(seen);
    free(stack);
    return 0;
}

closest_hull *closest_hull_new(const poly *p)
{
    closest_hull *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    h->p = p;
    size_t ne = (size_t)(p->ne > 0 ? p->ne : 1);
    h->eu = malloc(ne * sizeof *h->eu);
    h->eud = malloc(ne * sizeof *h->eud);
    h->elen = malloc(ne * sizeof *h->elen);
    h->ew = malloc(ne * sizeof *h->ew);
    h->ewd = malloc(ne * sizeof *h->ewd);
    h->face_order = malloc((size_t)(p->nf > 0 ? p->nf : 1) * sizeof *h->face_order);
    if (!h->eu || !h->elen || !h->eud || !h->ew || !h->ewd || !h->face_order ||
        hull_face_order(p, h->face_order) < 0) {
        closest_hull_free(h);
        return NULL;
    }
    /* the nearest face plane, a little nearer for the rounding of the planes */
    h->r_in = HUGE_VAL;
    for (int f = 0; f < p->nf; f++) h->r_in = d_min(h->r_in, p->f[f].d);
    h->r_in = h->r_in > 0 && p->nf > 0 ? h->r_in * (1 - 1e-9) : -HUGE_VAL;
    for (int e = 0; e < p->ne; e++) {
        vec3 t = p->v[p->e[e].v[0]], hd = p->v[p->e[e].v[1]];
        vec3 u = v3_norm(v3_sub(hd, t));
        h->eu[e] = u;
        h->elen[e] = v3_dist(hd, t);
        h->eud[e][0] = v3_dot(u, t);
        h->eud[e][1] = v3_dot(u, hd);
        /* the left face is walked tail -> head ccw: its inside is n x u */
        h->ew[e][0] = v3_norm(v3_cross(p->f[p->e[e].f[0]].n, u));
        h->ew[e][1] = v3_norm(v3_cross(u, p->f[p->e[e].f[1]].n));
        h->ewd[e][0] = v3_dot(h->ew[e][0], t);
        h->ewd[e][1] = v3_dot(h->ew[e][1], t);
    }
    for (int v = 0; v < p->nv; v++) h->size = fmax(h->size, v3_len(p->v[v]));
    hull_find_box(h);
    h->top = support_tree_new(p); /* (NULL: climbs, as short for small hulls) */
    return h;
}

void closest_hull_free(closest_hull *h)
{
    if (!h) return;
    free(h->eu);
    free(h->elen);
    free(h->eud);
    free(h->ew);
    free(h->ewd);
    free(h->face_order);
    support_tree_free(h->top);
    free(h);
}

int closest_hull_support(const closest_hull *h, vec3 d)
{
    return support_vertex(h->top, h->p, d);
}

const char *closest_kind_name(closest_kind k)
{
    switch (k) {
    case CLOSEST_VERTEX: return "vertex";
    case CLOSEST_EDGE: return "edge";
    case CLOSEST_FACE: return "face";
    case CLOSEST_SPHERE: return "sphere";
    default: return "none";
    }
}

/* ---- region planes: a point x is outside when n . x - d > 0 ---- */

typedef struct {
    vec3 n;
    double d;
    closest_feature nb; /* the neighbour beyond the plane */
} plane;

static inline closest_feature feat(closest_kind k, int i) { return (closest_feature){k, i}; }

static inline int vert_degree(const poly *p, int v) { return p->vert_first[v + 1] - p->vert_first[v]; }

/* j-th plane of vertex v's region: perpendicular to its j-th edge. */
static inline plane vertex_plane(const closest_hull *h, int v, int j)
{
    int e = h->p->vert_edge[h->p->vert_first[v] + j];
    if (h->p->e[e].v[0] == v) return (plane){h->eu[e], h->eud[e][0], feat(CLOSEST_EDGE, e)};
    return (plane){v3_neg(h->eu[e]), -h->eud[e][1], feat(CLOSEST_EDGE, e)};
}

/* Planes of edge e's region: 0 tail, 1 head, 2 and 3 its left and right face. */
static inline plane edge_plane(const closest_hull *h, int e, int j)
{
    const poly_edge *E = &h->p->e[e];
    switch (j) {
    case 0: return (plane){v3_neg(h->eu[e]), -h->eud[e][0], feat(CLOSEST_VERTEX, E->v[0])};
    case 1: return (plane){h->eu[e], h->eud[e][1], feat(CLOSEST_VERTEX, E->v[1])};
    default: return (plane){h->ew[e][j - 2], h->ewd[e][j - 2], feat(CLOSEST_FACE, E->f[j - 2])};
    }
}

/* j-th side plane of face f's region (through its j-th edge). */
static inline plane face_plane(const closest_hull *h, int f, int j)
{
    int e = h->p->face_edge[h->p->f[f].first + j];
    int s = h->p->e[e].f[0] == f ? 0 : 1;
    return (plane){v3_neg(h->ew[e][s]), -h->ewd[e][s], feat(CLOSEST_EDGE, e)};
}

static inline double plane_out(plane pl, vec3 x) { return v3_dot(pl.n, x) - pl.d; }

/* ---- small geometry ---- */

static inline double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

/* Parameter of the point of segment a-b closest to x. */
static inline double seg_point(vec3 a, vec3 b, vec3 x)
{
    vec3 d = v3_sub(b, a);
    double l2 = v3_len2(d);
    return l2 > 0 ? clamp01(v3_dot(v3_sub(x, a), d) / l2) : 0;
}

/* Parameters s, t of the closest points of segments p0-p1 and q0-q1 (Ericson,
 * Real-Time Collision Detection 5.1.9); parallel segments give the middle of the
 * overlap of their projections. */
static void seg_seg(vec3 p0, vec3 p1, vec3 q0, vec3 q1, double *s_out, double *t_out)
{
    vec3 d1 = v3_sub(p1, p0), d2 = v3_sub(q1, q0), r = v3_sub(p0, q0);
    double a = v3_len2(d1), e = v3_len2(d2), f = v3_dot(d2, r);
    double c = v3_dot(d1, r), b = v3_dot(d1, d2);
    double s, t;
    if (!(a > 0) || !(e > 0)) {
        s = a > 0 ? clamp01(-c / a) : 0;
        t = e > 0 ? clamp01((b * s + f) / e) : 0;
        *s_out = s;
        *t_out = t;
        return;
    }
    double denom = a * e - b * b;
    if (denom > 1e-14 * a * e) {
        s = clamp01((b * f - c * e) / denom);
    } else { /* parallel: q0, q1 at u0, u1 along p */
        double u0 = -c / a, u1 = (b - c) / a;
        double lo = d_max(0, d_min(u0, u1)), hi = d_min(1, d_max(u0, u1));
        s = lo <= hi ? 0.5 * (lo + hi) : (d_max(u0, u1) < 0 ? 0 : 1);
    }
    t = (b * s + f) / e;
    if (t < 0) {
        t = 0;
        s = clamp01(-c / a);
    } else if (t > 1) {
        t = 1;
        s = clamp01((b - c) / a);
    }
    *s_out = s;
    *t_out = t;
}

static double seg_seg_dist2(vec3 p0, vec3 p1, vec3 q0, vec3 q1)
{
    double s, t;
    seg_seg(p0, p1, q0, q1, &s, &t);
    return v3_len2(v3_sub(v3_lerp(p0, p1, s), v3_lerp(q0, q1, t)));
}

/* ---- the walk ---- */

enum { W_CONTINUE, W_DONE, W_PENETRATION, W_FAULT };

typedef struct {
    const poly *p[2];         /* NULL: a point (a sphere's centre) at its frame's origin */
    const closest_hull *h[2];
    mat3 R[2];                /* body k to world: R[k] x + X[k] */
    vec3 X[2];
    mat3 m[2];                /* frame 1-k to frame k: m[k] x + t[k] */
    vec3 t[2];
    double eps;               /* length tolerance */
    closest_feature f[2];     /* current features; a point is vertex 0 */
    int steps;
} walk;

static inline vec3 to(const walk *w, int k, vec3 x) { return v3_add(m3_mulv(w->m[k], x), w->t[k]); }
static inline vec3 dir_to(const walk *w, int k, vec3 d) { return m3_mulv(w->m[k], d); }
static inline vec3 world(const walk *w, int k, vec3 x) { return v3_add(m3_mulv(w->R[k], x), w->X[k]); }
static inline vec3 vpos(const walk *w, int k, int i) { return w->p[k] ? w->p[k]->v[i] : v3(0, 0, 0); }

typedef struct {
    double lo, hi;
    closest_feature nlo, nhi; /* the planes that set lo and hi (kind NONE: the ends) */
    bool simple;              /* excluded entirely by one plane */
} clip;

static inline clip clip_start(void) { return (clip){0, 1, {CLOSEST_NONE, 0}, {CLOSEST_NONE, 0}, false}; }

/* Clips segment a-b (parameters lo..hi) against one plane of a region; returns false
 * when nothing is left. */
static inline bool clip_plane(clip *c, vec3 a, vec3 b, plane pl, double eps)
{
    double sa = plane_out(pl, a) - eps, sb = plane_out(pl, b) - eps;
    if (sa > 0 && sb > 0) {
        c->nlo = c->nhi = pl.nb;
        c->simple = true;
        return false;
    }
    if (sa > 0) {
        double l = sa / (sa - sb);
        if (l > c->lo) {
            c->lo = l;
            c->nlo = pl.nb;
        }
    } else if (sb > 0) {
        double l = sa / (sa - sb);
        if (l < c->hi) {
            c->hi = l;
            c->nhi = pl.nb;
        }
    }
    return c->lo <= c->hi;
}

/* Sign (+1, -1, or 0 within tolerance) of the derivative along a-b (of length len),
 * at parameter l, of the distance from the segment's point to vertex position v. */
static inline int deriv_vertex(vec3 a, vec3 b, double len, double l, vec3 v, double eps)
{
    double g = v3_dot(v3_sub(b, a), v3_sub(v3_lerp(a, b, l), v)); /* len times the rate */
    return g > eps * len ? 1 : g < -eps * len ? -1 : 0;
}

/* The same for the distance to the plane of face f of poly p. */
static inline int deriv_face(const poly *p, int f, vec3 a, vec3 b, double len, double l, double eps)
{
    const poly_face *F = &p->f[f];
    double dist = v3_dot(F->n, v3_lerp(a, b, l)) - F->d;
    double slope = v3_dot(v3_sub(b, a), F->n); /* len times the rate */
    if (fabs(dist) <= eps || fabs(slope) <= EPS_DIR * len) return 0;
    return (dist > 0) == (slope > 0) ? 1 : -1;
}

/* Derivative along a-b (in frame s) of the distance to neighbour feature nb of poly s. */
static inline int deriv_nb(const walk *w, int s, closest_feature nb, vec3 a, vec3 b, double len, double l)
{
    if (nb.kind == CLOSEST_VERTEX) return deriv_vertex(a, b, len, l, w->p[s]->v[nb.index], w->eps);
    return deriv_face(w->p[s], nb.index, a, b, len, l, w->eps);
}

static int state_vv(walk *w)
{
    for (int s = 0; s < 2; s++) {
        if (!w->p[s]) continue; /* a point's region is all of space */
        int o = 1 - s, v = w->f[s].index;
        vec3 x = to(w, s, vpos(w, o, w->f[o].index));
        double best = w->eps;
        int bj = -1;
        for (int j = 0; j < vert_degree(w->p[s], v); j++) {
            double out = plane_out(vertex_plane(w->h[s], v, j), x);
            if (out > best) {
                best = out;
                bj = j;
            }
        }
        if (bj >= 0) {
            w->f[s] = vertex_plane(w->h[s], v, bj).nb;
            return W_CONTINUE;
        }
    }
    return W_DONE;
}

/* Vertex on side k, edge on the other. */
static int state_ve(walk *w, int k)
{
    int o = 1 - k, v = w->f[k].index, e = w->f[o].index;
    const closest_hull *he = w->h[o];
    vec3 x = to(w, o, vpos(w, k, v));
    for (int j = 0; j < 2; j++) {
        plane pl = edge_plane(he, e, j);
        if (plane_out(pl, x) > w->eps) {
            w->f[o] = pl.nb;
            return W_CONTINUE;
        }
    }
    double best = w->eps;
    int bj = -1;
    for (int j = 2; j < 4; j++) {
        double out = plane_out(edge_plane(he, e, j), x);
        if (out > best) {
            best = out;
            bj = j;
        }
    }
    if (bj >= 0) {
        w->f[o] = edge_plane(he, e, bj).nb;
        return W_CONTINUE;
    }
    if (!w->p[k]) return W_DONE;
    /* clip the edge against the vertex's region */
    const poly_edge *E = &w->p[o]->e[e];
    vec3 a = to(w, k, w->p[o]->v[E->v[0]]), b = to(w, k, w->p[o]->v[E->v[1]]);
    vec3 vp = w->p[k]->v[v];
    double len = w->h[o]->elen[e];
    clip c = clip_start();
    bool in = true;
    for (int j = 0; j < vert_degree(w->p[k], v) && in; j++)
        in = clip_plane(&c, a, b, vertex_plane(w->h[k], v, j), w->eps);
    if (!in) {
        /* the point of the edge closest to v lies beyond nlo when the distance
         * grows at lo, else beyond nhi */
        w->f[k] = c.simple || deriv_vertex(a, b, len, c.lo, vp, 0) > 0 ? c.nlo : c.nhi;
        return W_CONTINUE;
    }
    if (c.nlo.kind != CLOSEST_NONE && deriv_vertex(a, b, len, c.lo, vp, w->eps) > 0) {
        w->f[k] = c.nlo;
        return W_CONTINUE;
    }
    if (c.nhi.kind != CLOSEST_NONE && deriv_vertex(a, b, len, c.hi, vp, w->eps) < 0) {
        w->f[k] = c.nhi;
        return W_CONTINUE;
    }
    return W_DONE;
}

/* Vertex on side k below face f of side o with no edge leading up: scan o's faces.
 * x is the vertex in o's frame.  The face it is furthest above (or least below)
 * becomes the feature; penetration when that is not above. */
static int local_min(walk *w, int k, vec3 x)
{
    int o = 1 - k;
    const poly *p = w->p[o];
    double best = -INFINITY;
    int bf = 0;
    for (int g = 0; g < p->nf; g++) {
        double d = v3_dot(p->f[g].n, x) - p->f[g].d;
        if (d > best) {
            best = d;
            bf = g;
        }
    }
    w->f[o] = feat(CLOSEST_FACE, bf);
    return best <= w->eps ? W_PENETRATION : W_CONTINUE;
}

/* Vertex on side k, face on the other. */
static int state_vf(walk *w, int k)
{
    int o = 1 - k, v = w->f[k].index, f = w->f[o].index;
    const poly_face *F = &w->p[o]->f[f];
    vec3 x = to(w, o, vpos(w, k, v));
    double best = w->eps;
    int bj = -1;
    for (int j = 0; j < F->count; j++) {
        double out = plane_out(face_plane(w->h[o], f, j), x);
        if (out > best) {
            best = out;
            bj = j;
        }
    }
    if (bj >= 0) {
        w->f[o] = face_plane(w->h[o], f, bj).nb;
        return W_CONTINUE;
    }
    double dv = v3_dot(F->n, x) - F->d;
    if (w->p[k]) { /* an edge of v leading towards the face's plane */
        vec3 nk = dir_to(w, k, F->n);
        double most = EPS_DIR;
        int bj2 = -1;
        for (int j = 0; j < vert_degree(w->p[k], v); j++) {
            double slope = v3_dot(nk, vertex_plane(w->h[k], v, j).n);
            double towards = dv > 0 ? -slope : slope;
            if (towards > most) {
                most = towards;
                bj2 = j;
            }
        }
        if (bj2 >= 0) {
            w->f[k] = vertex_plane(w->h[k], v, bj2).nb;
            return W_CONTINUE;
        }
    }
    if (dv > 0) return W_DONE;
    return local_min(w, k, x);
}

/* E_o (a-b in frame s) left edge e of side s's region through two planes: the new
 * feature of side s is the neighbour whose plane the point of E_o closest to e is
 * beyond (a vertex first: equal distance, lower dimension; else the face most
 * beyond: smaller distance).  fallback if rounding finds none. */
static closest_feature ee_compound(const walk *w, int s, vec3 a, vec3 b, closest_feature fallback)
{
    const poly *p = w->p[s];
    int e = w->f[s].index;
    double sp, tp;
    seg_seg(a, b, p->v[p->e[e].v[0]], p->v[p->e[e].v[1]], &sp, &tp);
    vec3 x = v3_lerp(a, b, sp);
    for (int j = 0; j < 2; j++) {
        plane pl = edge_plane(w->h[s], e, j);
        if (plane_out(pl, x) > w->eps) return pl.nb;
    }
    double best = w->eps;
    closest_feature r = fallback;
    for (int j = 2; j < 4; j++) {
        plane pl = edge_plane(w->h[s], e, j);
        double out = plane_out(pl, x);
        if (out > best) {
            best = out;
            r = pl.nb;
        }
    }
    return r;
}

static int state_ee(walk *w)
{
    for (int s = 0; s < 2; s++) {
        int o = 1 - s, es = w->f[s].index;
        const poly_edge *Eo = &w->p[o]->e[w->f[o].index];
        vec3 a = to(w, s, w->p[o]->v[Eo->v[0]]), b = to(w, s, w->p[o]->v[Eo->v[1]]);
        double len = w->h[o]->elen[w->f[o].index];
        clip c = clip_start();
        /* the vertex planes of es's region first, then its face planes */
        for (int stage = 0; stage < 2; stage++) {
            bool in = clip_plane(&c, a, b, edge_plane(w->h[s], es, 2 * stage), w->eps) &&
                      clip_plane(&c, a, b, edge_plane(w->h[s], es, 2 * stage + 1), w->eps);
            if (!in) {
                w->f[s] = c.simple ? c.nlo : ee_compound(w, s, a, b, c.nlo);
                return W_CONTINUE;
            }
            if (c.nlo.kind != CLOSEST_NONE && deriv_nb(w, s, c.nlo, a, b, len, c.lo) > 0) {
                w->f[s] = c.nlo;
                return W_CONTINUE;
            }
            if (c.nhi.kind != CLOSEST_NONE && deriv_nb(w, s, c.nhi, a, b, len, c.hi) < 0) {
                w->f[s] = c.nhi;
                return W_CONTINUE;
            }
        }
    }
    return W_DONE;
}

/* Edge of face f (poly p) closest to segment a-b (in p's frame). */
static int face_edge_closest(const poly *p, int f, vec3 a, vec3 b)
{
    double best = INFINITY;
    int be = p->face_edge[p->f[f].first];
    for (int j = 0; j < p->f[f].count; j++) {
        int e = p->face_edge[p->f[f].first + j];
        double d2 = seg_seg_dist2(a, b, p->v[p->e[e].v[0]], p->v[p->e[e].v[1]]);
        if (d2 < best) {
            best = d2;
            be = e;
        }
    }
    return be;
}

/* Edge on side k, face on the other.  Never final: the edge crosses the face
 * (penetration), or one end of the clipped edge is the nearer to the face's plane
 * and the walk moves to the face's edge there, or to the edge's vertex there. */
static int state_ef(walk *w, int k)
{
    int o = 1 - k, e = w->f[k].index, f = w->f[o].index;
    const poly *pe = w->p[k], *pf = w->p[o];
    const poly_edge *E = &pe->e[e];
    vec3 a = to(w, o, pe->v[E->v[0]]), b = to(w, o, pe->v[E->v[1]]);
    clip c = clip_start();
    bool in = true;
    for (int j = 0; j < pf->f[f].count && in; j++)
        in = clip_plane(&c, a, b, face_plane(w->h[o], f, j), w->eps);
    if (!in) {
        w->f[o] = feat(CLOSEST_EDGE, face_edge_closest(pf, f, a, b));
        return W_CONTINUE;
    }
    const poly_face *F = &pf->f[f];
    double dl = v3_dot(F->n, v3_lerp(a, b, c.lo)) - F->d;
    double du = v3_dot(F->n, v3_lerp(a, b, c.hi)) - F->d;
    if (d_min(dl, du) <= w->eps && d_max(dl, du) >= -w->eps) return W_PENETRATION;
    double slope = v3_dot(v3_sub(b, a), F->n); /* len times the rate */
    if (dl < 0) slope = -slope;                 /* below the plane the distance is -d */
    if (slope >= -EPS_DIR * w->h[k]->elen[e]) { /* nearest at lo (ties too) */
        if (c.nlo.kind != CLOSEST_NONE) w->f[o] = c.nlo;
        else w->f[k] = feat(CLOSEST_VERTEX, E->v[0]);
    } else {
        if (c.nhi.kind != CLOSEST_NONE) w->f[o] = c.nhi;
        else w->f[k] = feat(CLOSEST_VERTEX, E->v[1]);
    }
    return W_CONTINUE;
}

/* Two faces only come from a cache given from outside: start from a vertex. */
static int state_ff(walk *w)
{
    const poly *p = w->p[0];
    w->f[0] = feat(CLOSEST_VERTEX, p->face_vert[p->f[w->f[0].index].first]);
    return W_CONTINUE;
}

static int walk_run(walk *w, int max_steps)
{
    for (;;) {
        if (w->steps >= max_steps) return W_FAULT;
        w->steps++;
        closest_kind ka = w->f[0].kind, kb = w->f[1].kind;
        int r;
        if (ka == CLOSEST_VERTEX && kb == CLOSEST_VERTEX) r = state_vv(w);
        else if (ka == CLOSEST_VERTEX && kb == CLOSEST_EDGE) r = state_ve(w, 0);
        else if (ka == CLOSEST_EDGE && kb == CLOSEST_VERTEX) r = state_ve(w, 1);
        else if (ka == CLOSEST_VERTEX && kb == CLOSEST_FACE) r = state_vf(w, 0);
        else if (ka == CLOSEST_FACE && kb == CLOSEST_VERTEX) r = state_vf(w, 1);
        else if (ka == CLOSEST_EDGE && kb == CLOSEST_EDGE) r = state_ee(w);
        else if (ka == CLOSEST_EDGE && kb == CLOSEST_FACE) r = state_ef(w, 0);
        else if (ka == CLOSEST_FACE && kb == CLOSEST_EDGE) r = state_ef(w, 1);
        else r = state_ff(w);
        if (r != W_CONTINUE) return r;
    }
}

/* ---- brute force: the last resort after a faulty walk ---- */

/* Smallest vertex-face (the vertex over the face) and edge-edge distance; the
 * features go to w->f.  With a point (side 1), W_PENETRATION when it is inside.
 * O(size of A x size of B). */
static int brute_force(walk *w)
{
    double best = INFINITY;
    if (!w->p[1]) { /* a point: inside when under every face */
        int f0 = w->f[0].kind == CLOSEST_FACE ? w->f[0].index : 0;
        w->f[0] = feat(CLOSEST_FACE, f0);
        w->f[1] = feat(CLOSEST_VERTEX, 0);
        if (local_min(w, 1, w->t[0]) == W_PENETRATION) return W_PENETRATION;
    }
    for (int s = 0; s < 2; s++) {
        int o = 1 - s;
        const poly *ps = w->p[s], *po = w->p[o];
        int nvo = po ? po->nv : 1;
        for (int v = 0; v < nvo; v++) {
            vec3 x = to(w, s, vpos(w, o, v));
            for (int f = 0; f < ps->nf; f++) {
                double d = v3_dot(ps->f[f].n, x) - ps->f[f].d;
                if (!(d >= 0 && d < best)) continue;
                bool inside = true;
                for (int j = 0; j < ps->f[f].count && inside; j++)
                    inside = plane_out(face_plane(w->h[s], f, j), x) <= 0;
                if (!inside) continue;
                best = d;
                w->f[s] = feat(CLOSEST_FACE, f);
                w->f[o] = feat(CLOSEST_VERTEX, v);
            }
        }
        if (!po) break;
    }
    if (w->p[1]) {
        for (int e0 = 0; e0 < w->p[0]->ne; e0++) {
            const poly_edge *E0 = &w->p[0]->e[e0];
            vec3 a0 = w->p[0]->v[E0->v[0]], b0 = w->p[0]->v[E0->v[1]];
            for (int e1 = 0; e1 < w->p[1]->ne; e1++) {
                const poly_edge *E1 = &w->p[1]->e[e1];
                vec3 a1 = to(w, 0, w->p[1]->v[E1->v[0]]), b1 = to(w, 0, w->p[1]->v[E1->v[1]]);
                double d = sqrt(seg_seg_dist2(a0, b0, a1, b1));
                if (d < best) {
                    best = d;
                    w->f[0] = feat(CLOSEST_EDGE, e0);
                    w->f[1] = feat(CLOSEST_EDGE, e1);
                }
            }
        }
    } else { /* a point: its distance to the edges */
        for (int e0 = 0; e0 < w->p[0]->ne; e0++) {
            const poly_edge *E0 = &w->p[0]->e[e0];
            vec3 a0 = w->p[0]->v[E0->v[0]], b0 = w->p[0]->v[E0->v[1]], x = w->t[0];
            double d = v3_dist(v3_lerp(a0, b0, seg_point(a0, b0, x)), x);
            if (d < best) {
                best = d;
                w->f[0] = feat(CLOSEST_EDGE, e0);
                w->f[1] = feat(CLOSEST_VERTEX, 0);
            }
        }
    }
    return W_DONE; /* for two polyhedra the caller certifies the separation */
}

/* ---- results ---- */

/* Closest points (world) of the current feature pair: p[k] on side k; normal from
 * side 1 to side 0 when the features give it (a face), else zero. */
typedef struct {
    vec3 p[2];
    double dist;
    vec3 n;
} pair_geom;

static void pair_closest(const walk *w, pair_geom *g)
{
    g->n = v3(0, 0, 0);
    closest_kind ka = w->f[0].kind, kb = w->f[1].kind;
    int k, o;
    if (ka == CLOSEST_EDGE && kb == CLOSEST_EDGE) {
        const poly_edge *E0 = &w->p[0]->e[w->f[0].index], *E1 = &w->p[1]->e[w->f[1].index];
        vec3 a0 = w->p[0]->v[E0->v[0]], b0 = w->p[0]->v[E0->v[1]];
        vec3 a1 = to(w, 0, w->p[1]->v[E1->v[0]]), b1 = to(w, 0, w->p[1]->v[E1->v[1]]);
        double s, t;
        seg_seg(a0, b0, a1, b1, &s, &t);
        vec3 x0 = v3_lerp(a0, b0, s), x1 = v3_lerp(a1, b1, t);
        g->dist = v3_dist(x0, x1);
        g->p[0] = world(w, 0, x0);
        g->p[1] = world(w, 0, x1);
        return;
    }
    if (ka == CLOSEST_FACE || kb == CLOSEST_FACE) { /* vertex-face */
        k = ka == CLOSEST_FACE ? 1 : 0;
        o = 1 - k;
        const poly_face *F = &w->p[o]->f[w->f[o].index];
        vec3 x = to(w, o, vpos(w, k, w->f[k].index));
        g->dist = v3_dot(F->n, x) - F->d;
        g->p[k] = world(w, k, vpos(w, k, w->f[k].index));
        g->p[o] = world(w, o, v3_mad(x, F->n, -g->dist));
        vec3 n = m3_mulv(w->R[o], F->n);
        g->n = o == 1 ? n : v3_neg(n);
        return;
    }
    if (ka == CLOSEST_EDGE || kb == CLOSEST_EDGE) { /* vertex-edge */
        k = ka == CLOSEST_EDGE ? 1 : 0;
        o = 1 - k;
        const poly_edge *E = &w->p[o]->e[w->f[o].index];
        vec3 x = to(w, o, vpos(w, k, w->f[k].index));
        vec3 a = w->p[o]->v[E->v[0]], b = w->p[o]->v[E->v[1]];
        vec3 q = v3_lerp(a, b, seg_point(a, b, x));
        g->dist = v3_dist(x, q);
        g->p[k] = world(w, k, vpos(w, k, w->f[k].index));
        g->p[o] = world(w, o, q);
        return;
    }
    vec3 x = to(w, 0, vpos(w, 1, w->f[1].index)), v = vpos(w, 0, w->f[0].index);
    g->dist = v3_dist(x, v);
    g->p[0] = world(w, 0, v);
    g->p[1] = world(w, 1, vpos(w, 1, w->f[1].index));
}

/* (Results are filled in place: copying them through the layers by value cost more
 * than a walk step.) */
void closest_invalid(closest_result *r)
{
    memset(r, 0, sizeof *r);
    r->status = CLOSEST_INVALID;
    r->distance = NAN;
}

void closest_mirror(closest_result *r)
{
    vec3 p = r->pa;
    closest_feature f = r->fa;
    r->pa = r->pb;
    r->pb = p;
    r->fa = r->fb;
    r->fb = f;
    int k = r->ka;
    r->ka = r->kb;
    r->kb = k;
    r->normal = v3_neg(r->normal);
}

static void set_status(closest_result *r)
{
    r->status = r->distance > 0 ? CLOSEST_SEPARATED : CLOSEST_PENETRATING;
}

/* ---- setting up ---- */

static bool feature_fits(closest_feature f, const poly *p)
{
    if (!p) return f.kind == CLOSEST_SPHERE;
    switch (f.kind) {
    case CLOSEST_VERTEX: return f.index >= 0 && f.index < p->nv;
    case CLOSEST_EDGE: return f.index >= 0 && f.index < p->ne;
    case CLOSEST_FACE: return f.index >= 0 && f.index < p->nf;
    default: return false;
    }
}

static bool object_ok(const closest_proxy *o)
{
    if (!v3_finite(o->x)) return false;
    quat q = o->q;
    double q2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (!isfinite(q2) || !(q2 > 1e-300)) return false;
    return o->hull != NULL || o->radius >= 0;
}

/* *r = the rotation of q / |q| (one division, no square root).  (Matrices here are
 * written in place: copying them by value showed in the profile.) */
static inline void rot_of(quat q, mat3 *r)
{
    double s = 2.0 / (q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    double xs = q.x * s, ys = q.y * s, zs = q.z * s;
    double wx = q.w * xs, wy = q.w * ys, wz = q.w * zs;
    double xx = q.x * xs, xy = q.x * ys, xz = q.x * zs, yy = q.y * ys, yz = q.y * zs, zz = q.z * zs;
    r->m[0][0] = 1 - (yy + zz), r->m[0][1] = xy - wz, r->m[0][2] = xz + wy;
    r->m[1][0] = xy + wz, r->m[1][1] = 1 - (xx + zz), r->m[1][2] = yz - wx;
    r->m[2][0] = xz - wy, r->m[2][1] = yz + wx, r->m[2][2] = 1 - (xx + yy);
}

/* a^T v */
static inline vec3 m3_tmulv(const mat3 *a, vec3 v)
{
    return v3(a->m[0][0] * v.x + a->m[1][0] * v.y + a->m[2][0] * v.z,
              a->m[0][1] * v.x + a->m[1][1] * v.y + a->m[2][1] * v.z,
              a->m[0][2] * v.x + a->m[1][2] * v.y + a->m[2][2] * v.z);
}

/* Frames and tolerance of a walk between objects a (side 0) and b (side 1); a
 * sphere is a point.  hulls are the closest_hull of each (NULL for a sphere). */
static void walk_init(walk *w, const closest_proxy *a, const closest_proxy *b,
                      const closest_hull *ha, const closest_hull *hb)
{
    const closest_proxy *ob[2] = {a, b};
    const closest_hull *hh[2] = {ha, hb};
    double scale = 0;
    for (int k = 0; k < 2; k++) {
        w->h[k] = hh[k];
        w->p[k] = hh[k] ? hh[k]->p : NULL;
        rot_of(ob[k]->q, &w->R[k]);
        w->X[k] = ob[k]->x;
        scale += hh[k] ? hh[k]->size : ob[k]->radius;
    }
    for (int i = 0; i < 3; i++) /* m[0] = R[0]^T R[1], m[1] its transpose */
        for (int j = 0; j < 3; j++)
            w->m[1].m[j][i] = w->m[0].m[i][j] = w->R[0].m[0][i] * w->R[1].m[0][j] +
                                                w->R[0].m[1][i] * w->R[1].m[1][j] +
                                                w->R[0].m[2][i] * w->R[1].m[2][j];
    w->t[0] = m3_tmulv(&w->R[0], v3_sub(w->X[1], w->X[0]));
    w->t[1] = m3_tmulv(&w->R[1], v3_sub(w->X[0], w->X[1]));
    w->eps = EPS_REL * (scale + fabs(w->t[0].x) + fabs(w->t[0].y) + fabs(w->t[0].z));
    w->steps = 0;
}

/* Starting features without a cache: the vertices furthest towards each other
 * along the line between the centres. */
static void walk_scratch(walk *w, const closest_proxy *a, const closest_proxy *b)
{
    vec3 c0 = world(w, 0, a->com), c1 = world(w, 1, b->com);
    vec3 d = v3_sub(c1, c0);
    if (!(v3_len2(d) > 0)) d = v3(1, 0, 0);
    for (int k = 0; k < 2; k++) {
        vec3 dk = m3_tmulv(&w->R[k], k == 0 ? d : v3_neg(d));
        w->f[k] = feat(CLOSEST_VERTEX, w->p[k] ? support_vertex(w->h[k]->top, w->p[k], dk) : 0);
    }
}

static int walk_bound(const walk *w)
{
    int n = 64;
    for (int k = 0; k < 2; k++)
        if (w->p[k]) n += 2 * (w->p[k]->nv + w->p[k]->nf);
    return n;
}

/* Runs the walk from w->f (from_cache: those came from a cache), redoing it from
 * scratch and then by brute force (*brute) if it faults. */
static int walk_solve(walk *w, const closest_proxy *a, const closest_proxy *b,
                      bool from_cache, bool *restarted, bool *brute)
{
    int bound = walk_bound(w);
    int r = walk_run(w, bound);
    *restarted = *brute = false;
    if (r != W_FAULT) return r;
    *restarted = true;
    if (from_cache) {
        walk_scratch(w, a, b);
        r = walk_run(w, w->steps + bound);
        if (r != W_FAULT) return r;
    }
    *brute = true;
    return brute_force(w);
}

/* ---- polyhedron - polyhedron ---- */

/* Directions (frame 0) of the edges at feature f of side k: a vertex's edges, the
 * edge, a face's edges.  Writes at most max, returns the count. */
static int feature_edges(const walk *w, int k, closest_feature f, vec3 *out, int max)
{
    const poly *p = w->p[k];
    const closest_hull *h = w->h[k];
    int n = 0;
    if (f.kind == CLOSEST_VERTEX) {
        for (int j = p->vert_first[f.index]; j < p->vert_first[f.index + 1] && n < max; j++)
            out[n++] = h->eu[p->vert_edge[j]];
    } else if (f.kind == CLOSEST_EDGE) {
        if (max > 0) out[n++] = h->eu[f.index];
    } else if (f.kind == CLOSEST_FACE) {
        for (int j = 0; j < p->f[f.index].count && n < max; j++)
            out[n++] = h->eu[p->face_edge[p->f[f.index].first + j]];
    }
    if (k == 1)
        for (int j = 0; j < n; j++) out[j] = dir_to(w, 0, out[j]);
    return n;
}

#define LOCAL_EDGES 64

/* Penetration estimate: the smallest overlap of the projections over the face
 * normals of both and the cross products of the edges at the current features (for
 * touching edges and vertices).  The overlap along axis a is how far A must move
 * along a to clear B. */
/* How far the other side reaches past face g of side s (its overlap along the
 * face's outward normal), at its deepest vertex, climbed to from *j. */
static inline double face_overlap(const walk *w, int s, int g, int *j)
{
    const poly *ps = w->p[s], *po = w->p[1 - s];
    *j = poly_climb(po, dir_to(w, 1 - s, v3_neg(ps->f[g].n)), *j);
    return ps->f[g].d - v3_dot(ps->f[g].n, to(w, s, po->v[*j]));
}

static void sat_estimate(const walk *w, closest_result *r)
{
    double best = INFINITY;
    int bs = 0, bg = 0, bv = 0, bja = -1, bjb = 0;
    vec3 bax = v3(0, 0, 0);
    /* the overlap at the faces the walk ended on: no face that must overlap more
     * can be the least (pruned below without changing which face wins a tie) */
    double seed = INFINITY;
    for (int s = 0; s < 2; s++) {
        int j = 0;
        if (w->f[s].kind == CLOSEST_FACE) seed = d_min(seed, face_overlap(w, s, w->f[s].index, &j));
    }
    for (int s = 0; s < 2; s++) {
        int o = 1 - s, j = 0;
        const poly *ps = w->p[s];
        /* a ball of radius r_in about the other's centre is inside it, so some
         * vertex of it lies r_in or more behind its centre along a face's
         * outward normal: a face that the centre is past by r_in - best or less
         * cannot overlap less (no climb) */
        vec3 centre = to(w, s, v3(0, 0, 0));
        double r_in = w->h[o]->r_in;
        for (int i = 0; i < ps->nf; i++) {
            int g = w->h[s]->face_order[i];
            double least = ps->f[g].d - v3_dot(ps->f[g].n, centre) + r_in;
            if (least >= best || least > seed) continue;
            double ov = face_overlap(w, s, g, &j);
            if (ov < best) {
                best = ov;
                bs = s;
                bg = g;
                bv = j;
            }
        }
    }
    vec3 ea[LOCAL_EDGES], eb[LOCAL_EDGES];
    int na = feature_edges(w, 0, w->f[0], ea, LOCAL_EDGES);
    int nb = feature_edges(w, 1, w->f[1], eb, LOCAL_EDGES);
    int ja = 0, jb = 0;
    /* along an axis, B reaches at least r_in past its centre and A at least r_in
     * before its own: an axis on which even that overlaps best or more is no
     * better (no climbs) */
    vec3 cb = to(w, 0, v3(0, 0, 0));
    double r_ins = w->h[0]->r_in + w->h[1]->r_in;
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++) {
            vec3 c = v3_cross(ea[i], eb[j]);
            if (v3_len(c) < 1e-9) continue;
            for (int sg = 0; sg < 2; sg++) {
                vec3 ax = sg ? v3_neg(v3_norm(c)) : v3_norm(c);
                if (v3_dot(ax, cb) + r_ins >= best) continue;
                ja = poly_climb(w->p[0], v3_neg(ax), ja);
                jb = poly_climb(w->p[1], dir_to(w, 1, ax), jb);
                double ov = v3_dot(ax, to(w, 0, w->p[1]->v[jb])) - v3_dot(ax, w->p[0]->v[ja]);
                if (ov < best) {
                    best = ov;
                    bax = ax;
                    bja = ja;
                    bjb = jb;
                }
            }
        }
    double depth = d_max(best, 0);
    r->distance = depth > 0 ? -depth : 0.0;
    if (bja >= 0) { /* an edge-edge axis: A moves along it */
        r->normal = m3_mulv(w->R[0], bax);
        r->pa = world(w, 0, w->p[0]->v[bja]);
        r->pb = world(w, 1, w->p[1]->v[bjb]);
        r->fa = feat(CLOSEST_VERTEX, bja);
        r->fb = feat(CLOSEST_VERTEX, bjb);
        return;
    }
    int o = 1 - bs;
    vec3 n = m3_mulv(w->R[bs], w->p[bs]->f[bg].n); /* outward of bs's face, world */
    vec3 deep = world(w, o, w->p[o]->v[bv]);
    vec3 proj = v3_mad(deep, n, depth);
    if (bs == 0) { /* B's vertex under A's face: A moves along -n */
        r->normal = v3_neg(n);
        r->pa = proj;
        r->pb = deep;
        r->fa = feat(CLOSEST_FACE, bg);
        r->fb = feat(CLOSEST_VERTEX, bv);
    } else {
        r->normal = n;
        r->pa = deep;
        r->pb = proj;
        r->fa = feat(CLOSEST_VERTEX, bv);
        r->fb = feat(CLOSEST_FACE, bg);
    }
}

/* The result of a finished walk between two polyhedra (or a brute-force pair).  A
 * pair at distance 0 (within tolerance) is touching when some candidate axis of
 * sat_estimate separates the two, else penetrating. */
static void finish_pair(const walk *w, int how, closest_result *r, bool depth)
{
    if (how != W_DONE) {
        if (depth) sat_estimate(w, r);
        else r->distance = 0;
        return;
    }
    pair_geom g;
    pair_closest(w, &g);
    r->distance = g.dist;
    r->pa = g.p[0];
    r->pb = g.p[1];
    r->fa = w->f[0];
    r->fb = w->f[1];
    if (g.dist > w->eps) {
        r->normal = v3_len2(g.n) > 0 ? g.n : v3_norm(v3_sub(g.p[0], g.p[1]));
        return;
    }
    if (!depth) { /* touching or penetrating: which, does not matter */
        r->distance = 0;
        r->normal = g.n;
        return;
    }
    closest_result e;
    sat_estimate(w, &e);
    if (!(e.distance >= -w->eps)) {
        *r = e;
        return;
    }
    r->distance = 0; /* touching */
    r->normal = v3_len2(g.n) > 0 ? g.n : e.normal;
}

static void poly_poly(const closest_proxy *a, const closest_proxy *b, const closest_hull *ha,
                      const closest_hull *hb, closest_cache *cache, closest_result *r, bool depth)
{
    walk w;
    walk_init(&w, a, b, ha, hb);
    bool from_cache = cache && cache->valid && feature_fits(cache->fa, ha->p) &&
                      feature_fits(cache->fb, hb->p);
    if (from_cache) {
        w.f[0] = cache->fa;
        w.f[1] = cache->fb;
    } else {
        walk_scratch(&w, a, b);
    }
    bool restarted, brute;
    int how = walk_solve(&w, a, b, from_cache, &restarted, &brute);
    finish_pair(&w, how, r, depth);
    if (brute) {
        /* the smallest pair is the answer only if its plane separates the two */
        vec3 n = r->normal;
        double lo = v3_dot(n, r->pa) - w.eps, hi = v3_dot(n, r->pb) + w.eps;
        bool sep = r->distance > 0;
        for (int v = 0; v < ha->p->nv && sep; v++) sep = v3_dot(n, world(&w, 0, ha->p->v[v])) >= lo;
        for (int v = 0; v < hb->p->nv && sep; v++) sep = v3_dot(n, world(&w, 1, hb->p->v[v])) <= hi;
        if (!sep && depth) sat_estimate(&w, r);
        else if (!sep) r->distance = 0;
    }
    set_status(r);
    r->steps = w.steps;
    r->restarted = restarted;
    if (cache) *cache = (closest_cache){w.f[0], w.f[1], true};
}

/* ---- spheres ---- */

static void sphere_sphere(const closest_proxy *a, const closest_proxy *b, closest_cache *cache,
                          closest_result *r)
{
    vec3 d = v3_sub(a->x, b->x);
    double len = v3_len(d);
    r->normal = len > 0 ? v3_scale(d, 1.0 / len) : v3(0, 0, 1);
    double ra = a->radius, rb = b->radius;
    r->pa = v3_mad(a->x, r->normal, -ra);
    r->pb = v3_mad(b->x, r->normal, rb);
    r->distance = len - ra - rb;
    r->fa = r->fb = feat(CLOSEST_SPHERE, 0);
    set_status(r);
    if (cache) *cache = (closest_cache){r->fa, r->fb, true};
}

/* Sphere s against box hull h of object p, closed form.  Results with p as A. */
static void sphere_box(const closest_proxy *p, const closest_proxy *s, const closest_hull *h,
                       closest_result *r)
{
    mat3 R;
    rot_of(p->q, &R);
    vec3 c = m3_tmulv(&R, v3_sub(s->x, p->x)); /* centre, box frame */
    double cc[3] = {c.x, c.y, c.z}, q[3];
    int side[3], nclamp = 0;
    for (int i = 0; i < 3; i++) {
        double lo = v3_comp(h->lo, i), hi = v3_comp(h->hi, i);
        side[i] = cc[i] < lo ? 0 : cc[i] > hi ? 1 : -1;
        q[i] = side[i] == 0 ? lo : side[i] == 1 ? hi : cc[i];
        nclamp += side[i] >= 0;
    }
    double rad = s->radius, dist;
    vec3 nb; /* box frame, from the sphere to the box */
    if (nclamp == 0) { /* centre inside: out through the nearest face */
        int bi = 0, bs = 0;
        double depth = INFINITY;
        for (int i = 0; i < 3; i++)
            for (int sd = 0; sd < 2; sd++) {
                double d = sd ? v3_comp(h->hi, i) - cc[i] : cc[i] - v3_comp(h->lo, i);
                if (d < depth) {
                    depth = d;
                    bi = i;
                    bs = sd;
                }
            }
        q[bi] = bs ? v3_comp(h->hi, bi) : v3_comp(h->lo, bi);
        double m[3] = {0, 0, 0};
        m[bi] = bs ? -1 : 1; /* minus the face's outward normal */
        nb = v3(m[0], m[1], m[2]);
        dist = -depth;
        r->fa = feat(CLOSEST_FACE, h->box_face[bi][bs]);
    } else {
        vec3 d = v3_sub(v3(q[0], q[1], q[2]), c);
        dist = v3_len(d);
        if (nclamp == 1) {
            int i = side[0] >= 0 ? 0 : side[1] >= 0 ? 1 : 2;
            r->fa = feat(CLOSEST_FACE, h->box_face[i][side[i]]);
            double m[3] = {0, 0, 0};
            m[i] = side[i] ? -1 : 1;
            nb = v3(m[0], m[1], m[2]);
        } else {
            if (nclamp == 2) {
                int i = side[0] < 0 ? 0 : side[1] < 0 ? 1 : 2;
                int bits = side[(i + 1) % 3] | side[(i + 2) % 3] << 1;
                r->fa = feat(CLOSEST_EDGE, h->box_edge[i][bits]);
            } else {
                r->fa = feat(CLOSEST_VERTEX, h->box_vert[side[0] | side[1] << 1 | side[2] << 2]);
            }
            nb = dist > 0 ? v3_scale(d, 1.0 / dist) : v3_norm(v3_neg(c));
        }
    }
    r->normal = m3_mulv(R, nb);
    r->pa = v3_add(m3_mulv(R, v3(q[0], q[1], q[2])), p->x);
    r->pb = v3_mad(s->x, r->normal, rad);
    r->distance = dist - rad;
    r->fb = feat(CLOSEST_SPHERE, 0);
    set_status(r);
}

/* Sphere s (side 1) against polyhedron p (side 0): the centre's walk. */
static void sphere_poly(const closest_proxy *p, const closest_proxy *s, const closest_hull *h,
                        closest_cache *cache, closest_result *r)
{
    if (h->box) {
        sphere_box(p, s, h, r);
        if (cache) *cache = (closest_cache){r->fa, r->fb, true};
        return;
    }
    walk w;
    walk_init(&w, p, s, h, NULL);
    bool from_cache = cache && cache->valid && feature_fits(cache->fa, h->p) &&
                      feature_fits(cache->fb, NULL);
    if (from_cache) w.f[0] = cache->fa;
    else walk_scratch(&w, p, s);
    w.f[1] = feat(CLOSEST_VERTEX, 0);
    bool restarted, brute;
    int how = walk_solve(&w, p, s, from_cache, &restarted, &brute);
    double rad = s->radius;
    vec3 c = s->x;
    pair_geom g = {{c, c}, 0, v3(0, 0, 0)};
    if (how == W_DONE) pair_closest(&w, &g);
    if (how == W_DONE && g.dist > w.eps) {
        r->pa = g.p[0];
        r->normal = v3_len2(g.n) > 0 ? g.n : v3_norm(v3_sub(g.p[0], c));
        r->distance = g.dist - rad;
    } else { /* centre inside or on the surface: out through the face it is nearest to */
        if (how == W_DONE) local_min(&w, 1, w.t[0]);
        const poly_face *F = &h->p->f[w.f[0].index];
        vec3 x = w.t[0];
        double d = v3_dot(F->n, x) - F->d;
        r->pa = world(&w, 0, v3_mad(x, F->n, -d));
        r->normal = v3_neg(m3_mulv(w.R[0], F->n));
        r->distance = d - rad;
    }
    r->pb = v3_mad(c, r->normal, rad);
    r->fa = w.f[0];
    r->fb = feat(CLOSEST_SPHERE, 0);
    set_status(r);
    r->steps = w.steps;
    r->restarted = restarted;
    if (cache) *cache = (closest_cache){w.f[0], r->fb, true};
}

/* ---- entry points ---- */

static closest_result distance_of(const closest_proxy *a, const closest_proxy *b,
                                  closest_cache *cache, bool depth)
{
    closest_result r;
    memset(&r, 0, sizeof r);
    if (!object_ok(a) || !object_ok(b)) {
        closest_invalid(&r);
        return r;
    }
    bool sa = a->hull == NULL, sb = b->hull == NULL;
    if (sa && sb) {
        sphere_sphere(a, b, cache, &r);
        return r;
    }
    /* the closest data of each polyhedron, built for the call if the proxy lacks it */
    closest_hull *own[2] = {NULL, NULL};
    const closest_hull *h[2] = {NULL, NULL};
    const closest_proxy *ob[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        const closest_proxy *o = ob[k];
        if (!o->hull) continue;
        h[k] = o->feat;
        if (!h[k]) h[k] = own[k] = closest_hull_new(o->hull);
        if (!h[k]) {
            closest_hull_free(own[0]);
            closest_invalid(&r);
            return r;
        }
    }
    if (sa) {
        closest_cache c2, *cp = NULL;
        if (cache) {
            c2 = (closest_cache){cache->fb, cache->fa, cache->valid};
            cp = &c2;
        }
        sphere_poly(b, a, h[1], cp, &r);
        closest_mirror(&r);
        if (cache) *cache = (closest_cache){c2.fb, c2.fa, c2.valid};
    } else if (sb) {
        sphere_poly(a, b, h[0], cache, &r);
    } else {
        poly_poly(a, b, h[0], h[1], cache, &r, depth);
    }
    closest_hull_free(own[0]);
    closest_hull_free(own[1]);
    return r;
}

closest_result closest_distance(const closest_proxy *a, const closest_proxy *b,
                                closest_cache *cache)
{
    return distance_of(a, b, cache, true);
}

closest_result closest_distance_apart(const closest_proxy *a, const closest_proxy *b,
                                      closest_cache *cache)
{
    return distance_of(a, b, cache, false);
}
