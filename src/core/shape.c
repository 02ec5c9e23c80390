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
 * A polyhedron (the thesis's future work, 6.2) collides as the exact convex hulls
 * of its source's pieces, scaled: a rigid union of convex pieces (Mirtich 1998,
 * V-Clip on hierarchies of convex pieces; Bullet's btCompoundShape), or one hull.
 * A static piece whose faces close no volume (a room's wall as one face) becomes
 * one slab per face, `thickness` behind it.  Mass properties: one convex piece's
 * hull's; a closed, consistently oriented mesh's by the signed tetrahedra sum
 * (Blow and Binstock 2004: each triangle with the origin is a tetrahedron whose
 * covariance has a closed form); else the pieces' hulls' summed.  It is drawn
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
                          .src = NULL,
                          .thickness = 0.02};
}

void shape_free(shape *s)
{
    if (!s) return;
    closest_hull_free(s->feat);
    poly_free(s->hull);
    for (int k = 0; s->piece && k < s->pieces; k++) {
        closest_hull_free(s->piece[k].feat);
        poly_free(s->piece[k].hull);
    }
    free(s->piece);
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

/* The powers each point's coordinates take of its ring's and its column's sines
 * and cosines, found once per ring and per column (a point multiplies them as
 * sq_point and sq_normal would: the same numbers, to the bit). */
typedef struct {
    double ce, se, so, co;     /* sq_angle's */
    double pce, pse, pco, pso; /* spow of those at the surface's exponents */
    double nce, nse, nco, nso; /* ... and at the normal's, 2 - exponent */
} sq_power;

/* Ring j's (eta) powers in r, column i's (omega) in c. */
static void sq_powers(const shape_params *p, int j, int i, sq_power *r, sq_power *c)
{
    sq_angle a = sq_at(p, j, i);
    if (r) {
        r->ce = a.ce, r->se = a.se;
        r->pce = spow(a.ce, p->exp1), r->pse = spow(a.se, p->exp1);
        r->nce = spow(a.ce, 2 - p->exp1), r->nse = spow(a.se, 2 - p->exp1);
    }
    if (c) {
        c->co = a.co, c->so = a.so;
        c->pco = spow(a.co, p->exp2), c->pso = spow(a.so, p->exp2);
        c->nco = spow(a.co, 2 - p->exp2), c->nso = spow(a.so, 2 - p->exp2);
    }
}

static vec3 sq_point_of(const shape_params *p, const sq_power *r, const sq_power *c)
{
    return v3(p->a1 * r->pce * c->pco, p->a2 * r->pce * c->pso, p->a3 * r->pse);
}

int superquadric_points(const shape_params *p, vec3 *out, int max)
{
    int n = sq_count(p), k = 0;
    if (n < 0) return -1;
    sq_power *col = out ? malloc((size_t)p->ures * sizeof *col) : NULL;
    if (out && !col) { /* (out of memory: point by point) */
        if (k < max) out[k] = sq_point(p, sq_at(p, 0, 0));
        k++;
        for (int j = 1; j < p->vres; j++)
            for (int i = 0; i < p->ures; i++, k++)
                if (k < max) out[k] = sq_point(p, sq_at(p, j, i));
        if (k < max) out[k] = sq_point(p, sq_at(p, p->vres, 0));
        return n;
    }
    if (out && k < max) out[k] = sq_point(p, sq_at(p, 0, 0));
    k++;
    for (int i = 0; col && i < p->ures; i++) sq_powers(p, 1, i, NULL, &col[i]);
    for (int j = 1; j < p->vres; j++) {
        sq_power ring;
        if (out) sq_powers(p, j, 0, &ring, NULL);
        for (int i = 0; i < p->ures; i++, k++)
            if (out && k < max) out[k] = sq_point_of(p, &ring, &col[i]);
    }
    if (out && k < max) out[k] = sq_point(p, sq_at(p, p->vres, 0));
    free(col);
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
    sq_power *col = malloc((size_t)p->ures * sizeof *col), ring = {0};
    for (int i = 0; col && i < p->ures; i++) sq_powers(p, 1, i, NULL, &col[i]);
    for (int v = 0; v < m->nv; v++) {
        vec3 n = v3(NAN, NAN, NAN);
        if (v == 0 || v == m->nv - 1) {
            if (p->exp1 < 2) n = v3(0, 0, v == 0 ? -1 : 1);
        } else {
            int j = 1 + (v - 1) / p->ures, i = (v - 1) % p->ures;
            if (!col) {
                n = sq_normal(p, sq_at(p, j, i));
            } else {
                if (i == 0) sq_powers(p, j, 0, &ring, NULL);
                /* (sq_normal's products, from the powers found once) */
                n = v3(ring.nce * col[i].nco / p->a1, ring.nce * col[i].nso / p->a2, ring.nse / p->a3);
            }
        }
        if (!v3_finite(n) || !(v3_len(n) > 0)) n = m->nrm[v];
        if (!v3_finite(n) || !(v3_len(n) > 0)) n = m->pos[v];
        m->nrm[v] = v3_norm(n);
    }
    free(col);
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
    if (sq_count(&ball) < 0) {
        errmsg_set(err, errlen, "sphere: resolution %d x %d is too large", s->p.ures,
                s->p.vres);
        return -1;
    }
    if (sq_mesh(&ball, &s->draw) < 0) {
        errmsg_set(err, errlen, "sphere: out of memory at resolution %d x %d", s->p.ures,
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

/* ---- polyhedra: one hull, or a union of convex pieces ---- */

static int cmp_ll(const void *x, const void *y)
{
    long long a = *(const long long *)x, b = *(const long long *)y;
    return (a > b) - (a < b);
}

/* True when faces first .. last - 1 of src close volumes consistently oriented:
 * every edge that a face runs from u to v another runs from v to u, as often
 * (their boundary is empty).  Sorts the directed edges: n log n. */
static bool faces_closed(const shape_source *src, int first, int last)
{
    long ne = src->face_first[last] - src->face_first[first];
    if (last - first < 4) return false;
    long long *e = malloc((size_t)ne * sizeof *e), *r = malloc((size_t)ne * sizeof *r);
    bool closed = e && r;
    long n = 0;
    for (int f = first; f < last && closed; f++) {
        int a = src->face_first[f], b = src->face_first[f + 1];
        for (int k = a; k < b; k++) {
            long long u = src->corner[k], v = src->corner[k + 1 < b ? k + 1 : a];
            e[n] = u * 2147483648LL + v;
            r[n++] = v * 2147483648LL + u;
        }
    }
    if (closed) {
        qsort(e, (size_t)n, sizeof *e, cmp_ll);
        qsort(r, (size_t)n, sizeof *r, cmp_ll);
        closed = memcmp(e, r, (size_t)n * sizeof *e) == 0;
    }
    free(e);
    free(r);
    return closed;
}

/* Six times the signed volume faces first .. last - 1 of src enclose (fans with
 * the origin): > 0 when they face outward. */
static double faces_volume6(const shape_source *src, int first, int last)
{
    double v = 0;
    for (int f = first; f < last; f++) {
        int a = src->face_first[f], e = src->face_first[f + 1];
        for (int k = a + 1; k + 1 < e; k++)
            v += v3_dot(src->pts[src->corner[a]],
                        v3_cross(src->pts[src->corner[k]], src->pts[src->corner[k + 1]]));
    }
    return v;
}

/* True when faces first .. last - 1 of src close a solid for a static object:
 * closed, and facing outward (a closed surface whose faces all face inward, as
 * a room's walls, floor and ceiling do, holds the room's empty inside: its
 * faces are slabs). */
static bool faces_solid(const shape_source *src, int first, int last)
{
    return faces_closed(src, first, last) && faces_volume6(src, first, last) > 0;
}

/* Newell's normal of face f of the scaled points pts: twice its area long. */
static vec3 face_newell(const shape_source *src, const vec3 *pts, int f)
{
    vec3 n = v3(0, 0, 0);
    int a = src->face_first[f], e = src->face_first[f + 1];
    for (int k = a; k < e; k++) {
        vec3 p = pts[src->corner[k]], q = pts[src->corner[k + 1 < e ? k + 1 : a]];
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    return n;
}

/* Mass properties of the closed mesh of faces 0 .. nf - 1 (fans of the polygons,
 * each triangle with the origin a signed tetrahedron: volume det / 6, second
 * moment det / 120 (a a' + b b' + c c' + s s'), s = a + b + c), turned outward
 * when the faces run inward.  Volume 0 when they enclose nothing. */
static mass_props mesh_mass(const shape_source *src, const vec3 *pts)
{
    double vol = 0, m[3][3] = {{0}};
    vec3 first = v3(0, 0, 0);
    for (int f = 0; f < src->nf; f++) {
        int a = src->face_first[f], e = src->face_first[f + 1];
        for (int k = a + 1; k + 1 < e; k++) {
            vec3 p[3] = {pts[src->corner[a]], pts[src->corner[k]], pts[src->corner[k + 1]]};
            double det = v3_dot(p[0], v3_cross(p[1], p[2]));
            vec3 sum = v3_add(p[0], v3_add(p[1], p[2]));
            vol += det / 6;
            first = v3_add(first, v3_scale(sum, det / 24));
            double c[3][3] = {{0}};
            for (int t = 0; t < 4; t++) {
                vec3 x = t < 3 ? p[t] : sum;
                double xv[3] = {x.x, x.y, x.z};
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++) c[i][j] += xv[i] * xv[j];
            }
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) m[i][j] += det / 120 * c[i][j];
        }
    }
    if (vol < 0) { /* inside out: the same solid */
        vol = -vol;
        first = v3_neg(first);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) m[i][j] = -m[i][j];
    }
    mass_props mp = {0};
    if (!(vol > 0)) return mp;
    vec3 com = v3_scale(first, 1 / vol);
    double cv[3] = {com.x, com.y, com.z};
    /* the second moment about the centre of mass, then the inertia tensor */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) m[i][j] -= vol * cv[i] * cv[j];
    double tr = m[0][0] + m[1][1] + m[2][2];
    mat3 I;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) I.m[i][j] = (i == j ? tr : 0) - m[i][j];
    mp.volume = vol;
    mp.com = com;
    mp.inertia = I;
    return mp;
}

/* The sum of parts' mass properties (each about its own centre of mass). */
static mass_props mass_add(mass_props a, mass_props b)
{
    double v = a.volume + b.volume;
    if (!(v > 0)) return a;
    vec3 c = v3_scale(v3_add(v3_scale(a.com, a.volume), v3_scale(b.com, b.volume)), 1 / v);
    mat3 I = m3_zero();
    const mass_props *part[2] = {&a, &b};
    for (int k = 0; k < 2; k++) {
        vec3 d = v3_sub(part[k]->com, c);
        double dd[3] = {d.x, d.y, d.z}, l2 = v3_len2(d);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                I.m[i][j] += part[k]->inertia.m[i][j] +
                             part[k]->volume * ((i == j ? l2 : 0) - dd[i] * dd[j]);
    }
    return (mass_props){v, c, I};
}

/* Piece list being made: its hulls. */
typedef struct {
    shape_piece *p;
    int n, cap;
} piece_list;

/* Adds the exact hull of the n points pts as a piece; -1 with err on failure
 * (what names the piece in the message). */
static int piece_add(piece_list *pl, const vec3 *pts, int n, const char *what, char *err,
                     size_t errlen)
{
    if (pl->n == pl->cap) {
        int cap = pl->cap ? 2 * pl->cap : 8;
        shape_piece *np = realloc(pl->p, (size_t)cap * sizeof *np);
        if (!np) {
            errmsg_set(err, errlen, "polyhedron: out of memory for its pieces");
            return -1;
        }
        pl->p = np;
        pl->cap = cap;
    }
    char why[200];
    shape_piece *pc = &pl->p[pl->n];
    memset(pc, 0, sizeof *pc);
    pc->hull = poly_hull_merge(pts, n, 0, why, sizeof why);
    if (!pc->hull) {
        errmsg_set(err, errlen, "polyhedron: %s makes no solid: %s", what, strip_hull(why));
        return -1;
    }
    pl->n++;
    if (!(pc->feat = closest_hull_new(pc->hull))) {
        errmsg_set(err, errlen, "out of memory for the closest-feature data");
        return -1;
    }
    const poly *h = pc->hull;
    pc->box_lo = pc->box_hi = h->v[0];
    for (int k = 1; k < h->nv; k++) {
        pc->box_lo = v3_min(pc->box_lo, h->v[k]);
        pc->box_hi = v3_max(pc->box_hi, h->v[k]);
    }
    pc->c = v3_scale(v3_add(pc->box_lo, pc->box_hi), 0.5);
    for (int k = 0; k < h->nv; k++) pc->r = fmax(pc->r, v3_dist(h->v[k], pc->c));
    return 0;
}

static void pieces_free(piece_list *pl)
{
    for (int k = 0; k < pl->n; k++) {
        closest_hull_free(pl->p[k].feat);
        poly_free(pl->p[k].hull);
    }
    free(pl->p);
}

/* The pieces of src at the scaled points pts: each run of faces the hull of its
 * points, or, when fixed and the run closes no volume, one slab per face. */
static int make_pieces(const shape_source *src, const vec3 *pts, bool fixed, double thick,
                       piece_list *pl, int *slabs, char *err, size_t errlen)
{
    int runs = src->npieces > 1 ? src->npieces : 1, maxc = 0;
    for (int f = 0; f < src->nf; f++) maxc = fmax(maxc, src->face_first[f + 1] - src->face_first[f]);
    vec3 *buf = malloc((size_t)(src->np + 2 * maxc + 1) * sizeof *buf);
    int *seen = calloc((size_t)src->np + 1, sizeof *seen);
    int rc = buf && seen ? 0 : -1;
    if (rc) errmsg_set(err, errlen, "polyhedron: out of memory for its pieces");
    char what[96];
    for (int k = 0; k < runs && rc == 0; k++) {
        int first = src->npieces > 1 ? src->piece_first[k] : 0;
        int last = src->npieces > 1 ? src->piece_first[k + 1] : src->nf;
        if (fixed && !faces_solid(src, first, last)) {
            for (int f = first; f < last && rc == 0; f++) {
                vec3 n = face_newell(src, pts, f);
                double l = v3_len(n);
                if (!(l > 0)) continue; /* (no area: no slab) */
                n = v3_scale(n, -thick / l);
                int m = 0;
                for (int c = src->face_first[f]; c < src->face_first[f + 1]; c++) {
                    buf[m++] = pts[src->corner[c]];
                    buf[m++] = v3_add(pts[src->corner[c]], n);
                }
                snprintf(what, sizeof what, "the slab of face %d", f + 1);
                rc = piece_add(pl, buf, m, what, err, errlen);
                (*slabs)++;
            }
            continue;
        }
        int m = 0;
        for (int c = src->face_first[first]; c < src->face_first[last]; c++)
            if (seen[src->corner[c]] != k + 1) {
                seen[src->corner[c]] = k + 1;
                buf[m++] = pts[src->corner[c]];
            }
        snprintf(what, sizeof what, "piece %d of %d (%d points)", k + 1, runs, m);
        rc = piece_add(pl, buf, m, what, err, errlen);
        if (rc && !fixed)
            errmsg_set(err + strlen(err), errlen - strlen(err),
                       "; a static object (mass = -1 before file) makes an open piece a slab "
                       "per face");
    }
    free(buf);
    free(seen);
    return rc;
}

/* The scaled points of s's source into *out (allocated): -1 with err when one
 * lies beyond LIM_LENGTH_MAX of the origin. */
static int scaled_points(const shape *s, vec3 **out, char *err, size_t errlen)
{
    const shape_source *src = s->p.src;
    vec3 k = s->p.scale;
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
    *out = pts;
    return 0;
}

static int build_polyhedron(shape *s, char *err, size_t errlen)
{
    const shape_source *src = s->p.src;
    vec3 k = s->p.scale;
    if (!src) return build_box(s, k, "polyhedron: the box of scale", err, errlen);
    vec3 *pts;
    if (scaled_points(s, &pts, err, errlen) != 0) return -1;
    char why[200];
    bool whole = src->nf == 0 || (src->npieces <= 1 && !(s->p.fixed && !faces_solid(src, 0, src->nf)));
    piece_list pl = {0};
    int slabs = 0;
    if (!whole && make_pieces(src, pts, s->p.fixed, s->p.thickness, &pl, &slabs, err, errlen) != 0) {
        pieces_free(&pl);
        free(pts);
        return -1;
    }
    whole = whole || (pl.n == 1 && slabs == 0);
    if (whole) {
        /* one piece: the exact hull of all the points ("the hull of all its
         * vertices"), and shape_off_hull's test is then exact too */
        pieces_free(&pl);
        pl = (piece_list){0};
        s->hull = poly_hull_merge(pts, src->np, 0, why, sizeof why);
        if (!s->hull) {
            errmsg_set(err, errlen, "polyhedron: its %d points make no solid: %s%s", src->np,
                       strip_hull(why),
                       s->p.fixed ? "" : "; a static object (mass = -1 before file) makes an "
                                         "open piece a slab per face");
            free(pts);
            return -1;
        }
    } else {
        /* the hull of them all: a bound of the whole, as the hand and the view see it */
        int nv = 0;
        for (int p = 0; p < pl.n; p++) nv += pl.p[p].hull->nv;
        vec3 *all = malloc((size_t)nv * sizeof *all);
        nv = 0;
        for (int p = 0; all && p < pl.n; p++)
            for (int v = 0; v < pl.p[p].hull->nv; v++) all[nv++] = pl.p[p].hull->v[v];
        s->hull = all ? poly_hull_merge(all, nv, 0, why, sizeof why) : NULL;
        free(all);
        if (!s->hull) {
            errmsg_set(err, errlen, "polyhedron: its pieces make no solid together: %s",
                       all ? strip_hull(why) : "out of memory");
            pieces_free(&pl);
            free(pts);
            return -1;
        }
        s->pieces = pl.n;
        s->piece = pl.p;
        s->slabs = slabs;
        for (int p = 0; p < pl.n; p++) {
            pl.p[p].face0 = s->nfaces;
            s->nfaces += pl.p[p].hull->nf;
        }
    }
    int rc = src->draw.nt > 0 ? scaled_mesh(s, &src->draw, k) : hull_mesh(s->hull, &s->draw);
    if (rc < 0) {
        errmsg_set(err, errlen, "polyhedron: out of memory for its mesh");
        free(pts);
        return -1;
    }
    s->mass_from = MASS_HULL;
    if (whole) {
        s->mass = poly_mass(s->hull);
    } else {
        s->mass_from = MASS_PIECES;
        s->mass = poly_mass(s->piece[0].hull);
        for (int p = 1; p < s->pieces; p++) s->mass = mass_add(s->mass, poly_mass(s->piece[p].hull));
    }
    s->r_out = poly_outer_radius(s->hull, s->mass.com); /* (shape_off_hull's tolerance) */
    /* a closed mesh's own, unless it is its hull (the hull's are the same, and
     * were what such a file had before pieces: the same motion to the bit) */
    if ((!whole || shape_off_hull(s) > 0) && slabs == 0 && faces_closed(src, 0, src->nf)) {
        mass_props mm = mesh_mass(src, pts);
        if (mm.volume > 1e-12 * s->mass.volume) {
            s->mass = mm;
            s->mass_from = MASS_MESH;
        }
    }
    free(pts);
    if (whole) {
        s->r_in = poly_inner_radius(s->hull, s->mass.com);
    } else {
        s->r_in = 0; /* (a bound the schedule takes off a turning object's gap) */
        if (!(s->feat = closest_hull_new(s->hull))) {
            errmsg_set(err, errlen, "out of memory for the closest-feature data");
            return -1;
        }
    }
    s->r_out = poly_outer_radius(s->hull, s->mass.com);
    return 0;
}

int shape_face_piece(const shape *s, int face, int *local)
{
    *local = face;
    if (s->pieces <= 1) return s->hull && face >= 0 && face < s->hull->nf ? 0 : -1;
    if (face < 0 || face >= s->nfaces) return -1;
    int lo = 0, hi = s->pieces - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (s->piece[mid].face0 <= face) lo = mid;
        else hi = mid - 1;
    }
    *local = face - s->piece[lo].face0;
    return lo;
}

const poly *shape_face(const shape *s, int face, int *local)
{
    int k = shape_face_piece(s, face, local);
    return k < 0 ? NULL : shape_piece_hull(s, k);
}

/* True when the plane of normal n through mid supports hull h (either way round)
 * within tol; *j the vertex a climb starts from. */
static bool on_hull(const poly *h, vec3 n, vec3 mid, double tol, int *j)
{
    for (int side = 0; side < 2; side++, n = v3_neg(n)) {
        *j = poly_climb(h, n, *j);
        if (v3_dot(n, v3_sub(h->v[*j], mid)) <= tol) return true;
    }
    return false;
}

long shape_off_hull(const shape *s)
{
    const poly *h = s->hull;
    const mesh *m = &s->draw;
    if (!h || s->p.kind != SHAPE_POLYHEDRON || s->slabs > 0) return 0;
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
        if (s->pieces <= 1) on = on_hull(h, n, mid, tol, &j);
        /* on the surface of a piece whose box holds it */
        for (int k = 0; k < s->pieces && s->pieces > 1 && !on; k++) {
            const shape_piece *pc = &s->piece[k];
            if (v3_dist(mid, pc->c) > pc->r + tol) continue;
            int jk = 0;
            on = on_hull(pc->hull, n, mid, tol, &jk);
        }
        if (!on) off++;
    }
    return off;
}

/* The faces of the tessellation's hull, as cycles ccw seen from outside: the caps'
 * triangles about the poles, and each quad between two rings whole when its four
 * corners are coplanar to roundoff, else split along the diagonal that folds out
 * (the one whose two triangles leave the other corner below).  Returns the count,
 * or -1 where a quad is neither clearly flat nor clearly folded (qhull decides). */
static int sq_hull_faces(const shape_params *p, const vec3 *pos, int *count, int *fvert)
{
    int u = p->ures, top = p->vres - 1, north = u * top + 1, nf = 0, at = 0;
    double size = fmax(p->a1, fmax(p->a2, p->a3));
#define RING(j, i) (1 + ((j) - 1) * u + ((i) % u))
#define FACE3(x, y, z) (fvert[at++] = (x), fvert[at++] = (y), fvert[at++] = (z), count[nf++] = 3)
    for (int i = 0; i < u; i++) {
        FACE3(0, RING(1, i + 1), RING(1, i));
        FACE3(RING(top, i), RING(top, i + 1), north);
    }
    for (int j = 1; j < top; j++)
        for (int i = 0; i < u; i++) {
            int a = RING(j, i), b = RING(j, i + 1), c = RING(j + 1, i + 1), d = RING(j + 1, i);
            vec3 n = v3_cross(v3_sub(pos[b], pos[a]), v3_sub(pos[c], pos[a]));
            double ln = v3_len(n);
            if (!(ln > 0)) return -1;
            double h = v3_dot(n, v3_sub(pos[d], pos[a])) / ln; /* d above abc */
            if (fabs(h) <= 1e-14 * size) {
                fvert[at++] = a;
                fvert[at++] = b;
                fvert[at++] = c;
                fvert[at++] = d;
                count[nf++] = 4;
            } else if (h < -1e-9 * size) {
                FACE3(a, b, c);
                FACE3(a, c, d);
            } else if (h > 1e-9 * size) {
                FACE3(a, b, d);
                FACE3(b, c, d);
            } else {
                return -1;
            }
        }
#undef FACE3
#undef RING
    return nf;
}

/* The superquadric's hull: from its tessellation where that is checked to be its
 * hull (poly_hull_surface: exponents up to 2 put every point on it), else by qhull;
 * the same solid either way. */
static poly *sq_hull(const shape_params *p, const mesh *m, char *err, size_t errlen)
{
    int *count = malloc((size_t)m->nt * sizeof *count), *fvert = malloc((size_t)m->nt * 3 * sizeof *fvert);
    poly *h = NULL;
    if (!count || !fvert) {
        errmsg_set(err, errlen, "out of memory");
    } else {
        int nf = sq_hull_faces(p, m->pos, count, fvert);
        h = nf > 0 ? poly_hull_surface(m->pos, m->nv, nf, count, fvert, POLY_FLAT_ANGLE, err, errlen)
                   : poly_hull(m->pos, m->nv, err, errlen);
    }
    free(count);
    free(fvert);
    return h;
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
    s->hull = sq_hull(&s->p, &s->draw, why, sizeof why);
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
    if (rc == 0) { /* one piece unless more were made, and the bounding box, in body axes */
        if (s->pieces == 0) {
            s->pieces = 1;
            s->nfaces = s->hull ? s->hull->nf : 0;
        }
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
    if (rc == 0 && s->hull && !s->feat && !(s->feat = closest_hull_new(s->hull))) {
        errmsg_set(err, errlen, "out of memory for the closest-feature data");
        rc = -1;
    }
    if (rc < 0) shape_free(s);
    return rc;
}
