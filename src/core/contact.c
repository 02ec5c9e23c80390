/* contact.c: contact region and collision impulse (thesis 3.2.2; design.md,
 * "Dynamics").
 *
 * The impulse j along the normal n solves the thesis's momentum equations with
 * restitution e for the normal component of the relative velocity at the contact
 * point:  j = (1 + e) s / (1/m_a + 1/m_b + n.((I_a^-1 (r_a x n)) x r_a)
 *                                     + n.((I_b^-1 (r_b x n)) x r_b)),
 * s the closing speed.  The contact region is found from the objects' supporting
 * features along n, projected onto the contact plane: a vertex, a segment or a
 * convex polygon each; their overlap's centre is the contact point.
 */
#include "contact.h"

#include <assert.h>

#include <stdlib.h>
#include <string.h>

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

/* The same for any hull, by a walk: the furthest vertex is reached along edges
 * that go further (poly_climb); and each vertex within tol of it has an edge to
 * one further on, so they are all reached from it through such vertices.  0 when
 * out of memory. */
static int support_walk(const poly *h, vec3 dl, double tol, int *idx, int max)
{
    int top = poly_climb(h, dl, 0);
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
                                 : support_walk(h, dl, tol, s->idx, max);
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

/* The contact region of a and b (see contact_point), in the contact plane's
 * coordinates (u, v), the plane at height h along the normal. */
typedef struct {
    vec3 u, v;
    double h;
    int n;    /* corners: 2 a segment's ends, >= 3 a polygon's (ccw); 0 no overlap */
    p2 *p;    /* the corners */
    p2 c;     /* the centre */
    p2 *pts;  /* where the points are worked on: local, or allocated */
    p2 local[12 * LOCAL_SUPPORT];
    support sa, sb; /* the supporting sets of the two objects */
} region;

/* Finds the region: false when out of memory.  n is 0 when the features do not
 * overlap, or when one is a vertex or a sphere: the midpoint of the closest points
 * is the contact point then. */
static bool region_of(const body *a, const body *b, const closest_result *r, double tol,
                      region *z)
{
    vec3 n = r->normal;
    z->n = 0;
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
    double eps = 1e-12 * (a->shape.r_out + b->shape.r_out) * (a->shape.r_out + b->shape.r_out);
    int na = hull2(sa, ka, eps), nb = hull2(sb, kb, eps);
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
    }
    return true;
}

/* Point c of the region's plane, in world axes (n = u x v). */
static vec3 region_world(const region *z, vec3 n, p2 c)
{
    return v3_add(v3_add(v3_scale(z->u, c.x), v3_scale(z->v, c.y)), v3_scale(n, z->h));
}

vec3 contact_point(const body *a, const body *b, const closest_result *r, double tol)
{
    region z;
    vec3 p = v3_scale(v3_add(r->pa, r->pb), 0.5);
    if (region_of(a, b, r, tol, &z) && z.n > 0) p = region_world(&z, r->normal, z.c);
    free_points(z.pts, z.local);
    return p;
}

vec3 contact_closing_corner(const body *a, const body *b, const closest_result *r, double tol,
                            vec3 p)
{
    region z;
    if (region_of(a, b, r, tol, &z)) {
        double best = 0;
        for (int i = 0; i < z.n; i++) {
            vec3 c = region_world(&z, r->normal, z.p[i]);
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

bool contact_stable(const body *m, vec3 n, double tol)
{
    if (m->sp.kind == SHAPE_SPHERE) return true;
    vec3 u, v;
    plane_axes(n, &u, &v);
    support f;
    support_find(m, v3_neg(n), tol, &f);
    p2 local[2 * LOCAL_SUPPORT];
    p2 *s = room_for(local, 2 * LOCAL_SUPPORT, 2 * f.n + 1); /* and room for its hull */
    if (!s) return false;
    support_place(m, v3_neg(n), &f, u, v, s);
    double r = m->shape.r_out;
    int k = hull2(s, f.n, 1e-12 * r * r);
    vec3 c = body_com(m);
    p2 cp = {v3_dot(c, u), v3_dot(c, v)};
    bool inside = k >= 3;
    for (int i = 0; i < k && inside; i++)
        if (cross2(s[i], s[(i + 1) % k], cp) < 1e-9 * r * r) inside = false;
    free_points(s, local);
    return inside;
}

double contact_footprint(const body *m, vec3 n, double tol)
{
    vec3 u, v;
    plane_axes(n, &u, &v);
    support f;
    support_find(m, v3_neg(n), tol, &f);
    p2 local[LOCAL_SUPPORT];
    p2 *s = room_for(local, LOCAL_SUPPORT, f.n);
    if (!s) return HUGE_VAL;
    support_place(m, v3_neg(n), &f, u, v, s);
    int k = f.n;
    vec3 c = body_com(m);
    double cu = v3_dot(c, u), cv = v3_dot(c, v), r = k > 0 ? 0 : HUGE_VAL;
    for (int i = 0; i < k; i++) r = d_max(r, hypot(s[i].x - cu, s[i].y - cv));
    free_points(s, local);
    return r;
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

/* n . ((I^-1 (r x n)) x r): the rotational part of the effective inverse mass. */
static double angular_term(const body *b, vec3 r, vec3 n)
{
    if (body_is_static(b)) return 0;
    vec3 t = body_inertia_inv_mulv(b, v3_cross(r, n));
    return v3_dot(n, v3_cross(t, r));
}

contact contact_respond(body *a, body *b, vec3 p, vec3 n, double e, int held, vec3 s)
{
    assert(fabs(v3_len2(n) - 1) < 1e-9 && e >= 0);
    contact c = {p, n, contact_closing_speed(a, b, p, n), 0};
    if (c.speed <= 0) return c;
    vec3 ra = v3_sub(p, body_com(a)), rb = v3_sub(p, body_com(b));
    bool move_a = !body_is_static(a) && held != 1, move_b = !body_is_static(b) && held != 2;
    /* the held one moves across s only: n's part across s, times its inverse mass */
    vec3 across = v3_len2(s) > 0 ? v3_mad(n, s, -v3_dot(n, s)) : v3(0, 0, 0);
    const body *h = held == 1 ? a : held == 2 ? b : NULL;
    double k = (move_a ? a->inv_mass + angular_term(a, ra, n) : 0) +
               (move_b ? b->inv_mass + angular_term(b, rb, n) : 0) +
               (h && !body_is_static(h) ? h->inv_mass * v3_dot(across, n) : 0);
    if (!(k > 0)) return c;
    double j = (1 + e) * c.speed / k;
    vec3 J = v3_scale(n, j);
    if (move_a) {
        a->v = v3_mad(a->v, J, a->inv_mass);
        a->L = v3_add(a->L, v3_cross(ra, J));
        body_update_w(a);
    }
    if (move_b) {
        b->v = v3_mad(b->v, J, -b->inv_mass);
        b->L = v3_sub(b->L, v3_cross(rb, J));
        body_update_w(b);
    }
    if (held == 1 && !body_is_static(a)) a->v = v3_mad(a->v, across, j * a->inv_mass);
    if (held == 2 && !body_is_static(b)) b->v = v3_mad(b->v, across, -j * b->inv_mass);
    c.impulse = j;
    return c;
}

/* The shortest rotation taking unit vector a onto unit vector b. */
static quat rotation_between(vec3 a, vec3 b)
{
    vec3 axis = v3_cross(a, b);
    double s = v3_len(axis), c = v3_dot(a, b);
    if (s < 1e-15) {
        if (c > 0) return q_identity();
        vec3 p = fabs(a.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
        return q_axis_angle(v3_norm(v3_cross(a, p)), M_PI);
    }
    return q_axis_angle(v3_scale(axis, 1 / s), atan2(s, c));
}

bool contact_settle_pose(const body *m, vec3 n, double max_angle, quat *q, double *height)
{
    const poly *h = m->shape.hull;
    if (!h) return false;
    vec3 com = m->shape.mass.com, down = q_unrotate(m->q, v3_neg(n));
    double margin = 1e-3 * m->shape.r_out, best = cos(max_angle);
    int pick = -1;
    for (int f = 0; f < h->nf; f++) {
        const poly_face *F = &h->f[f];
        double c = v3_dot(F->n, down);
        if (c <= best) continue;
        /* stable: the centre of mass, dropped onto the face's plane, lies inside the
         * face by margin */
        vec3 p = v3_mad(com, F->n, F->d - v3_dot(F->n, com));
        bool inside = true;
        for (int k = 0; k < F->count && inside; k++) {
            vec3 a = h->v[h->face_vert[F->first + k]];
            vec3 b = h->v[h->face_vert[F->first + (k + 1) % F->count]];
            vec3 e = v3_sub(b, a);
            double l = v3_len(e);
            if (l > 0 && v3_dot(v3_cross(e, v3_sub(p, a)), F->n) < margin * l) inside = false;
        }
        if (inside) {
            best = c;
            pick = f;
        }
    }
    if (pick < 0) return false;
    const poly_face *F = &h->f[pick];
    /* turn the face's normal, in world axes, onto -n */
    *q = q_normalize(q_mul(rotation_between(q_rotate(m->q, F->n), v3_neg(n)), m->q));
    *height = F->d - v3_dot(F->n, com);
    return true;
}
