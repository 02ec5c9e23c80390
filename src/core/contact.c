/* contact.c: contact regions and pressing points (contact.h; design.md,
 * "Dynamics").
 */
#include "contact.h"

#include "pieces.h"

#include <assert.h>

#include <stdlib.h>
#include <string.h>

#include "tolerance.h"

typedef struct {
    double x, y;
} p2;

#define CONTACT_MAX_SUPPORT 256

/* Supporting sets of up to this many points (a box's or a die's face, and nearly
 * every superquadric's) are worked on in arrays on the stack; larger ones are
 * allocated. */
#define LOCAL_SUPPORT 32

/* A hull of at most this many vertices is read in turn; a larger one (a
 * superquadric's) is walked. */
#define SUPPORT_SCAN 32

/* The walk marks the vertices it has seen in a bit set of this many bytes on the
 * stack: hulls of up to 4,096 vertices (a superquadric of 64 x 64 divisions) are
 * walked without allocating; larger ones allocate theirs. */
#define WALK_SEEN_LOCAL 512

/* The vertices of h (at most SUPPORT_SCAN) within tol of the furthest along dl
 * (body axes), read in turn: their indices in idx, at most max; returns the count. */
static int support_scan(const poly *h, vec3 dl, double tol, int *idx, int max)
{
    double x[SUPPORT_SCAN], best = -HUGE_VAL;
    for (int i = 0; i < h->nv; i++) best = d_max(best, x[i] = v3_dot(h->v[i], dl));
    int n = 0;
    for (int i = 0; i < h->nv && n < max; i++)
        if (x[i] >= best - tol) idx[n++] = i;
    return n;
}

/* The same for any hull, by a walk: the furthest vertex is found (down feat's
 * support hierarchy on a large hull, else by a climb); and each vertex within tol
 * of it has an edge to one further on, so they are all reached from it through
 * such vertices.  0 when out of memory. */
static int support_walk(const poly *h, const closest_hull *feat, vec3 dl, double tol, int *idx,
                        int max)
{
    int top = feat ? closest_hull_support(feat, dl) : poly_climb(h, dl, 0);
    double best = v3_dot(h->v[top], dl);
    unsigned char local[WALK_SEEN_LOCAL];
    size_t bytes = (size_t)h->nv / 8 + 1;
    unsigned char *seen = bytes <= sizeof local ? memset(local, 0, bytes) : calloc(bytes, 1);
    if (!seen) return 0;
    int n = 0;
    idx[n++] = top;
    seen[top / 8] |= (unsigned char)(1u << top % 8);
    for (int i = 0; i < n; i++) {
        for (int k = h->vert_first[idx[i]]; k < h->vert_first[idx[i] + 1]; k++) {
            const poly_edge *e = &h->e[h->vert_edge[k]];
            int o = e->v[0] == idx[i] ? e->v[1] : e->v[0];
            if (n == max || seen[o / 8] & 1u << o % 8 || v3_dot(h->v[o], dl) < best - tol) continue;
            seen[o / 8] |= (unsigned char)(1u << o % 8);
            idx[n++] = o;
        }
    }
    if (seen != local) free(seen);
    return n;
}

/* A supporting set: the indices of n of a hull's vertices; a sphere's set is its
 * one point (n 1, no index). */
typedef struct {
    int n;
    int idx[CONTACT_MAX_SUPPORT];
} support;

/* The supporting set of b in direction d (world): the vertices within tol of the
 * furthest (n 0 when out of memory). */
static void support_find(const body *b, vec3 d, double tol, support *s)
{
    if (b->sp.kind == SHAPE_SPHERE) {
        s->n = 1;
        return;
    }
    const poly *h = b->shape.hull;
    vec3 dl = q_unrotate(b->q, d);
    int max = h->nv < CONTACT_MAX_SUPPORT ? h->nv : CONTACT_MAX_SUPPORT;
    s->n = h->nv <= SUPPORT_SCAN ? support_scan(h, dl, tol, s->idx, max)
                                 : support_walk(h, b->shape.feat, dl, tol, s->idx, max);
}

/* Those points (found in direction d) in plane coordinates (u, v), in out. */
static void support_place(const body *b, vec3 d, const support *s, vec3 u, vec3 v, p2 *out)
{
    if (b->sp.kind == SHAPE_SPHERE) {
        vec3 p = v3_mad(body_com(b), v3_norm(d), b->sp.radius);
        out[0] = (p2){v3_dot(p, u), v3_dot(p, v)};
        return;
    }
    const poly *h = b->shape.hull;
    for (int i = 0; i < s->n; i++) {
        vec3 p = v3_add(b->x, q_rotate(b->q, h->v[s->idx[i]]));
        out[i] = (p2){v3_dot(p, u), v3_dot(p, v)};
    }
}

/* Room for n points: local (nlocal of them) when they fit, else allocated (NULL
 * when out of memory); release it with free_points. */
static p2 *room_for(p2 *local, int nlocal, int n)
{
    return n <= nlocal ? local : malloc((size_t)n * sizeof *local);
}

static void free_points(p2 *p, const p2 *local)
{
    if (p != local) free(p);
}

/* Unit axes u, v of the plane across unit vector n, with u x v = n. */
static void plane_axes(vec3 n, vec3 *u, vec3 *v)
{
    *u = v3_norm(fabs(n.x) < 0.6 ? v3_cross(n, v3(1, 0, 0)) : v3_cross(n, v3(0, 1, 0)));
    *v = v3_cross(n, *u);
}

static double cross2(p2 o, p2 a, p2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

/* The squared distance from c to the segment from a to b (a point when a = b). */
static double seg_dist2(p2 a, p2 b, p2 c)
{
    double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey;
    double t = len2 > 0 ? ((c.x - a.x) * ex + (c.y - a.y) * ey) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double dx = a.x + t * ex - c.x, dy = a.y + t * ey - c.y;
    return dx * dx + dy * dy;
}

static int cmp_p2(const void *a, const void *b)
{
    const p2 *p = a, *q = b;
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    return p->y < q->y ? -1 : p->y > q->y;
}

/* True when p comes before q: by x, then by y. */
static bool before_p2(p2 p, p2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

/* Sorts the n points by x, then by y.  A few corners, as most sets are, by
 * insertion: qsort's calls cost more than such a sort. */
static void sort_p2(p2 *pts, int n)
{
    if (n > 16) {
        qsort(pts, (size_t)n, sizeof *pts, cmp_p2);
        return;
    }
    for (int i = 1; i < n; i++) {
        p2 x = pts[i];
        int j = i;
        for (; j > 0 && before_p2(x, pts[j - 1]); j--) pts[j] = pts[j - 1];
        pts[j] = x;
    }
}

/* Convex hull in place, counter-clockwise (Andrew's monotone chain); returns the
 * count: 1 a point, 2 a segment, >= 3 a polygon.  pts needs room for 2n + 1 points
 * (the chain closes on its first point). */
static int hull2(p2 *pts, int n, double eps)
{
    if (n <= 1) return n;
    sort_p2(pts, n);
    p2 *h = pts + n;
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross2(h[k - 2], h[k - 1], pts[i]) <= eps) k--;
        h[k++] = pts[i];
    }
    for (int i = n - 2, t = k + 1; i >= 0; i--) {
        while (k >= t && cross2(h[k - 2], h[k - 1], pts[i]) <= eps) k--;
        h[k++] = pts[i];
    }
    k--; /* the last point repeats the first */
    if (k < 1) k = 1;
    for (int i = 0; i < k; i++) pts[i] = h[i];
    return k;
}

/* Clips polygon (n points, ccw) by the half-plane left of a->b into out, which has
 * room for room points (a convex one gains at most one corner); returns the count. */
static int clip_poly(const p2 *in, int n, p2 a, p2 b, p2 *out, int room)
{
    int m = 0;
    for (int i = 0; i < n && m + 2 <= room; i++) {
        p2 p = in[i], q = in[(i + 1) % n];
        double dp = cross2(a, b, p), dq = cross2(a, b, q);
        if (dp >= 0) out[m++] = p;
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            out[m++] = (p2){p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
        }
    }
    return m;
}

static bool polygon_centroid(const p2 *p, int n, p2 *c)
{
    double a = 0, cx = 0, cy = 0;
    for (int i = 0; i < n; i++) {
        p2 s = p[i], t = p[(i + 1) % n];
        double w = s.x * t.y - t.x * s.y;
        a += w;
        cx += (s.x + t.x) * w;
        cy += (s.y + t.y) * w;
    }
    if (fabs(a) < 1e-18) return false;
    *c = (p2){cx / (3 * a), cy / (3 * a)};
    return true;
}

/* Part of segment s0-s1 inside convex polygon pg (ccw): its two ends in out and
 * its middle in mid; false when none. */
static bool clip_segment(p2 s0, p2 s1, const p2 *pg, int n, p2 *out, p2 *mid)
{
    double t0 = 0, t1 = 1;
    for (int i = 0; i < n; i++) {
        p2 a = pg[i], b = pg[(i + 1) % n];
        double d0 = cross2(a, b, s0), d1 = cross2(a, b, s1);
        if (d0 < 0 && d1 < 0) return false;
        if (d0 < 0) t0 = d_max(t0, d0 / (d0 - d1));
        else if (d1 < 0) t1 = d_min(t1, d0 / (d0 - d1));
    }
    if (t0 > t1) return false;
    out[0] = (p2){s0.x + t0 * (s1.x - s0.x), s0.y + t0 * (s1.y - s0.y)};
    out[1] = (p2){s0.x + t1 * (s1.x - s0.x), s0.y + t1 * (s1.y - s0.y)};
    double t = 0.5 * (t0 + t1);
    *mid = (p2){s0.x + t * (s1.x - s0.x), s0.y + t * (s1.y - s0.y)};
    return true;
}

/* Overlap of two nearly parallel segments: its two ends in out and its middle in
 * mid; false when not parallel or apart. */
static bool segment_overlap(const p2 *a, const p2 *b, double eps, p2 *out, p2 *mid)
{
    p2 d = {a[1].x - a[0].x, a[1].y - a[0].y};
    double l = sqrt(d.x * d.x + d.y * d.y);
    if (l == 0) return false;
    d.x /= l;
    d.y /= l;
    p2 e = {b[1].x - b[0].x, b[1].y - b[0].y};
    double le = sqrt(e.x * e.x + e.y * e.y);
    if (le == 0 || fabs(d.x * e.y - d.y * e.x) > 1e-6 * le) return false;
    if (fabs(d.x * (b[0].y - a[0].y) - d.y * (b[0].x - a[0].x)) > eps) return false;
    double s0 = 0, s1 = l;
    double t0 = d.x * (b[0].x - a[0].x) + d.y * (b[0].y - a[0].y);
    double t1 = d.x * (b[1].x - a[0].x) + d.y * (b[1].y - a[0].y);
    double lo = d_max(s0, d_min(t0, t1)), hi = d_min(s1, d_max(t0, t1));
    if (lo > hi) return false;
    out[0] = (p2){a[0].x + d.x * lo, a[0].y + d.y * lo};
    out[1] = (p2){a[0].x + d.x * hi, a[0].y + d.y * hi};
    double t = 0.5 * (lo + hi);
    *mid = (p2){a[0].x + d.x * t, a[0].y + d.y * t};
    return true;
}

/* The normal of a and b's closest features, from b to a, as exact as their kinds
 * allow: a face's normal; for two edges, their common perpendicular.  For objects
 * a hair apart the normal from the closest points (pa - pb over a tiny distance)
 * carries their rounding, a millionth at 1e-10 m: enough to tilt a contact plane
 * off a face and lose the face's corners. */
static vec3 exact_normal(const body *a, const body *b, const closest_result *r)
{
    vec3 n = r->normal;
    const poly *ha = a->shape.hull, *hb = b->shape.hull;
    if (r->fa.kind == CLOSEST_FACE && ha && r->fa.index < ha->nf)
        return v3_neg(q_rotate(a->q, ha->f[r->fa.index].n));
    if (r->fb.kind == CLOSEST_FACE && hb && r->fb.index < hb->nf)
        return q_rotate(b->q, hb->f[r->fb.index].n);
    if (r->fa.kind == CLOSEST_EDGE && r->fb.kind == CLOSEST_EDGE && ha && hb &&
        r->fa.index < ha->ne && r->fb.index < hb->ne) {
        const poly_edge *ea = &ha->e[r->fa.index], *eb = &hb->e[r->fb.index];
        vec3 da = q_rotate(a->q, v3_sub(ha->v[ea->v[1]], ha->v[ea->v[0]]));
        vec3 db = q_rotate(b->q, v3_sub(hb->v[eb->v[1]], hb->v[eb->v[0]]));
        vec3 c = v3_cross(da, db);
        double l = v3_len(c);
        if (l > 1e-9 * v3_len(da) * v3_len(db)) {
            c = v3_scale(c, 1 / l);
            return v3_dot(c, n) < 0 ? v3_neg(c) : c;
        }
    }
    return n;
}

/* The contact region of a and b (see contact_point), in the contact plane's
 * coordinates (u, v), the plane at height h along the normal. */
typedef struct {
    vec3 u, v;
    double h;
    int n;    /* corners: 2 a segment's ends, >= 3 a polygon's (ccw); 0 no overlap */
    int na, nb; /* the points of each object's supporting set's hull: 1 a vertex,
                 * 2 an edge, >= 3 a face */
    p2 *p;    /* the corners */
    p2 c;     /* the centre */
    p2 *pts;  /* where the points are worked on: local, or allocated */
    p2 local[12 * LOCAL_SUPPORT];
    support sa, sb; /* the supporting sets of the two objects */
    vec3 n_used;    /* the normal it was found along (exact_normal) */
} region;

/* Finds the region: false when out of memory.  n is 0 when the features do not
 * overlap, or when one is a vertex or a sphere: the midpoint of the closest points
 * is the contact point then. */
static bool region_of(const body *a, const body *b, const closest_result *r, double tol,
                      region *z)
{
    vec3 n = exact_normal(a, b, r);
    z->n_used = n;
    z->n = 0;
    z->na = z->nb = 1;
    z->pts = z->local;
    /* a sphere touches a convex object at one point */
    if (a->sp.kind == SHAPE_SPHERE || b->sp.kind == SHAPE_SPHERE) return true;
    plane_axes(n, &z->u, &z->v);
    z->h = 0.5 * v3_dot(v3_add(r->pa, r->pb), n);
    /* a's features facing b lie along -n; b's facing a along +n */
    support *fa = &z->sa, *fb = &z->sb;
    support_find(a, v3_neg(n), tol, fa);
    support_find(b, n, tol, fb);
    /* each set, and room for its hull (hull2); two buffers for the clipping, which
     * adds at most one corner per edge it clips by */
    int ka = fa->n, kb = fb->n, clip = 2 * (ka + kb);
    p2 *sa = z->pts = room_for(z->local, 12 * LOCAL_SUPPORT, 2 * ka + 2 * kb + 2 + 2 * clip);
    if (!sa || ka == 0 || kb == 0) return false;
    p2 *sb = sa + 2 * ka + 1;
    p2 *buf[2] = {sb + 2 * kb + 1, sb + 2 * kb + 1 + clip};
    z->p = buf[0];
    support_place(a, v3_neg(n), fa, z->u, z->v, sa);
    support_place(b, n, fb, z->u, z->v, sb);
    /* (an area: a millionth of the size, squared) */
    double size = tol_size(a, b), eps = d_max(1e-12 * size * size, tol_round(a, b) * size);
    int na = hull2(sa, ka, eps), nb = hull2(sb, kb, eps);
    z->na = na;
    z->nb = nb;
    if (na >= 3 && nb >= 3) {
        int m = na, cur = 0;
        for (int i = 0; i < m; i++) buf[0][i] = sa[i];
        for (int i = 0; i < nb && m > 0; i++) {
            m = clip_poly(buf[cur], m, sb[i], sb[(i + 1) % nb], buf[1 - cur], clip);
            cur = 1 - cur;
        }
        z->p = buf[cur];
        z->n = m >= 3 && polygon_centroid(z->p, m, &z->c) ? m : 0;
    } else if (na == 2 && nb >= 3) {
        z->n = clip_segment(sa[0], sa[1], sb, nb, z->p, &z->c) ? 2 : 0;
    } else if (nb == 2 && na >= 3) {
        z->n = clip_segment(sb[0], sb[1], sa, na, z->p, &z->c) ? 2 : 0;
    } else if (na == 2 && nb == 2) {
        z->n = segment_overlap(sa, sb, sqrt(eps) + tol, z->p, &z->c) ? 2 : 0;
    } else if (na == 1 || nb == 1) {
        /* a vertex on the other: the region is that point */
        z->p[0] = z->c = na == 1 ? sa[0] : sb[0];
        z->n = 1;
    }
    return true;
}

/* Point c of the region's plane, in world axes (n = u x v). */
static vec3 region_world(const region *z, vec3 n, p2 c)
{
    return v3_add(v3_add(v3_scale(z->u, c.x), v3_scale(z->v, c.y)), v3_scale(n, z->h));
}

vec3 contact_point(const body *a0, const body *b0, const closest_result *r, double tol)
{
    body ta, tb;
    const body *a = pieces_view(a0, r->ka, &ta), *b = pieces_view(b0, r->kb, &tb);
    region z;
    vec3 p = v3_scale(v3_add(r->pa, r->pb), 0.5);
    if (region_of(a, b, r, tol, &z) && z.n > 0) p = region_world(&z, z.n_used, z.c);
    free_points(z.pts, z.local);
    return p;
}

vec3 contact_closing_corner(const body *a0, const body *b0, const closest_result *r, double tol,
                            vec3 p)
{
    body ta, tb;
    const body *a = pieces_view(a0, r->ka, &ta), *b = pieces_view(b0, r->kb, &tb);
    region z;
    if (region_of(a, b, r, tol, &z)) {
        double best = 0;
        for (int i = 0; i < z.n; i++) {
            vec3 c = region_world(&z, z.n_used, z.p[i]);
            double s = contact_closing_speed(a, b, c, r->normal);
            if (s > best) {
                best = s;
                p = c;
            }
        }
    }
    free_points(z.pts, z.local);
    return p;
}

/* ---- pressing points ---- */

/* A point of the object on side p (0: a, 1: b) at world point x, in its frame. */
static vec3 local_of(const body *o, vec3 x) { return q_unrotate(o->q, v3_sub(x, o->x)); }

int contact_facing(const body *o, vec3 d)
{
    const poly *h = o->shape.hull;
    if (!h || o->sp.kind == SHAPE_SPHERE) return -1;
    vec3 dl = q_unrotate(o->q, d);
    int best = 0;
    for (int k = 1; k < h->nf; k++)
        if (v3_dot(h->f[k].n, dl) > v3_dot(h->f[best].n, dl)) best = k;
    return best;
}

int contact_face_outline(const body *m, vec3 n, vec3 e1, vec3 e2, region_pt *out, int max, double *height)
{
    int fi = contact_facing(m, v3_neg(n));
    if (fi < 0 || body_compound(m)) return -1;
    const poly *h = m->shape.hull;
    const poly_face *F = &h->f[fi];
    if (F->count < 3 || F->count > max || v3_dot(q_rotate(m->q, F->n), n) > -1 + SIM_PARALLEL) return -1;
    vec3 c = body_com(m);
    for (int k = 0; k < F->count; k++) {
        vec3 x = v3_sub(v3_add(m->x, q_rotate(m->q, h->v[h->face_vert[F->first + k]])), c);
        out[k] = (region_pt){v3_dot(x, e1), v3_dot(x, e2)};
        if (k == 0) *height = -v3_dot(x, n);
    }
    /* (the hull's face turns counterclockwise about its own normal, -n) */
    double area = 0;
    for (int k = 0; k < F->count; k++) {
        region_pt a = out[k], b = out[(k + 1) % F->count];
        area += a.x * b.y - a.y * b.x;
    }
    if (area < 0)
        for (int k = 0; k < F->count / 2; k++) {
            region_pt x = out[k];
            out[k] = out[F->count - 1 - k];
            out[F->count - 1 - k] = x;
        }
    return area != 0 ? F->count : -1;
}

double contact_face_arm(const body *m, vec3 n)
{
    int fi = contact_facing(m, v3_neg(n));
    if (fi < 0 || body_compound(m)) return -1;
    const poly *h = m->shape.hull;
    const poly_face *F = &h->f[fi];
    if (F->count < 3 || v3_dot(q_rotate(m->q, F->n), n) > -1 + SIM_PARALLEL) return -1;
    vec3 u, v, c = body_com(m);
    plane_axes(n, &u, &v);
    p2 local[LOCAL_SUPPORT];
    p2 *pg = room_for(local, LOCAL_SUPPORT, F->count);
    if (!pg) return -1;
    for (int k = 0; k < F->count; k++) {
        vec3 x = v3_sub(v3_add(m->x, q_rotate(m->q, h->v[h->face_vert[F->first + k]])), c);
        pg[k] = (p2){v3_dot(x, u), v3_dot(x, v)};
    }
    /* centrally symmetric about the foot of the centre of mass: each corner's
     * opposite is a corner too */
    double tol = 1e-9 * (1 + m->shape.r_out), area = 0, arm = 0;
    bool symmetric = true;
    for (int k = 0; k < F->count && symmetric; k++) {
        bool found = false;
        for (int j = 0; j < F->count && !found; j++)
            found = fabs(pg[k].x + pg[j].x) <= tol && fabs(pg[k].y + pg[j].y) <= tol;
        symmetric = found;
    }
    for (int k = 0; k < F->count && symmetric; k++) {
        p2 a = pg[k], b = pg[(k + 1) % F->count];
        area += 0.5 * (a.x * b.y - a.y * b.x);
        arm += region_arm((region_pt){a.x, a.y}, (region_pt){b.x, b.y});
    }
    free_points(pg, local);
    return symmetric && area != 0 ? arm / area : -1;
}

/* Where the line xb + s mb (P's frame) crosses the plane of P's face f inwards:
 * s, or -inf for a face it does not cross inwards (nearly parallel, or facing
 * away). */
static double entry(const poly *h, int f, vec3 xb, vec3 mb)
{
    double dn = v3_dot(h->f[f].n, mb);
    return dn < -1e-3 ? (h->f[f].d - v3_dot(h->f[f].n, xb)) / dn : -HUGE_VAL;
}

/* True when every point of P's supporting set s lies on the plane of its face f
 * (to the rounding of P's size r). */
static bool on_face(const poly *h, const support *s, int f, double r)
{
    const poly_face *F = &h->f[f];
    double tol = 1e-12 * (1 + r);
    for (int i = 0; i < s->n; i++)
        if (fabs(v3_dot(F->n, h->v[s->idx[i]]) - F->d) > tol) return false;
    return true;
}

/* Moves world point *x along m onto P's surface facing the other object (along
 * -m): the plane of its face f there when its supporting set s (np points in
 * the region's hull) is that face; where s spans several faces (a thick region
 * over a curved side), where the line along m enters P, so that no point is put
 * on a face's plane beyond the face, under P's surface, where P does not reach;
 * the line of its edge when an edge, its vertex when a vertex. */
static void lift(const body *P, const support *s, int np, int f, vec3 m, vec3 *x)
{
    const poly *h = P->shape.hull;
    if (!h || P->sp.kind == SHAPE_SPHERE || s->n < 1) return;
    if (np >= 3 && f >= 0 && on_face(h, s, f, P->shape.r_out)) {
        vec3 nf = q_rotate(P->q, h->f[f].n);
        double dn = v3_dot(nf, m);
        if (fabs(dn) < 1e-3) return;
        vec3 on = v3_add(P->x, q_rotate(P->q, h->v[h->face_vert[h->f[f].first]]));
        *x = v3_mad(*x, m, v3_dot(nf, v3_sub(on, *x)) / dn);
        return;
    }
    if (np >= 3 && f >= 0) {
        /* P is the faces' half-spaces n . y <= d: the line y = x + s m enters
         * it at the largest s over the faces it crosses inwards (n . m < 0).
         * Across each edge of the face found so far, the neighbour's plane is
         * the higher where the line meets P on its side of that edge, so the
         * walk from f up to the largest ends at the face the line enters by
         * (its values only grow, and P's facing side is convex) */
        vec3 xb = q_unrotate(P->q, v3_sub(*x, P->x)), mb = q_unrotate(P->q, m);
        int cur = f;
        double in = entry(h, f, xb, mb);
        for (bool moved = in > -HUGE_VAL; moved;) {
            moved = false;
            const poly_face *F = &h->f[cur];
            for (int k = 0; k < F->count && !moved; k++) {
                const poly_edge *e = &h->e[h->face_edge[F->first + k]];
                int g = e->f[0] == cur ? e->f[1] : e->f[0];
                double sg = entry(h, g, xb, mb);
                if (sg > in) {
                    in = sg;
                    cur = g;
                    moved = true;
                }
            }
        }
        if (in > -HUGE_VAL) *x = v3_mad(*x, m, in);
        return;
    }
    /* an edge or a vertex: its points furthest apart across m */
    vec3 p0 = v3_add(P->x, q_rotate(P->q, h->v[s->idx[0]])), p1 = p0;
    double far = -1;
    for (int i = 0; i < s->n; i++) {
        vec3 pi = v3_add(P->x, q_rotate(P->q, h->v[s->idx[i]]));
        for (int j = i + 1; j < s->n; j++) {
            vec3 pj = v3_add(P->x, q_rotate(P->q, h->v[s->idx[j]]));
            vec3 d = v3_sub(pj, pi);
            d = v3_mad(d, m, -v3_dot(d, m));
            if (v3_len2(d) > far) {
                far = v3_len2(d);
                p0 = pi;
                p1 = pj;
            }
        }
    }
    vec3 e = v3_sub(p1, p0), ep = v3_mad(e, m, -v3_dot(e, m));
    double len2 = v3_len2(ep), t = 0;
    if (np == 2 && len2 > 0) {
        vec3 d = v3_sub(*x, p0);
        t = v3_dot(v3_mad(d, m, -v3_dot(d, m)), ep) / len2;
    }
    vec3 on = v3_mad(p0, e, t);
    *x = v3_mad(*x, m, v3_dot(v3_sub(on, *x), m));
}

/* A plane of the object on side q through world point x with world normal m
 * (towards the other object), in q's frame. */
static void plane_of(const body *o, vec3 x, vec3 m, cpoint *cp)
{
    cp->kind = CPT_PLANE;
    cp->f0 = q_unrotate(o->q, m);
    cp->f1 = v3(v3_dot(cp->f0, local_of(o, x)), 0, 0);
}

/* Edges no closer to parallel than this (the sine of their angle) are followed as
 * two edges; closer, as a point and a line. */
#define CONTACT_EDGES_SIN 1e-6

/* Closest features two edges (r of a against b): cp becomes a's edge against b's
 * (EDGES), p = 0; false when they are too near parallel for it. */
static bool edges_of(const body *a, const body *b, const closest_result *r, cpoint *cp)
{
    const poly *ha = a->shape.hull, *hb = b->shape.hull;
    if (!ha || !hb || r->fa.index >= ha->ne || r->fb.index >= hb->ne) return false;
    const poly_edge *ea = &ha->e[r->fa.index], *eb = &hb->e[r->fb.index];
    vec3 a0 = ha->v[ea->v[0]], da = v3_norm(v3_sub(ha->v[ea->v[1]], a0));
    vec3 b0 = hb->v[eb->v[0]], db = v3_norm(v3_sub(hb->v[eb->v[1]], b0));
    vec3 c = v3_cross(q_rotate(a->q, da), q_rotate(b->q, db));
    double l = v3_len(c);
    if (!(l > 1e3 * CONTACT_EDGES_SIN)) return false;
    *cp = (cpoint){.p = 0, .q = 1, .kind = CPT_EDGES, .sp = a0, .r = 0, .f0 = b0, .f1 = db, .sd = da,
                   .sgn = v3_dot(c, r->normal) >= 0 ? 1 : -1};
    return true;
}

/* The point of sphere s (side p) against the feature f of polyhedron o (side q). */
static void sphere_against(const body *s, const body *o, closest_feature f, vec3 n_to_s,
                           vec3 on_o, cpoint *cp)
{
    cp->sp = s->shape.mass.com;
    cp->r = s->sp.radius;
    const poly *h = o->shape.hull;
    if (f.kind == CLOSEST_FACE && h && f.index < h->nf) {
        const poly_face *F = &h->f[f.index];
        cp->kind = CPT_PLANE;
        cp->f0 = F->n;
        cp->f1 = v3(F->d, 0, 0);
        /* a centre over the face's rim (a ball at the edge it slides off) is
         * against that edge: the face's plane reaches beyond it */
        vec3 c = q_unrotate(o->q, v3_sub(body_com(s), o->x));
        double eps = d_max(1e-9 * (1 + tol_size(s, o)), tol_round(s, o)), most = -eps;
        for (int k = 0; k < F->count; k++) {
            vec3 v0 = h->v[h->face_vert[F->first + k]];
            vec3 v1 = h->v[h->face_vert[F->first + (k + 1) % F->count]];
            vec3 e = v3_sub(v1, v0), out = v3_cross(e, F->n);
            double len = v3_len(out);
            if (!(len > 0)) continue;
            double side = v3_dot(v3_sub(c, v0), out) / len;
            if (side >= most) {
                most = side;
                cp->kind = CPT_LINE;
                cp->f0 = v0;
                cp->f1 = v3_norm(e);
            }
        }
    } else if (f.kind == CLOSEST_EDGE && h && f.index < h->ne) {
        cp->kind = CPT_LINE;
        cp->f0 = h->v[h->e[f.index].v[0]];
        cp->f1 = v3_norm(v3_sub(h->v[h->e[f.index].v[1]], cp->f0));
    } else if (f.kind == CLOSEST_VERTEX && h && f.index < h->nv) {
        cp->kind = CPT_POINT;
        cp->f0 = h->v[f.index];
        cp->f1 = v3(0, 0, 0);
    } else {
        plane_of(o, on_o, n_to_s, cp);
    }
}

/* contact_cpoints for one convex piece of each. */
static int cpoints_of(const body *a, const body *b, const closest_result *r, double tol, cpoint *out,
                      int max)
{
    if (max < 1) return 0;
    vec3 n = r->normal;
    double half = 0.5 * r->distance;
    bool sa = a->sp.kind == SHAPE_SPHERE, sb = b->sp.kind == SHAPE_SPHERE;
    if (sa && sb) {
        out[0] = (cpoint){.p = 0, .q = 1, .kind = CPT_POINT, .sp = a->shape.mass.com,
                          .r = a->sp.radius + b->sp.radius, .f0 = b->shape.mass.com};
        return 1;
    }
    if (sa || sb) {
        cpoint *cp = &out[0];
        cp->p = sa ? 0 : 1;
        cp->q = sa ? 1 : 0;
        if (sa) sphere_against(a, b, r->fb, n, r->pb, cp);
        else sphere_against(b, a, r->fa, v3_neg(n), r->pa, cp);
        return 1;
    }
    region z;
    if (!region_of(a, b, r, tol, &z)) {
        free_points(z.pts, z.local);
        return 0;
    }
    int count = 0;
    n = z.n_used;
    if (z.n > 0) {
        /* the plane is the face's side, the points the corners of the other's
         * side; when both are faces, the plane is the still or the heavier one's,
         * so that the other, turning off it, lifts its corners off the plane */
        int q = 1;
        if (z.na >= 3 && z.nb < 3) q = 0;
        else if (z.na >= 3 && z.nb >= 3 && (body_is_static(a) || (!body_is_static(b) && a->mass > b->mass)))
            q = 0;
        int pside = 1 - q;
        const body *P = pside == 0 ? a : b, *Q = q == 0 ? a : b;
        vec3 m = q == 1 ? n : v3_neg(n); /* from Q towards P */
        vec3 mid = region_world(&z, n, z.c);
        cpoint base = {.p = pside, .q = q, .r = 0};
        int nq = q == 0 ? z.na : z.nb, np = pside == 0 ? z.na : z.nb;
        /* the plane: the face of Q's side itself, when it is one */
        int fq = nq >= 3 ? contact_facing(Q, m) : -1;
        if (fq >= 0) {
            base.kind = CPT_PLANE;
            base.f0 = Q->shape.hull->f[fq].n;
            base.f1 = v3(Q->shape.hull->f[fq].d, 0, 0);
        } else {
            plane_of(Q, v3_mad(mid, m, -half), m, &base);
        }
        /* the points: on P's own surface (its face, edge or vertex that faces Q),
         * so that their gaps are the objects' own, however thick the region */
        const support *sp = pside == 0 ? &z.sa : &z.sb;
        int fp = np >= 3 ? contact_facing(P, v3_neg(m)) : -1;
        /* (more corners than room: every so many, around the whole region, so
         * that what they hold is still about its centre) */
        int take = z.n < max ? z.n : max;
        for (int k = 0; k < take; k++) {
            int i = z.n <= max ? k : (int)((long)k * z.n / take);
            vec3 x = v3_mad(region_world(&z, n, z.p[i]), m, half);
            lift(P, sp, np, fp, m, &x);
            out[count] = base;
            out[count++].sp = local_of(P, x);
        }
    } else {
        /* one point: on a face of b, on a face of a, two edges, or neither */
        cpoint *cp = &out[count++];
        if (r->fa.kind == CLOSEST_EDGE && r->fb.kind == CLOSEST_EDGE && edges_of(a, b, r, cp)) {
            free_points(z.pts, z.local);
            return count;
        }
        bool a_face = r->fa.kind == CLOSEST_FACE && r->fb.kind != CLOSEST_FACE;
        cp->p = a_face ? 1 : 0;
        cp->q = a_face ? 0 : 1;
        cp->r = 0;
        if (a_face) {
            plane_of(a, r->pa, v3_neg(n), cp);
            cp->sp = local_of(b, r->pb);
        } else {
            plane_of(b, r->pb, n, cp);
            cp->sp = local_of(a, r->pa);
        }
    }
    free_points(z.pts, z.local);
    return count;
}

int contact_cpoints(const body *a, const body *b, const piece_pairs *pp, const closest_result *r,
                    double tol, cpoint *out, int max)
{
    if (!body_compound(a) && !body_compound(b)) return cpoints_of(a, b, r, tol, out, max);
    /* bodies of several pieces: the points of every pair of their pieces that
     * touch, one contact problem (pieces.h); r's own pair first, as r has it */
    closest_result near[CONTACT_MAX_POINTS];
    int n = pieces_touching(a, b, pp, d_max(tol, r->distance), near, CONTACT_MAX_POINTS), count = 0;
    body ta, tb;
    count = cpoints_of(pieces_view(a, r->ka, &ta), pieces_view(b, r->kb, &tb), r, tol, out, max);
    for (int k = 0; k < n && count < max; k++) {
        if (near[k].ka == r->ka && near[k].kb == r->kb) continue;
        const body *va = pieces_view(a, near[k].ka, &ta), *vb = pieces_view(b, near[k].kb, &tb);
        count += cpoints_of(va, vb, &near[k], tol, out + count, max - count);
    }
    return count;
}

int contact_cpoints_of_pieces(const body *a, const body *b, const closest_result *r, double tol,
                              cpoint *out, int max)
{
    body ta, tb;
    return cpoints_of(pieces_view(a, r->ka, &ta), pieces_view(b, r->kb, &tb), r, tol, out, max);
}

/* The gap of EDGES point cp (see cpoint_eval), its normal and point. */
static double edges_eval(const cpoint *cp, const body *P, const body *Q, vec3 *n, vec3 *at)
{
    vec3 p0 = v3_add(P->x, q_rotate(P->q, cp->sp)), dp = q_rotate(P->q, cp->sd);
    vec3 q0 = v3_add(Q->x, q_rotate(Q->q, cp->f0)), dq = q_rotate(Q->q, cp->f1);
    vec3 c = v3_cross(dp, dq), w0 = v3_sub(p0, q0);
    double l = v3_len(c);
    if (!(l > CONTACT_EDGES_SIN)) {
        /* turned parallel: the distance of p's point from q's line */
        vec3 perp = v3_mad(w0, dq, -v3_dot(w0, dq));
        double d = v3_len(perp);
        *n = d > 0 ? v3_scale(perp, 1 / d) : v3_scale(c, cp->sgn / (l > 0 ? l : 1));
        *at = p0;
        return d;
    }
    vec3 m = v3_scale(c, cp->sgn / l);
    double b = v3_dot(dp, dq), s = (b * v3_dot(dq, w0) - v3_dot(dp, w0)) / (1 - b * b);
    *n = m;
    *at = v3_mad(p0, dp, s);
    return v3_dot(w0, m);
}

double cpoint_eval(const cpoint *cp, const body *P, const body *Q, vec3 *n, vec3 *at)
{
    if (cp->kind == CPT_EDGES) return edges_eval(cp, P, Q, n, at);
    vec3 pw = v3_add(P->x, q_rotate(P->q, cp->sp));
    vec3 pq = q_unrotate(Q->q, v3_sub(pw, Q->x));
    vec3 m;
    double gap;
    switch (cp->kind) {
    case CPT_PLANE:
        m = cp->f0;
        gap = v3_dot(cp->f0, pq) - cp->f1.x - cp->r;
        break;
    case CPT_LINE: {
        vec3 d = v3_sub(pq, cp->f0);
        vec3 perp = v3_mad(d, cp->f1, -v3_dot(d, cp->f1));
        double l = v3_len(perp);
        m = l > 0 ? v3_scale(perp, 1 / l) : v3(0, 0, 1);
        gap = l - cp->r;
        break;
    }
    default: {
        vec3 d = v3_sub(pq, cp->f0);
        double l = v3_len(d);
        m = l > 0 ? v3_scale(d, 1 / l) : v3(0, 0, 1);
        gap = l - cp->r;
        break;
    }
    }
    *n = q_rotate(Q->q, m);
    /* (on P's surface: two spheres' radii together less Q's) */
    double rp = cp->kind == CPT_POINT && Q->sp.kind == SHAPE_SPHERE ? cp->r - Q->sp.radius : cp->r;
    *at = v3_mad(pw, *n, -rp);
    return gap;
}

static bool holds(const body *m, const body *s, const closest_result *r, double tol, vec3 shift,
                  int *face);

bool contact_holds(const body *m0, const body *s0, const closest_result *r, double tol, int *face)
{
    return contact_holds_at(m0, s0, r, tol, v3(0, 0, 0), face);
}

bool contact_holds_at(const body *m0, const body *s0, const closest_result *r, double tol, vec3 shift,
                      int *face)
{
    body tm, ts;
    const body *m = pieces_view(m0, r->ka, &tm), *s = pieces_view(s0, r->kb, &ts);
    bool held = holds(m, s, r, tol, shift, face);
    if (*face >= 0) *face = shape_face_number(&s0->shape, r->kb, *face);
    return held;
}

/* contact_holds for one convex piece of each. */
static bool holds(const body *m, const body *s, const closest_result *r, double tol, vec3 shift,
                  int *face)
{
    *face = -1;
    const poly *h = s->shape.hull;
    if (!h) return false;
    /* the face of s the normal (from s to m) leaves by */
    vec3 nl = q_unrotate(s->q, r->normal);
    int fi = 0;
    for (int k = 1; k < h->nf; k++)
        if (v3_dot(h->f[k].n, nl) > v3_dot(h->f[fi].n, nl)) fi = k;
    if (v3_dot(h->f[fi].n, nl) < 1 - SIM_PARALLEL) {
        return false;
    }
    *face = fi;
    vec3 n = q_rotate(s->q, h->f[fi].n), u, v;
    plane_axes(n, &u, &v);
    vec3 c = v3_add(body_com(m), shift);
    p2 cp = {v3_dot(c, u), v3_dot(c, v)};
    /* (an area, and a length: a billionth of the size, squared and not) */
    double size = tol_size(m, s), round = tol_round(m, s);
    double margin = d_max(1e-9 * size * size, round * size);
    if (m->sp.kind == SHAPE_SPHERE) {
        /* the ball's lowest point, under its centre, on the face */
        const poly_face *F = &h->f[fi];
        p2 local[LOCAL_SUPPORT];
        p2 *pg = room_for(local, LOCAL_SUPPORT, F->count);
        if (!pg) return false;
        for (int k = 0; k < F->count; k++) {
            vec3 x = v3_add(s->x, q_rotate(s->q, h->v[h->face_vert[F->first + k]]));
            pg[k] = (p2){v3_dot(x, u), v3_dot(x, v)};
        }
        bool inside = true;
        for (int k = 0; k < F->count && inside; k++)
            if (cross2(pg[k], pg[(k + 1) % F->count], cp) < margin) inside = false;
        free_points(pg, local);
        return inside;
    }
    region z;
    bool inside = false;
    if (region_of(m, s, r, tol, &z) && z.n >= 1) {
        inside = z.n >= 3;
        for (int k = 0; k < z.n && inside; k++)
            if (cross2(z.p[k], z.p[(k + 1) % z.n], cp) < margin) inside = false;
        /* balanced: over the region's edge, or over a support that is a point or a
         * segment (a superquadric on its pole) */
        double reach = d_max(1e-9 * size, round);
        for (int k = 0; k < z.n && !inside; k++)
            inside = seg_dist2(z.p[k], z.p[(k + 1) % z.n], cp) <= reach * reach;
    }
    free_points(z.pts, z.local);
    return inside;
}

vec3 contact_point_velocity(const body *b, vec3 p)
{
    if (body_is_static(b) || b->state == STATE_RESTING) return v3(0, 0, 0);
    return v3_add(b->v, v3_cross(b->w, v3_sub(p, body_com(b))));
}

double contact_closing_speed(const body *a, const body *b, vec3 p, vec3 n)
{
    vec3 rel = v3_sub(contact_point_velocity(a, p), contact_point_velocity(b, p));
    return -v3_dot(rel, n);
}

bool contact_level(body *m, const body *s0, int face, double max_tilt, double gap)
{
    body ts;
    int k = shape_face_piece(&s0->shape, face, &face);
    if (k < 0) return false;
    const body *s = pieces_view(s0, k, &ts);
    const poly *hs = s->shape.hull, *hm = m->shape.hull;
    if (!hs || !hm || m->sp.kind == SHAPE_SPHERE || face < 0 || face >= hs->nf) return false;
    vec3 n = q_rotate(s->q, hs->f[face].n);
    int fm = contact_facing(m, v3_neg(n));
    vec3 nm = q_rotate(m->q, hm->f[fm].n), want = v3_neg(n);
    vec3 axis = v3_cross(nm, want);
    double sn = v3_len(axis), cs = v3_dot(nm, want), angle = atan2(sn, cs);
    if (!(angle <= max_tilt)) return false;
    vec3 c = body_com(m);
    if (sn > 0) {
        /* turned about its centre of mass, flat on the face */
        quat turn = q_axis_angle(v3_scale(axis, 1 / sn), angle);
        m->q = q_normalize(q_mul(turn, m->q));
        m->x = v3_add(c, q_rotate(turn, v3_sub(m->x, c)));
        m->rot_given = false;
        body_update_w(m);
    }
    /* and on its plane */
    vec3 on_s = v3_add(s->x, q_rotate(s->q, hs->v[hs->face_vert[hs->f[face].first]]));
    vec3 on_m = v3_add(m->x, q_rotate(m->q, hm->v[hm->face_vert[hm->f[fm].first]]));
    m->x = v3_mad(m->x, n, gap - v3_dot(v3_sub(on_m, on_s), n));
    return true;
}
