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

#include "friction.h"

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
    double gone = v3_dot(f->v0, f->u) * h + 0.5 * v3_dot(f->a, f->u) * h * h;
    out->x = v3_add(f->c0, v3_add(v3_scale(f->v0, h), v3_scale(f->a, 0.5 * h * h)));
    out->v = stopped ? v3(0, 0, 0) : v3_mad(f->v0, f->a, h);
    out->q = f->q0;
    if (gone > 0) out->q = q_normalize(q_mul(q_axis_angle(v3_cross(f->n, f->u), gone / f->radius), f->q0));
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
    f->axis = n;
    f->w0 = f->dw = 0;
    f->rate = 0;
    f->t_stop = HUGE_VAL;
    f->u = v3(0, 0, 0);
    f->closed = false;
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
        f->w0 = v3_dot(b->w, n);
        f->rate = fabs(f->w0);
    }
}

void flight_start_face(flight *f, const body *b, flight_kind kind, double t0, const face_motion *m,
                       vec3 n, double until, long id)
{
    flight_start(f, b, kind, t0, m->a, n, id);
    double h = d_max(0, d_min(until - t0, m->t_stop));
    f->t_stop = m->t_stop;
    f->closed = m->mode != MODE_GENERAL;
    if (kind == FLIGHT_SLIDE && m->spins) {
        /* one step of the slide and spin (facespin.h) */
        f->kind = FLIGHT_SPIN;
        f->step = m->step;
        friction_basis(n, &f->e1, &f->e2);
        double w0 = m->step.r[0][5], w1 = w0 + m->step.r[1][5];
        f->rate = d_max(fabs(w0), fabs(w1)) + fabs(w1 - w0); /* (a bound on the dense output's) */
        return;
    }
    if (kind == FLIGHT_SLIDE) {
        /* (a box: not turning; a ball: about the axis, which its spin is along) */
        f->axis = m->axis;
        f->w0 = v3_dot(b->w, m->axis);
        f->dw = m->dw;
        f->rate = d_max(fabs(f->w0), fabs(f->w0 + f->dw * h));
        return;
    }
    /* ROLL: along its velocity, or from rest along its acceleration */
    f->v0 = v3_mad(b->v, n, -v3_dot(b->v, n));
    f->u = v3_len2(f->v0) > 0 ? v3_norm(f->v0) : v3_len2(m->a) > 0 ? v3_norm(m->a) : v3(0, 0, 0);
    f->radius = b->shape.r_out;
    f->rate = d_max(v3_len(f->v0), v3_len(v3_mad(f->v0, m->a, h))) / f->radius;
}

/* The state of a sliding and spinning body's flight h after its start
 * (flight.h, FLIGHT_SPIN). */
static void spin_step_at(const flight *f, const body *shape_of, double h, body *out)
{
    const face_step *st = &f->step;
    bool stopped = h >= f->t_stop;
    double s = stopped || !(st->h > 0) ? (st->h > 0 ? 1 : 0) : h / st->h, y[6];
    for (int i = 0; i < 6; i++)
        y[i] = st->r[0][i] +
               s * (st->r[1][i] + (1 - s) * (st->r[2][i] + s * (st->r[3][i] + (1 - s) * st->r[4][i])));
    if (s == 1)
        for (int i = 0; i < 6; i++) y[i] = st->r[0][i] + st->r[1][i]; /* (the step's end, exactly) */
    vec3 c = v3_add(f->c0, v3_add(v3_scale(f->e1, y[0]), v3_scale(f->e2, y[1])));
    out->q = y[2] != 0 ? q_normalize(q_mul(q_axis_angle(f->n, y[2]), f->q0)) : f->q0;
    bool still = stopped && !st->more && !st->slides;
    out->v = still ? v3(0, 0, 0) : v3_add(v3_scale(f->e1, y[3]), v3_scale(f->e2, y[4]));
    out->w = still ? v3(0, 0, 0) : v3_scale(f->n, y[5]);
    out->L = m3_mulv(body_inertia_world(out), out->w);
    out->rot_given = false;
    vec3 com = shape_of->shape.mass.com;
    out->x = c;
    if (com.x != 0 || com.y != 0 || com.z != 0) out->x = v3_sub(c, q_rotate(out->q, com));
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
    if (f->kind == FLIGHT_SPIN) {
        spin_step_at(f, shape_of, h, out);
        return;
    }
    bool stopped = f->kind == FLIGHT_SLIDE && h >= f->t_stop;
    if (stopped) h = f->t_stop;
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
    } else if (f->kind == FLIGHT_SLIDE && (f->w0 != 0 || f->dw != 0)) {
        /* (a frictionless slide's rate is constant: w0 h, as it always was) */
        double angle = f->dw != 0 ? f->w0 * h + 0.5 * f->dw * h * h : f->w0 * h;
        out->q = q_normalize(q_mul(q_axis_angle(f->axis, angle), f->q0));
        out->w = v3_scale(f->axis, f->dw != 0 ? f->w0 + f->dw * h : f->w0);
        out->L = m3_mulv(body_inertia_world(out), out->w);
        out->rot_given = false;
    }
    if (stopped && f->dw == 0) out->v = v3(0, 0, 0); /* (a box: at its stop, still) */
    vec3 com = shape_of->shape.mass.com;
    out->x = c;
    if (com.x != 0 || com.y != 0 || com.z != 0) out->x = v3_sub(c, q_rotate(out->q, com));
}
