/* vmath.h: double-precision vectors, quaternions and 3x3 matrices as values.
 *
 * Everything here is a tiny static inline function taking and returning structs
 * by value, so that formulas in the core read like the thesis's equations.
 * Quaternions are (w, x, y, z) with w the scalar part; a unit quaternion q maps
 * body coordinates to world coordinates: p_world = q p_body q*.
 * Matrices are row-major: m.m[row][col].
 */
#ifndef VROC_VMATH_H
#define VROC_VMATH_H

#include <math.h>
#include <stdbool.h>

typedef struct { double x, y, z; } vec3;
typedef struct { double w, x, y, z; } quat;
typedef struct { double m[3][3]; } mat3;
/* A direction and an amount, as `force = (x,y,z) m` and `rotate = (x,y,z) r` are
 * typed. */
typedef struct {
    vec3 dir;
    double amount;
} dir_amount;

/* The smaller and the larger of two numbers, for the core's hot loops: fmin and
 * fmax are calls into libm, since they must also sort out NaN and signed zeros;
 * these need neither (with a NaN on either side, both give a). */
static inline double d_min(double a, double b) { return b < a ? b : a; }
static inline double d_max(double a, double b) { return b > a ? b : a; }

/* The roots of a t^2 + b t + c (a != 0), found without cancellation (Numerical
 * Recipes, 5.6): with q = -(b + sign(b) sqrt(b^2 - 4 a c)) / 2, they are q / a and
 * c / q (q / a again when q is 0).  False, and nothing written, when they are not
 * real. */
static inline bool quad_roots(double a, double b, double c, double *r1, double *r2)
{
    double disc = b * b - 4 * a * c;
    if (disc < 0) return false;
    double q = -0.5 * (b + copysign(sqrt(disc), b));
    *r1 = q / a;
    *r2 = q != 0 ? c / q : *r1;
    return true;
}

static inline vec3 v3(double x, double y, double z) { return (vec3){x, y, z}; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
/* a + b*s */
static inline vec3 v3_mad(vec3 a, vec3 b, double s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_len2(vec3 a) { return v3_dot(a, a); }
static inline double v3_len(vec3 a) { return sqrt(v3_dot(a, a)); }
static inline double v3_dist(vec3 a, vec3 b) { return v3_len(v3_sub(a, b)); }
/* a/|a|, or (0,0,0) for the zero vector */
static inline vec3 v3_norm(vec3 a)
{
    double l = v3_len(a);
    return l > 0 ? v3_scale(a, 1.0 / l) : v3(0, 0, 0);
}
static inline vec3 v3_lerp(vec3 a, vec3 b, double t) { return v3_add(a, v3_scale(v3_sub(b, a), t)); }
static inline double v3_comp(vec3 a, int i) { return i == 0 ? a.x : i == 1 ? a.y : a.z; }
static inline vec3 v3_min(vec3 a, vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
static inline bool v3_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* ---- quaternions ---- */
static inline quat q_identity(void) { return (quat){1, 0, 0, 0}; }
static inline quat q_mul(quat a, quat b)
{
    return (quat){a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
                  a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                  a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                  a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
static inline quat q_conj(quat a) { return (quat){a.w, -a.x, -a.y, -a.z}; }
static inline double q_len(quat a) { return sqrt(a.w * a.w + a.x * a.x + a.y * a.y + a.z * a.z); }
static inline quat q_normalize(quat a)
{
    double l = q_len(a);
    return (quat){a.w / l, a.x / l, a.y / l, a.z / l};
}
/* A quaternion whose length is within this of 1 is a unit quaternion as it
 * stands: one the simulation made, written exactly and read back, keeps its bits. */
#define Q_UNIT_TOL 1e-15
/* a as it stands when it is a unit quaternion (Q_UNIT_TOL), else normalised */
static inline quat q_as_unit(quat a)
{
    return fabs(q_len(a) - 1) <= Q_UNIT_TOL ? a : q_normalize(a);
}
/* sin x and cos x; for |x| <= 1/8 (a step's turn) by their Taylor series to
 * x^13 and x^14, whose remainders are below 1e-17 of the value, without a call */
static inline void sin_cos(double x, double *s, double *c)
{
    if (fabs(x) > 0.125) {
        *s = sin(x);
        *c = cos(x);
        return;
    }
    double y = x * x;
    *s = x * (1 - y * (1.0 / 6) * (1 - y * (1.0 / 20) * (1 - y * (1.0 / 42) *
         (1 - y * (1.0 / 72) * (1 - y * (1.0 / 110) * (1 - y * (1.0 / 156)))))));
    *c = 1 - y * 0.5 * (1 - y * (1.0 / 12) * (1 - y * (1.0 / 30) * (1 - y * (1.0 / 56) *
         (1 - y * (1.0 / 90) * (1 - y * (1.0 / 132) * (1 - y * (1.0 / 182)))))));
}
/* rotation by angle radians about axis (need not be unit; zero axis gives identity) */
static inline quat q_axis_angle(vec3 axis, double angle)
{
    vec3 u = v3_norm(axis);
    if (v3_len2(u) == 0) return q_identity();
    double s, c;
    sin_cos(0.5 * angle, &s, &c);
    return (quat){c, u.x * s, u.y * s, u.z * s};
}
/* q as a unit axis and an angle in [0, pi]; identity gives axis (1,0,0), angle 0 */
static inline void q_to_axis_angle(quat q, vec3 *axis, double *angle)
{
    if (q.w < 0) q = (quat){-q.w, -q.x, -q.y, -q.z};
    double s = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (s == 0) {
        *axis = v3(1, 0, 0);
        *angle = 0;
        return;
    }
    *axis = v3(q.x / s, q.y / s, q.z / s);
    *angle = 2.0 * atan2(s, q.w);
}
static inline vec3 q_rotate(quat q, vec3 v)
{
    /* v + 2 w (u x v) + 2 u x (u x v), u the vector part */
    vec3 u = v3(q.x, q.y, q.z);
    vec3 t = v3_scale(v3_cross(u, v), 2.0);
    return v3_add(v3_add(v, v3_scale(t, q.w)), v3_cross(u, t));
}
static inline vec3 q_unrotate(quat q, vec3 v) { return q_rotate(q_conj(q), v); }

/* ---- 3x3 matrices ---- */
static inline mat3 m3_zero(void) { return (mat3){{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}; }
static inline mat3 m3_identity(void) { return (mat3){{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }
static inline mat3 m3_diag(vec3 d) { return (mat3){{{d.x, 0, 0}, {0, d.y, 0}, {0, 0, d.z}}}; }
static inline vec3 m3_row(mat3 a, int i) { return v3(a.m[i][0], a.m[i][1], a.m[i][2]); }
static inline vec3 m3_col(mat3 a, int j) { return v3(a.m[0][j], a.m[1][j], a.m[2][j]); }
static inline vec3 m3_mulv(mat3 a, vec3 v)
{
    return v3(v3_dot(m3_row(a, 0), v), v3_dot(m3_row(a, 1), v), v3_dot(m3_row(a, 2), v));
}
static inline mat3 m3_transpose(mat3 a)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a.m[j][i];
    return r;
}
static inline mat3 m3_mul(mat3 a, mat3 b)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}
static inline mat3 m3_add(mat3 a, mat3 b)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a.m[i][j] + b.m[i][j];
    return r;
}
static inline mat3 m3_scale(mat3 a, double s)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a.m[i][j] * s;
    return r;
}
static inline mat3 m3_from_quat(quat q)
{
    double w = q.w, x = q.x, y = q.y, z = q.z;
    return (mat3){{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                   {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                   {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}
/* the unit quaternion of a proper rotation matrix (Shepperd's method) */
static inline quat q_from_m3(mat3 r)
{
    double t = r.m[0][0] + r.m[1][1] + r.m[2][2];
    quat q;
    if (t > 0) {
        double s = sqrt(t + 1.0) * 2;
        q = (quat){0.25 * s, (r.m[2][1] - r.m[1][2]) / s, (r.m[0][2] - r.m[2][0]) / s, (r.m[1][0] - r.m[0][1]) / s};
    } else if (r.m[0][0] > r.m[1][1] && r.m[0][0] > r.m[2][2]) {
        double s = sqrt(1.0 + r.m[0][0] - r.m[1][1] - r.m[2][2]) * 2;
        q = (quat){(r.m[2][1] - r.m[1][2]) / s, 0.25 * s, (r.m[0][1] + r.m[1][0]) / s, (r.m[0][2] + r.m[2][0]) / s};
    } else if (r.m[1][1] > r.m[2][2]) {
        double s = sqrt(1.0 + r.m[1][1] - r.m[0][0] - r.m[2][2]) * 2;
        q = (quat){(r.m[0][2] - r.m[2][0]) / s, (r.m[0][1] + r.m[1][0]) / s, 0.25 * s, (r.m[1][2] + r.m[2][1]) / s};
    } else {
        double s = sqrt(1.0 + r.m[2][2] - r.m[0][0] - r.m[1][1]) * 2;
        q = (quat){(r.m[1][0] - r.m[0][1]) / s, (r.m[0][2] + r.m[2][0]) / s, (r.m[1][2] + r.m[2][1]) / s, 0.25 * s};
    }
    return q_normalize(q);
}
/* the outer product a b^T */
static inline mat3 m3_outer(vec3 a, vec3 b)
{
    return (mat3){{{a.x * b.x, a.x * b.y, a.x * b.z}, {a.y * b.x, a.y * b.y, a.y * b.z}, {a.z * b.x, a.z * b.y, a.z * b.z}}};
}

#endif
