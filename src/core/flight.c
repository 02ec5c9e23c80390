/* flight.c: free flight of one body between collisions (thesis 3.2.3; design.md,
 * "Dynamics").
 *
 * Linear motion under a constant acceleration is integrated exactly, so a ball's
 * flight does not depend on the step length.  Rotation: the free rigid body's
 * energy H = sum_k pi_k^2 / (2 I_k) (pi the angular momentum in principal axes)
 * splits into three parts whose flows are exact rotations about one principal axis
 * each; composing them symmetrically (x/2, y/2, z, y/2, x/2) gives a second-order
 * method that leaves the world angular momentum untouched, whatever the inertia
 * tensor (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107, 1997).  A body
 * with two equal principal moments turns exactly.
 */
#include "flight.h"

#include <assert.h>

#include "hold.h"

/* |w|^2 below this fraction of a spin's: the spin has no part off the normal
 * (rounding). */
#define SPIN_ROUND 1e-24

/* Rotates the principal frame qp about its own axis k by angle and turns pi
 * (angular momentum in principal axes) the opposite way. */
static void turn_principal(quat *qp, vec3 *pi, int k, double angle)
{
    if (angle == 0) return;
    double hs, hc;
    sin_cos(0.5 * angle, &hs, &hc);
    double c = hc * hc - hs * hs, s = 2 * hs * hc; /* the whole angle's */
    vec3 p = *pi;
    /* pi' = Rot_k(-angle) pi */
    switch (k) {
    case 0: *pi = v3(p.x, c * p.y + s * p.z, -s * p.y + c * p.z); break;
    case 1: *pi = v3(c * p.x - s * p.z, p.y, s * p.x + c * p.z); break;
    default: *pi = v3(c * p.x + s * p.y, -s * p.x + c * p.y, p.z); break;
    }
    /* qp r, r = (hc, hs e_k): q_mul with r's two zero parts left out */
    quat a = *qp;
    switch (k) {
    case 0: *qp = (quat){a.w * hc - a.x * hs, a.w * hs + a.x * hc, a.y * hc + a.z * hs, a.z * hc - a.y * hs}; break;
    case 1: *qp = (quat){a.w * hc - a.y * hs, a.x * hc - a.z * hs, a.w * hs + a.y * hc, a.x * hs + a.z * hc}; break;
    default: *qp = (quat){a.w * hc - a.z * hs, a.x * hc + a.y * hs, a.y * hc - a.x * hs, a.w * hs + a.z * hc}; break;
    }
}

/* The same by the angle tau * pi_k / I_k, as the body turns about axis k alone. */
static void rotate_about_principal(quat *qp, vec3 *pi, int k, double tau, vec3 inertia)
{
    turn_principal(qp, pi, k, tau * v3_comp(*pi, k) / v3_comp(inertia, k));
}

/* The principal axis whose moment differs from the other two equal ones (any for
 * equal moments), or -1 when no two are equal. */
static int symmetry_axis(vec3 in)
{
    return in.x == in.y ? 2 : in.y == in.z ? 0 : in.x == in.z ? 1 : -1;
}

/* True when b's principal axes are its own (as for every box). */
static bool aligned(const body *b)
{
    quat p = b->q_principal;
    return p.w == 1 && p.x == 0 && p.y == 0 && p.z == 0;
}

/* b's principal axes to world axes. */
static quat principal_frame(const body *b)
{
    return aligned(b) ? b->q : q_mul(b->q, b->q_principal);
}

/* Turns b freely for h seconds, and sets its angular velocity there: w = L / I in
 * principal axes, turned to world axes.  A body with two equal principal moments
 * I_p (a symmetric top; a sphere or a cube has three) turns exactly: about L at
 * |L| / I_p, and about its own axis k at L_k (1 / I_k - 1 / I_p).  Any other is
 * turned by five rotations about its principal axes in turn. */
static void rotate_free(body *b, double h)
{
    double len = v3_len(b->L);
    if (len == 0) return;
    bool own = aligned(b);
    quat qp = own ? b->q : q_mul(b->q, b->q_principal); /* principal axes to world */
    vec3 pi = q_unrotate(qp, b->L);                     /* L in principal axes */
    vec3 in = b->I_princ;
    int k = symmetry_axis(in);
    if (k >= 0) {
        double ip = v3_comp(in, (k + 1) % 3);
        turn_principal(&qp, &pi, k, h * v3_comp(pi, k) * (1 / v3_comp(in, k) - 1 / ip));
        qp = q_mul(q_axis_angle(v3_scale(b->L, 1 / len), h * len / ip), qp);
    } else {
        rotate_about_principal(&qp, &pi, 0, 0.5 * h, in);
        rotate_about_principal(&qp, &pi, 1, 0.5 * h, in);
        rotate_about_principal(&qp, &pi, 2, h, in);
        rotate_about_principal(&qp, &pi, 1, 0.5 * h, in);
        rotate_about_principal(&qp, &pi, 0, 0.5 * h, in);
    }
    qp = q_normalize(qp);
    b->q = own ? qp : q_mul(qp, q_conj(b->q_principal));
    b->w = q_rotate(qp, v3(pi.x / in.x, pi.y / in.y, pi.z / in.z));
}

bool flight_spins_on_support(const body *b)
{
    if (b->slide < 0 || v3_len2(b->L) == 0) return false;
    vec3 off = v3_mad(b->w, b->slide_n, -v3_dot(b->w, b->slide_n));
    return v3_len2(off) <= SPIN_ROUND * v3_len2(b->w);
}

/* The speed limits: |v| <= max_linear, |w| <= max_angular (L scaled down). */
static void limit_speeds(body *b, double max_linear, double max_angular)
{
    double vl = v3_len(b->v), wl = v3_len(b->w);
    if (vl > max_linear) b->v = v3_scale(b->v, max_linear / vl);
    if (wl > max_angular) {
        b->L = v3_scale(b->L, max_angular / wl);
        body_update_w(b);
    }
}

void flight_fly(body *b, double h, vec3 a, double max_linear, double max_angular)
{
    assert(h >= 0 && b->state == STATE_DYNAMIC);
    if (b->held) { /* the hand moves it (hold.h), within the limits already */
        hold_fly(b, h);
        return;
    }
    vec3 c0 = body_com(b);
    vec3 d = v3_add(v3_scale(b->v, h), v3_scale(a, 0.5 * h * h));
    vec3 v = v3_mad(b->v, a, h);
    double dl = v3_len(d), vl = v3_len(v);
    if (dl > max_linear * h) d = v3_scale(d, max_linear * h / dl);
    if (vl > max_linear) v = v3_scale(v, max_linear / vl);
    b->v = v;

    if (flight_spins_on_support(b)) {
        /* lying on a face on the support it slides on: the contact holds the face
         * flat, and the body turns about the normal only */
        double omega = v3_dot(b->w, b->slide_n);
        if (fabs(omega) > max_angular) omega = copysign(max_angular, omega);
        b->q = q_normalize(q_mul(q_axis_angle(b->slide_n, omega * h), b->q));
        b->rot_given = false;
        b->w = v3_scale(b->slide_n, omega);
        quat qp = principal_frame(b); /* L = I w, in principal axes */
        vec3 wp = q_unrotate(qp, b->w), in = b->I_princ;
        b->L = q_rotate(qp, v3(wp.x * in.x, wp.y * in.y, wp.z * in.z));
    } else if (v3_len2(b->L) != 0) {
        rotate_free(b, h);
        b->rot_given = false;
        limit_speeds(b, max_linear, max_angular);
    }
    /* the centre of mass moved by d; the origin follows the new orientation (at
     * the centre of mass, as in every shape vroc builds, it moved so too) */
    vec3 com = b->shape.mass.com;
    b->x = v3_add(c0, d);
    if (com.x != 0 || com.y != 0 || com.z != 0) b->x = v3_sub(b->x, q_rotate(b->q, com));
}
