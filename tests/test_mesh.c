/* test_mesh.c: the mesh readers (src/mesh/) and polyhedra built from them.
 *
 * One box, its corners exact in float32, written as OBJ, binary and ASCII STL,
 * OFF, and ASCII and both binary PLYs, each with its vertices in another order,
 * gives the same hull to the bit and the same mass properties, which are the
 * box's closed forms.  An L-shaped block collides as its hull (its faces off the
 * hull are counted) with its own mass properties, which the test derives from
 * its two boxes; read as two groups it is two pieces with the same.  Bodies of
 * several pieces: a ball in a cup, a ball off a cup's outside, an L thrown into
 * the hook of another, balls in a room of single faces, slabs.  A ball dropped on a static polyhedron read from a file
 * lands at the closed-form time and bounces as from the same cube.  Every kind of
 * bad file is refused with a message that names the file and the place.  The
 * files are made in memory: the readers parse bytes (the shell's tests read
 * files from disk: tests/polyhedra.sh).
 */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/edit.h"
#include "core/sim.h"
#include "mesh/meshfile.h"
#include "worlds.h"

/* ---- files in memory ---- */

typedef struct {
    char *s;
    size_t n, cap;
} buf;

static void put(buf *b, const void *p, size_t n)
{
    if (b->n + n + 1 > b->cap) {
        b->cap = 2 * (b->n + n + 1);
        b->s = realloc(b->s, b->cap);
        assert_non_null(b->s);
    }
    memcpy(b->s + b->n, p, n);
    b->n += n;
    b->s[b->n] = '\0';
}

static void putf(buf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void putf(buf *b, const char *fmt, ...)
{
    char tmp[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    put(b, tmp, (size_t)n);
}

static void put_u32(buf *b, uint32_t u, bool big)
{
    unsigned char c[4];
    for (int k = 0; k < 4; k++) c[big ? 3 - k : k] = (unsigned char)(u >> (8 * k));
    put(b, c, 4);
}

static void put_f32(buf *b, double x, bool big)
{
    float f = (float)x;
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    put_u32(b, u, big);
}

/* The box: half-extents H about C, every corner exact in float32. */
static const vec3 H = {0.5, 0.25, 0.75}, C = {0.125, -0.375, 1.5};

/* Corner k (bits: x, y, z). */
static vec3 corner(int k)
{
    return v3(C.x + (k & 1 ? H.x : -H.x), C.y + (k & 2 ? H.y : -H.y), C.z + (k & 4 ? H.z : -H.z));
}

/* The six faces, counter-clockwise from outside, as corners. */
static const int QUADS[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

/* The order a file lists the corners in: perm[i] is the corner written i-th. */
static const int ORDER[3][8] = {{0, 1, 2, 3, 4, 5, 6, 7},
                                {7, 2, 4, 1, 6, 0, 3, 5},
                                {3, 6, 0, 5, 2, 7, 1, 4}};

static int where(const int *perm, int k)
{
    for (int i = 0; i < 8; i++)
        if (perm[i] == k) return i;
    return -1;
}

/* The box as text: its corners in the order p, one a line after vprefix, then
 * its faces, one a line after fprefix, their indices counted from base. */
static void box_text(buf *b, const int *p, const char *vprefix, const char *fprefix, int base)
{
    for (int i = 0; i < 8; i++)
        putf(b, "%s%.9g %.9g %.9g\n", vprefix, corner(p[i]).x, corner(p[i]).y, corner(p[i]).z);
    for (int f = 0; f < 6; f++) {
        putf(b, "%s", fprefix);
        for (int k = 0; k < 4; k++) putf(b, " %d", where(p, QUADS[f][k]) + base);
        putf(b, "\n");
    }
}

static void box_obj(buf *b)
{
    putf(b, "# a box\no box\n");
    box_text(b, ORDER[1], "v ", "f", 1);
}

static void box_off(buf *b)
{
    putf(b, "OFF\n# a box\n8 6 12\n");
    box_text(b, ORDER[2], "", "4", 0);
}

/* The twelve triangles of the box, in the file's order. */
static void box_triangles(int tri[12][3])
{
    for (int f = 0; f < 6; f++) {
        const int *q = QUADS[5 - f];
        int t0[3] = {q[0], q[1], q[2]}, t1[3] = {q[0], q[2], q[3]};
        memcpy(tri[2 * f], t0, sizeof t0);
        memcpy(tri[2 * f + 1], t1, sizeof t1);
    }
}

static void box_stl_ascii(buf *b)
{
    int tri[12][3];
    box_triangles(tri);
    putf(b, "solid box\n");
    for (int t = 0; t < 12; t++) {
        putf(b, "  facet normal 0 0 0\n    outer loop\n");
        for (int k = 0; k < 3; k++) {
            vec3 v = corner(tri[t][k]);
            putf(b, "      vertex %.9g %.9g %.9g\n", v.x, v.y, v.z);
        }
        putf(b, "    endloop\n  endfacet\n");
    }
    putf(b, "endsolid box\n");
}

static void box_stl_binary(buf *b, const char *header)
{
    char h[80] = {0};
    memcpy(h, header, strlen(header) < 80 ? strlen(header) : 80);
    put(b, h, 80);
    put_u32(b, 12, false);
    int tri[12][3];
    box_triangles(tri);
    for (int t = 0; t < 12; t++) {
        for (int k = 0; k < 3; k++) put_f32(b, 0, false);
        for (int k = 0; k < 3; k++) {
            vec3 v = corner(tri[t][k]);
            put_f32(b, v.x, false);
            put_f32(b, v.y, false);
            put_f32(b, v.z, false);
        }
        put(b, "\0\0", 2);
    }
}

/* format: 0 ascii, 1 little-endian, 2 big-endian; faces with uchar counts and int
 * indices as "vertex_indices", or ushort counts and uint indices as
 * "vertex_index" */
static void box_ply(buf *b, int format, bool other_names)
{
    static const char *forms[] = {"ascii", "binary_little_endian", "binary_big_endian"};
    const int *p = ORDER[format == 1 ? 2 : 1];
    bool big = format == 2;
    putf(b, "ply\nformat %s 1.0\ncomment a box\nelement vertex 8\n", forms[format]);
    putf(b, "property %s x\nproperty %s y\nproperty %s z\n", other_names ? "float32" : "float",
         other_names ? "float32" : "float", other_names ? "double" : "float");
    putf(b, "element face 6\nproperty list %s %s %s\nend_header\n",
         other_names ? "ushort" : "uchar", other_names ? "uint" : "int",
         other_names ? "vertex_index" : "vertex_indices");
    if (format == 0) {
        box_text(b, p, "", "4", 0);
        return;
    }
    for (int i = 0; i < 8; i++) {
        vec3 v = corner(p[i]);
        put_f32(b, v.x, big);
        put_f32(b, v.y, big);
        if (other_names) { /* z as a double */
            double z = v.z;
            uint64_t u;
            memcpy(&u, &z, sizeof u);
            put_u32(b, (uint32_t)(big ? u >> 32 : u), big);
            put_u32(b, (uint32_t)(big ? u : u >> 32), big);
        } else {
            put_f32(b, v.z, big);
        }
    }
    for (int f = 0; f < 6; f++) {
        if (other_names) {
            unsigned char n[2] = {big ? 0 : 4, big ? 4 : 0};
            put(b, n, 2);
        } else {
            put(b, "\4", 1);
        }
        for (int k = 0; k < 4; k++) put_u32(b, (uint32_t)where(p, QUADS[f][k]), big);
    }
}

/* ---- reading them ---- */

/* Parses b as a file named name; 0 or -1 with the message in err. */
static int parse(const buf *b, const char *name, mesh_file *m, char *err, size_t errlen)
{
    return mesh_parse((const unsigned char *)b->s, b->n, name, m, err, errlen);
}

/* The source of text b named name (which must read). */
static mesh_source *source_of(const buf *b, const char *name)
{
    mesh_file m;
    char err[512];
    if (parse(b, name, &m, err, sizeof err) != 0) fail_msg("%s", err);
    mesh_source *src = mesh_source_make(&m, name, err, sizeof err);
    assert_non_null(src);
    mesh_file_free(&m);
    return src;
}

/* The shape of a polyhedron from b (which must read), at scale k, and its source
 * (which the shape borrows from: free it after the shape). */
static mesh_source *shape_of(const buf *b, const char *name, vec3 k, shape *s)
{
    char err[512];
    mesh_source *src = source_of(b, name);
    shape_params p = shape_defaults(SHAPE_POLYHEDRON);
    p.src = &src->src;
    p.scale = k;
    if (shape_build(s, &p, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
    return src;
}

static void free_shape(shape *s, mesh_source *src)
{
    shape_free(s);
    shape_source_release(&src->src);
}

/* The error parsing b gives: it must fail, name the file, and contain want. */
static void refused(const buf *b, const char *name, const char *want)
{
    mesh_file m;
    char err[512] = "";
    if (parse(b, name, &m, err, sizeof err) == 0) fail_msg("%s was read; wanted '%s'", name, want);
    if (strncmp(err, name, strlen(name)) != 0) fail_msg("the message does not name %s: %s", name, err);
    if (!strstr(err, want)) fail_msg("%s: wanted '%s' in: %s", name, want, err);
    print_message("refused as it should be: %s\n", err);
}

static void refused_text(const char *text, const char *name, const char *want)
{
    buf b = {0};
    put(&b, text, strlen(text));
    refused(&b, name, want);
    free(b.s);
}

static void same_hull(const poly *a, const poly *b, const char *what)
{
    if (a->nv != b->nv || a->ne != b->ne || a->nf != b->nf)
        fail_msg("%s: %d/%d/%d features, not %d/%d/%d", what, b->nv, b->ne, b->nf, a->nv, a->ne, a->nf);
    if (memcmp(a->v, b->v, (size_t)a->nv * sizeof *a->v) != 0) fail_msg("%s: the vertices differ", what);
    int nfv = 0;
    for (int f = 0; f < a->nf; f++) nfv += a->f[f].count;
    if (memcmp(a->f, b->f, (size_t)a->nf * sizeof *a->f) != 0 ||
        memcmp(a->face_vert, b->face_vert, (size_t)nfv * sizeof *a->face_vert) != 0)
        fail_msg("%s: the faces differ", what);
}

static void one_box_in_every_format_gives_one_hull(void **state)
{
    (void)state;
    buf files[9] = {{0}};
    const char *names[9] = {"box.obj", "box.stl", "box-solid.stl", "box-ascii.stl", "box.off",
                            "box.ply", "box-le.ply", "box-be.ply", "box-le2.ply"};
    box_obj(&files[0]);
    box_stl_binary(&files[1], "made by a test");
    box_stl_binary(&files[2], "solid box (a binary STL that begins with solid)");
    box_stl_ascii(&files[3]);
    box_off(&files[4]);
    box_ply(&files[5], 0, false);
    box_ply(&files[6], 1, false);
    box_ply(&files[7], 2, true);
    box_ply(&files[8], 1, true);
    static const char *forms[9] = {"OBJ", "binary STL", "binary STL", "ASCII STL", "OFF",
                                   "ASCII PLY", "binary little-endian PLY",
                                   "binary big-endian PLY", "binary little-endian PLY"};
    shape s[9];
    mesh_source *src[9];
    for (int i = 0; i < 9; i++) {
        mesh_file m;
        char err[512];
        if (parse(&files[i], names[i], &m, err, sizeof err) != 0) fail_msg("%s", err);
        assert_string_equal(m.form, forms[i]);
        assert_int_equal(m.nv, 8);
        assert_int_equal(m.nf, i >= 1 && i <= 3 ? 12 : 6);
        for (int k = 1; k < 8; k++) /* sorted by x, then y, then z */
            assert_true(m.v[k - 1].x < m.v[k].x ||
                        (m.v[k - 1].x == m.v[k].x &&
                         (m.v[k - 1].y < m.v[k].y || (m.v[k - 1].y == m.v[k].y && m.v[k - 1].z < m.v[k].z))));
        mesh_file_free(&m);
        src[i] = shape_of(&files[i], names[i], v3(1, 1, 1), &s[i]);
        assert_int_equal(shape_off_hull(&s[i]), 0);
    }
    /* the box's closed forms */
    double vol = 8 * H.x * H.y * H.z;
    mass_props mp = s[0].mass;
    assert_rel(mp.volume, vol, 1e-15);
    assert_vec_near(mp.com, C, 1e-15);
    vec3 I = v3_scale(v3(H.y * H.y + H.z * H.z, H.x * H.x + H.z * H.z, H.x * H.x + H.y * H.y), vol / 3);
    assert_rel(mp.inertia.m[0][0], I.x, 1e-14);
    assert_rel(mp.inertia.m[1][1], I.y, 1e-14);
    assert_rel(mp.inertia.m[2][2], I.z, 1e-14);
    assert_near(mp.inertia.m[0][1], 0, 1e-15);
    for (int i = 1; i < 9; i++) {
        same_hull(s[0].hull, s[i].hull, names[i]);
        assert_near(s[i].mass.volume, mp.volume, 1e-15);
        assert_vec_near(s[i].mass.com, mp.com, 1e-15);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) assert_near(s[i].mass.inertia.m[r][c], mp.inertia.m[r][c], 1e-15);
        assert_true(s[i].r_in == s[0].r_in && s[i].r_out == s[0].r_out);
    }
    for (int i = 0; i < 9; i++) {
        free_shape(&s[i], src[i]);
        free(files[i].s);
    }
}

/* ---- the L-shaped block ---- */

static const char *L_OBJ =
    "# an L: 2 x 1 x 2 with a 1 x 1 x 1 notch out of its top right\n"
    "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\n"
    "v 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nv 1 0 1\nv 1 1 1\n"
    "f 1 4 3 2\nf 1 2 6 13 10 9\nf 4 12 11 14 7 3\nf 2 3 7 6\nf 13 6 7 14\n"
    "f 10 13 14 11\nf 9 10 11 12\nf 1 9 12 4\n";

/* S = the integral of r r^T over the solid, and its volume, for a box [lo, hi]. */
static void box_moments(vec3 lo, vec3 hi, double *vol, vec3 *first, mat3 *S)
{
    double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z}, len[3], m1[3], m2[3];
    for (int k = 0; k < 3; k++) {
        len[k] = h[k] - l[k];
        m1[k] = (h[k] * h[k] - l[k] * l[k]) / 2;            /* integral of x */
        m2[k] = (h[k] * h[k] * h[k] - l[k] * l[k] * l[k]) / 3; /* of x^2 */
    }
    *vol = len[0] * len[1] * len[2];
    double f[3];
    for (int k = 0; k < 3; k++) f[k] = m1[k] * *vol / len[k];
    *first = v3(f[0], f[1], f[2]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            S->m[i][j] = i == j ? m2[i] * *vol / len[i] : m1[i] * m1[j] * *vol / (len[i] * len[j]);
}

/* ---- bodies of several convex pieces ---- */

/* A box from lo to hi as an OBJ group named g (its faces outward), its corners
 * counted from *nv + 1. */
static void obj_box(buf *b, const char *g, vec3 lo, vec3 hi, int *nv)
{
    putf(b, "g %s\n", g);
    for (int k = 0; k < 8; k++)
        putf(b, "v %.17g %.17g %.17g\n", k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    for (int f = 0; f < 6; f++)
        putf(b, "f %d %d %d %d\n", *nv + 1 + QUADS[f][0], *nv + 1 + QUADS[f][1], *nv + 1 + QUADS[f][2],
             *nv + 1 + QUADS[f][3]);
    *nv += 8;
}

/* A polyhedron named name from text b in w, of mass mass (-1: static, set before
 * its file, as a scene does), at x. */
static body *add_file(world *w, const char *name, const buf *b, double mass, vec3 x)
{
    body *p = add(w, name, SHAPE_POLYHEDRON);
    int i = w->n - 1;
    char err[512];
    double num[4] = {mass, 0, 0, 0}; /* (edit_property reads a statement's four numbers) */
    if (edit_property(w, i, offsetof(body, mass), num, err, sizeof err) != 0) fail_msg("%s", err);
    if (edit_source(w, i, &source_of(b, name)->src, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
    p->x = x;
    return p;
}

/* The L's exact mass properties: the boxes [0,2] x [0,1] x [0,1] and [0,1] x
 * [0,1] x [1,2] together, from their moments (I = tr(S_c) E - S_c). */
static mass_props l_exact(void)
{
    double v1, v2;
    vec3 f1, f2;
    mat3 S1, S2, S;
    box_moments(v3(0, 0, 0), v3(2, 1, 1), &v1, &f1, &S1);
    box_moments(v3(0, 0, 1), v3(1, 1, 2), &v2, &f2, &S2);
    double vol = v1 + v2;
    vec3 com = v3_scale(v3_add(f1, f2), 1 / vol);
    double c[3] = {com.x, com.y, com.z}, tr = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) S.m[i][j] = S1.m[i][j] + S2.m[i][j] - vol * c[i] * c[j];
    for (int i = 0; i < 3; i++) tr += S.m[i][i];
    mass_props mp = {vol, com, m3_zero()};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) mp.inertia.m[i][j] = (i == j ? tr : 0) - S.m[i][j];
    return mp;
}

static void same_mass(const mass_props *got, const mass_props *want, double rel, const char *what)
{
    double size = fabs(want->inertia.m[0][0]) + fabs(want->inertia.m[1][1]) + fabs(want->inertia.m[2][2]);
    if (!(fabs(got->volume - want->volume) <= rel * want->volume)) fail_msg("%s: volume %.17g, not %.17g", what, got->volume, want->volume);
    if (!(v3_dist(got->com, want->com) <= rel * v3_len(want->com)))
        fail_msg("%s: centre of mass off by %g", what, v3_dist(got->com, want->com));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!(fabs(got->inertia.m[i][j] - want->inertia.m[i][j]) <= rel * size))
                fail_msg("%s: inertia [%d][%d] %.17g, not %.17g", what, i, j, got->inertia.m[i][j],
                         want->inertia.m[i][j]);
}

/* An L read as one closed mesh, or as its two convex groups (in either order,
 * scaled, and moved off the origin), has its own volume, centre of mass and
 * inertia, to 1e-12; two open groups have their hulls' together. */
static void l_block_has_its_own_mass_as_one_mesh_or_two_pieces(void **state)
{
    (void)state;
    mass_props want = l_exact();
    buf one = {0};
    put(&one, L_OBJ, strlen(L_OBJ));
    shape s;
    mesh_source *src = shape_of(&one, "L.obj", v3(1, 1, 1), &s);
    assert_int_equal(s.pieces, 1);
    assert_int_equal(s.mass_from, MASS_MESH);
    same_mass(&s.mass, &want, 1e-12, "the L as one mesh");
    print_message("the L as one mesh: volume %.17g (3), centre (%.17g, %.17g, %.17g)\n", s.mass.volume,
                  s.mass.com.x, s.mass.com.y, s.mass.com.z);
    /* it collides as its hull: the step's two quads are off it */
    assert_int_equal(shape_off_hull(&s), 4);
    assert_int_equal(s.hull->nv, 10);
    free_shape(&s, src);
    free(one.s);
    /* two groups, each a closed box: two pieces, each its own hull */
    static const vec3 scales[3] = {{1, 1, 1}, {0.25, 2, 3}, {1e-3, 1e-3, 1e-3}};
    for (int order = 0; order < 2; order++)
        for (int k = 0; k < 3; k++) {
            buf two = {0};
            int nv = 0;
            vec3 sh = v3(0.5, -0.25, 1.5); /* the file's origin is not the L's corner */
            vec3 lo[2] = {v3_add(sh, v3(0, 0, 0)), v3_add(sh, v3(0, 0, 1))};
            vec3 hi[2] = {v3_add(sh, v3(2, 1, 1)), v3_add(sh, v3(1, 1, 2))};
            obj_box(&two, "lower", lo[order], hi[order], &nv);
            obj_box(&two, "upper", lo[1 - order], hi[1 - order], &nv);
            src = shape_of(&two, "L2.obj", scales[k], &s);
            assert_int_equal(s.pieces, 2);
            assert_int_equal(s.mass_from, MASS_MESH);
            assert_int_equal(shape_off_hull(&s), 0);
            /* the exact L, moved and scaled */
            vec3 q = scales[k];
            double det = q.x * q.y * q.z;
            mass_props w2 = want;
            w2.volume *= det;
            vec3 c = v3_add(want.com, sh);
            w2.com = v3(c.x * q.x, c.y * q.y, c.z * q.z);
            /* I about the com scales as: S' = K S K det, I = tr(S) E - S */
            mat3 S;
            double tr = want.inertia.m[0][0] + want.inertia.m[1][1] + want.inertia.m[2][2];
            double qv[3] = {q.x, q.y, q.z};
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    S.m[i][j] = ((i == j ? tr / 2 : 0) - want.inertia.m[i][j]) * qv[i] * qv[j] * det;
            double tr2 = S.m[0][0] + S.m[1][1] + S.m[2][2];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) w2.inertia.m[i][j] = (i == j ? tr2 : 0) - S.m[i][j];
            char what[64];
            snprintf(what, sizeof what, "the L as two groups (order %d, scale %d)", order, k);
            same_mass(&s.mass, &w2, 1e-12, what);
            free_shape(&s, src);
            free(two.s);
        }
    /* two groups that are not closed (each box without its top): their hulls'
     * together */
    buf open = {0};
    int nv = 0;
    obj_box(&open, "lower", v3(0, 0, 0), v3(2, 1, 1), &nv);
    obj_box(&open, "upper", v3(0, 0, 1), v3(1, 1, 2), &nv);
    char *top1 = strstr(open.s, "f 5 6 8 7\n");
    assert_non_null(top1);
    memcpy(top1, "#", 1);
    src = shape_of(&open, "L-open.obj", v3(1, 1, 1), &s);
    assert_int_equal(s.pieces, 2);
    assert_int_equal(s.mass_from, MASS_PIECES);
    same_mass(&s.mass, &want, 1e-12, "the L as two open groups");
    free_shape(&s, src);
    free(open.s);
}

/* Two boxes, the second shifted dx along x (1: they share a face; 3: apart), as
 * a file of form: 0 OBJ with an o for each, 1 OBJ of one group, 2 ASCII STL of a
 * solid for each, 3 binary STL, 4 OFF, 5 ASCII PLY, 6 binary PLY. */
static void two_boxes(buf *b, int form, double dx)
{
    vec3 v[16];
    for (int k = 0; k < 16; k++) v[k] = v3_add(corner(k % 8), v3(k < 8 ? 0 : dx, 0, 0));
    int tri[12][3];
    box_triangles(tri);
    if (form <= 1) {
        for (int box = 0; box < 2; box++) {
            if (form == 0 || box == 0) putf(b, "o box%d\n", box + 1);
            for (int k = 8 * box; k < 8 * box + 8; k++) putf(b, "v %.9g %.9g %.9g\n", v[k].x, v[k].y, v[k].z);
            for (int f = 0; f < 6; f++)
                putf(b, "f %d %d %d %d\n", QUADS[f][0] + 8 * box + 1, QUADS[f][1] + 8 * box + 1,
                     QUADS[f][2] + 8 * box + 1, QUADS[f][3] + 8 * box + 1);
        }
    } else if (form == 2) {
        for (int box = 0; box < 2; box++) {
            putf(b, "solid box%d\n", box + 1);
            for (int t = 0; t < 12; t++) {
                putf(b, "facet normal 0 0 0\nouter loop\n");
                for (int k = 0; k < 3; k++) {
                    vec3 c = v[8 * box + tri[t][k]];
                    putf(b, "vertex %.9g %.9g %.9g\n", c.x, c.y, c.z);
                }
                putf(b, "endloop\nendfacet\n");
            }
            putf(b, "endsolid box%d\n", box + 1);
        }
    } else if (form == 3) {
        char h[80] = "two boxes";
        put(b, h, 80);
        put_u32(b, 24, false);
        for (int t = 0; t < 24; t++) {
            for (int k = 0; k < 3; k++) put_f32(b, 0, false);
            for (int k = 0; k < 3; k++) {
                vec3 c = v[8 * (t / 12) + tri[t % 12][k]];
                put_f32(b, c.x, false);
                put_f32(b, c.y, false);
                put_f32(b, c.z, false);
            }
            put(b, "\0\0", 2);
        }
    } else {
        if (form == 4) putf(b, "OFF\n16 12 0\n");
        else
            putf(b, "ply\nformat %s 1.0\nelement vertex 16\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 12\nproperty list uchar int vertex_indices\n"
                    "end_header\n", form == 5 ? "ascii" : "binary_little_endian");
        for (int k = 0; k < 16; k++) {
            if (form == 6) {
                put_f32(b, v[k].x, false);
                put_f32(b, v[k].y, false);
                put_f32(b, v[k].z, false);
            } else {
                putf(b, "%.9g %.9g %.9g\n", v[k].x, v[k].y, v[k].z);
            }
        }
        for (int f = 0; f < 12; f++) {
            if (form == 6) put(b, "\4", 1);
            else putf(b, "4");
            for (int k = 0; k < 4; k++) {
                int i = QUADS[f % 6][k] + 8 * (f / 6);
                if (form == 6) put_u32(b, (uint32_t)i, false);
                else putf(b, " %d", i);
            }
            if (form != 6) putf(b, "\n");
        }
    }
}

/* Pieces: each OBJ group and each ASCII STL solid is one; in formats without
 * groups (binary STL, OFF, PLY, or an OBJ of one group) each connected
 * component of the faces, after welding, is one.  Two boxes apart are two
 * pieces in every format; sharing a face, they are still two groups, but one
 * component.  Either way the volume is the two boxes' and the centre of mass
 * their middle. */
static void pieces_are_groups_or_components(void **state)
{
    (void)state;
    static const char *names[7] = {"two.obj", "one-group.obj", "two.stl", "two-binary.stl",
                                   "two.off", "two.ply", "two-binary.ply"};
    static const bool groups[7] = {true, false, true, false, false, false, false};
    for (int form = 0; form < 7; form++)
        for (int touch = 0; touch < 2; touch++) {
            double dx = touch ? 2 * H.x : 3;
            buf b = {0};
            two_boxes(&b, form, dx);
            shape s;
            mesh_source *src = shape_of(&b, names[form], v3(1, 1, 1), &s);
            int want = groups[form] || !touch ? 2 : 1;
            if (s.pieces != want)
                fail_msg("%s, dx = %g: %d pieces, not %d", names[form], dx, s.pieces, want);
            double vol = 2 * 8 * H.x * H.y * H.z;
            assert_rel(s.mass.volume, vol, 1e-12);
            vec3 com = v3_add(C, v3(dx / 2, 0, 0));
            assert_true(v3_dist(s.mass.com, com) <= 1e-12 * v3_len(com));
            free_shape(&s, src);
            free(b.s);
        }
}

/* A cup: a base (a prism of 2n sides) and n wall pieces, inner radius ri, outer
 * ro, height h, base thickness tb, as OBJ groups. */
static void cup_obj(buf *b, int n, double ri, double ro, double h, double tb)
{
    const double PI = 3.14159265358979323846;
    int nv = 0;
    putf(b, "g base\n");
    for (int z = 0; z < 2; z++)
        for (int k = 0; k < 2 * n; k++)
            putf(b, "v %.17g %.17g %.17g\n", ro * cos(PI * k / n), ro * sin(PI * k / n), z ? tb : 0.0);
    putf(b, "f");
    for (int k = 2 * n; k >= 1; k--) putf(b, " %d", k);
    putf(b, "\nf");
    for (int k = 1; k <= 2 * n; k++) putf(b, " %d", 2 * n + k);
    putf(b, "\n");
    for (int k = 1; k <= 2 * n; k++)
        putf(b, "f %d %d %d %d\n", k, k % (2 * n) + 1, 2 * n + k % (2 * n) + 1, 2 * n + k);
    nv = 4 * n;
    for (int k = 0; k < n; k++) {
        double t0 = 2 * PI * k / n, t1 = 2 * PI * (k + 1) / n;
        putf(b, "g wall%d\n", k + 1);
        double r[2] = {ri, ro}, t[2] = {t0, t1}, z[2] = {tb, h};
        /* corner (radius i, angle j, height l) is nv + 1 + i + 2 j + 4 l */
        for (int l = 0; l < 2; l++)
            for (int j = 0; j < 2; j++)
                for (int i = 0; i < 2; i++)
                    putf(b, "v %.17g %.17g %.17g\n", r[i] * cos(t[j]), r[i] * sin(t[j]), z[l]);
        int v = nv + 1;
        putf(b, "f %d %d %d %d\n", v + 0, v + 2, v + 3, v + 1); /* bottom */
        putf(b, "f %d %d %d %d\n", v + 4, v + 5, v + 7, v + 6); /* top */
        putf(b, "f %d %d %d %d\n", v + 0, v + 4, v + 6, v + 2); /* inner */
        putf(b, "f %d %d %d %d\n", v + 1, v + 3, v + 7, v + 5); /* outer */
        putf(b, "f %d %d %d %d\n", v + 0, v + 1, v + 5, v + 4); /* side at t0 */
        putf(b, "f %d %d %d %d\n", v + 2, v + 6, v + 7, v + 3); /* side at t1 */
        nv += 8;
    }
}

/* A ball dropped into a cup of convex pieces standing on a floor comes to rest
 * inside, on its base, and is never outside its inner wall on the way; for
 * several cups, balls, drop heights and places over the base. */
static void a_ball_dropped_into_a_cup_rests_on_its_base(void **state)
{
    (void)state;
    static const struct {
        int n;
        double ri, ball, h, off, e;
    } cases[] = {{12, 0.05, 0.025, 0.3, 0.0, 0.5}, {12, 0.05, 0.03, 0.5, 0.012, 0.3},
                 {8, 0.08, 0.02, 0.2, 0.04, 0.6}, {16, 0.04, 0.035, 0.4, 0.003, 0.2}};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        double ri = cases[c].ri, ro = ri + 0.01, hc = 2 * ri, tb = 0.01, r = cases[c].ball;
        world w;
        world_init(&w);
        w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
        w.set.max_angular = 1000;
        body *floor = add_static_box(&w, "floor", v3(1, 1, 0.05));
        floor->x = v3(0, 0, -0.05);
        buf b = {0};
        cup_obj(&b, cases[c].n, ri, ro, hc, tb);
        body *cup = add_file(&w, "cup", &b, 0.3, v3(0.1, -0.2, 1e-4));
        free(b.s);
        assert_int_equal(cup->shape.pieces, cases[c].n + 1);
        cup->elasticity = 0.3;
        body *ball = add_ball(&w, "ball", r);
        ball->mass = 0.05;
        body_set_mass(ball, 0.05);
        ball->elasticity = cases[c].e;
        ball->x = v3(0.1 + cases[c].off, -0.2 + 0.5 * cases[c].off, tb + r + cases[c].h);
        char err[256];
        double worst = 0;
        bool in = false;
        for (int f = 0; f < 100; f++) {
            assert_int_equal(sim_frame(&w, err, sizeof err), 0);
            /* the ball's centre in the cup's axes */
            vec3 p = q_unrotate(cup->q, v3_sub(ball->x, cup->x));
            double rad = sqrt(p.x * p.x + p.y * p.y);
            if (p.z < hc) in = true;
            /* inside the inner wall (a polygon of n sides inside the circle ri) */
            if (in) worst = fmax(worst, rad + r * cos(3.14159265358979 / cases[c].n) - ri);
            if (in && !(p.z < hc + r)) fail_msg("cup %zu: the ball left the cup (height %g)", c, p.z);
        }
        vec3 p = q_unrotate(cup->q, v3_sub(ball->x, cup->x));
        print_message("cup %zu: at rest %d (mode %d), height over the base %.3g (radius %g), worst "
                      "reach past the wall %.3g, speed %.3g\n", c, ball->state == STATE_RESTING,
                      (int)ball->mode, p.z - tb, r, worst, v3_len(ball->v));
        assert_true(worst <= 1e-6);
        assert_int_equal(ball->state, STATE_RESTING);
        assert_near(p.z, tb + r, 1e-6);
        world_free(&w);
    }
}

/* A ball thrown at a wall piece of a still cup from outside, along the piece's
 * outward normal, at elasticity 1, comes straight back at the same speed: it met
 * that piece's outer face and nothing else. */
static void a_ball_beside_a_cup_bounces_off_its_outside(void **state)
{
    (void)state;
    const double PI = 3.14159265358979323846;
    for (int k = 0; k < 3; k++) {
        world w;
        world_init(&w);
        buf b = {0};
        int n = 12;
        cup_obj(&b, n, 0.05, 0.06, 0.1, 0.01);
        body *cup = add_file(&w, "cup", &b, -1, v3(0, 0, 0));
        free(b.s);
        body *ball = add_ball(&w, "ball", 0.02);
        /* the middle of wall piece k's outer face, and its normal */
        double t = 2 * PI * (k + 0.5) / n, ap = 0.06 * cos(PI / n);
        vec3 nrm = v3(cos(t), sin(t), 0);
        ball->x = v3_add(v3_scale(nrm, ap + 0.02 + 0.3), v3(0, 0, 0.055));
        ball->v = v3_scale(nrm, -2.0);
        char err[256];
        for (int f = 0; f < 5; f++) assert_int_equal(sim_frame(&w, err, sizeof err), 0);
        assert_vec_near(ball->v, v3_scale(nrm, 2.0), 1e-9);
        /* where it turned: on the outer face, 0.3 m in (0.15 s), back out since */
        assert_vec_near(ball->x, v3_add(v3_scale(nrm, ap + 0.02 + 2.0 * 0.5 - 0.3), v3(0, 0, 0.055)), 1e-9);
        (void)cup;
        world_free(&w);
    }
}

/* A static L (two pieces) and a moving L (two pieces) thrown along the hook of
 * the first so that both its pieces meet both of the static one's at once, with
 * no friction and elasticity 1: the contacts are answered together (one
 * collision), and energy is kept to 1e-6. */
static void an_l_thrown_along_the_hook_of_an_l_keeps_its_energy(void **state)
{
    (void)state;
    static const double speeds[3][2] = {{-1, -1}, {-2, -0.5}, {-0.7, -1.9}};
    for (int c = 0; c < 3; c++) {
        world w;
        world_init(&w);
        buf b = {0};
        int nv = 0;
        /* the static hook: a floor bar and a wall at its left */
        obj_box(&b, "bar", v3(0, 0, 0), v3(3, 1, 0.5), &nv);
        obj_box(&b, "wall", v3(0, 0, 0.5), v3(0.5, 1, 2), &nv);
        body *hook = add_file(&w, "hook", &b, -1, v3(0, 0, 0));
        free(b.s);
        /* the moving L: the same shape, half as large, its corner 0.2 m off the
         * hook's inner corner along the throw, so that its bar meets the hook's
         * bar and its wall the hook's wall at the same instant */
        buf m = {0};
        nv = 0;
        obj_box(&m, "bar", v3(0, 0, 0), v3(1.5, 0.5, 0.25), &nv);
        obj_box(&m, "wall", v3(0, 0, 0.25), v3(0.25, 0.5, 1), &nv);
        vec3 u = v3(speeds[c][0], 0, speeds[c][1]);
        vec3 at = v3(0.5, 0.25, 0.5);
        body *l = add_file(&w, "l", &m, 2, v3_sub(at, v3_scale(u, 0.2)));
        free(m.s);
        assert_int_equal(hook->shape.pieces, 2);
        assert_int_equal(l->shape.pieces, 2);
        l->v = u;
        double e0 = body_energy(l);
        char err[256];
        long collisions = 0;
        for (int f = 0; f < 3; f++) {
            assert_int_equal(sim_frame(&w, err, sizeof err), 0);
            collisions += w.nevents;
        }
        double e1 = body_energy(l);
        print_message("throw %d: %ld collision(s), v (%.6f, %.6f, %.6f), energy %.12g -> %.12g\n", c,
                      collisions, l->v.x, l->v.y, l->v.z, e0, e1);
        assert_true(collisions == 1);
        assert_true(fabs(e1 - e0) <= 1e-6 * e0);
        /* both pieces pushed: it leaves the corner along both axes */
        assert_true(l->v.x > 0 && l->v.z > 0);
        world_free(&w);
    }
}

/* A room of one OBJ file whose walls, floor and ceiling are single faces facing
 * in (a closed surface facing inward: no solid): each face is a slab behind it,
 * and balls thrown inside stay inside for 60 s; with few objects (every pair
 * near) and with many (the static tree, piece by piece). */
static void balls_stay_inside_a_room_of_single_faces(void **state)
{
    (void)state;
    static const char *ROOM =
        "o room\nv -2 -1.5 0\nv 2 -1.5 0\nv 2 1.5 0\nv -2 1.5 0\n"
        "v -2 -1.5 2.5\nv 2 -1.5 2.5\nv 2 1.5 2.5\nv -2 1.5 2.5\n"
        "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";
    static const int counts[2] = {6, 30};
    for (int c = 0; c < 2; c++) {
        world w;
        world_init(&w);
        w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
        w.set.max_angular = 1000;
        buf b = {0};
        put(&b, ROOM, strlen(ROOM));
        body *room = add_file(&w, "room", &b, -1, v3(0, 0, 0));
        free(b.s);
        assert_int_equal(room->shape.pieces, 6);
        assert_int_equal(room->shape.slabs, 6);
        unsigned long long seed = 7 + (unsigned long long)c;
        body *balls[30];
        for (int k = 0; k < counts[c]; k++) {
            char name[16];
            snprintf(name, sizeof name, "ball%d", k);
            double r = urand(&seed, 0.05, 0.15);
            balls[k] = add_ball(&w, name, r);
            balls[k]->elasticity = urand(&seed, 0.5, 1);
            balls[k]->x = v3(-1.6 + 3.2 * (k % 6) / 5.0, -1 + 2.0 * (k / 6 % 5) / 4.0, 1.2 + 0.2 * (k % 2));
            balls[k]->v = v3(urand(&seed, -6, 6), urand(&seed, -6, 6), urand(&seed, -3, 6));
        }
        char err[256];
        double worst = -1;
        for (int f = 0; f < 600; f++) {
            assert_int_equal(sim_frame(&w, err, sizeof err), 0);
            for (int k = 0; k < counts[c]; k++) {
                vec3 p = balls[k]->x;
                double r = balls[k]->sp.radius;
                double out = fmax(fmax(fabs(p.x) + r - 2, fabs(p.y) + r - 1.5), fmax(r - p.z, p.z + r - 2.5));
                worst = fmax(worst, out);
                if (!(out <= 1e-6)) fail_msg("%d balls: ball%d left the room at frame %d: (%g, %g, %g)",
                                             counts[c], k, f, p.x, p.y, p.z);
            }
        }
        print_message("%d balls in the room for 60 s: %ld collisions, deepest past a wall %.3g m\n",
                      counts[c], w.st.collisions, worst);
        world_free(&w);
    }
}

/* A piece that closes no volume: refused on a moving object, with the way to a
 * static one; a slab per face on a static one; and a slab's thickness follows
 * `thickness`. */
static void open_pieces_are_slabs_only_when_static(void **state)
{
    (void)state;
    static const char *QUAD = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    buf b = {0};
    put(&b, QUAD, strlen(QUAD));
    mesh_source *src = source_of(&b, "floor.obj");
    shape_params p = shape_defaults(SHAPE_POLYHEDRON);
    p.src = &src->src;
    shape s;
    char err[512];
    assert_int_equal(shape_build(&s, &p, err, sizeof err), -1);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "mass = -1 before file"));
    p.fixed = true;
    for (int k = 0; k < 2; k++) {
        p.thickness = k ? 0.5 : 0.02;
        assert_int_equal(shape_build(&s, &p, err, sizeof err), 0);
        assert_int_equal(s.slabs, 1);
        /* behind the face, opposite its normal (+z) */
        assert_near(s.box_lo.z, -p.thickness, 1e-15);
        assert_near(s.box_hi.z, 0, 1e-15);
        assert_rel(s.mass.volume, 4 * p.thickness, 1e-14);
        shape_free(&s);
    }
    shape_source_release(&src->src);
    free(b.s);
}

/* ---- the drop ---- */

/* A ball of radius 0.1 dropped from rest with its bottom h above the top of a
 * static 1 m box (top at z = 0), under g: it lands at sqrt(2 h / g) and bounces
 * (elasticity 1) back to where it came from.  The box is a cube, or a polyhedron
 * read from a file; returns the ball's landing time and its state after a second. */
static void drop(bool from_file, double *t_land, body *after)
{
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    body *box;
    if (from_file) {
        box = add(&w, "box", SHAPE_POLYHEDRON);
        buf b = {0};
        putf(&b, "OFF\n8 6 0\n");
        for (int k = 0; k < 8; k++)
            putf(&b, "%g %g %g\n", k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5);
        for (int f = 0; f < 6; f++)
            putf(&b, "4 %d %d %d %d\n", QUADS[f][0], QUADS[f][1], QUADS[f][2], QUADS[f][3]);
        mesh_file m;
        char err[256];
        assert_int_equal(parse(&b, "box.off", &m, err, sizeof err), 0);
        mesh_source *src = mesh_source_make(&m, "box.off", err, sizeof err);
        mesh_file_free(&m);
        free(b.s);
        assert_int_equal(edit_source(&w, 0, &src->src, err, sizeof err), 0);
    } else {
        box = add_box(&w, "box", v3(0.5, 0.5, 0.5));
    }
    body_set_mass(box, -1);
    box->x = v3(0, 0, -0.5);
    body *ball = add_ball(&w, "ball", 0.1);
    const double h = 0.8;
    ball->x = v3(0.1, -0.05, 0.1 + h);
    char err[256];
    *t_land = -1;
    for (int f = 0; f < 10; f++) {
        assert_int_equal(sim_frame(&w, err, sizeof err), 0);
        if (*t_land < 0 && w.nevents > 0) *t_land = w.events[0].t;
    }
    *after = *ball;
    world_free(&w);
}

static void a_ball_lands_on_a_file_as_on_a_cube(void **state)
{
    (void)state;
    double t_file, t_cube;
    body a, b;
    drop(true, &t_file, &a);
    drop(false, &t_cube, &b);
    double want = sqrt(2 * 0.8 / 9.8);
    print_message("landed at %.12f s on the file's box, %.12f s on the cube (closed form %.12f)\n",
                  t_file, t_cube, want);
    assert_near(t_file, want, 1e-9);
    assert_near(t_cube, want, 1e-9);
    /* and bounces alike: after a second, at the same place and speed */
    assert_vec_near(a.x, b.x, 1e-12);
    assert_vec_near(a.v, b.v, 1e-12);
    /* elasticity 1: at t = 2 t_land it is back where it started, at rest */
    assert_near(a.x.z, 0.1 + 0.8 - 0.5 * 9.8 * pow(1.0 - 2 * want, 2), 1e-9);
}

/* ---- what each reader takes ---- */

static void read_ok(const char *text, const char *name, mesh_file *m)
{
    char err[512];
    if (mesh_parse((const unsigned char *)text, strlen(text), name, m, err, sizeof err) != 0)
        fail_msg("%s", err);
}

static void obj_forms_groups_and_continuations(void **state)
{
    (void)state;
    mesh_file m;
    read_ok("v 0 0 0\nv 1 0 0 1.0\nv 0 1 0 0.5 0.5 0.5\nv 0 0 1\nvt 0 0\nvn 0 0 1\n"
            "o a\nf 1/1/1 3/1/1 2/1/1\ng one\nf -4//1 -3//1 -1//1\n"
            "g one\nf 1/1 4/1 3/1 # same group: g one again\n"
            "o b\nf 2 \\\n 3 \\\n 4\nusemtl x\ns 1\nl 1 2\n",
            "forms.obj", &m);
    assert_int_equal(m.nv, 4);
    assert_int_equal(m.nf, 4);
    assert_int_equal(m.ng, 3); /* o a; g one (twice: one group); o b */
    assert_string_equal(m.g[0].name, "a");
    assert_int_equal(m.g[1].count, 2);
    assert_string_equal(m.g[2].name, "b");
    assert_int_equal(m.g[2].first, 3);
    assert_non_null(m.corner_n);
    assert_int_equal(m.corner_n[0], 0);
    assert_int_equal(m.corner_n[6], -1); /* 1/1: no normal */
    /* the continued face: 2 3 4 */
    assert_int_equal(m.face_first[4] - m.face_first[3], 3);
    mesh_file_free(&m);
    /* a positive index may name a vertex given later */
    read_ok("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "later.obj", &m);
    assert_int_equal(m.nf, 1);
    mesh_file_free(&m);
}

static void off_headers(void **state)
{
    (void)state;
    static const char *tet = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    static const char *heads[] = {"OFF\n4 4 6\n", "OFF 4 4 6\n", "OFF4 4 6\n", "# c\nOFF\n# c\n4 4\n"};
    char text[512];
    mesh_file m;
    for (int k = 0; k < 4; k++) {
        snprintf(text, sizeof text, "%s%s", heads[k], tet);
        read_ok(text, "t.off", &m);
        assert_int_equal(m.nv, 4);
        assert_int_equal(m.nf, 4);
        mesh_file_free(&m);
    }
    /* COFF: colours after x y z, and after a face's indices */
    read_ok("COFF\n4 4 6\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n0 0 1 1 0 0 1\n"
            "3 0 2 1 255 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "c.off", &m);
    assert_int_equal(m.nv, 4);
    assert_null(m.corner_n);
    mesh_file_free(&m);
    /* NOFF: each vertex's normal, kept */
    read_ok("NOFF\n4 4 6\n0 0 0 -1 -1 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n"
            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", "n.off", &m);
    assert_int_equal(m.nn, 4);
    assert_non_null(m.corner_n);
    mesh_file_free(&m);
    /* no keyword in a file named .off */
    snprintf(text, sizeof text, "4 4 6\n%s", tet);
    read_ok(text, "bare.off", &m);
    assert_int_equal(m.format, MESH_OFF);
    mesh_file_free(&m);
}

static void ply_normals_and_other_elements(void **state)
{
    (void)state;
    mesh_file m;
    read_ok("ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
            "property double z\nproperty float nx\nproperty float ny\nproperty float nz\n"
            "property uchar red\nelement face 4\nproperty list uchar uint vertex_indices\n"
            "property int flags\nelement edge 1\nproperty int a\nproperty int b\nend_header\n"
            "0 0 0 0 0 -1 9\n1 0 0 1 0 0 9\n0 1 0 0 1 0 9\n0 0 1 0 0 1 9\n"
            "3 0 2 1 7\n3 0 1 3 7\n3 0 3 2 7\n3 1 2 3 7\n0 1\n",
            "n.ply", &m);
    assert_int_equal(m.nv, 4);
    assert_int_equal(m.nf, 4);
    assert_int_equal(m.nn, 4);
    mesh_file_free(&m);
}

static void stl_solids_are_groups(void **state)
{
    (void)state;
    mesh_file m;
    read_ok("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
            "endloop\nendfacet\nendsolid a\nSOLID b\n FACET NORMAL 0 0 0\n  OUTER LOOP\n"
            "   VERTEX 0 0 1\n   VERTEX 1 0 0\n   VERTEX 0 1 0\n  ENDLOOP\n ENDFACET\nENDSOLID b\n",
            "two.stl", &m);
    assert_int_equal(m.ng, 2);
    assert_int_equal(m.nv, 4); /* welded */
    assert_string_equal(m.g[1].name, "b");
    mesh_file_free(&m);
}

/* ---- bad files ---- */

static void bad_files_name_the_file_and_the_place(void **state)
{
    (void)state;
    buf b = {0};
    /* a binary STL cut short by 10 bytes: both sizes */
    box_stl_binary(&b, "made by a test");
    b.n -= 10;
    refused(&b, "cut.stl", "it has 674 bytes, where a binary STL of the 12 triangles its header counts has 684");
    b.n = 0;
    /* NaN in a binary STL: the byte */
    box_stl_binary(&b, "x");
    float nan_f = NAN;
    memcpy(b.s + 84 + 50 * 3 + 12 + 4, &nan_f, 4);
    refused(&b, "nan.stl", "byte 250: triangle 4, corner 1: a coordinate is NaN");
    b.n = 0;
    /* random bytes as OBJ */
    for (int k = 0; k < 300; k++) put(&b, (char[]){(char)(k * 37 + 11)}, 1);
    refused(&b, "noise.obj", "not text, and not a binary STL");
    free(b.s);
    refused_text("", "empty.obj", "the file is empty");
    refused_text("# nothing but a comment\n", "none.obj", "it has no vertex");
    refused_text("v 0 0 0\nv 1 0 nan\n", "nan.obj", "nan.obj:2: v: nan is not a finite number");
    refused_text("v 0 0 0\nv 1 0 1e999\n", "inf.obj", "inf.obj:2: v: 1e999 is not a finite number");
    refused_text("v 0 0 0\nv 1 0\n", "short.obj", "short.obj:2: v needs 3 numbers");
    refused_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "range.obj",
                 "range.obj:4: vertex index 7 is out of range: the file has 3");
    refused_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "back.obj", "back.obj:4: vertex index -4");
    refused_text("v 0 0 0\nv 1 0 0\nf 1 2\n", "two.obj", "two.obj:3: a face needs at least 3 corners");
    refused_text("v 0 0 0\nf 0 1 2\n", "zero.obj", "zero.obj:2: vertex index 0");
    refused_text("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 4\n", "range.off",
                 "range.off:7: face 0: vertex index 4 is out of range: the file has 4 vertices");
    refused_text("OFF\n100000000000 1 0\n0 0 0\n", "huge.off",
                 "huge.off:2: the header declares 100000000000 vertices");
    refused_text("OFF\n4 1 0\n0 0 0\n1 0 0\n", "short.off",
                 "short.off:2: the header declares 4 vertices and 1 faces, which need at least 32 "
                 "bytes; the file has 12 after it");
    refused_text("OFF\n4 1 0\n0 0 0 # a comment long enough to pass the size check\n1 0 0\n",
                 "cut.off", "cut.off:4: the file ends after 2 of the 4 vertices");
    refused_text("4OFF\n", "four.off", "more than 3 dimensions");
    refused_text("ply\nformat ascii 1.0\nelement vertex 1000\nproperty float x\nproperty float y\n"
                 "property float z\nend_header\n0 0 0\n1 0 0\n",
                 "count.ply", "element vertex: 1000 instances need at least 6000 bytes");
}

/* A PLY of points alone is read (its hull is drawn); one whose counts exceed its
 * data is not. */
static void ply_counts_against_the_data(void **state)
{
    (void)state;
    mesh_file m;
    read_ok("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
            "points.ply", &m);
    assert_int_equal(m.nv, 4);
    assert_int_equal(m.nf, 0);
    mesh_file_free(&m);
    /* a binary PLY whose face count exceeds its data */
    buf b = {0};
    putf(&b, "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 50\n"
             "property list uchar int vertex_indices\nend_header\n");
    for (int k = 0; k < 9; k++) put_f32(&b, k, false);
    refused(&b, "faces.ply", "faces.ply:9: element face: 50 instances need at least 50 bytes, but "
                             "only 0 are left for them (of the 36 after the header)");
    static const char nan_ply[] = "ply\nformat binary_big_endian 1.0\nelement vertex 1\n"
                                  "property float x\nproperty float y\nproperty float z\n"
                                  "end_header\n\0\0\0\0\x7f\xc0\0\0\0\0\0\0";
    b.n = 0;
    put(&b, nan_ply, sizeof nan_ply - 1);
    refused(&b, "nan.ply", "nan.ply: byte 116: vertex 0: a value is NaN");
    free(b.s);
}

/* Flat points: read, but no solid: the core refuses to build them. */
static void flat_points_make_no_solid(void **state)
{
    (void)state;
    mesh_file m;
    read_ok("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "flat.obj", &m);
    char err[512];
    mesh_source *src = mesh_source_make(&m, "flat.obj", err, sizeof err);
    mesh_file_free(&m);
    shape_params p = shape_defaults(SHAPE_POLYHEDRON);
    p.src = &src->src;
    shape s;
    assert_int_equal(shape_build(&s, &p, err, sizeof err), -1);
    print_message("%s\n", err);
    assert_non_null(strstr(err, "coplanar"));
    shape_source_release(&src->src);
}

/* ---- ear clipping and normals ---- */

static double area2(vec3 a, vec3 b, vec3 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

static void ear_clipping_keeps_concave_outlines(void **state)
{
    (void)state;
    /* a comb: an outline of 4 n + ... corners with deep notches, and a star */
    vec3 comb[] = {{0, 0, 0}, {7, 0, 0}, {7, 3, 0}, {6, 3, 0}, {6, 1, 0}, {5, 1, 0}, {5, 3, 0},
                   {4, 3, 0}, {4, 1, 0}, {3, 1, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0},
                   {1, 3, 0}, {0, 3, 0}};
    vec3 star[10];
    for (int k = 0; k < 10; k++) {
        double r = k % 2 ? 0.4 : 1, a = 2 * 3.141592653589793 * k / 10;
        star[k] = v3(r * cos(a), r * sin(a), 0);
    }
    struct { vec3 *p; int n; } polys[2] = {{comb, 16}, {star, 10}};
    for (int q = 0; q < 2; q++) {
        int n = polys[q].n;
        const vec3 *p = polys[q].p;
        double want = 0;
        for (int k = 0; k < n; k++) want += area2(v3(0, 0, 0), p[k], p[(k + 1) % n]);
        for (int flip = 0; flip < 2; flip++) { /* also the other way round: normal -z */
            vec3 r[16];
            for (int k = 0; k < n; k++) r[k] = flip ? p[n - 1 - k] : p[k];
            int tri[16][3];
            assert_int_equal(mesh_ear_clip(r, n, v3(0, 0, flip ? -3 : 3), tri), n - 2);
            double sum = 0;
            for (int t = 0; t < n - 2; t++) {
                double a = area2(r[tri[t][0]], r[tri[t][1]], r[tri[t][2]]);
                assert_true(flip ? a < 0 : a > 0); /* in the polygon's winding: none folded */
                sum += a;
            }
            assert_near(sum, flip ? -want : want, 1e-12);
        }
    }
}

/* A tessellated sphere in OBJ (no normals): its drawn normals are smooth, close
 * to the radial direction; a box's stay flat, one per face. */
static void smooth_normals_where_the_file_gives_none(void **state)
{
    (void)state;
    buf b = {0};
    int nu = 24, nv = 12;
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i < nu; i++) {
            double th = 3.141592653589793 * j / nv, ph = 2 * 3.141592653589793 * i / nu;
            double st = j == 0 || j == nv ? 0 : sin(th); /* the poles: one point each */
            putf(&b, "v %.17g %.17g %.17g\n", st * cos(ph), st * sin(ph), cos(th));
        }
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            int a = j * nu + i + 1, c = j * nu + (i + 1) % nu + 1;
            putf(&b, "f %d %d %d %d\n", a, a + nu, c + nu, c);
        }
    shape s;
    mesh_source *src = shape_of(&b, "ball.obj", v3(1, 1, 1), &s);
    double worst = 1;
    for (int k = 0; k < s.draw.nv; k++) {
        vec3 p = s.draw.pos[k];
        double d = v3_dot(v3_norm(p), s.draw.nrm[k]); /* (the faces run outwards) */
        if (d < worst) worst = d;
    }
    print_message("ball: %d points, %d drawn vertices, normals within %.3g rad of radial\n",
                  src->src.np, s.draw.nv, acos(worst));
    assert_int_equal(src->src.np, 24 * 11 + 2);
    assert_true(worst > cos(0.02));
    free_shape(&s, src);
    b.n = 0;
    box_obj(&b);
    src = shape_of(&b, "box.obj", v3(1, 2, 3), &s); /* also scaled: normals stay on the axes */
    assert_int_equal(s.draw.nv, 24);
    for (int k = 0; k < s.draw.nv; k++) {
        vec3 n = s.draw.nrm[k];
        assert_near(fabs(n.x) + fabs(n.y) + fabs(n.z), 1, 1e-15);
    }
    assert_rel(s.mass.volume, 8 * H.x * H.y * H.z * 6, 1e-14);
    free_shape(&s, src);
    free(b.s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_box_in_every_format_gives_one_hull),
        cmocka_unit_test(l_block_has_its_own_mass_as_one_mesh_or_two_pieces),
        cmocka_unit_test(pieces_are_groups_or_components),
        cmocka_unit_test(a_ball_dropped_into_a_cup_rests_on_its_base),
        cmocka_unit_test(a_ball_beside_a_cup_bounces_off_its_outside),
        cmocka_unit_test(an_l_thrown_along_the_hook_of_an_l_keeps_its_energy),
        cmocka_unit_test(balls_stay_inside_a_room_of_single_faces),
        cmocka_unit_test(open_pieces_are_slabs_only_when_static),
        cmocka_unit_test(a_ball_lands_on_a_file_as_on_a_cube),
        cmocka_unit_test(obj_forms_groups_and_continuations),
        cmocka_unit_test(off_headers),
        cmocka_unit_test(ply_normals_and_other_elements),
        cmocka_unit_test(stl_solids_are_groups),
        cmocka_unit_test(bad_files_name_the_file_and_the_place),
        cmocka_unit_test(ply_counts_against_the_data),
        cmocka_unit_test(flat_points_make_no_solid),
        cmocka_unit_test(ear_clipping_keeps_concave_outlines),
        cmocka_unit_test(smooth_normals_where_the_file_gives_none),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
