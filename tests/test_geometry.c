/* test_geometry.c: unit tests of poly.c (hulls, adjacency, mass properties) and
 * shape.c (the three primitives), all against closed forms: the box, the regular
 * tetrahedron and octahedron, the sphere and the ellipsoid (V = 4/3 pi a b c,
 * Ixx = V (b^2 + c^2) / 5), and the box that a superquadric with small exponents
 * approaches.  The adjacency conventions of poly.h are checked here directly, not
 * only through poly_check.  And vmath's sin_cos against libm. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/poly.h"
#include "core/shape.h"

static const double PI = 3.14159265358979323846;

/* ---- helpers ---- */

/* A fixed-seed generator (64-bit LCG), uniform in [-1, 1). */
static double rnd(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0 * 2.0 - 1.0;
}

static double extent(const vec3 *pts, int n)
{
    vec3 lo = pts[0], hi = pts[0];
    for (int i = 1; i < n; i++) {
        lo = v3_min(lo, pts[i]);
        hi = v3_max(hi, pts[i]);
    }
    vec3 d = v3_sub(hi, lo);
    return fmax(d.x, fmax(d.y, d.z));
}

static vec3 face_centroid(const poly *p, int f)
{
    vec3 c = v3(0, 0, 0);
    for (int k = 0; k < p->f[f].count; k++) c = v3_add(c, p->v[p->face_vert[p->f[f].first + k]]);
    return v3_scale(c, 1.0 / p->f[f].count);
}

static double face_area(const poly *p, int f)
{
    const int *fv = p->face_vert + p->f[f].first;
    vec3 a = v3(0, 0, 0);
    for (int k = 1; k + 1 < p->f[f].count; k++)
        a = v3_add(a, v3_cross(v3_sub(p->v[fv[k]], p->v[fv[0]]), v3_sub(p->v[fv[k + 1]], p->v[fv[0]])));
    return 0.5 * v3_len(a);
}

/* poly_check, plus the conventions of poly.h checked independently of it: the face
 * on an edge's left (seen from outside, walking tail -> head) has its interior to
 * the left, i.e. along n x (head - tail); vertex -> edge lists hold each edge at its
 * two ends. */
static void check_poly(const poly *p, double tol)
{
    char err[256] = "";
    if (poly_check(p, tol, err, sizeof err) != 0) fail_msg("poly_check: %s", err);
    assert_int_equal(p->nv - p->ne + p->nf, 2);
    for (int e = 0; e < p->ne; e++) {
        vec3 a = p->v[p->e[e].v[0]], b = p->v[p->e[e].v[1]], mid = v3_lerp(a, b, 0.5);
        vec3 left0 = v3_cross(p->f[p->e[e].f[0]].n, v3_sub(b, a));
        vec3 left1 = v3_cross(p->f[p->e[e].f[1]].n, v3_sub(a, b));
        assert_true(v3_dot(left0, v3_sub(face_centroid(p, p->e[e].f[0]), mid)) > 0);
        assert_true(v3_dot(left1, v3_sub(face_centroid(p, p->e[e].f[1]), mid)) > 0);
    }
    int *seen = calloc((size_t)p->ne, sizeof *seen);
    assert_non_null(seen);
    for (int v = 0; v < p->nv; v++)
        for (int j = p->vert_first[v]; j < p->vert_first[v + 1]; j++) {
            int e = p->vert_edge[j];
            assert_true(p->e[e].v[0] == v || p->e[e].v[1] == v);
            seen[e]++;
        }
    for (int e = 0; e < p->ne; e++) assert_int_equal(seen[e], 2);
    free(seen);
}

/* |a - b| <= tol * scale, elementwise */
static void assert_mat_near(mat3 a, mat3 b, double tol)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) assert_near(a.m[i][j], b.m[i][j], tol);
}

static mat3 box_inertia(vec3 h)
{
    double v = 8 * h.x * h.y * h.z;
    return m3_diag(v3_scale(v3(h.y * h.y + h.z * h.z, h.x * h.x + h.z * h.z, h.x * h.x + h.y * h.y), v / 3));
}

static poly *hull_or_fail(const vec3 *pts, int n)
{
    char err[256] = "";
    poly *p = poly_hull(pts, n, err, sizeof err);
    if (!p) fail_msg("poly_hull: %s", err);
    return p;
}

/* ---- poly ---- */

static void test_box_hull(void **state)
{
    (void)state;
    const vec3 sizes[] = {{1, 1, 1}, {0.5, 2, 3}, {1e-3, 1, 20}, {7, 0.25, 0.25}};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        vec3 h = sizes[s], c[8];
        for (int k = 0; k < 8; k++)
            c[k] = v3(k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z);
        poly *p = hull_or_fail(c, 8);
        assert_int_equal(p->nv, 8);
        assert_int_equal(p->ne, 12);
        assert_int_equal(p->nf, 6);
        for (int f = 0; f < 6; f++) assert_int_equal(p->f[f].count, 4);
        for (int v = 0; v < 8; v++) assert_int_equal(p->vert_first[v + 1] - p->vert_first[v], 3);
        double size = 2 * fmax(h.x, fmax(h.y, h.z));
        check_poly(p, 1e-9 * size);
        mass_props m = poly_mass(p);
        double vol = 8 * h.x * h.y * h.z;
        assert_rel(m.volume, vol, 1e-12);
        assert_vec_near(m.com, v3(0, 0, 0), 1e-12 * size);
        mat3 want = box_inertia(h);
        for (int i = 0; i < 3; i++) assert_rel(m.inertia.m[i][i], want.m[i][i], 1e-12);
        assert_mat_near(m.inertia, want, 1e-12 * want.m[0][0] * 10);
        assert_rel(poly_inner_radius(p, m.com), fmin(h.x, fmin(h.y, h.z)), 1e-12);
        assert_rel(poly_outer_radius(p, m.com), v3_len(h), 1e-12);
        poly_free(p);
    }
}

static void test_box_moved(void **state)
{
    (void)state;
    vec3 h = v3(0.3, 1.1, 2.0), t = v3(5, -3, 12), c[8];
    mat3 r = m3_from_quat(q_axis_angle(v3(1, 2, 3), 0.7));
    for (int k = 0; k < 8; k++)
        c[k] = v3_add(t, m3_mulv(r, v3(k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z)));
    poly *p = hull_or_fail(c, 8);
    assert_int_equal(p->nv, 8);
    assert_int_equal(p->ne, 12);
    assert_int_equal(p->nf, 6);
    check_poly(p, 1e-9 * 4);
    mass_props m = poly_mass(p);
    assert_rel(m.volume, 8 * h.x * h.y * h.z, 1e-12);
    assert_vec_near(m.com, t, 1e-12 * 15);
    mat3 want = m3_mul(m3_mul(r, box_inertia(h)), m3_transpose(r));
    assert_mat_near(m.inertia, want, 1e-12 * want.m[2][2] * 10);
    /* every face normal is one of the rotated axes */
    for (int f = 0; f < 6; f++) {
        double best = 0;
        for (int a = 0; a < 3; a++) best = fmax(best, fabs(v3_dot(p->f[f].n, m3_col(r, a))));
        assert_near(best, 1, 1e-12);
    }
    poly_free(p);
}

static void test_tetrahedron(void **state)
{
    (void)state;
    vec3 c[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    poly *p = hull_or_fail(c, 4);
    assert_int_equal(p->nv, 4);
    assert_int_equal(p->ne, 6);
    assert_int_equal(p->nf, 4);
    check_poly(p, 1e-9 * 2);
    mass_props m = poly_mass(p);
    double a = 2 * sqrt(2.0), vol = a * a * a / (6 * sqrt(2.0)); /* = 8/3 */
    assert_rel(m.volume, vol, 1e-12);
    assert_vec_near(m.com, v3(0, 0, 0), 1e-12);
    /* regular tetrahedron: I = m a^2 / 20 about any axis through the centroid */
    assert_mat_near(m.inertia, m3_scale(m3_identity(), vol * a * a / 20), 1e-12);
    /* inscribed radius a / sqrt(24), circumscribed a sqrt(3/8) */
    assert_rel(poly_inner_radius(p, m.com), a / sqrt(24.0), 1e-12);
    assert_rel(poly_outer_radius(p, m.com), a * sqrt(3.0 / 8.0), 1e-12);
    poly_free(p);
}

static void test_octahedron(void **state)
{
    (void)state;
    /* with interior points and midpoints of edges, which must not become vertices */
    vec3 c[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                {0, 0, 0}, {0.1, 0.2, -0.3}, {0.5, 0.5, 0}, {0, -0.5, 0.5}};
    poly *p = hull_or_fail(c, (int)(sizeof c / sizeof c[0]));
    assert_int_equal(p->nv, 6);
    assert_int_equal(p->ne, 12);
    assert_int_equal(p->nf, 8);
    for (int f = 0; f < 8; f++) assert_int_equal(p->f[f].count, 3);
    check_poly(p, 1e-9 * 2);
    mass_props m = poly_mass(p);
    /* |x|+|y|+|z| <= 1: V = 4/3, integral of x^2 = 8 * 2!/5! = 2/15, Ixx = 4/15 */
    assert_rel(m.volume, 4.0 / 3.0, 1e-12);
    assert_mat_near(m.inertia, m3_scale(m3_identity(), 4.0 / 15.0), 1e-12);
    assert_rel(poly_inner_radius(p, m.com), 1 / sqrt(3.0), 1e-12);
    poly_free(p);
}

/* Fails unless polyhedra p and q are the same to the bit: counts, vertices,
 * edges, faces and every adjacency list. */
static void same_poly(const poly *p, const poly *q)
{
    assert_int_equal(p->nv, q->nv);
    assert_int_equal(p->ne, q->ne);
    assert_int_equal(p->nf, q->nf);
    int nfv = p->f[p->nf - 1].first + p->f[p->nf - 1].count;
    assert_memory_equal(p->v, q->v, (size_t)p->nv * sizeof *p->v);
    assert_memory_equal(p->e, q->e, (size_t)p->ne * sizeof *p->e);
    assert_memory_equal(p->f, q->f, (size_t)p->nf * sizeof *p->f);
    assert_memory_equal(p->face_vert, q->face_vert, (size_t)nfv * sizeof *p->face_vert);
    assert_memory_equal(p->face_edge, q->face_edge, (size_t)nfv * sizeof *p->face_edge);
    assert_memory_equal(p->vert_first, q->vert_first, (size_t)(p->nv + 1) * sizeof *p->vert_first);
    assert_memory_equal(p->vert_edge, q->vert_edge, (size_t)(2 * p->ne) * sizeof *p->vert_edge);
}

/* A box built directly (poly_box, no qhull run) is the box poly_hull makes of its
 * eight corners, to the bit: vertices, edges, faces and every list, over boxes of
 * every proportion; so that no closest-feature walk, and no trace, changes. */
static void test_box_as_qhull_makes_it(void **state)
{
    (void)state;
    uint64_t s = 27;
    for (int k = 0; k < 300; k++) {
        double scale = pow(10, 3 * rnd(&s));
        vec3 h = v3(scale * pow(10, 2 * rnd(&s)), scale * pow(10, 2 * rnd(&s)),
                    scale * pow(10, 2 * rnd(&s)));
        if (k == 0) h = v3(1, 1, 1);
        vec3 c[8];
        for (int j = 0; j < 8; j++) c[j] = v3(j & 1 ? h.x : -h.x, j & 2 ? h.y : -h.y, j & 4 ? h.z : -h.z);
        char err[200];
        poly *q = poly_hull(c, 8, err, sizeof err), *p = poly_box(h, err, sizeof err);
        assert_non_null(q);
        assert_non_null(p);
        same_poly(p, q);
        poly_free(p);
        poly_free(q);
    }
}

/* Random clouds: a valid polyhedron containing every point; the exact hull's
 * vertices are input points, and merging only grows the hull. */
static void test_random_clouds(void **state)
{
    (void)state;
    uint64_t seed = 12345;
    const int sizes[] = {4, 5, 10, 50, 300, 2000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int kind = 0; kind < 2; kind++) {
            int n = sizes[s];
            vec3 *pts = malloc((size_t)n * sizeof *pts);
            assert_non_null(pts);
            for (int i = 0; i < n; i++) {
                pts[i] = v3(rnd(&seed) * 2, rnd(&seed), rnd(&seed) * 0.5);
                if (kind == 1) pts[i] = v3_scale(v3_norm(pts[i]), 3); /* on a sphere */
            }
            double size = extent(pts, n);
            poly *p = hull_or_fail(pts, n);
            check_poly(p, 1e-9 * size);
            mass_props m = poly_mass(p);
            assert_true(m.volume > 0);
            for (int i = 0; i < n; i++)
                for (int f = 0; f < p->nf; f++)
                    assert_true(v3_dot(p->f[f].n, pts[i]) - p->f[f].d <= 1e-12 * size);
            char err[256];
            poly *x = poly_hull_merge(pts, n, 0, err, sizeof err);
            assert_non_null(x);
            check_poly(x, 1e-9 * size);
            for (int v = 0; v < x->nv; v++) {
                int found = 0;
                for (int i = 0; i < n && !found; i++) found = memcmp(&x->v[v], &pts[i], sizeof(vec3)) == 0;
                assert_true(found);
            }
            assert_true(poly_mass(x).volume <= m.volume * (1 + 1e-12));
            poly_free(x);
            poly_free(p);
            free(pts);
        }
}

static void test_degenerate(void **state)
{
    (void)state;
    char err[256];
    vec3 three[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    err[0] = 0;
    assert_null(poly_hull(three, 3, err, sizeof err));
    assert_non_null(strstr(err, "at least 4 points"));

    vec3 flat[20], line[10], same[6], bad[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {NAN, 0, 0}};
    for (int i = 0; i < 20; i++) flat[i] = v3(i % 5, i / 5, 0.5 * (i % 5) - 0.25 * (i / 5));
    for (int i = 0; i < 10; i++) line[i] = v3(i, 2.0 * i, -1.0 * i);
    for (int i = 0; i < 6; i++) same[i] = v3(1, 2, 3);
    const vec3 *sets[] = {flat, line, same, bad};
    const int counts[] = {20, 10, 6, 5};
    for (int k = 0; k < 4; k++) {
        err[0] = 0;
        assert_null(poly_hull(sets[k], counts[k], err, sizeof err));
        assert_true(strlen(err) > 0);
        assert_true(err[0] >= 'a' && err[0] <= 'z');
    }
    err[0] = 0;
    assert_null(poly_hull(flat, 20, err, sizeof err));
    assert_non_null(strstr(err, "coplanar"));
}

static void test_copy_support(void **state)
{
    (void)state;
    shape_params sp = shape_defaults(SHAPE_SUPERQUADRIC);
    sp.exp1 = 0.6, sp.exp2 = 1.4, sp.a1 = 1.2, sp.a2 = 0.8, sp.a3 = 0.5, sp.ures = 17, sp.vres = 11;
    int n = superquadric_points(&sp, NULL, 0);
    vec3 *pts = malloc((size_t)n * sizeof *pts);
    assert_non_null(pts);
    assert_int_equal(superquadric_points(&sp, pts, n), n);
    poly *p = hull_or_fail(pts, n), *q = poly_copy(p);
    assert_non_null(q);
    assert_true(q->v != p->v);
    same_poly(p, q);
    poly_free(p);
    uint64_t seed = 99;
    for (int t = 0; t < 200; t++) {
        vec3 d = v3(rnd(&seed), rnd(&seed), rnd(&seed));
        if (t < 6) d = v3(t == 0 ? 1 : t == 1 ? -1 : 0, t == 2 ? 1 : t == 3 ? -1 : 0, t == 4 ? 1 : t == 5 ? -1 : 0);
        int s = poly_support(q, d);
        assert_true(s >= 0 && s < q->nv);
        double best = -INFINITY;
        for (int v = 0; v < q->nv; v++) best = fmax(best, v3_dot(q->v[v], d));
        for (int i = 0; i < n; i++) assert_true(v3_dot(pts[i], d) <= best + 1e-12);
        assert_true(v3_dot(q->v[s], d) == best);
    }
    poly_free(q);
    free(pts);
}

/* ---- shapes ---- */

static void test_defaults(void **state)
{
    (void)state;
    shape_params p = shape_defaults(SHAPE_CUBE);
    assert_int_equal(p.kind, SHAPE_CUBE);
    assert_true(p.radius == 1 && p.exp1 == 1 && p.exp2 == 1 && p.a1 == 1 && p.a2 == 1 && p.a3 == 1);
    assert_true(p.size.x == 1 && p.size.y == 1 && p.size.z == 1);
    assert_int_equal(p.ures, 10);
    assert_int_equal(p.vres, 10);
}

/* Mesh sanity: unit finite normals; for convex shapes centred at the origin,
 * triangles ccw seen from outside and normals pointing out. */
static void check_mesh(const mesh *m, bool convex)
{
    for (int v = 0; v < m->nv; v++) {
        assert_true(v3_finite(m->pos[v]));
        assert_true(v3_finite(m->nrm[v]));
        assert_near(v3_len(m->nrm[v]), 1, 1e-12);
        if (convex) assert_true(v3_dot(m->nrm[v], m->pos[v]) > 0);
    }
    for (int t = 0; t < m->nt; t++) {
        for (int k = 0; k < 3; k++) assert_true(m->tri[t][k] >= 0 && m->tri[t][k] < m->nv);
        if (!convex) continue;
        vec3 a = m->pos[m->tri[t][0]], b = m->pos[m->tri[t][1]], c = m->pos[m->tri[t][2]];
        vec3 g = v3_scale(v3_add(a, v3_add(b, c)), 1.0 / 3.0);
        assert_true(v3_dot(v3_cross(v3_sub(b, a), v3_sub(c, a)), g) > 0);
    }
}

static void test_sphere(void **state)
{
    (void)state;
    shape_params p = shape_defaults(SHAPE_SPHERE);
    p.radius = 1.5, p.ures = 16, p.vres = 9;
    shape s;
    char err[256];
    assert_int_equal(shape_build(&s, &p, err, sizeof err), 0);
    assert_null(s.hull);
    double vol = 4.0 / 3.0 * PI * 1.5 * 1.5 * 1.5;
    assert_rel(s.mass.volume, vol, 1e-15);
    assert_vec_near(s.mass.com, v3(0, 0, 0), 0);
    assert_mat_near(s.mass.inertia, m3_scale(m3_identity(), 0.4 * vol * 1.5 * 1.5), 1e-13);
    assert_true(s.r_in == 1.5 && s.r_out == 1.5);
    assert_int_equal(s.draw.nv, 16 * 8 + 2);
    assert_int_equal(s.draw.nt, 2 * 16 * 8);
    check_mesh(&s.draw, true);
    for (int v = 0; v < s.draw.nv; v++) {
        assert_near(v3_len(s.draw.pos[v]), 1.5, 1e-14);
        assert_vec_near(s.draw.nrm[v], v3_scale(s.draw.pos[v], 1 / 1.5), 1e-14);
    }
    shape_free(&s);
    shape_free(&s); /* freeing twice is harmless */
}

static void test_cube(void **state)
{
    (void)state;
    shape_params p = shape_defaults(SHAPE_CUBE);
    p.size = v3(0.5, 1, 2);
    shape s;
    char err[256];
    assert_int_equal(shape_build(&s, &p, err, sizeof err), 0);
    assert_non_null(s.hull);
    assert_int_equal(s.hull->nv, 8);
    assert_int_equal(s.hull->ne, 12);
    assert_int_equal(s.hull->nf, 6);
    assert_rel(s.mass.volume, 8 * 0.5 * 1 * 2, 1e-15);
    assert_mat_near(s.mass.inertia, box_inertia(p.size), 1e-14);
    mass_props m = poly_mass(s.hull);
    assert_rel(m.volume, s.mass.volume, 1e-12);
    assert_vec_near(m.com, s.mass.com, 1e-12);
    for (int i = 0; i < 3; i++) assert_rel(m.inertia.m[i][i], s.mass.inertia.m[i][i], 1e-12);
    assert_mat_near(m.inertia, s.mass.inertia, 1e-12 * s.mass.inertia.m[0][0]);
    assert_true(s.r_in == 0.5);
    assert_rel(s.r_out, sqrt(0.25 + 1 + 4), 1e-15);
    assert_int_equal(s.draw.nv, 24);
    assert_int_equal(s.draw.nt, 12);
    check_mesh(&s.draw, true);
    for (int t = 0; t < 12; t++) /* flat: the three corners share one axis normal */
        for (int k = 0; k < 3; k++) {
            vec3 n = s.draw.nrm[s.draw.tri[t][k]];
            assert_vec_near(n, s.draw.nrm[s.draw.tri[t][0]], 0);
            assert_near(fabs(n.x) + fabs(n.y) + fabs(n.z), 1, 0);
        }
    shape_free(&s);
}

/* Builds the superquadric e1 = e2 = e with radii a at resolution res x res. */
static void build_sq(shape *s, double e, vec3 a, int res)
{
    shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
    p.exp1 = p.exp2 = e, p.a1 = a.x, p.a2 = a.y, p.a3 = a.z, p.ures = p.vres = res;
    char err[256] = "";
    if (shape_build(s, &p, err, sizeof err) != 0) fail_msg("shape_build: %s", err);
}

/* Exponents 1: the hull's volume and inertia converge to the ellipsoid's, at second
 * order.  Measured relative errors at 10, 20, 40, 80: volume 8.7e-2, 2.2e-2, 5.6e-3,
 * 1.4e-3; largest inertia component 1.6e-1, 4.2e-2, 1.1e-2, 2.7e-3. */
static void test_ellipsoid_convergence(void **state)
{
    (void)state;
    vec3 a = v3(1, 0.7, 0.4);
    double vol = 4.0 / 3.0 * PI * a.x * a.y * a.z;
    vec3 inertia = v3_scale(v3(a.y * a.y + a.z * a.z, a.x * a.x + a.z * a.z, a.x * a.x + a.y * a.y), vol / 5);
    const int res[] = {10, 20, 40, 80};
    double last_v = INFINITY, last_i = INFINITY;
    for (int r = 0; r < 4; r++) {
        shape s;
        build_sq(&s, 1, a, res[r]);
        check_poly(s.hull, 1e-9 * 2);
        double ev = fabs(s.mass.volume / vol - 1), ei = 0;
        for (int i = 0; i < 3; i++) ei = fmax(ei, fabs(s.mass.inertia.m[i][i] / v3_comp(inertia, i) - 1));
        assert_true(s.mass.volume < vol); /* an inscribed polyhedron */
        assert_vec_near(s.mass.com, v3(0, 0, 0), 1e-6); /* merging is not symmetric */
        assert_true(ev * 3.5 < last_v); /* error / 4 per doubling, at least / 3.5 */
        assert_true(ei * 3.5 < last_i);
        last_v = ev, last_i = ei;
        assert_true(s.r_in > 0 && s.r_in < a.z && s.r_out <= a.x * (1 + 1e-6));
        check_mesh(&s.draw, true);
        shape_free(&s);
    }
    assert_true(last_v < 1.5e-3);
    assert_true(last_i < 3e-3);
}

/* The area of p's face furthest along axis, as a fraction of side; *cos gets the
 * cosine between its normal and the axis. */
static double side_fraction(const poly *p, vec3 axis, double side, double *cos)
{
    int best = 0;
    for (int f = 1; f < p->nf; f++)
        if (v3_dot(p->f[f].n, axis) > v3_dot(p->f[best].n, axis)) best = f;
    *cos = v3_dot(p->f[best].n, axis);
    return face_area(p, best) / side;
}

/* Exponents 0.1: nearly the box of half-extents a1, a2, a3.  Its sides are not
 * flat, only nearly so, and poly_hull's merging must make each one face.  Measured
 * at 30, 40, 80: the merged hull's single face covers 57% to 65% of each side; the
 * exact hull's largest face 0.1% to 32%; faces 634, 1086, 3774 against 900, 1600,
 * 6400 exact and 1740, 3120, 12640 triangles; volume 1.1% to 1.2% below the box. */
static void test_superquadric_box(void **state)
{
    (void)state;
    vec3 a = v3(1, 0.7, 0.4);
    const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const double side[6] = {4 * 0.7 * 0.4, 4 * 0.7 * 0.4, 4 * 0.4, 4 * 0.4, 4 * 0.7, 4 * 0.7};
    const int res[] = {30, 40, 80};
    for (int r = 0; r < 3; r++) {
        shape s;
        build_sq(&s, 0.1, a, res[r]);
        check_poly(s.hull, 1e-9 * 2);
        assert_rel(s.mass.volume, 8 * a.x * a.y * a.z, 0.03);
        assert_true(s.hull->nf < 2 * res[r] * (res[r] - 1) * 4 / 10);
        double cos;
        for (int k = 0; k < 6; k++) {
            assert_true(side_fraction(s.hull, axes[k], side[k], &cos) > 0.55);
            assert_near(cos, 1, 1e-9); /* and faces straight along the axis */
        }
        /* the same points without merging: no side is one face */
        char err[256];
        poly *x = poly_hull_merge(s.draw.pos, s.draw.nv, 0, err, sizeof err);
        assert_non_null(x);
        check_poly(x, 1e-9 * 2);
        assert_true(x->nf > s.hull->nf);
        for (int k = 0; k < 6; k++) assert_true(side_fraction(x, axes[k], side[k], &cos) < 0.35);
        /* and merging grew the hull by little */
        double exact = poly_mass(x).volume;
        assert_true(s.mass.volume >= exact);
        assert_rel(s.mass.volume, exact, 0.005);
        poly_free(x);
        shape_free(&s);
    }
}

/* Every exponent in (0, 4] at small and odd resolutions: finite meshes with unit
 * normals, the documented counts, a valid hull. */
static void test_superquadric_range(void **state)
{
    (void)state;
    const double exps[] = {0.05, 0.1, 0.3, 1, 1.7, 2, 2.5, 4};
    const int res[][2] = {{3, 3}, {4, 3}, {3, 4}, {5, 7}, {8, 8}, {13, 6}};
    for (size_t i = 0; i < sizeof exps / sizeof exps[0]; i++)
        for (size_t j = 0; j < sizeof exps / sizeof exps[0]; j++)
            for (size_t r = 0; r < sizeof res / sizeof res[0]; r++) {
                shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
                p.exp1 = exps[i], p.exp2 = exps[j], p.a1 = 1, p.a2 = 2, p.a3 = 0.5;
                p.ures = res[r][0], p.vres = res[r][1];
                shape s;
                char err[256] = "";
                if (shape_build(&s, &p, err, sizeof err) != 0)
                    fail_msg("e %g %g res %d %d: %s", p.exp1, p.exp2, p.ures, p.vres, err);
                int nv = p.ures * (p.vres - 1) + 2;
                assert_int_equal(s.draw.nv, nv);
                assert_int_equal(superquadric_points(&p, NULL, 0), nv);
                assert_int_equal(s.draw.nt, 2 * p.ures * (p.vres - 1));
                check_mesh(&s.draw, p.exp1 <= 2 && p.exp2 <= 2);
                check_poly(s.hull, 1e-9 * 4);
                assert_true(s.mass.volume > 0);
                assert_true(s.r_in > 0 && s.r_in < s.r_out);
                for (int v = 0; v < s.draw.nv; v++) /* the hull holds the points */
                    for (int f = 0; f < s.hull->nf; f++)
                        assert_true(v3_dot(s.hull->f[f].n, s.draw.pos[v]) - s.hull->f[f].d < 1e-12 * 4);
                shape_free(&s);
            }
}

static int cmp_vec3(const void *a, const void *b)
{
    const vec3 *x = a, *y = b;
    if (x->x != y->x) return x->x < y->x ? -1 : 1;
    if (x->y != y->y) return x->y < y->y ? -1 : 1;
    return (x->z > y->z) - (x->z < y->z);
}

/* A superquadric's hull built from its tessellation (poly_hull_surface, no qhull
 * run for the exact hull where it checks out) is the solid qhull makes of the
 * same points (poly_hull): the same counts, the same vertices to the bit (nearly
 * flat regions merged too: merging goes by the faces' geometry, not their
 * numbering), every face's plane one of the other's to roundoff, the same volume;
 * over exponents on both sides of 2 (beyond it, points inside: qhull's), radii
 * and resolutions. */
static void test_superquadric_hull_direct(void **state)
{
    (void)state;
    const double exps[] = {0.3, 0.55, 1, 1.3, 1.8, 2, 2.5};
    const int res[][2] = {{3, 3}, {4, 4}, {10, 10}, {7, 12}, {20, 20}};
    uint64_t sd = 40;
    long same_bits = 0, cases = 0;
    for (size_t i = 0; i < sizeof exps / sizeof exps[0]; i++)
        for (size_t j = 0; j < sizeof exps / sizeof exps[0]; j++)
            for (size_t r = 0; r < sizeof res / sizeof res[0]; r++) {
                shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
                p.exp1 = exps[i], p.exp2 = exps[j];
                p.a1 = 0.55 + 0.5 * rnd(&sd), p.a2 = 0.55 + 0.5 * rnd(&sd), p.a3 = 0.55 + 0.5 * rnd(&sd);
                if (r == 0) p.a1 = p.a2 = p.a3 = 1; /* (symmetric: coplanar quads) */
                p.ures = res[r][0], p.vres = res[r][1];
                shape s;
                char err[256] = "";
                if (shape_build(&s, &p, err, sizeof err) != 0)
                    fail_msg("e %g %g res %d %d: %s", p.exp1, p.exp2, p.ures, p.vres, err);
                poly *q = poly_hull(s.draw.pos, s.draw.nv, err, sizeof err);
                if (!q) fail_msg("poly_hull: %s", err);
                const poly *h = s.hull;
                double size = fmax(p.a1, fmax(p.a2, p.a3));
                check_poly(h, 1e-9 * size);
                if (h->nv != q->nv || h->ne != q->ne || h->nf != q->nf)
                    fail_msg("e %g %g res %d %d: %d %d %d, qhull's %d %d %d", p.exp1, p.exp2, p.ures, p.vres, h->nv,
                             h->ne, h->nf, q->nv, q->ne, q->nf);
                vec3 *a = malloc((size_t)h->nv * sizeof *a), *b = malloc((size_t)q->nv * sizeof *b);
                assert_non_null(a);
                assert_non_null(b);
                memcpy(a, h->v, (size_t)h->nv * sizeof *a);
                memcpy(b, q->v, (size_t)q->nv * sizeof *b);
                qsort(a, (size_t)h->nv, sizeof *a, cmp_vec3);
                qsort(b, (size_t)q->nv, sizeof *b, cmp_vec3);
                if (memcmp(a, b, (size_t)h->nv * sizeof *a) != 0)
                    fail_msg("e %g %g res %d %d: the vertices are not qhull's", p.exp1, p.exp2, p.ures, p.vres);
                for (int f = 0; f < h->nf; f++) {
                    int match = 0;
                    for (int g = 0; g < q->nf && !match; g++)
                        match = v3_dot(h->f[f].n, q->f[g].n) > 1 - 1e-10 && fabs(h->f[f].d - q->f[g].d) < 1e-10 * size;
                    if (!match)
                        fail_msg("e %g %g res %d %d: face %d of the tessellation's hull is none of qhull's", p.exp1,
                                 p.exp2, p.ures, p.vres, f);
                }
                double va = poly_mass(h).volume, vb = poly_mass(q).volume;
                assert_true(fabs(va - vb) <= 1e-10 * vb);
                /* (built from the tessellation: its vertices in the points' order) */
                same_bits += h->nv == s.draw.nv && memcmp(h->v, s.draw.pos, (size_t)h->nv * sizeof *h->v) == 0;
                cases++;
                free(a);
                free(b);
                poly_free(q);
                shape_free(&s);
            }
    print_message("%ld superquadric hulls as qhull's, %ld of them unmerged, in the tessellation's order\n", cases,
                  same_bits);
    assert_true(same_bits >= cases / 3);
}

/* The tessellation's layout: south pole, rings from south to north, north pole;
 * exact axis points where the angles hit them. */
static void test_superquadric_points(void **state)
{
    (void)state;
    shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
    p.exp1 = 0.1, p.exp2 = 0.1, p.a1 = 1, p.a2 = 2, p.a3 = 3, p.ures = 8, p.vres = 4;
    vec3 pts[8 * 3 + 2];
    assert_int_equal(superquadric_points(&p, pts, 5), 26); /* writes only 5 */
    assert_int_equal(superquadric_points(&p, pts, 26), 26);
    assert_vec_near(pts[0], v3(0, 0, -3), 0);
    assert_vec_near(pts[25], v3(0, 0, 3), 0);
    /* ring 2 is the equator; omega = -pi, -3pi/4, ..., so i = 0, 2, 4, 6 are on axes */
    assert_vec_near(pts[1 + 8 + 0], v3(-1, 0, 0), 0);
    assert_vec_near(pts[1 + 8 + 2], v3(0, -2, 0), 0);
    assert_vec_near(pts[1 + 8 + 4], v3(1, 0, 0), 0);
    assert_vec_near(pts[1 + 8 + 6], v3(0, 2, 0), 0);
    /* mirror symmetry of the rings */
    for (int i = 0; i < 8; i++) {
        vec3 s = pts[1 + i], n = pts[1 + 16 + i];
        assert_near(s.x, n.x, 0);
        assert_near(s.y, n.y, 0);
        assert_near(s.z, -n.z, 0);
    }
}

static void test_build_failure(void **state)
{
    (void)state;
    shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
    p.ures = p.vres = 100000;
    shape s;
    char err[256] = "";
    assert_int_equal(shape_build(&s, &p, err, sizeof err), -1);
    assert_true(strlen(err) > 0);
    assert_null(s.hull);
    assert_null(s.draw.pos);
    assert_null(s.draw.nrm);
    assert_null(s.draw.tri);
}

/* vmath's sin_cos, by series for small angles, against libm: within 2 ulp, and
 * exact where the answer is (0 and 1 at 0). */
static void test_sin_cos(void **state)
{
    (void)state;
    double s, c;
    sin_cos(0, &s, &c);
    assert_true(s == 0 && c == 1);
    for (int i = -100000; i <= 100000; i++) {
        double x = 0.3 * i / 100000; /* both sides of the series' limit, 1/8 */
        sin_cos(x, &s, &c);
        assert_true(fabs(s - sin(x)) <= 4.5e-16 * fabs(sin(x)));
        assert_true(fabs(c - cos(x)) <= 4.5e-16);
    }
}

int main(void)
{
    const struct CMUnitTest t[] = {
        cmocka_unit_test(test_box_hull),
        cmocka_unit_test(test_box_moved),
        cmocka_unit_test(test_tetrahedron),
        cmocka_unit_test(test_octahedron),
        cmocka_unit_test(test_box_as_qhull_makes_it),
        cmocka_unit_test(test_random_clouds),
        cmocka_unit_test(test_degenerate),
        cmocka_unit_test(test_copy_support),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_cube),
        cmocka_unit_test(test_ellipsoid_convergence),
        cmocka_unit_test(test_superquadric_box),
        cmocka_unit_test(test_superquadric_range),
        cmocka_unit_test(test_superquadric_points),
        cmocka_unit_test(test_superquadric_hull_direct),
        cmocka_unit_test(test_build_failure),
        cmocka_unit_test(test_sin_cos),
    };
    return cmocka_run_group_tests(t, NULL, NULL);
}
