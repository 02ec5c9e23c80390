/* flight.c: a body's flight between events, evaluated at any time (flight.h).
 *
 * The centre of mass: c = c0 + v0 t + a t^2 / 2, exact.  Free rotation: the
 * principal frame turns by the exact torque-free motion (spin.h) with L constant;
 * a body whose principal axes are its own (every box) is turned directly.  A slide
 * turns about the support's normal at a constant rate: a frictionless face exerts
 * no torque about its normal, and holds the body flat against itself.  A ball
 * rolling on a level face goes straight with a constant deceleration, and turns
 * about a fixed axis by the distance it has gone over its radius.
 */
#include "flight.h"

#include <assert.h>
#include <math.h>

/* True when b's principal axes are its own (as for every box). */
static bool aligned(const body *b)
{
    quat p = b->q_principal;
    return p.w == 1 && p.x == 0 && p.y == 0 && p.z == 0;
}

/* The state of a held body's flight h after its start (flight.h, FLIGHT_HELD). */
static void held_at(const flight *f, const body *shape_of, double h, body *out)
{
    vec3 pivot = v3_mad(f->p0, f->v0, h), r = f->r0;
    out->q = f->q0;
    if (f->rate > 0) {
        quat turn = q_axis_angle(f->w, f->rate * h);
        r = q_rotate(turn, r);
        out->q = q_normalize(q_mul(turn, f->q0));
        out->rot_given = false;
    }
    vec3 c = v3_add(pivot, r), com = shape_of->shape.mass.com;
    out->x = c;
    if (com.x != 0 || com.y != 0 || com.z != 0) out->x = v3_sub(c, q_rotate(out->q, com));
    out->v = v3_add(f->v0, v3_cross(f->w, r));
    out->w = f->w;
    out->L = m3_mulv(body_inertia_world(out), f->w);
    out->hold_pivot = pivot;
    out->hold_v = f->v0;
}

/* The state of a rolling ball's flight h after its start (flight.h, FLIGHT_ROLL). */
static void roll_at(const flight *f, const body *shape_of, double h, body *out)
{
    bool stopped = h >= f->t_stop;
    if (stopped) h = f->t_stop;
    double speed = v3_len(f->v0), d = v3_len(f->a);
    double gone = speed * h - 0.5 * d * h * h; /* (the distance, without rounding's turn) */
    out->x = v3_add(f->c0, v3_add(v3_scale(f->v0, h), v3_scale(f->a, 0.5 * h * h)));
    out->v = stopped ? v3(0, 0, 0) : v3_mad(f->v0, f->a, h);
    out->q = f->q0;
    if (speed > 0 && gone > 0) {
        vec3 axis = v3_scale(v3_cross(f->n, f->v0), 1 / speed);
        out->q = q_normalize(q_mul(q_axis_angle(axis, gone / f->radius), f->q0));
    }
    out->w = v3_scale(v3_cross(f->n, out->v), 1 / f->radius);
    out->L = m3_mulv(body_inertia_world(out), out->w);
    out->rot_given = false;
    (void)shape_of; /* (a ball's centre of mass is its centre) */
}

void flight_start(flight *f, const body *b, flight_kind kind, double t0, vec3 a, vec3 n, long id)
{
    f->kind = kind;
    f->t0 = t0;
    f->c0 = body_com(b);
    f->v0 = kind == FLIGHT_STILL ? v3(0, 0, 0) : b->v;
    f->a = kind == FLIGHT_STILL ? v3(0, 0, 0) : a;
    f->q0 = b->q;
    f->L = kind == FLIGHT_STILL ? v3(0, 0, 0) : b->L;
    f->spins = false;
    f->n = n;
    f->wn = 0;
    f->rate = 0;
    f->t_stop = HUGE_VAL;
    f->radius = 0;
    f->id = id;
    if (kind == FLIGHT_HELD) {
        f->p0 = b->hold_pivot;
        f->v0 = b->hold_v;
        f->r0 = v3_sub(f->c0, f->p0);
        f->w = b->w;
        f->rate = v3_len(b->w);
    } else if (kind == FLIGHT_FREE && v3_len2(b->L) != 0) {
        f->spins = true;
        quat qp = aligned(b) ? b->q : q_mul(b->q, b->q_principal);
        spin_init(&f->spin, b->I_princ, qp, b->L);
        f->rate = spin_rate_bound(&f->spin);
    } else if (kind == FLIGHT_SLIDE) {
        f->wn = v3_dot(b->w, n);
        f->rate = fabs(f->wn);
    } else if (kind == FLIGHT_ROLL) {
        /* along the face, and against the motion */
        f->v0 = v3_mad(b->v, n, -v3_dot(b->v, n));
        double speed = v3_len(f->v0), d = v3_len(a);
        f->radius = b->shape.r_out;
        f->a = speed > 0 ? v3_scale(f->v0, -d / speed) : v3(0, 0, 0);
        f->t_stop = speed > 0 && d > 0 ? speed / d : speed > 0 ? HUGE_VAL : 0;
        f->rate = speed / f->radius;
    }
}

void flight_at(const flight *f, const body *shape_of, double t, body *out)
{
    double h = t - f->t0;
    assert(h >= 0 || f->kind == FLIGHT_STILL);
    if (f->kind == FLIGHT_HELD) {
        held_at(f, shape_of, h, out);
        return;
    }
    if (f->kind == FLIGHT_ROLL) {
        roll_at(f, shape_of, h, out);
        return;
    }
    vec3 c = f->c0;
    out->v = v3(0, 0, 0);
    out->q = f->q0;
    out->L = v3(0, 0, 0);
    out->w = v3(0, 0, 0);
    if (f->kind != FLIGHT_STILL) {
        c = v3_add(f->c0, v3_add(v3_scale(f->v0, h), v3_scale(f->a, 0.5 * h * h)));
        out->v = v3_mad(f->v0, f->a, h);
        out->L = f->L;
    }
    if (f->kind == FLIGHT_FREE && f->spins) {
        quat qp;
        spin_at(&f->spin, h, &qp, &out->w);
        /* (normalised: the turns composed here would leave it a few roundings
         * off unit length, and a saved orientation reads back as it is only
         * within Q_UNIT_TOL) */
        out->q = q_normalize(aligned(shape_of) ? qp : q_mul(qp, q_conj(shape_of->q_principal)));
        out->rot_given = false;
    } else if (f->kind == FLIGHT_SLIDE && f->wn != 0) {
        out->q = q_normalize(q_mul(q_axis_angle(f->n, f->wn * h), f->q0));
        out->w = v3_scale(f->n, f->wn);
        out->L = m3_mulv(body_inertia_world(out), out->w);
        out->rot_given = false;
    }
    vec3 com = shape_of->shape.mass.com;
    out->x = c;
    if (com.x != 0 || com.y != 0 || com.z != 0) out->x = v3_sub(c, q_rotate(out->q, com));
}
