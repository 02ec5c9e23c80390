/* test_closest.c: closest features (closest.c) against an exact brute-force oracle.
 *
 * The oracle works on the world-coordinate vertices and face planes alone: the
 * distance between two polyhedra is the minimum over all vertex-face (point to
 * polygon) and edge-edge (segment to segment) pairs; they are separated exactly when
 * the plane through that closest pair, perpendicular to it, separates every vertex
 * (and intersect at once when a vertex of one is inside the other).  Pairs that
 * cannot beat the best distance found so far are skipped (a slab test along the
 * direction of the best pair), which keeps it exact; oracle_is_exact checks the
 * pruned oracle against the full one.
 *
 * Random configurations: VROC_TEST_SCALE (default 1, or 0.2 in a sanitizer build)
 * scales their number, 100,000 at scale 1, over every pair of a pool of spheres,
 * boxes and superquadrics with exponents 0.1, 0.5, 1, 1.5 and 2 and resolutions 4 to
 * 40.  Each is queried from scratch and from the previous configuration's features
 * (a stale cache: long walks), in both orders.  Then coherent motion (each step from
 * the last step's features), degenerate cases from every starting feature pair,
 * snapped configurations (45-degree turns on a grid: parallel faces, exact touching)
 * and the body-level API's exact symmetry.  VROC_TEST_SEED varies the random
 * numbers and VROC_TEST_FILTER picks tests by name (cmocka's pattern), for stress runs.
 */
#include "check.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/body.h"
#include "core/closest.h"
#include "core/envelope.h"
#include "core/shape.h"
#include "core/support.h"

/* ---- random numbers ---- */

static uint64_t g_rng = 0x9e3779b97f4a7c15ull;

static double rnd(void)
{
    g_rng = g_rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(g_rng >> 11) / 9007199254740992.0;
}

static double rnd_in(double lo, double hi) { return lo + (hi - lo) * rnd(); }

static vec3 rnd_unit(void)
{
    for (;;) {
        vec3 v = v3(rnd_in(-1, 1), rnd_in(-1, 1), rnd_in(-1, 1));
        double l = v3_len(v);
        if (l > 0.1 && l <= 1) return v3_scale(v, 1 / l);
    }
}

/* uniform random rotation (Shoemake) */
static quat rnd_quat(void)
{
    double u1 = rnd(), u2 = 2 * M_PI * rnd(), u3 = 2 * M_PI * rnd();
    double a = sqrt(1 - u1), b = sqrt(u1);
    return (quat){b * cos(u3), a * sin(u2), a * cos(u2), b * sin(u3)};
}

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* VROC_TEST_SEED (optional) varies every test's random numbers, for stress runs. */
static uint64_t seed(uint64_t s)
{
    const char *e = getenv("VROC_TEST_SEED");
    return e && *e ? s ^ (strtoull(e, NULL, 10) * 0x9e3779b97f4a7c15ull) : s;
}

static double test_scale(void)
{
    const char *s = getenv("VROC_TEST_SCALE");
    if (s && *s) return atof(s);
#if defined(__SANITIZE_ADDRESS__)
    return 0.2;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return 0.2;
#endif
#endif
    return 1.0;
}

/* ---- shapes ---- */

/* shape_build, with the closest data attached if shape_build does not do it yet */
typedef struct {
    shape s;
    bool own_feat;
    char name[64];
} tshape;

static void tshape_build(tshape *t, const shape_params *p)
{
    char err[256];
    memset(t, 0, sizeof *t);
    if (shape_build(&t->s, p, err, sizeof err) != 0) fail_msg("shape_build: %s", err);
    if (t->s.hull && !t->s.feat) {
        t->s.feat = closest_hull_new(t->s.hull);
        t->own_feat = true;
        assert_non_null(t->s.feat);
    }
    switch (p->kind) {
    case SHAPE_SPHERE: snprintf(t->name, sizeof t->name, "sphere r%g", p->radius); break;
    case SHAPE_CUBE:
        snprintf(t->name, sizeof t->name, "box %gx%gx%g", p->size.x, p->size.y, p->size.z);
        break;
    case SHAPE_SUPERQUADRIC:
        snprintf(t->name, sizeof t->name, "sq e%g,%g %dx%d", p->exp1, p->exp2, p->ures, p->vres);
        break;
    case SHAPE_POLYHEDRON:
        snprintf(t->name, sizeof t->name, "polyhedron of %d points", p->src ? p->src->np : 8);
        break;
    }
}

static void tshape_free(tshape *t)
{
    if (t->own_feat) {
        closest_hull_free(t->s.feat);
        t->s.feat = NULL;
    }
    shape_free(&t->s);
}

static shape_params sphere_p(double r)
{
    shape_params p = shape_defaults(SHAPE_SPHERE);
    p.radius = r;
    return p;
}

static shape_params box_p(double x, double y, double z)
{
    shape_params p = shape_defaults(SHAPE_CUBE);
    p.size = v3(x, y, z);
    return p;
}

static shape_params sq_p(double e1, double e2, int u, int v, double a1, double a2, double a3)
{
    shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
    p.exp1 = e1;
    p.exp2 = e2;
    p.ures = u;
    p.vres = v;
    p.a1 = a1;
    p.a2 = a2;
    p.a3 = a3;
    return p;
}

/* ---- the oracle ---- */

/* A placed object in world coordinates. */
typedef struct {
    const poly *hull;
    bool sphere;
    vec3 c; /* sphere centre */
    double r;
    int nv, nf;
    vec3 *v;  /* world vertices */
    vec3 *fn; /* world face normals */
    double *fd;
    double size;
} wobj;

static wobj wobj_make(closest_proxy o)
{
    wobj w;
    memset(&w, 0, sizeof w);
    w.hull = o.hull;
    mat3 R = m3_from_quat(q_normalize(o.q));
    if (!o.hull) {
        w.sphere = true;
        w.c = o.x;
        w.r = o.radius;
        w.size = w.r;
        return w;
    }
    const poly *p = o.hull;
    w.nv = p->nv;
    w.nf = p->nf;
    w.v = malloc((size_t)p->nv * sizeof *w.v);
    w.fn = malloc((size_t)p->nf * sizeof *w.fn);
    w.fd = malloc((size_t)p->nf * sizeof *w.fd);
    for (int i = 0; i < p->nv; i++) {
        w.v[i] = v3_add(m3_mulv(R, p->v[i]), o.x);
        w.size = fmax(w.size, v3_len(p->v[i]));
    }
    for (int f = 0; f < p->nf; f++) {
        w.fn[f] = m3_mulv(R, p->f[f].n);
        w.fd[f] = p->f[f].d + v3_dot(w.fn[f], o.x);
    }
    return w;
}

static void wobj_free(wobj *w)
{
    free(w->v);
    free(w->fn);
    free(w->fd);
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

static vec3 or_point_seg(vec3 x, vec3 a, vec3 b)
{
    vec3 d = v3_sub(b, a);
    double l2 = v3_len2(d);
    double t = l2 > 0 ? clampd(v3_dot(v3_sub(x, a), d) / l2, 0, 1) : 0;
    return v3_mad(a, d, t);
}

/* Closest points of two segments: the interior stationary point when it lies inside
 * both (then *cross is their common normal), else the best of the four
 * endpoint-to-segment distances (*cross zero). */
static double or_seg_seg(vec3 a0, vec3 a1, vec3 b0, vec3 b1, vec3 *pa, vec3 *pb, vec3 *cross)
{
    vec3 u = v3_sub(a1, a0), v = v3_sub(b1, b0), w0 = v3_sub(a0, b0);
    double a = v3_dot(u, u), b = v3_dot(u, v), c = v3_dot(v, v), d = v3_dot(u, w0),
           e = v3_dot(v, w0);
    double den = a * c - b * b, best = INFINITY;
    if (den > 1e-13 * a * c) {
        double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
            *pa = v3_mad(a0, u, s);
            *pb = v3_mad(b0, v, t);
            best = v3_dist(*pa, *pb);
        }
    }
    double interior = best;
    vec3 q = v3(0, 0, 0);
    q = or_point_seg(a0, b0, b1);
    if (v3_dist(a0, q) < best) best = v3_dist(a0, q), *pa = a0, *pb = q;
    q = or_point_seg(a1, b0, b1);
    if (v3_dist(a1, q) < best) best = v3_dist(a1, q), *pa = a1, *pb = q;
    q = or_point_seg(b0, a0, a1);
    if (v3_dist(b0, q) < best) best = v3_dist(b0, q), *pa = q, *pb = b0;
    q = or_point_seg(b1, a0, a1);
    if (v3_dist(b1, q) < best) best = v3_dist(b1, q), *pa = q, *pb = b1;
    *cross = best == interior ? v3_norm(v3_cross(u, v)) : v3(0, 0, 0);
    return best;
}

/* Distance from x to face f (the polygon) of w, closest point to *q; *interior
 * (may be NULL) tells whether that is x's projection inside the polygon. */
static double or_point_face_in(const wobj *w, int f, vec3 x, vec3 *q, bool *interior)
{
    const poly *p = w->hull;
    const int *fv = p->face_vert + p->f[f].first;
    int cnt = p->f[f].count;
    vec3 n = w->fn[f];
    double h = v3_dot(n, x) - w->fd[f];
    vec3 xp = v3_mad(x, n, -h);
    bool inside = true;
    for (int k = 0; k < cnt && inside; k++) {
        vec3 a = w->v[fv[k]], b = w->v[fv[(k + 1) % cnt]];
        inside = v3_dot(v3_cross(v3_sub(b, a), v3_sub(xp, a)), n) >= 0;
    }
    if (interior) *interior = inside;
    if (inside) {
        *q = xp;
        return fabs(h);
    }
    double best = INFINITY;
    for (int k = 0; k < cnt; k++) {
        vec3 y = or_point_seg(x, w->v[fv[k]], w->v[fv[(k + 1) % cnt]]);
        double d = v3_dist(x, y);
        if (d < best) {
            best = d;
            *q = y;
        }
    }
    return best;
}

static double or_point_face(const wobj *w, int f, vec3 x, vec3 *q)
{
    return or_point_face_in(w, f, x, q, NULL);
}

/* Signed distance of x to polyhedron w's surface when outside is positive:
 * max over face planes (exact inside, a lower bound outside). */
static double or_plane_max(const wobj *w, vec3 x)
{
    double m = -INFINITY;
    for (int f = 0; f < w->nf; f++) m = fmax(m, v3_dot(w->fn[f], x) - w->fd[f]);
    return m;
}

/* Distance from x to the surface of polyhedron w (0 inside), closest point to *q. */
static double or_point_poly(const wobj *w, vec3 x, vec3 *q)
{
    double best = INFINITY;
    for (int f = 0; f < w->nf; f++) {
        vec3 y;
        double d = or_point_face(w, f, x, &y);
        if (d < best) {
            best = d;
            *q = y;
        }
    }
    return best;
}

typedef struct {
    bool intersect;
    double dist; /* separated: the distance */
    vec3 pa, pb;
    vec3 n; /* unit, from A to B, when the pair's type gives it exactly (else zero) */
} oracle;


/* Is x inside (or on) polyhedron w?  Stops at the first plane it is outside of. */
static bool or_inside(const wobj *w, vec3 x, double tol)
{
    for (int f = 0; f < w->nf; f++)
        if (v3_dot(w->fn[f], x) - w->fd[f] > tol) return false;
    return true;
}

typedef struct {
    int *v, *e, *f;
    int nv, ne, nf;
} cands;

/* Features of w whose projections on n reach beyond thr (side > 0: max >= thr;
 * side < 0: min <= thr); all of them when full. */
static cands or_candidates(const wobj *w, const double *proj, double thr, int side, bool full)
{
    const poly *p = w->hull;
    cands c = {malloc((size_t)p->nv * sizeof(int)), malloc((size_t)p->ne * sizeof(int)),
               malloc((size_t)p->nf * sizeof(int)), 0, 0, 0};
#define PASS(x) (full || (side > 0 ? (x) >= thr : (x) <= thr))
    for (int i = 0; i < p->nv; i++)
        if (PASS(proj[i])) c.v[c.nv++] = i;
    for (int e = 0; e < p->ne; e++) {
        double a = proj[p->e[e].v[0]], b = proj[p->e[e].v[1]];
        if (PASS((side > 0) == (a > b) ? a : b)) c.e[c.ne++] = e;
    }
    for (int f = 0; f < p->nf; f++) {
        const int *fv = p->face_vert + p->f[f].first;
        double x = proj[fv[0]];
        for (int k = 1; k < p->f[f].count; k++)
            x = (side > 0) == (proj[fv[k]] > x) ? proj[fv[k]] : x;
        if (PASS(x)) c.f[c.nf++] = f;
    }
#undef PASS
    return c;
}

static void cands_free(cands *c)
{
    free(c->v);
    free(c->e);
    free(c->f);
}

/* Projections of the vertices on n, and the extremes facing each other. */
static void or_project(const wobj *A, const wobj *B, vec3 n, double *sa, double *sb, double *hA,
                       double *lB)
{
    *hA = -INFINITY;
    *lB = INFINITY;
    for (int i = 0; i < A->nv; i++) *hA = fmax(*hA, sa[i] = v3_dot(n, A->v[i]));
    for (int j = 0; j < B->nv; j++) *lB = fmin(*lB, sb[j] = v3_dot(n, B->v[j]));
}

/* A unit vector from o.pa to o.pb, or fallback. */
static vec3 or_dir(vec3 pa, vec3 pb, vec3 fallback)
{
    vec3 n = v3_norm(v3_sub(pb, pa));
    return v3_len2(n) > 0 ? n : fallback;
}

static oracle oracle_poly_poly(const wobj *A, const wobj *B, bool full)
{
    const poly *pa = A->hull, *pb = B->hull;
    double scale = A->size + B->size + v3_len(A->v[0]);
    double tol = 1e-11 * scale;
    oracle o = {true, 0, v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)};
    /* a vertex of one inside the other proves an intersection at once */
    if (!full) {
        for (int i = 0; i < A->nv; i++)
            if (or_inside(B, A->v[i], -tol)) return o;
        for (int j = 0; j < B->nv; j++)
            if (or_inside(A, B->v[j], -tol)) return o;
    }
    /* an upper bound from vertices, and the direction between them */
    vec3 ca = v3(0, 0, 0), cb = v3(0, 0, 0);
    for (int i = 0; i < A->nv; i++) ca = v3_add(ca, A->v[i]);
    for (int i = 0; i < B->nv; i++) cb = v3_add(cb, B->v[i]);
    vec3 n0 = v3_norm(v3_sub(v3_scale(cb, 1.0 / B->nv), v3_scale(ca, 1.0 / A->nv)));
    if (v3_len2(n0) == 0) n0 = v3(1, 0, 0);
    int ia = 0, ib = 0;
    for (int i = 1; i < A->nv; i++)
        if (v3_dot(A->v[i], n0) > v3_dot(A->v[ia], n0)) ia = i;
    for (int it = 0; it < 2; it++) {
        double best = INFINITY;
        for (int j = 0; j < B->nv; j++) {
            double d2 = v3_len2(v3_sub(B->v[j], A->v[ia]));
            if (d2 < best) best = d2, ib = j;
        }
        best = INFINITY;
        for (int i = 0; i < A->nv; i++) {
            double d2 = v3_len2(v3_sub(A->v[i], B->v[ib]));
            if (d2 < best) best = d2, ia = i;
        }
    }
    o = (oracle){false, v3_dist(A->v[ia], B->v[ib]), A->v[ia], B->v[ib], v3(0, 0, 0)};
    double U = o.dist, hA, lB;
    vec3 n = or_dir(A->v[ia], B->v[ib], n0);
    double *sa = malloc((size_t)A->nv * sizeof *sa), *sb = malloc((size_t)B->nv * sizeof *sb);
    or_project(A, B, n, sa, sb, &hA, &lB);
    /* a closest pair (p, q) has n.p >= lB - U and n.q <= hA + U; U shrinks as
     * pairs are found: first the two vertices against the other's faces */
    cands ka = or_candidates(A, sa, lB - U - tol, 1, full);
    cands kb = or_candidates(B, sb, hA + U + tol, -1, full);
    for (int jf = 0; jf < kb.nf; jf++) {
        vec3 q = v3(0, 0, 0);
        bool in;
        double d = or_point_face_in(B, kb.f[jf], A->v[ia], &q, &in);
        if (d < o.dist)
            o = (oracle){false, d, A->v[ia], q, in ? v3_neg(B->fn[kb.f[jf]]) : v3(0, 0, 0)};
    }
    for (int jf = 0; jf < ka.nf; jf++) {
        vec3 q = v3(0, 0, 0);
        bool in;
        double d = or_point_face_in(A, ka.f[jf], B->v[ib], &q, &in);
        if (d < o.dist) o = (oracle){false, d, q, B->v[ib], in ? A->fn[ka.f[jf]] : v3(0, 0, 0)};
    }
    cands_free(&ka);
    cands_free(&kb);
    or_project(A, B, or_dir(o.pa, o.pb, n), sa, sb, &hA, &lB);
    ka = or_candidates(A, sa, lB - o.dist - tol, 1, full);
    kb = or_candidates(B, sb, hA + o.dist + tol, -1, full);
    /* vertex of A - face of B */
    for (int jf = 0; jf < kb.nf; jf++) {
        int f = kb.f[jf];
        for (int ji = 0; ji < ka.nv; ji++) {
            int i = ka.v[ji];
            if (fabs(v3_dot(B->fn[f], A->v[i]) - B->fd[f]) >= o.dist) continue;
            vec3 q = v3(0, 0, 0);
            bool in;
            double d = or_point_face_in(B, f, A->v[i], &q, &in);
            if (d < o.dist) o = (oracle){false, d, A->v[i], q, in ? v3_neg(B->fn[f]) : v3(0, 0, 0)};
        }
    }
    /* face of A - vertex of B */
    for (int jf = 0; jf < ka.nf; jf++) {
        int f = ka.f[jf];
        for (int jj = 0; jj < kb.nv; jj++) {
            int j = kb.v[jj];
            if (fabs(v3_dot(A->fn[f], B->v[j]) - A->fd[f]) >= o.dist) continue;
            vec3 q = v3(0, 0, 0);
            bool in;
            double d = or_point_face_in(A, f, B->v[j], &q, &in);
            if (d < o.dist) o = (oracle){false, d, q, B->v[j], in ? A->fn[f] : v3(0, 0, 0)};
        }
    }
    /* edge - edge, with the slab narrowed to the best distance so far */
    cands_free(&ka);
    cands_free(&kb);
    or_project(A, B, or_dir(o.pa, o.pb, n), sa, sb, &hA, &lB);
    ka = or_candidates(A, sa, lB - o.dist - tol, 1, full);
    kb = or_candidates(B, sb, hA + o.dist + tol, -1, full);
    vec3 *mb = malloc((size_t)(kb.ne + 1) * sizeof *mb);
    double *rb = malloc((size_t)(kb.ne + 1) * sizeof *rb);
    for (int jg = 0; jg < kb.ne; jg++) {
        int b0 = pb->e[kb.e[jg]].v[0], b1 = pb->e[kb.e[jg]].v[1];
        mb[jg] = v3_lerp(B->v[b0], B->v[b1], 0.5);
        rb[jg] = 0.5 * v3_dist(B->v[b0], B->v[b1]);
    }
    for (int je = 0; je < ka.ne; je++) {
        int a0 = pa->e[ka.e[je]].v[0], a1 = pa->e[ka.e[je]].v[1];
        vec3 ma = v3_lerp(A->v[a0], A->v[a1], 0.5);
        double ra = 0.5 * v3_dist(A->v[a0], A->v[a1]);
        for (int jg = 0; jg < kb.ne; jg++) {
            double reach = o.dist + ra + rb[jg];
            if (v3_len2(v3_sub(ma, mb[jg])) >= reach * reach) continue;
            int b0 = pb->e[kb.e[jg]].v[0], b1 = pb->e[kb.e[jg]].v[1];
            vec3 p = v3(0, 0, 0), q = p, c;
            double d = or_seg_seg(A->v[a0], A->v[a1], B->v[b0], B->v[b1], &p, &q, &c);
            if (d < o.dist) o = (oracle){false, d, p, q, c};
        }
    }
    free(mb);
    free(rb);
    cands_free(&ka);
    cands_free(&kb);
    free(sa);
    free(sb);
    /* the intersection test: does the closest pair's plane separate?  Its normal
     * is exact for a vertex over a face and two edges crossing; from the points
     * it is off by about roundoff / distance, which the tolerance allows for */
    if (!(o.dist > tol)) {
        o.intersect = true;
        return o;
    }
    vec3 m = v3_scale(v3_sub(o.pb, o.pa), 1 / o.dist);
    if (v3_len2(o.n) > 0) m = v3_dot(o.n, m) >= 0 ? o.n : v3_neg(o.n);
    else tol += 1e-15 * scale * scale / o.dist;
    double ha = v3_dot(m, o.pa) + tol, lb = v3_dot(m, o.pb) - tol;
    for (int i = 0; i < A->nv && !o.intersect; i++) o.intersect = v3_dot(m, A->v[i]) > ha;
    for (int j = 0; j < B->nv && !o.intersect; j++) o.intersect = v3_dot(m, B->v[j]) < lb;
    return o;
}

/* The oracle for any two objects. */
static oracle oracle_of(const wobj *A, const wobj *B, bool full)
{
    oracle o;
    if (A->sphere && B->sphere) {
        double d = v3_dist(A->c, B->c);
        vec3 u = d > 0 ? v3_scale(v3_sub(B->c, A->c), 1 / d) : v3(1, 0, 0);
        o = (oracle){d <= A->r + B->r, d - A->r - B->r, v3_mad(A->c, u, A->r),
                     v3_mad(B->c, u, -B->r), u};
        return o;
    }
    if (A->sphere || B->sphere) {
        const wobj *P = A->sphere ? B : A, *S = A->sphere ? A : B;
        vec3 q = v3(0, 0, 0);
        if (or_plane_max(P, S->c) <= 0) {
            o.intersect = true;
            o.dist = 0;
            o.pa = o.pb = S->c;
            return o;
        }
        double d = or_point_poly(P, S->c, &q);
        vec3 onS = v3_mad(S->c, v3_norm(v3_sub(q, S->c)), S->r);
        o.intersect = d <= S->r;
        o.dist = d - S->r;
        o.pa = A->sphere ? onS : q;
        o.pb = A->sphere ? q : onS;
        return o;
    }
    return oracle_poly_poly(A, B, full);
}

/* Signed distance of x from object w's surface (exact on and inside polyhedra). */
static double surface_dist(const wobj *w, vec3 x)
{
    if (w->sphere) return v3_dist(x, w->c) - w->r;
    return or_plane_max(w, x);
}

/* Distance of x from feature f of w. */
static double feature_dist(const wobj *w, closest_feature f, vec3 x)
{
    const poly *p = w->sphere ? NULL : w->hull;
    vec3 q = v3(0, 0, 0);
    switch (f.kind) {
    case CLOSEST_SPHERE: return w->sphere ? fabs(v3_dist(x, w->c) - w->r) : INFINITY;
    case CLOSEST_VERTEX: return p && f.index < p->nv ? v3_dist(x, w->v[f.index]) : INFINITY;
    case CLOSEST_EDGE:
        if (!p || f.index >= p->ne) return INFINITY;
        return v3_dist(x, or_point_seg(x, w->v[p->e[f.index].v[0]], w->v[p->e[f.index].v[1]]));
    case CLOSEST_FACE: return p && f.index < p->nf ? or_point_face(w, f.index, x, &q) : INFINITY;
    default: return INFINITY;
    }
}

/* ---- checking one answer ---- */

typedef struct {
    long n, separated, penetrating, steps, max_steps, restarts;
    double max_err;
} tally;

#define DIST_TOL 1e-9

static char g_what[256]; /* the configuration being checked, for messages */

static void check_answer(const wobj *A, const wobj *B, const oracle *o, closest_result r,
                         tally *t)
{
    t->n++;
    t->steps += r.steps;
    if (r.steps > t->max_steps) t->max_steps = r.steps;
    if (r.restarted) t->restarts++;
    if (r.status == CLOSEST_INVALID) fail_msg("%s: invalid result", g_what);
    if (!isfinite(r.distance) || !v3_finite(r.pa) || !v3_finite(r.pb) || !v3_finite(r.normal))
        fail_msg("%s: non-finite result", g_what);
    if (fabs(v3_len(r.normal) - 1) > 1e-9)
        fail_msg("%s: normal not unit (%g)", g_what, v3_len(r.normal));
    if ((r.status == CLOSEST_PENETRATING) != (r.distance <= 0))
        fail_msg("%s: status %d with distance %g", g_what, r.status, r.distance);
    if (o->intersect) {
        t->penetrating++;
        if (!(r.distance <= 0))
            fail_msg("%s: oracle says intersecting, got distance %.17g (oracle pair %.3g)", g_what,
                     r.distance, o->dist);
        return; /* the estimate is checked by check_estimate */
    }
    t->separated++;
    if (!(r.distance > 0))
        fail_msg("%s: oracle says separated by %.17g, got %.17g", g_what, o->dist, r.distance);
    double err = fabs(r.distance - o->dist);
    if (err > t->max_err) t->max_err = err;
    if (err > DIST_TOL)
        fail_msg("%s: distance %.17g, oracle %.17g (error %.3g)", g_what, r.distance, o->dist, err);
    double sa = surface_dist(A, r.pa), sb = surface_dist(B, r.pb);
    if (fabs(sa) > DIST_TOL || fabs(sb) > DIST_TOL)
        fail_msg("%s: closest points off the surfaces by %.3g and %.3g", g_what, sa, sb);
    if (fabs(v3_dist(r.pa, r.pb) - r.distance) > DIST_TOL)
        fail_msg("%s: |pa - pb| = %.17g, distance %.17g", g_what, v3_dist(r.pa, r.pb), r.distance);
    double fa = feature_dist(A, r.fa, r.pa), fb = feature_dist(B, r.fb, r.pb);
    if (fa > DIST_TOL || fb > DIST_TOL)
        fail_msg("%s: points off their features (%s %d: %.3g, %s %d: %.3g)", g_what,
                 closest_kind_name(r.fa.kind), r.fa.index, fa, closest_kind_name(r.fb.kind),
                 r.fb.index, fb);
    if (r.distance > 1e-6) {
        vec3 dir = v3_scale(v3_sub(r.pa, r.pb), 1 / v3_dist(r.pa, r.pb));
        if (v3_dist(dir, r.normal) > 1e-6)
            fail_msg("%s: normal (%g %g %g) is not along pa - pb (%g %g %g)", g_what, r.normal.x,
                     r.normal.y, r.normal.z, dir.x, dir.y, dir.z);
    }
}

/* After a penetrating answer: A moved along the normal by the estimate plus a margin
 * no longer intersects B (the estimate is an overlap along a separating axis). */
static void check_estimate(closest_proxy a, closest_proxy b, closest_result r)
{
    double margin = 1e-7 * (1 + fabs(r.distance));
    a.x = v3_mad(a.x, r.normal, -r.distance + margin);
    wobj A = wobj_make(a), B = wobj_make(b);
    oracle o = oracle_of(&A, &B, false);
    if (o.intersect)
        fail_msg("%s: moving A by the penetration estimate %.17g along the normal does not "
                 "separate", g_what, r.distance);
    wobj_free(&A);
    wobj_free(&B);
}

/* Every query of the tests goes through here. */
static closest_result query(closest_proxy a, closest_proxy b, closest_cache *cache)
{
    return closest_distance(&a, &b, cache);
}

/* ---- the pool of shapes ---- */

#define POOL_MAX 48
static tshape g_pool[POOL_MAX];
static int g_npool;

static int pool_setup(void **state)
{
    (void)state;
    static const double ex[5] = {0.1, 0.5, 1, 1.5, 2};
    g_npool = 0;
    shape_params sp[POOL_MAX];
    int n = 0;
    sp[n++] = sphere_p(0.3);
    sp[n++] = sphere_p(1.0);
    sp[n++] = sphere_p(1.7);
    sp[n++] = box_p(1, 1, 1);
    sp[n++] = box_p(0.2, 1.5, 0.7);
    sp[n++] = box_p(2, 0.1, 0.5);
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            int k = 5 * i + j;
            int u = 4 + (k * 13) % 37, v = 4 + (k * 23 + 7) % 37;
            sp[n++] = sq_p(ex[i], ex[j], u, v, 0.5 + 0.05 * ((k * 7) % 21),
                           0.5 + 0.05 * ((k * 11) % 21), 0.5 + 0.05 * ((k * 5) % 21));
        }
    sp[n++] = sq_p(1, 1, 4, 4, 1, 1, 1);
    sp[n++] = sq_p(1, 1, 40, 40, 1, 1, 1);
    sp[n++] = sq_p(0.5, 1, 40, 40, 1.2, 0.8, 1);
    sp[n++] = sq_p(2, 2, 40, 4, 1, 1, 1.5);
    sp[n++] = sq_p(0.1, 0.1, 4, 40, 1, 0.6, 0.9);
    for (int i = 0; i < n; i++) tshape_build(&g_pool[g_npool++], &sp[i]);
    return 0;
}

static int pool_teardown(void **state)
{
    (void)state;
    for (int i = 0; i < g_npool; i++) tshape_free(&g_pool[i]);
    g_npool = 0;
    return 0;
}

/* ---- tests ---- */

static closest_proxy place(const shape *s, vec3 x, quat q) { return shape_proxy(s, x, q); }

/* A random configuration of a and b: B at a random direction, its centre at a
 * random fraction of the sum of the outer radii (many penetrate, many are near). */
static void random_config(const shape *sa, const shape *sb, closest_proxy *a, closest_proxy *b)
{
    double ra = sa->r_out + v3_len(sa->mass.com), rb = sb->r_out + v3_len(sb->mass.com);
    *a = place(sa, v3(rnd_in(-3, 3), rnd_in(-3, 3), rnd_in(-3, 3)), rnd_quat());
    double f = rnd() < 0.3 ? rnd_in(0.1, 0.9) : rnd_in(0.6, 1.6);
    *b = place(sb, v3_mad(a->x, rnd_unit(), f * (ra + rb)), rnd_quat());
}

static void random_configurations(void **state)
{
    (void)state;
    long total = (long)(100000 * test_scale());
    if (total < 1) total = 1;
    int npairs = g_npool * (g_npool + 1) / 2;
    tally t = {0};
    long near = 0, done = 0, checked_estimates = 0;
    double t0 = seconds();
    g_rng = seed(12345);
    for (int i = 0; i < g_npool; i++)
        for (int j = i; j < g_npool; j++) {
            int pair = i * g_npool + j - i * (i + 1) / 2;
            long quota = total * (pair + 1) / npairs - total * pair / npairs;
            closest_cache stale = {0}, stale_ba = {0};
            for (long k = 0; k < quota; k++, done++) {
                closest_proxy a, b;
                random_config(&g_pool[i].s, &g_pool[j].s, &a, &b);
                wobj A = wobj_make(a), B = wobj_make(b);
                oracle o = oracle_of(&A, &B, false);
                if (!o.intersect && done % 4 == 3) {
                    /* near contact: move B towards A along the normal, leaving a gap of
                     * 1e-8 to 1e-1 (well above the tolerances, 1e-11 of the size) */
                    wobj_free(&B);
                    double gap = fmin(o.dist, pow(10, -rnd_in(1, 8)));
                    b.x = v3_mad(b.x, v3_norm(v3_sub(o.pa, o.pb)), o.dist - gap);
                    B = wobj_make(b);
                    o = oracle_of(&A, &B, false);
                    near++;
                }
                snprintf(g_what, sizeof g_what, "config %ld: %s / %s", done, g_pool[i].name,
                         g_pool[j].name);
                closest_result r = query(a, b, NULL);
                check_answer(&A, &B, &o, r, &t);
                closest_result rs = query(a, b, &stale);
                check_answer(&A, &B, &o, rs, &t);
                closest_result rb = query(b, a, &stale_ba);
                oracle ob = {o.intersect, o.dist, o.pb, o.pa, v3_neg(o.n)};
                check_answer(&B, &A, &ob, rb, &t);
                if (!o.intersect && fabs(rb.distance - r.distance) > 1e-12)
                    fail_msg("%s: a-b %.17g, b-a %.17g", g_what, r.distance, rb.distance);
                if (o.intersect && k % 8 == 0) {
                    check_estimate(a, b, r);
                    checked_estimates++;
                }
                wobj_free(&A);
                wobj_free(&B);
            }
        }
    print_message("# %ld random configurations (%ld near contact) over %d shape pairs, "
                  "%ld queries: %ld separated, %ld penetrating; max distance error %.3g; "
                  "mean steps %.2f, max %ld; restarts %ld; %ld estimates checked; %.1f s\n",
                  done, near, npairs, t.n, t.separated, t.penetrating, t.max_err,
                  (double)t.steps / (double)t.n, t.max_steps, t.restarts, checked_estimates,
                  seconds() - t0);
    assert_int_equal(t.restarts, 0);
    assert_true(t.separated > t.n / 5);
    assert_true(t.penetrating > t.n / 10);
}

/* The pruned oracle equals the full brute force. */
static void oracle_is_exact(void **state)
{
    (void)state;
    g_rng = seed(777);
    long n = (long)(600 * test_scale()) + 10;
    for (long k = 0; k < n; k++) {
        int i = 3 + (int)(rnd() * (g_npool - 3)), j = 3 + (int)(rnd() * (g_npool - 3));
        if (g_pool[i].s.hull->nv * g_pool[j].s.hull->nv > 100000) {
            k--;
            continue;
        }
        closest_proxy a, b;
        random_config(&g_pool[i].s, &g_pool[j].s, &a, &b);
        wobj A = wobj_make(a), B = wobj_make(b);
        oracle o1 = oracle_of(&A, &B, false), o2 = oracle_of(&A, &B, true);
        if (o1.intersect != o2.intersect || (!o1.intersect && fabs(o1.dist - o2.dist) > 1e-13))
            fail_msg("pruned oracle %d %.17g, full %d %.17g (%s / %s)", o1.intersect, o1.dist,
                     o2.intersect, o2.dist, g_pool[i].name, g_pool[j].name);
        wobj_free(&A);
        wobj_free(&B);
    }
}

/* Two objects moving by small steps, each step from the last step's features. */
static void coherent_run(const shape *sa, const shape *sb, int nsteps, double angle_step,
                         const char *name, tally *t)
{
    double ra = sa->r_out + v3_len(sa->mass.com), rb = sb->r_out + v3_len(sb->mass.com);
    vec3 wa = rnd_unit(), wb = rnd_unit(), orbit = rnd_unit();
    quat qa0 = rnd_quat(), qb0 = rnd_quat();
    vec3 start = v3_norm(v3_cross(orbit, rnd_unit()));
    closest_cache cache = {0};
    tally mine = {0};
    for (int s = 0; s < nsteps; s++) {
        double th = angle_step * s;
        quat qa = q_mul(q_axis_angle(wa, th), qa0), qb = q_mul(q_axis_angle(wb, -1.3 * th), qb0);
        /* B orbits A, in and out of contact */
        double dist = (ra + rb) * (0.85 + 0.3 * sin(0.37 * th));
        vec3 dir = q_rotate(q_axis_angle(orbit, 0.5 * th), start);
        closest_proxy a = place(sa, v3(0.1, -0.2, 0.3), qa);
        closest_proxy b = place(sb, v3_mad(v3(0.1, -0.2, 0.3), dir, dist), qb);
        wobj A = wobj_make(a), B = wobj_make(b);
        oracle o = oracle_of(&A, &B, false);
        snprintf(g_what, sizeof g_what, "%s step %d", name, s);
        closest_result r = query(a, b, &cache);
        check_answer(&A, &B, &o, r, &mine);
        wobj_free(&A);
        wobj_free(&B);
    }
    print_message("# coherent %-40s %5ld steps: %ld separated, %ld penetrating, mean walk %.2f, "
                  "max %ld, max error %.3g\n",
                  name, mine.n, mine.separated, mine.penetrating,
                  (double)mine.steps / (double)mine.n, mine.max_steps, mine.max_err);
    t->n += mine.n;
    t->steps += mine.steps;
    t->restarts += mine.restarts;
    if (mine.max_steps > t->max_steps) t->max_steps = mine.max_steps;
    t->max_err = fmax(t->max_err, mine.max_err);
}

static void coherent_sequences(void **state)
{
    (void)state;
    g_rng = seed(4242);
    int n = (int)(3000 * test_scale());
    if (n < 100) n = 100;
    struct {
        shape_params a, b;
        double step;
    } runs[] = {
        {sq_p(1, 1, 40, 40, 1, 1, 1), sq_p(1, 1, 40, 40, 1, 1, 1), 0.01},
        {sq_p(0.5, 1, 40, 40, 1.2, 0.8, 1), sq_p(1.5, 0.5, 30, 20, 1, 0.7, 1.2), 0.01},
        {sq_p(0.1, 0.1, 10, 10, 1, 1, 1), box_p(1, 0.5, 0.3), 0.01},
        {sq_p(2, 2, 20, 20, 1, 1, 1), sq_p(0.1, 2, 12, 8, 0.8, 1, 1), 0.02},
        {box_p(1, 1, 1), box_p(0.5, 1, 0.2), 0.01},
        {sphere_p(0.7), sq_p(1, 1, 40, 40, 1, 1, 1), 0.01},
        {sq_p(0.5, 0.5, 20, 20, 1, 1, 1), sphere_p(0.4), 0.01},
        {sphere_p(0.5), box_p(1, 0.6, 0.3), 0.01},
        {sq_p(1, 1, 10, 10, 1, 1, 1), sq_p(1, 1, 10, 10, 1, 1, 1), 0.05},
    };
    tally t = {0};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        tshape a, b;
        tshape_build(&a, &runs[i].a);
        tshape_build(&b, &runs[i].b);
        char name[160];
        snprintf(name, sizeof name, "%s / %s", a.name, b.name);
        coherent_run(&a.s, &b.s, n, runs[i].step, name, &t);
        tshape_free(&a);
        tshape_free(&b);
    }
    assert_int_equal(t.restarts, 0);
    /* coherence: the mean walk is a few steps */
    assert_true((double)t.steps / (double)t.n < 4);
}

/* ---- degenerate configurations ---- */

/* Every start: from scratch, and from every feature pair when the shapes are small. */
static void degenerate_case(const char *what, const shape *sa, vec3 xa, quat qa,
                            const shape *sb, vec3 xb, quat qb, double want, double tol)
{
    closest_proxy a = place(sa, xa, qa), b = place(sb, xb, qb);
    wobj A = wobj_make(a), B = wobj_make(b);
    oracle o = oracle_of(&A, &B, true);
    tally t = {0};
    snprintf(g_what, sizeof g_what, "%s (scratch)", what);
    closest_result r0 = query(a, b, NULL);
    if (isfinite(want)) {
        if (fabs(r0.distance - want) > tol)
            fail_msg("%s: distance %.17g, want %.17g", g_what, r0.distance, want);
    }
    if (!(fabs(r0.distance) <= 1e-9 && (o.intersect || o.dist <= 1e-9)))
        check_answer(&A, &B, &o, r0, &t);
    int nfa = sa->hull ? sa->hull->nv + sa->hull->ne + sa->hull->nf : 1;
    int nfb = sb->hull ? sb->hull->nv + sb->hull->ne + sb->hull->nf : 1;
    long starts = 0;
    if ((long)nfa * nfb <= 20000) {
        for (int i = 0; i < nfa; i++)
            for (int j = 0; j < nfb; j++) {
                closest_cache c = {{CLOSEST_SPHERE, 0}, {CLOSEST_SPHERE, 0}, true};
                const poly *pa = sa->hull, *pb = sb->hull;
                if (pa) c.fa = i < pa->nv ? (closest_feature){CLOSEST_VERTEX, i}
                        : i < pa->nv + pa->ne ? (closest_feature){CLOSEST_EDGE, i - pa->nv}
                        : (closest_feature){CLOSEST_FACE, i - pa->nv - pa->ne};
                if (pb) c.fb = j < pb->nv ? (closest_feature){CLOSEST_VERTEX, j}
                        : j < pb->nv + pb->ne ? (closest_feature){CLOSEST_EDGE, j - pb->nv}
                        : (closest_feature){CLOSEST_FACE, j - pb->nv - pb->ne};
                snprintf(g_what, sizeof g_what, "%s (from %s %d / %s %d)", what,
                         closest_kind_name(c.fa.kind), c.fa.index, closest_kind_name(c.fb.kind),
                         c.fb.index);
                closest_result r = query(a, b, &c);
                starts++;
                if (r.restarted) fail_msg("%s: restarted", g_what);
                if (isfinite(want) && fabs(r.distance - want) > tol)
                    fail_msg("%s: distance %.17g, want %.17g", g_what, r.distance, want);
                if (fabs(r.distance) <= 1e-9 && (o.intersect || o.dist <= 1e-9)) continue;
                check_answer(&A, &B, &o, r, &t);
            }
    }
    assert_int_equal(t.restarts, 0);
    if (r0.restarted) fail_msg("%s: restarted from scratch", what);
    wobj_free(&A);
    wobj_free(&B);
}

static void degenerate_configurations(void **state)
{
    (void)state;
    enum { CUBE, SMALL, SQ, SQ4, BALL, NSHAPES };
    tshape sh[NSHAPES];
    shape_params ps[NSHAPES] = {box_p(1, 1, 1), box_p(0.2, 0.2, 0.2),
                                sq_p(0.1, 0.1, 8, 8, 1, 1, 1), sq_p(1, 1, 4, 4, 1, 1, 1),
                                sphere_p(0.5)};
    for (int i = 0; i < NSHAPES; i++) tshape_build(&sh[i], &ps[i]);
    double zlo = INFINITY, zhi = -INFINITY; /* the flat superquadric's extent */
    for (int i = 0; i < sh[SQ].s.hull->nv; i++) {
        zlo = fmin(zlo, sh[SQ].s.hull->v[i].z);
        zhi = fmax(zhi, sh[SQ].s.hull->v[i].z);
    }
    quat I = q_identity(), rz90 = {sqrt(0.5), 0, 0, sqrt(0.5)};
    quat rx45 = q_axis_angle(v3(1, 0, 0), M_PI / 4), flip = {0, 1, 0, 0};
    quat corner = q_axis_angle(v3(1, -1, 0), acos(1 / sqrt(3))); /* (1,1,1) to +z */
    double inf = INFINITY, r2 = sqrt(2), r3 = sqrt(3);
    vec3 O = v3(0, 0, 0);
    const struct {
        const char *what;
        int a;
        vec3 xa;
        quat qa;
        int b;
        vec3 xb;
        quat qb;
        double want, tol; /* want infinite: only against the oracle */
    } cases[] = {
        /* face on face, parallel: aligned, turned, offset, edge over edge, corners */
        {"face on face", CUBE, O, I, CUBE, v3(0, 0, 2.5), I, 0.5, 1e-12},
        {"face on face, turned 90", CUBE, O, I, CUBE, v3(0, 0, 2.5), rz90, 0.5, 1e-12},
        {"face on face, offset", CUBE, O, I, CUBE, v3(0.3, 0.2, 2.5), I, 0.5, 1e-12},
        {"edge over edge", CUBE, O, I, CUBE, v3(2, 0, 2.5), I, 0.5, 1e-12},
        {"corner over corner", CUBE, O, I, CUBE, v3(2, 2, 2.5), I, 0.5, 1e-12},
        {"side by side", CUBE, O, I, CUBE, v3(2.5, 0.5, 0), I, 0.5, 1e-12},
        /* edge parallel to a face, over it and over its edge */
        {"edge parallel to face", CUBE, O, I, CUBE, v3(0, 0, 1.25 + r2), rx45, 0.25,
         1e-12},
        {"edge parallel to face, at its edge", CUBE, O, I, CUBE, v3(0, 1, 1.25 + r2),
         rx45, 0.25, 1e-12},
        /* vertex on vertex, along the diagonal; a vertex down onto a face */
        {"vertex on vertex", CUBE, O, I, CUBE, v3(2.5, 2.5, 2.5), I, r3 / 2, 1e-12},
        {"vertex down on a face", CUBE, O, I, CUBE, v3(0, 0, 1.1 + r3), corner, 0.1,
         1e-12},
        /* touching at distance 0 */
        {"touching face to face", CUBE, O, I, CUBE, v3(0, 0, 2), I, 0, 1e-12},
        {"touching, offset", CUBE, O, I, CUBE, v3(0.5, 1.5, 2), I, 0, 1e-12},
        {"touching corner to corner", CUBE, O, I, CUBE, v3(2, 2, 2), I, 0, 1e-12},
        {"touching edge to edge", CUBE, O, I, CUBE, v3(2, 0, 2), I, 0, 1e-12},
        {"touching, vertex on face", CUBE, O, I, CUBE, v3(0.1, 0.2, 1 + r3), corner, 0,
         1e-12},
        {"superquadrics touching", SQ, O, I, SQ, v3(0, 0, zhi - zlo), I, 0, 1e-12},
        /* penetration: inside, deep, identical */
        {"small cube inside", CUBE, O, I, SMALL, v3(0, 0, 0), I, -1.2, 1e-12},
        {"small cube inside, off centre", CUBE, O, I, SMALL, v3(0.5, 0.3, 0.1), rx45,
         inf, 0},
        {"deep penetration", CUBE, O, I, CUBE, v3(0.2, 0.1, 0.3), rx45, inf, 0},
        {"identical at the same place", CUBE, O, I, CUBE, v3(0, 0, 0), I, -2, 1e-12},
        {"identical, turned", CUBE, v3(1, 2, 3), rx45, CUBE, v3(1, 2, 3), rx45, -2, 1e-9},
        {"superquadrics identical", SQ, O, I, SQ, v3(0, 0, 0), I, inf, 0},
        {"4x4 superquadric in a cube", CUBE, O, I, SQ4, v3(0, 0, 0), I, inf, 0},
        /* superquadrics with parallel faces */
        {"superquadrics side by side", SQ, O, I, SQ, v3(2.3, 0, 0), I, inf, 0},
        {"superquadrics stacked, turned", SQ, O, I, SQ, v3(0, 0, 2.2), rz90, inf, 0},
        {"4x4 superquadrics vertex to vertex", SQ4, O, I, SQ4, v3(0, 0, 2.5), I, inf,
         0},
        {"4x4 superquadrics face to face", SQ4, O, I, SQ4, v3(1, 1, 1), flip, inf, 0},
        /* spheres on a face, an edge, a vertex; touching; inside */
        {"sphere over a face", CUBE, O, I, BALL, v3(0.2, 0.3, 2), I, 0.5, 1e-12},
        {"sphere over an edge", CUBE, O, I, BALL, v3(1.5, 0, 1.5), I, sqrt(0.5) - 0.5,
         1e-12},
        {"sphere over a vertex", CUBE, O, I, BALL, v3(2, 2, 2), I, r3 - 0.5, 1e-12},
        {"sphere touching", CUBE, O, I, BALL, v3(0, 0, 1.5), I, 0, 1e-12},
        {"sphere at the centre", CUBE, O, I, BALL, v3(0, 0, 0), I, -1.5, 1e-12},
        {"sphere centre on a face", CUBE, O, I, BALL, v3(0.3, 0, 1), I, -0.5, 1e-12},
        {"sphere over a superquadric", SQ4, O, I, BALL, v3(0, 0, 2), I, 0.5, 1e-12},
        {"sphere in a superquadric", SQ4, O, I, BALL, v3(0, 0, 0), I, inf, 0},
        {"spheres at one place", BALL, v3(1, 1, 1), I, BALL, v3(1, 1, 1), I, -1, 1e-12},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        degenerate_case(cases[i].what, &sh[cases[i].a].s, cases[i].xa, cases[i].qa,
                        &sh[cases[i].b].s, cases[i].xb, cases[i].qb, cases[i].want, cases[i].tol);
    for (int i = 0; i < NSHAPES; i++) tshape_free(&sh[i]);
}

/* Snapped configurations: rotations by multiples of 45 degrees about the axes and
 * positions on a grid of 0.25, so that faces are parallel, vertices meet edges and
 * objects touch exactly (as far as rounding lets them).  Each is queried from
 * scratch, from the last configuration's features and from a random feature pair. */
static void snapped_configurations(void **state)
{
    (void)state;
    g_rng = seed(2024);
    shape_params ps[] = {box_p(1, 1, 1), box_p(0.5, 1, 0.25), sq_p(0.1, 0.1, 8, 8, 1, 1, 1),
                         sq_p(1, 1, 4, 4, 1, 1, 1), sq_p(2, 2, 8, 8, 1, 1, 1),
                         sq_p(1, 1, 8, 6, 0.75, 1, 0.5), sphere_p(0.5)};
    int np = (int)(sizeof ps / sizeof ps[0]);
    tshape sh[8];
    for (int i = 0; i < np; i++) tshape_build(&sh[i], &ps[i]);
    vec3 axes[3] = {v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
    long n = (long)(20000 * test_scale()) + 100, touching = 0;
    tally t = {0};
    closest_cache stale[8][8];
    memset(stale, 0, sizeof stale);
    for (long k = 0; k < n; k++) {
        int i = (int)(rnd() * np), j = (int)(rnd() * np);
        quat q[2];
        for (int s = 0; s < 2; s++) {
            q[s] = q_identity();
            for (int m = 0; m < 2; m++)
                q[s] = q_mul(q_axis_angle(axes[(int)(rnd() * 3)], M_PI / 4 * (int)(rnd() * 8)),
                             q[s]);
        }
        vec3 xb = v3(0.25 * (int)(rnd() * 17 - 8), 0.25 * (int)(rnd() * 17 - 8),
                     0.25 * (int)(rnd() * 17 - 8));
        closest_proxy a = place(&sh[i].s, v3(0, 0, 0), q[0]), b = place(&sh[j].s, xb, q[1]);
        wobj A = wobj_make(a), B = wobj_make(b);
        oracle o = oracle_of(&A, &B, false);
        closest_cache rc = {0};
        const poly *pa = sh[i].s.hull, *pb = sh[j].s.hull;
        closest_feature sphere = {CLOSEST_SPHERE, 0};
        rc.fa = pa ? (closest_feature){CLOSEST_FACE, (int)(rnd() * pa->nf)} : sphere;
        rc.fb = pb ? (closest_feature){CLOSEST_EDGE, (int)(rnd() * pb->ne)} : sphere;
        rc.valid = true;
        closest_cache *caches[3] = {NULL, &stale[i][j], &rc};
        for (int c = 0; c < 3; c++) {
            snprintf(g_what, sizeof g_what, "snapped %ld (%s / %s at %g %g %g, start %d)", k,
                     sh[i].name, sh[j].name, xb.x, xb.y, xb.z, c);
            closest_result r = query(a, b, caches[c]);
            if (fabs(r.distance) <= 1e-9 && (o.intersect || o.dist <= 1e-9)) {
                touching += c == 0;
                t.n++;
                if (r.restarted) t.restarts++;
                continue;
            }
            check_answer(&A, &B, &o, r, &t);
        }
        wobj_free(&A);
        wobj_free(&B);
    }
    print_message("# %ld snapped configurations (%ld touching), %ld queries: %ld separated, "
                  "%ld penetrating; max error %.3g; mean steps %.2f, max %ld; restarts %ld\n",
                  n, touching, t.n, t.separated, t.penetrating, t.max_err,
                  (double)t.steps / (double)t.n, t.max_steps, t.restarts);
    assert_int_equal(t.restarts, 0);
    for (int i = 0; i < np; i++) tshape_free(&sh[i]);
}

/* ---- the body-level API ---- */

static body *make_body(const char *name, shape_params p, vec3 x, quat q, bool *own_feat)
{
    body *b = malloc(sizeof *b);
    body_init(b, name, p.kind);
    b->sp = p;
    char err[256];
    if (body_build(b, err, sizeof err) != 0) fail_msg("body_build: %s", err);
    *own_feat = !b->shape.feat && b->shape.hull;
    if (*own_feat) b->shape.feat = closest_hull_new(b->shape.hull);
    b->x = x;
    b->q = q;
    return b;
}

static void drop_body(body *b, bool own_feat)
{
    if (own_feat) {
        closest_hull_free(b->shape.feat);
        b->shape.feat = NULL;
    }
    body_free(b);
    free(b);
}

static bool same_result(closest_result r, closest_result m)
{
    /* r against m mirrored, bit for bit */
    return r.status == m.status && memcmp(&r.distance, &m.distance, sizeof r.distance) == 0 &&
           memcmp(&r.pa, &m.pb, sizeof r.pa) == 0 && memcmp(&r.pb, &m.pa, sizeof r.pb) == 0 &&
           r.normal.x == -m.normal.x && r.normal.y == -m.normal.y && r.normal.z == -m.normal.z &&
           r.fa.kind == m.fb.kind && r.fa.index == m.fb.index && r.fb.kind == m.fa.kind &&
           r.fb.index == m.fa.index;
}

static void symmetric_bodies(void **state)
{
    (void)state;
    g_rng = seed(99);
    shape_params ps[] = {sphere_p(0.6), box_p(1, 0.5, 0.3), sq_p(0.5, 1.5, 12, 9, 1, 0.8, 1.1),
                         box_p(1, 1, 1)};
    int np = (int)(sizeof ps / sizeof ps[0]);
    for (int i = 0; i < np; i++)
        for (int j = 0; j < np; j++) {
            bool owna, ownb;
            body *a = make_body("alpha", ps[i], v3(0, 0, 0), q_identity(), &owna);
            body *b = make_body("beta", ps[j], v3(0, 0, 0), q_identity(), &ownb);
            closest_cache cab = {0}, cba = {0};
            for (int k = 0; k < 300; k++) {
                a->x = v3(rnd_in(-1, 1), rnd_in(-1, 1), rnd_in(-1, 1));
                a->q = rnd_quat();
                b->x = v3_mad(a->x, rnd_unit(), rnd_in(0.5, 3));
                b->q = rnd_quat();
                if (k % 10 == 0) b->x = a->x, b->q = a->q; /* exactly degenerate */
                closest_result r1 = body_distance(a, b, &cab), r2 = body_distance(b, a, &cba);
                if (!same_result(r1, r2))
                    fail_msg("%s / %s config %d: query(a, b) and query(b, a) differ",
                             body_type_name(ps[i].kind), body_type_name(ps[j].kind), k);
                if (cab.fa.kind != cba.fb.kind || cab.fa.index != cba.fb.index ||
                    cab.fb.kind != cba.fa.kind || cab.fb.index != cba.fa.index)
                    fail_msg("caches differ");
                assert_false(r1.restarted);
            }
            drop_body(a, owna);
            drop_body(b, ownb);
        }
}

static void invalid_input(void **state)
{
    (void)state;
    bool owna, ownb;
    body *a = make_body("a", box_p(1, 1, 1), v3(0, 0, 0), q_identity(), &owna);
    body *b = make_body("b", sphere_p(1), v3(5, 0, 0), q_identity(), &ownb);
    closest_cache c = {0};
    closest_result r = body_distance(a, b, &c);
    assert_int_equal(r.status, CLOSEST_SEPARATED);
    assert_near(r.distance, 3, 1e-15);
    assert_true(c.valid);
    /* a stale cache from other shapes (indices out of range) is ignored */
    closest_cache bad = {{CLOSEST_FACE, 1000}, {CLOSEST_EDGE, 3}, true};
    r = body_distance(a, b, &bad);
    assert_near(r.distance, 3, 1e-15);
    b->x.y = NAN;
    closest_cache keep = c;
    r = body_distance(a, b, &c);
    assert_int_equal(r.status, CLOSEST_INVALID);
    assert_true(isnan(r.distance));
    assert_memory_equal(&c, &keep, sizeof c);
    b->x.y = 0;
    b->built = false;
    r = body_distance(a, b, NULL);
    assert_int_equal(r.status, CLOSEST_INVALID);
    b->built = true;
    r = body_distance(a, b, NULL);
    assert_int_equal(r.status, CLOSEST_SEPARATED);
    assert_string_equal(closest_kind_name(r.fb.kind), "sphere");
    assert_string_equal(closest_kind_name(r.fa.kind), "face");
    drop_body(a, owna);
    drop_body(b, ownb);
}

/* ---- the support hierarchy (support.h) ---- */

/* support_vertex gives a vertex no other is further along d than, on hulls with a
 * hierarchy (tessellations, a Fibonacci sphere of points, a box-like superquadric
 * with flat merged faces) and without, along random directions and along the axes
 * and diagonals (where many vertices tie). */
static void check_support(const poly *h, const char *name)
{
    support_tree *t = support_tree_new(h);
    if (h->nv > SUPPORT_MIN_VERTICES) assert_non_null(t);
    else assert_null(t);
    for (int i = 0; i < 2000 + 27; i++) {
        vec3 d;
        if (i < 27) d = v3(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1); /* (0, 0, 0) too */
        else d = v3(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5);
        int j = support_vertex(t, h, d);
        assert_true(j >= 0 && j < h->nv);
        double best = -INFINITY;
        for (int v = 0; v < h->nv; v++) best = fmax(best, v3_dot(h->v[v], d));
        if (v3_dot(h->v[j], d) != best)
            fail_msg("%s: support along (%g, %g, %g) is vertex %d at %.17g, not %.17g", name, d.x,
                     d.y, d.z, j, v3_dot(h->v[j], d), best);
    }
    support_tree_free(t);
}

static void support_hierarchy(void **state)
{
    (void)state;
    struct {
        double e1, e2;
        int res;
    } sq[] = {{1, 1, 10}, {1, 1, 40}, {1, 1, 96}, {0.1, 0.1, 40}, {0.5, 1.5, 48}, {2, 0.3, 60}};
    for (size_t i = 0; i < sizeof sq / sizeof sq[0]; i++) {
        shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
        p.exp1 = sq[i].e1;
        p.exp2 = sq[i].e2;
        p.ures = p.vres = sq[i].res;
        tshape t;
        tshape_build(&t, &p);
        check_support(t.s.hull, t.name);
        tshape_free(&t);
    }
    int np = 5000;
    vec3 *pts = malloc((size_t)np * sizeof *pts);
    assert_non_null(pts);
    const double golden = 3.14159265358979323846 * (3 - sqrt(5));
    for (int i = 0; i < np; i++) {
        double z = 1 - (2 * i + 1.0) / np, r = sqrt(1 - z * z);
        pts[i] = v3(r * cos(golden * i), r * sin(golden * i), z);
    }
    char err[256];
    poly *h = poly_hull_merge(pts, np, 0, err, sizeof err);
    if (!h) fail_msg("poly_hull_merge: %s", err);
    assert_int_equal(h->nv, np);
    check_support(h, "5,000 points on a sphere");
    poly_free(h);
    free(pts);
}

/* ---- the time of impact's points' bound, walked on large hulls (envelope.h) ---- */

/* A random side for hull h: its lowest vertex gap above the plane, its vertices
 * rising at rates that differ by up to a few m/s across it (a turn). */
static env_side rnd_side(const poly *h, const closest_hull *feat)
{
    /* (a walk starts down the hierarchy, or by a climb from a vertex anywhere) */
    env_side s = {.dh0 = rnd_unit(), .dh1 = v3_scale(rnd_unit(), rnd_in(0, 3)), .hull = h, .feat = feat,
                  .near = rnd() < 0.5 ? -1 : (int)(rnd() * h->nv)};
    double lo = HUGE_VAL;
    for (int i = 0; i < h->nv; i++) lo = fmin(lo, v3_dot(h->v[i], s.dh0));
    s.h0 = -lo + rnd_in(0, 0.02);
    s.h1 = rnd_in(-4, 1);
    return s;
}

/* The first time in [0, T) at which c0 + c1 t + q t^2 <= 0, else HUGE_VAL. */
static double first_root(double c0, double c1, double q, double T)
{
    if (!(c0 > 0)) return 0;
    double r = HUGE_VAL;
    if (q == 0) {
        if (c1 < 0) r = -c0 / c1;
    } else {
        double disc = c1 * c1 - 4 * q * c0;
        if (disc >= 0) {
            double s = sqrt(disc);
            double r1 = (-c1 - s) / (2 * q), r2 = (-c1 + s) / (2 * q);
            if (r1 >= 0) r = r1;
            if (r2 >= 0 && r2 < r) r = r2;
        }
    }
    return r < T ? r : HUGE_VAL;
}

/* The oracle: the first time any vertex of a and any of b (each its own line)
 * plus q t^2 come down to goal, pair by pair. */
static double oracle_time(const env_side *a, const env_side *b, double q, double goal, double T)
{
    double best = HUGE_VAL;
    for (int i = 0; i < a->hull->nv; i++) {
        vec3 y = a->hull->v[i];
        double a0 = a->h0 + v3_dot(y, a->dh0), a1 = a->h1 + v3_dot(y, a->dh1);
        for (int j = 0; j < (b->hull ? b->hull->nv : 1); j++) {
            double b0 = b->hull ? b->h0 + v3_dot(b->hull->v[j], b->dh0) : b->h0;
            double b1 = b->hull ? b->h1 + v3_dot(b->hull->v[j], b->dh1) : b->h1;
            best = fmin(best, first_root(a0 + b0 - goal, a1 + b1, q, T));
        }
    }
    return best;
}

/* Hulls of 2,000 and 10,000 vertices (points over an ellipsoid) and a 48 x 48
 * superquadric with flat merged faces under random motions, against a ball, a
 * small hull and another large one: the walked bound is never later than the
 * first contact of the vertices (each pair's own quadratic, solved), no earlier
 * than it by more than rounding (as sharp as the vertex-by-vertex envelope, which
 * is that contact), and reads a few dozen vertices, not all. */
static void envelope_walk(void **state)
{
    (void)state;
    shape_params sp = shape_defaults(SHAPE_SUPERQUADRIC);
    sp.exp1 = 0.1;
    sp.exp2 = 1;
    sp.ures = sp.vres = 48;
    tshape sq;
    tshape_build(&sq, &sp);
    int sizes[] = {2000, 10000, 0};
    vec3 *small = malloc(64 * sizeof *small);
    assert_non_null(small);
    for (int i = 0; i < 64; i++) small[i] = v3_scale(rnd_unit(), 0.1);
    char err[256];
    poly *ph = poly_hull_merge(small, 64, 0, err, sizeof err);
    if (!ph) fail_msg("poly_hull_merge: %s", err);
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
        int np = sizes[z];
        poly *h = sq.s.hull;
        if (np > 0) {
            vec3 *pts = malloc((size_t)np * sizeof *pts);
            assert_non_null(pts);
            const double golden = 3.14159265358979323846 * (3 - sqrt(5));
            for (int i = 0; i < np; i++) {
                double zz = 1 - (2 * i + 1.0) / np, r = sqrt(1 - zz * zz);
                pts[i] = v3(0.4 * r * cos(golden * i), 0.25 * r * sin(golden * i), 0.15 * zz);
            }
            h = poly_hull_merge(pts, np, 0, err, sizeof err);
            free(pts);
            if (!h) fail_msg("poly_hull_merge: %s", err);
        }
        assert_true(h->nv > ENV_FLAT_VERTICES);
        closest_hull *feat = closest_hull_new(h);
        assert_non_null(feat);
        long reads = 0, met = 0;
        int trials = h->nv > 2500 ? 50 : 90;
        for (int k = 0; k < trials; k++) {
            env_side a = rnd_side(h, feat), b;
            if (k % 3 == 0) b = (env_side){.h0 = rnd_in(0, 0.02), .h1 = rnd_in(-4, 1), .near = -1}; /* a ball */
            else if (k % 3 == 1 || h->nv > 2500) b = rnd_side(ph, NULL);
            else b = rnd_side(h, feat);
            double q = k % 4 == 0 ? 0 : rnd_in(-3, 0.5), target = rnd_in(0, 0.01), margin = 1e-9;
            double T = rnd_in(0.002, 0.02);
            int n = 0;
            double t = env_first_time(&a, &b, q, target, margin, T, &n);
            reads += n;
            double truth = oracle_time(&a, &b, q, target + margin, T);
            met += truth < HUGE_VAL;
            /* (within rounding: the oracle's roots and the bound's sums round apart) */
            if (!(t <= truth + 1e-12 * (1 + truth)))
                fail_msg("%d vertices, trial %d: the walked bound %.17g is after the contact at %.17g",
                         h->nv, k, t, truth);
            if (truth < HUGE_VAL && !(t >= truth - 1e-9 * (1 + truth)))
                fail_msg("%d vertices, trial %d: the walked bound %.17g is well before the contact at %.17g",
                         h->nv, k, t, truth);
            if (truth == HUGE_VAL) assert_true(t == HUGE_VAL);
        }
        double per = (double)reads / trials;
        print_message("envelope walked on %d vertices: %.1f vertices read a query (besides finding the "
                      "lowest now); %ld of %d meet\n",
                      h->nv, per, met, trials);
        assert_true(met > trials / 4 && met < trials);
        assert_true(per < 200);
        closest_hull_free(feat);
        if (h != sq.s.hull) poly_free(h);
    }
    poly_free(ph);
    free(small);
    tshape_free(&sq);
}

int main(void)
{
    const char *filter = getenv("VROC_TEST_FILTER");
    if (filter && *filter) cmocka_set_test_filter(filter);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(oracle_is_exact),
        cmocka_unit_test(random_configurations),
        cmocka_unit_test(coherent_sequences),
        cmocka_unit_test(degenerate_configurations),
        cmocka_unit_test(snapped_configurations),
        cmocka_unit_test(symmetric_bodies),
        cmocka_unit_test(invalid_input),
        cmocka_unit_test(support_hierarchy),
        cmocka_unit_test(envelope_walk),
    };
    return cmocka_run_group_tests(tests, pool_setup, pool_teardown);
}
