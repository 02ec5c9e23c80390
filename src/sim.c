/* sim.c: frames, internal steps and free flight (thesis 3.2.3, 3.4.2; design.md,
 * "Dynamics").
 *
 * Linear motion under a constant acceleration is integrated exactly, so a ball's
 * flight does not depend on the step length.  Rotation: the free rigid body's
 * energy H = sum_k pi_k^2 / (2 I_k) (pi the angular momentum in principal axes)
 * splits into three parts whose flows are exact rotations about one principal axis
 * each; composing them symmetrically (x/2, y/2, z, y/2, x/2) gives a second-order
 * method that leaves the world angular momentum untouched, whatever the inertia
 * tensor (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107, 1997).
 */
#include "sim.h"

#include <stdio.h>

#include "log.h"

/* Rotates the principal frame qp about its own axis k by the angle tau * pi_k / I_k
 * and turns pi (angular momentum in principal axes) the opposite way. */
static void rotate_about_principal(quat *qp, vec3 *pi, int k, double tau, vec3 inertia)
{
    double pk = v3_comp(*pi, k), ik = v3_comp(inertia, k);
    double angle = tau * pk / ik;
    if (angle == 0) return;
    double c = cos(angle), s = sin(angle);
    vec3 p = *pi;
    /* pi' = Rot_k(-angle) pi */
    switch (k) {
    case 0: *pi = v3(p.x, c * p.y + s * p.z, -s * p.y + c * p.z); break;
    case 1: *pi = v3(c * p.x - s * p.z, p.y, s * p.x + c * p.z); break;
    default: *pi = v3(c * p.x + s * p.y, -s * p.x + c * p.y, p.z); break;
    }
    double hs = sin(0.5 * angle), hc = cos(0.5 * angle);
    quat r = {hc, k == 0 ? hs : 0, k == 1 ? hs : 0, k == 2 ? hs : 0};
    *qp = q_mul(*qp, r);
}

static void rotate_free(body *b, double h)
{
    if (v3_len2(b->L) == 0) return;
    quat qp = q_mul(b->q, b->q_principal);       /* principal axes to world */
    vec3 pi = q_unrotate(qp, b->L);              /* L in principal axes */
    vec3 in = b->I_princ;
    rotate_about_principal(&qp, &pi, 0, 0.5 * h, in);
    rotate_about_principal(&qp, &pi, 1, 0.5 * h, in);
    rotate_about_principal(&qp, &pi, 2, h, in);
    rotate_about_principal(&qp, &pi, 1, 0.5 * h, in);
    rotate_about_principal(&qp, &pi, 0, 0.5 * h, in);
    b->q = q_normalize(q_mul(qp, q_conj(b->q_principal)));
}

void sim_flight(body *b, double h, vec3 a, double max_linear, double max_angular)
{
    vec3 c0 = body_com(b);
    vec3 d = v3_add(v3_scale(b->v, h), v3_scale(a, 0.5 * h * h));
    vec3 v = v3_mad(b->v, a, h);
    double dl = v3_len(d), vl = v3_len(v);
    if (dl > max_linear * h) d = v3_scale(d, max_linear * h / dl);
    if (vl > max_linear) v = v3_scale(v, max_linear / vl);
    b->v = v;

    rotate_free(b, h);
    b->rot_given = b->rot_given && v3_len2(b->L) == 0;
    body_update_w(b);
    double wl = v3_len(b->w);
    if (wl > max_angular) {
        b->L = v3_scale(b->L, max_angular / wl);
        body_update_w(b);
    }
    /* the centre of mass moved by d; the origin follows the new orientation */
    b->x = v3_sub(v3_add(c0, d), q_rotate(b->q, b->shape.mass.com));
}

int sim_frame(world *w, char *err, size_t errlen)
{
    long n = world_subframes(w);
    if (n > SIM_MAX_SUBFRAMES) {
        snprintf(err, errlen,
                 "time_step %g needs %ld internal steps per frame (limit %ld): raise "
                 "collision_dist or internal_step, or lower time_step",
                 w->set.time_step, n, SIM_MAX_SUBFRAMES);
        return -1;
    }
    const settings *s = &w->set;
    vec3 a = world_accel(w);
    double h = n > 0 ? s->time_step / (double)n : 0;
    for (long k = 0; k < n; k++) {
        for (int i = 0; i < w->n; i++) {
            body *b = w->bodies[i];
            if (b->state != STATE_DYNAMIC) continue;
            sim_flight(b, h, a, s->max_linear, s->max_angular);
        }
        w->st.subframes++;
    }
    w->time += s->time_step;
    w->frame++;
    w->st.frames++;
    log_trace_frame(w);
    return 0;
}
