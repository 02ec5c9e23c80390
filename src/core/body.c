/* body.c: defaults, geometry and inertia of one object (thesis Tables A.1 to A.4).
 *
 * The inertia tensor comes from the shape's mass properties at uniform density
 * (mass / volume).  Its principal axes are found once per build with Jacobi
 * rotations; the free-rotation integrator (flight.c) works in them.
 */
#include "body.h"

#include "pieces.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

void body_init(body *b, const char *name, shape_kind kind)
{
    memset(b, 0, sizeof *b);
    snprintf(b->name, sizeof b->name, "%s", name);
    b->sp = shape_defaults(kind);
    b->mass = 1.0;
    b->elasticity = 1.0;
    b->volume = 1.0;
    b->color[0] = 255;
    b->q = q_identity();
    b->rot_axis = v3(1, 0, 0);
    b->rot_angle = 0;
    b->rot_given = true;
    b->state = STATE_DYNAMIC;
    b->mode = MODE_FREE;
    b->slide_on = -1;
    b->slide_face = -1;
    b->moved = b->woken = true;
    b->I_body = m3_identity();
    b->I_body_inv = m3_identity();
    b->q_principal = q_identity();
    b->I_princ = v3(1, 1, 1);
}

/* Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations:
 * a = P diag(d) P^T, P a proper rotation. */
static void sym_eigen(mat3 a, mat3 *p, vec3 *d)
{
    mat3 v = m3_identity();
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = a.m[0][1] * a.m[0][1] + a.m[0][2] * a.m[0][2] + a.m[1][2] * a.m[1][2];
        double diag = a.m[0][0] * a.m[0][0] + a.m[1][1] * a.m[1][1] + a.m[2][2] * a.m[2][2];
        if (off <= 1e-30 * diag || off == 0) break;
        for (int i = 0; i < 2; i++) {
            for (int j = i + 1; j < 3; j++) {
                if (a.m[i][j] == 0) continue;
                double theta = (a.m[j][j] - a.m[i][i]) / (2 * a.m[i][j]);
                double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                mat3 r = m3_identity();
                r.m[i][i] = c;
                r.m[j][j] = c;
                r.m[i][j] = s;
                r.m[j][i] = -s;
                a = m3_mul(m3_transpose(r), m3_mul(a, r));
                v = m3_mul(v, r);
            }
        }
    }
    /* make P a rotation (det +1) */
    vec3 c0 = m3_col(v, 0), c1 = m3_col(v, 1), c2 = m3_col(v, 2);
    if (v3_dot(v3_cross(c0, c1), c2) < 0) {
        for (int i = 0; i < 3; i++) v.m[i][2] = -v.m[i][2];
    }
    *p = v;
    *d = v3(a.m[0][0], a.m[1][1], a.m[2][2]);
}

/* Inertia from the built shape and the mass; static bodies get zero inverses. */
static void body_update_inertia(body *b)
{
    const mass_props *mp = &b->shape.mass;
    if (body_is_static(b)) {
        b->inv_mass = 0;
        b->I_body = m3_scale(mp->inertia, 1.0);
        b->I_body_inv = m3_zero();
        b->q_principal = q_identity();
        b->I_princ = v3(0, 0, 0);
        return;
    }
    double density = b->mass / mp->volume;
    b->inv_mass = 1.0 / b->mass;
    b->I_body = m3_scale(mp->inertia, density);
    mat3 p;
    vec3 d;
    sym_eigen(b->I_body, &p, &d);
    b->q_principal = q_from_m3(p);
    b->I_princ = d;
    b->I_body_inv = m3_mul(p, m3_mul(m3_diag(v3(1 / d.x, 1 / d.y, 1 / d.z)), m3_transpose(p)));
}

int body_build(body *b, char *err, size_t errlen)
{
    shape s;
    if (shape_build(&s, &b->sp, err, errlen) != 0) return -1;
    if (b->built) shape_free(&b->shape);
    b->shape = s;
    b->built = true;
    body_update_inertia(b);
    body_set_angular_vel(b, b->w);
    return 0;
}

void body_set_mass(body *b, double mass)
{
    b->mass = mass;
    if (body_is_static(b))
        b->state = STATE_STATIC;
    else if (b->state == STATE_STATIC)
        b->state = STATE_DYNAMIC;
    if (b->built) body_update_inertia(b);
    body_set_angular_vel(b, b->w);
}

void body_free(body *b)
{
    if (b->built) shape_free(&b->shape);
    b->built = false;
    shape_source_release(b->sp.src);
    b->sp.src = NULL;
}


mat3 body_inertia_world(const body *b)
{
    mat3 r = m3_from_quat(b->q);
    return m3_mul(r, m3_mul(b->I_body, m3_transpose(r)));
}

void body_set_angular_vel(body *b, vec3 w)
{
    b->w = w;
    b->L = body_is_static(b) ? v3(0, 0, 0) : m3_mulv(body_inertia_world(b), w);
}

void body_set_rotation(body *b, vec3 axis, double angle)
{
    b->rot_axis = axis;
    b->rot_angle = angle;
    b->rot_given = true;
    b->q = q_axis_angle(axis, angle);
    /* the angular velocity stays as typed; its momentum follows the new axes */
    body_set_angular_vel(b, b->w);
}

vec3 body_inertia_inv_mulv(const body *b, vec3 v)
{
    if (body_is_static(b)) return v3(0, 0, 0);
    return q_rotate(b->q, m3_mulv(b->I_body_inv, q_unrotate(b->q, v)));
}

void body_update_w(body *b)
{
    b->w = body_inertia_inv_mulv(b, b->L);
}

double body_energy(const body *b)
{
    if (body_is_static(b)) return 0;
    return 0.5 * b->mass * v3_len2(b->v) + 0.5 * v3_dot(b->w, b->L);
}

static closest_result distance_of(const body *a, const body *b, closest_cache *cache, bool depth)
{
    closest_result r;
    if (!a || !b || !a->built || !b->built) {
        closest_invalid(&r);
        return r;
    }
    if (body_compound(a) || body_compound(b)) return pieces_distance(a, b, NULL, PIECES_PEEK, depth);
    closest_proxy pa = shape_proxy(&a->shape, a->x, a->q), pb = shape_proxy(&b->shape, b->x, b->q);
    if (body_before(a, b))
        return depth ? closest_distance(&pa, &pb, cache) : closest_distance_apart(&pa, &pb, cache);
    closest_cache c2, *cp = NULL;
    if (cache) {
        c2 = (closest_cache){cache->fb, cache->fa, cache->valid};
        cp = &c2;
    }
    r = depth ? closest_distance(&pb, &pa, cp) : closest_distance_apart(&pb, &pa, cp);
    if (r.status == CLOSEST_INVALID) return r;
    if (cache) *cache = (closest_cache){c2.fb, c2.fa, c2.valid};
    closest_mirror(&r);
    return r;
}

closest_result body_distance(const body *a, const body *b, closest_cache *cache)
{
    return distance_of(a, b, cache, true);
}

closest_result body_distance_apart(const body *a, const body *b, closest_cache *cache)
{
    return distance_of(a, b, cache, false);
}

const char *body_type_name(shape_kind kind)
{
    switch (kind) {
    case SHAPE_SPHERE: return "sphere";
    case SHAPE_CUBE: return "cube";
    case SHAPE_SUPERQUADRIC: return "superquadric";
    case SHAPE_POLYHEDRON: return "polyhedron";
    }
    return "?";
}
