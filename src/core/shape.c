/* shape.c: the thesis's primitives (sphere, cube, superquadric; Tables A.2 to A.4)
 * and polyhedra given as point sets turned into a drawing mesh, a collision
 * polyhedron and mass properties.
 *
 * Spheres and cubes have closed-form mass properties; a superquadric's are those of
 * its collision polyhedron, the convex hull of its tessellation (poly.c), which is
 * what collides.  The superquadric is Barr's superellipsoid (Barr 1981,
 * "Superquadrics and angle-preserving transformations"), with the normal
 *   n = (c(eta,2-e1) c(omega,2-e2) / a1, c(eta,2-e1) s(omega,2-e2) / a2, s(eta,2-e1) / a3)
 * where it is finite; at cusps (exponents >= 2 where a cosine or sine vanishes) the
 * mesh takes the area-weighted mean of the neighbouring triangles' normals.
 * Angles are multiples of pi / (2 vres) and 2 pi / ures, so their sines and cosines
 * are computed by octant reduction: exactly 0 and 1 at the axes and symmetric, so
 * that |cos|^e with a small e gives no stray points near the poles and axes.
 * A polyhedron (the thesis's future work, 6.2) collides as the exact convex hull of
 * its source's points, scaled, and has that hull's mass properties; it is drawn
 * with its source's own mesh (normals turned by the inverse of the scale).
 */
#include "shape.h"

#include "closest.h"
#include "errmsg.h"
#include "limits.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* A hull's failure (poly.h) for a message that names the shape: without the
 * "convex hull: " it starts with. */
static const char *strip_hull(const char *why)
{
    const char *p = "convex hull: ";
    return strncmp(why, p, strlen(p)) == 0 ? why + strlen(p) : why;
}

shape_params shape_defaults(shape_kind kind)
{
    return (shape_params){.kind = kind,
                          .radius = 1,
                          .size = v3(1, 1, 1),
                          .exp1 = 1,
                          .exp2 = 1,
                          .a1 = 1,
                          .a2 = 1,
                          .a3 = 1,
                          .ures = 10,
                          .vres = 10,
                          .scale = v3(1, 1, 1),
                          .src = NULL};
}

void shape_free(shape *s)
{
    if (!s) return;
    closest_hull_free(s->feat);
    poly_free(s->hull);
    if (!s->draw_borrowed) {
        free(s->draw.pos);
        free(s->draw.nrm);
        free(s->draw.tri);
    }
    memset(s, 0, sizeof *s);
}

/* ---- the superquadric tessellation ---- */

/* sin and cos of pi k / m, exact at multiples of pi / 2 and symmetric about them. */
static void sincos_pi(long k, long m, double *s, double *c)
{
    double ss = 1, sc = 1;
    k %= 2 * m;
    if (k < 0) k += 2 * m;
    if (k >= m) { /* x + pi */
        k -= m;
        ss = sc = -1;
    }
    if (2 * k > m) { /* pi - x */
        k = m - k;
        sc = -sc;
    }
    double sv, cv;
    if (4 * k > m) { /* x = pi/2 - y */
        double y = PI * (double)(m - 2 * k) / (double)(2 * m);
        sv = cos(y);
        cv = sin(y);
    } else {
        double x = PI * (double)k / (double)m;
        sv = sin(x);
        cv = cos(x);
    }
    *s = ss * sv;
    *c = sc * cv;
}

/* sign(v) |v|^e; at v = 0 it is 0 for e > 0 and undefined (NaN) otherwise. */
static double spow(double v, double e)
{
    if (v == 0) return e > 0 ? 0.0 : NAN;
    return copysign(pow(fabs(v), e), v);
}

/* The angles of the tessellation: eta_j = -pi/2 + pi j / vres (j = 0 and vres are
 * the poles), omega_i = -pi + 2 pi i / ures. */
typedef struct {
    double se, ce, so, co;
} sq_angle;

static sq_angle sq_at(const shape_params *p, int j, int i)
{
    sq_angle a;
    sincos_pi(2L * j - p->vres, 2L * p->vres, &a.se, &a.ce);
    sincos_pi(2L * i - p->ures, p->ures, &a.so, &a.co);
    return a;
}

static vec3 sq_point(const shape_params *p, sq_angle a)
{
    double ce = spow(a.ce, p->exp1);
    return v3(p->a1 * ce * spow(a.co, p->exp2), p->a2 * ce * spow(a.so, p->exp2),
              p->a3 * spow(a.se, p->exp1));
}

/* The analytic outward normal (not unit), NaN where the surface has a cusp. */
static vec3 sq_normal(const shape_params *p, sq_angle a)
{
    double ce = spow(a.ce, 2 - p->exp1);
    return v3(ce * spow(a.co, 2 - p->exp2) / p->a1, ce * spow(a.so, 2 - p->exp2) / p->a2,
              spow(a.se, 2 - p->exp1) / p->a3);
}

static int sq_count(const shape_params *p)
{
    long long n = (long long)p->ures * (p->vres - 1) + 2;
    return n > INT_MAX / 8 ? -1 : (int)n;
}

int superquadric_points(const shape_params *p, vec3 *out, int max)
{
    int n = sq_count(p), k = 0;
    if (n < 0) return -1;
    if (out && k < max) out[k] = sq_point(p, sq_at(p, 0, 0));
    k++;
    for (int j = 1; j < p->vres; j++)
        for (int i = 0; i < p->ures; i++, k++)
            if (out && k < max) out[k] = sq_point(p, sq_at(p, j, i));
    if (out && k < max) out[k] = sq_point(p, sq_at(p, p->vres, 0));
    return n;
}

static int mesh_alloc(mesh *m, int nv, int nt)
{
    m->nv = nv;
    m->nt = nt;
    m->pos = malloc((size_t)nv * sizeof *m->pos);
    m->nrm = malloc((size_t)nv * sizeof *m->nrm);
    m->tri = malloc((size_t)nt * sizeof *m->tri);
    return m->pos && m->nrm && m->tri ? 0 : -1;
}

static void put_tri(int (*tri)[3], int *t, int a, int b, int c)
{
    tri[*t][0] = a;
    tri[*t][1] = b;
    tri[*t][2] = c;
    (*t)++;
}

/* Triangles of the tessellation, ccw seen from outside: a quad between ring j and
 * ring j + 1 is (j,i) (j,i+1) (j+1,i+1) (j+1,i); the caps are fans about the poles. */
static void sq_triangles(const shape_params *p, int (*tri)[3])
{
    int u = p->ures, top = p->vres - 1, north = u * top + 1, t = 0;
#define RING(j, i) (1 + ((j) - 1) * u + ((i) % u))
    for (int i = 0; i < u; i++) {
        put_tri(tri, &t, 0, RING(1, i + 1), RING(1, i));
        put_tri(tri, &t, RING(top, i), RING(top, i + 1), north);
    }
    for (int j = 1; j < top; j++)
        for (int i = 0; i < u; i++) {
            put_tri(tri, &t, RING(j, i), RING(j, i + 1), RING(j + 1, i + 1));
            put_tri(tri, &t, RING(j, i), RING(j + 1, i + 1), RING(j + 1, i));
        }
#undef RING
}

/* Unit normals: analytic where finite, else the area-weighted mean of the
 * neighbouring triangles' normals, else the direction from the centre. */
static void sq_normals(const shape_params *p, mesh *m)
{
    for (int v = 0; v < m->nv; v++) m->nrm[v] = v3(0, 0, 0);
    for (int t = 0; t < m->nt; t++) {
        vec3 a = m->pos[m->tri[t][0]], b = m->pos[m->tri[t][1]], c = m->pos[m->tri[t][2]];
        vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
        for (int k = 0; k < 3; k++) m->nrm[m->tri[t][k]] = v3_add(m->nrm[m->tri[t][k]], n);
    }
    for (int v = 0; v < m->nv; v++) {
        vec3 n = v3(NAN, NAN, NAN);
        if (v == 0 || v == m->nv - 1) {
            if (p->exp1 < 2) n = v3(0, 0, v == 0 ? -1 : 1);
        } else {
            int j = 1 + (v - 1) / p->ures, i = (v - 1) % p->ures;
            n = sq_normal(p, sq_at(p, j, i));
        }
        if (!v3_finite(n) || !(v3_len(n) > 0)) n = m->nrm[v];
        if (!v3_finite(n) || !(v3_len(n) > 0)) n = m->pos[v];
        m->nrm[v] = v3_norm(n);
    }
}

/* The tessellation as a smooth triangle mesh. */
static int sq_mesh(const shape_params *p, mesh *m)
{
    int nv = sq_count(p);
    if (nv < 0 || mesh_alloc(m, nv, 2 * p->ures * (p->vres - 1)) < 0) return -1;
    superquadric_points(p, m->pos, nv);
    sq_triangles(p, m->tri);
    sq_normals(p, m);
    return 0;
}

/* ---- the cube ---- */

/* 24 vertices (4 per face, flat normals) and 12 triangles. */
static int cube_mesh(vec3 h, mesh *m)
{
    if (mesh_alloc(m, 24, 12) < 0) return -1;
    double hh[3] = {h.x, h.y, h.z};
    int v = 0, t = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int s = -1; s <= 1; s += 2) {
            int u = (axis + 1) % 3, w = (axis + 2) % 3;
            if (s < 0) { /* keep u x w = outward normal */
                int x = u;
                u = w;
                w = x;
            }
            static const double su[4] = {-1, 1, 1, -1}, sw[4] = {-1, -1, 1, 1};
            for (int k = 0; k < 4; k++) {
                double c[3], n[3] = {0, 0, 0};
                c[axis] = s * hh[axis];
                c[u] = su[k] * hh[u];
                c[w] = sw[k] * hh[w];
                n[axis] = s;
                m->pos[v + k] = v3(c[0], c[1], c[2]);
                m->nrm[v + k] = v3(n[0], n[1], n[2]);
            }
            m->tri[t][0] = v, m->tri[t][1] = v + 1, m->tri[t++][2] = v + 2;
            m->tri[t][0] = v, m->tri[t][1] = v + 2, m->tri[t++][2] = v + 3;
            v += 4;
        }
    return 0;
}

static mass_props box_mass(vec3 h)
{
    double vol = 8 * h.x * h.y * h.z;
    double xx = h.x * h.x, yy = h.y * h.y, zz = h.z * h.z;
    return (mass_props){vol, v3(0, 0, 0),
                        m3_diag(v3_scale(v3(yy + zz, xx + zz, xx + yy), vol / 3))};
}

/* ---- building ---- */

static int build_sphere(shape *s, char *err, size_t errlen)
{
    double r = s->p.radius;
    shape_params ball = s->p;
    ball.a1 = ball.a2 = ball.a3 = r;
    ball.exp1 = ball.exp2 = 1;
    if (sq_count(&ball) < 0 || sq_mesh(&ball, &s->draw) < 0) {
        errmsg_set(err, errlen, "sphere: resolution %d x %d is too large", s->p.ures,
                s->p.vres);
        return -1;
    }
    double vol = 4.0 / 3.0 * PI * r * r * r;
    s->mass = (mass_props){vol, v3(0, 0, 0), m3_scale(m3_identity(), 0.4 * vol * r * r)};
    s->r_in = s->r_out = r;
    return 0;
}

/* The box of half-extents h: a cube's, or a polyhedron's without a source (what
 * names it in messages). */
static int build_box(shape *s, vec3 h, const char *what, char *err, size_t errlen)
{
    char why[200];
    double big = 2 * fmax(h.x, fmax(h.y, h.z));
    /* (as poly_hull would say of its corners) */
    if (!(8 * h.x * h.y * h.z > 1e-12 * big * big * big))
        snprintf(why, sizeof why, "the solid is too thin: its volume is under 1e-12 of the cube "
                 "around it");
    else
        s->hull = poly_box(h, why, sizeof why); /* (its hull is known: no qhull run) */
    if (!s->hull && strstr(why, "out of memory")) {
        errmsg_set(err, errlen, "%s: out of memory", what);
        return -1;
    }
    if (!s->hull) {
        errmsg_set(err, errlen, "%s (%.6g, %.6g, %.6g) cannot be built: %s", what, h.x, h.y, h.z,
                strip_hull(why));
        return -1;
    }
    if (cube_mesh(h, &s->draw) < 0) {
        errmsg_set(err, errlen, "%s: out of memory", what);
        return -1;
    }
    s->mass = box_mass(h);
    s->r_in = fmin(h.x, fmin(h.y, h.z));
    s->r_out = v3_len(h);
    return 0;
}

/* ---- polyhedra from point sets ---- */

/* A mesh of the hull's faces (fans, flat normals): what a source without faces
 * draws. */
static int hull_mesh(const poly *h, mesh *m)
{
    int nv = 0, nt = 0;
    for (int f = 0; f < h->nf; f++) {
        nv += h->f[f].count;
        nt += h->f[f].count - 2;
    }
    if (mesh_alloc(m, nv, nt) < 0) return -1;
    int v = 0, t = 0;
    for (int f = 0; f < h->nf; f++) {
        const poly_face *pf = &h->f[f];
        for (int k = 0; k < pf->count; k++) {
            m->pos[v + k] = h->v[h->face_vert[pf->first + k]];
            m->nrm[v + k] = pf->n;
        }
        for (int k = 1; k + 1 < pf->count; k++) put_tri(m->tri, &t, v, v + k, v + k + 1);
        v += pf->count;
    }
    return 0;
}

/* The source's mesh at scale k: its own when k is 1 (borrowed), else a copy with
 * the positions scaled and the normals turned by the inverse scale. */
static int scaled_mesh(shape *s, const mesh *src, vec3 k)
{
    if (k.x == 1 && k.y == 1 && k.z == 1) {
        s->draw = *src;
        s->draw_borrowed = true;
        return 0;
    }
    mesh *m = &s->draw;
    if (mesh_alloc(m, src->nv, src->nt) < 0) return -1;
    for (int v = 0; v < src->nv; v++) {
        vec3 p = src->pos[v], n = src->nrm[v];
        m->pos[v] = v3(p.x * k.x, p.y * k.y, p.z * k.z);
        m->nrm[v] = v3_norm(v3(n.x / k.x, n.y / k.y, n.z / k.z));
    }
    memcpy(m->tri, src->tri, (size_t)src->nt * sizeof *m->tri);
    return 0;
}

static int build_polyhedron(shape *s, char *err, size_t errlen)
{
    const shape_source *src = s->p.src;
    vec3 k = s->p.scale;
    if (!src) return build_box(s, k, "polyhedron: the box of scale", err, errlen);
    vec3 *pts = malloc((size_t)(src->np > 0 ? src->np : 1) * sizeof *pts);
    if (!pts) {
        errmsg_set(err, errlen, "polyhedron: out of memory for %d points", src->np);
        return -1;
    }
    for (int i = 0; i < src->np; i++) {
        vec3 p = src->pts[i], q = v3(p.x * k.x, p.y * k.y, p.z * k.z);
        if (!(fabs(q.x) <= LIM_LENGTH_MAX && fabs(q.y) <= LIM_LENGTH_MAX &&
              fabs(q.z) <= LIM_LENGTH_MAX)) {
            errmsg_set(err, errlen,
                    "polyhedron: scaled by (%.6g, %.6g, %.6g), the point (%.6g, %.6g, %.6g) lies "
                    "beyond %g m of its origin",
                    k.x, k.y, k.z, q.x, q.y, q.z, LIM_LENGTH_MAX);
            free(pts);
            return -1;
        }
        pts[i] = q;
    }
    char why[200];
    /* the exact hull: "the hull of all its vertices", and shape_off_hull's test is
     * then exact too */
    s->hull = poly_hull_merge(pts, src->np, 0, why, sizeof why);
    free(pts);
    if (!s->hull) {
        errmsg_set(err, errlen, "polyhedron: its %d points make no solid: %s", src->np,
                strip_hull(why));
        return -1;
    }
    int rc = src->draw.nt > 0 ? scaled_mesh(s, &src->draw, k) : hull_mesh(s->hull, &s->draw);
    if (rc < 0) {
        errmsg_set(err, errlen, "polyhedron: out of memory for its mesh");
        return -1;
    }
    s->mass = poly_mass(s->hull);
    s->r_in = poly_inner_radius(s->hull, s->mass.com);
    s->r_out = poly_outer_radius(s->hull, s->mass.com);
    return 0;
}

long shape_off_hull(const shape *s)
{
    const poly *h = s->hull;
    const mesh *m = &s->draw;
    if (!h || s->p.kind != SHAPE_POLYHEDRON) return 0;
    double tol = 1e-6 * s->r_out;
    long off = 0;
    int j = 0;
    for (int t = 0; t < m->nt; t++) {
        vec3 a = m->pos[m->tri[t][0]], b = m->pos[m->tri[t][1]], c = m->pos[m->tri[t][2]];
        vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
        if (!(v3_len(n) > 0)) continue; /* no plane to test */
        n = v3_norm(n);
        vec3 mid = v3_scale(v3_add(a, v3_add(b, c)), 1.0 / 3);
        bool on = false;
        for (int side = 0; side < 2 && !on; side++, n = v3_neg(n)) {
            j = poly_climb(h, n, j);
            on = v3_dot(n, v3_sub(h->v[j], mid)) <= tol;
        }
        if (!on) off++;
    }
    return off;
}

static int build_superquadric(shape *s, char *err, size_t errlen)
{
    if (sq_count(&s->p) < 0) {
        errmsg_set(err, errlen, "superquadric: resolution %d x %d is too large", s->p.ures,
                s->p.vres);
        return -1;
    }
    if (sq_mesh(&s->p, &s->draw) < 0) {
        errmsg_set(err, errlen, "superquadric: out of memory at resolution %d x %d",
                s->p.ures, s->p.vres);
        return -1;
    }
    char why[200];
    s->hull = poly_hull(s->draw.pos, s->draw.nv, why, sizeof why);
    if (!s->hull && strstr(why, "out of memory")) { /* not the shape's fault */
        errmsg_set(err, errlen, "superquadric: out of memory");
        return -1;
    }
    if (!s->hull) {
        errmsg_set(err, errlen,
                "superquadric: a1 %.6g, a2 %.6g, a3 %.6g with exp1 %.6g, exp2 %.6g cannot be "
                "built: %s",
                s->p.a1, s->p.a2, s->p.a3, s->p.exp1, s->p.exp2, strip_hull(why));
        return -1;
    }
    s->mass = poly_mass(s->hull);
    /* with an even ures the tessellation is symmetric about its centre (omega and
     * omega + pi both occur), so that its centre of mass is there: the hull's
     * integration leaves only rounding (1e-17 m) */
    if (s->p.ures % 2 == 0) s->mass.com = v3(0, 0, 0);
    s->r_in = poly_inner_radius(s->hull, s->mass.com);
    s->r_out = poly_outer_radius(s->hull, s->mass.com);
    return 0;
}

int shape_build(shape *s, const shape_params *p, char *err, size_t errlen)
{
    shape_params params = *p; /* p may point into s */
    memset(s, 0, sizeof *s);
    s->p = params;
    int rc;
    switch (params.kind) {
    case SHAPE_SPHERE: rc = build_sphere(s, err, errlen); break;
    case SHAPE_CUBE: rc = build_box(s, params.size, "cube: size", err, errlen); break;
    case SHAPE_SUPERQUADRIC: rc = build_superquadric(s, err, errlen); break;
    case SHAPE_POLYHEDRON: rc = build_polyhedron(s, err, errlen); break;
    default:
        errmsg_set(err, errlen, "unknown shape kind %d", (int)params.kind);
        rc = -1;
    }
    if (rc == 0) { /* one piece, and the bounding box, in body axes */
        s->pieces = 1;
        vec3 r = v3(s->p.radius, s->p.radius, s->p.radius);
        s->box_lo = v3_neg(r);
        s->box_hi = r;
        for (int k = 0; s->hull && k < s->hull->nv; k++) {
            vec3 v = s->hull->v[k];
            if (k == 0) s->box_lo = s->box_hi = v;
            s->box_lo = v3(fmin(s->box_lo.x, v.x), fmin(s->box_lo.y, v.y), fmin(s->box_lo.z, v.z));
            s->box_hi = v3(fmax(s->box_hi.x, v.x), fmax(s->box_hi.y, v.y), fmax(s->box_hi.z, v.z));
        }
    }
    /* the Voronoi regions of the hull's features, for closest-feature tracking */
    if (rc == 0 && s->hull && !(s->feat = closest_hull_new(s->hull))) {
        errmsg_set(err, errlen, "out of memory for the closest-feature data");
        rc = -1;
    }
    if (rc < 0) shape_free(s);
    return rc;
}
