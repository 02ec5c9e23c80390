/* toi.c: the first contact of a pair within an internal step (toi.h). */
#include "toi.h"

#include <assert.h>
#include <math.h>

#include "contact.h"
#include "flight.h"
#include "schedule.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* Searches a pair may make in one internal step before it gives up on a grazing
 * run (the objects pass within the contact distance without meeting). */
#define TOI_MAX_QUERIES 100000

double toi_touch(const body *a, const body *b)
{
    return d_max(SIM_TOUCH, SIM_ROUND_REL * (a->shape.r_out + b->shape.r_out));
}

/* Object i's motion at time t, as the bounds see it (o its state then). */
static sched_move move_of(const world *w, int i, const body *o)
{
    const flight *f = &w->step.fl[i];
    sched_move m = {.moves = step_moves(w, i) && f->kind != FLIGHT_STILL};
    if (!m.moves) return m;
    m.c = body_com(o);
    m.v = o->v;
    m.a = f->a;
    m.rate = f->rate;
    return m;
}

/* How a (moving as ma) and b (mb), touching with closest result r, meet there: 1
 * when some point of their contact region closes (approach) or is pressed together
 * (the relative acceleration along the normal closes), else 0. */
static int meeting(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                   const closest_result *r, double tol)
{
    cpoint cp[16];
    int n = contact_cpoints(a, b, r, tol, cp, 16);
    flight_motion fa = flight_motion_of(a, ma->moves, ma->a);
    flight_motion fb = flight_motion_of(b, mb->moves, mb->a);
    double scale = 1 + a->shape.r_out + b->shape.r_out;
    for (int k = 0; k < n; k++) {
        const body *P = cp[k].p == 0 ? a : b, *Q = cp[k].p == 0 ? b : a;
        const flight_motion *fp = cp[k].p == 0 ? &fa : &fb, *fq = cp[k].p == 0 ? &fb : &fa;
        vec3 nrm, at;
        cpoint_eval(&cp[k], P, Q, &nrm, &at);
        double u = v3_dot(v3_sub(flight_point_velocity(fp, at), flight_point_velocity(fq, at)), nrm);
        double c = v3_dot(v3_sub(flight_point_accel(fp, at), flight_point_accel(fq, at)), nrm);
        if (u < -SIM_SPEED_ROUND * scale || (u <= SIM_SPEED_ROUND * scale && c < -SIM_ACCEL_ROUND * scale))
            return 1;
    }
    return 0;
}

toi_output toi_find(world *w, const toi_input *in)
{
    assert(in->a != in->b && in->lo <= in->hi);
    toi_output out = {.state = TOI_NONE, .t = HUGE_VAL, .queries = 0};
    closest_cache cache = in->cache;
    double t = in->lo;
    const body *A0 = w->bodies[in->a], *B0 = w->bodies[in->b];
    double touch = toi_touch(A0, B0);
    while (out.queries < TOI_MAX_QUERIES) {
        const body *a = step_flown(w, in->a, t, 0), *b = step_flown(w, in->b, t, 0);
        closest_result r = body_distance_apart(a, b, &cache);
        out.queries++;
        if (r.status == CLOSEST_INVALID) return out;
        sched_move ma = move_of(w, in->a, a), mb = move_of(w, in->b, b);
        double d = r.status == CLOSEST_SEPARATED ? r.distance : 0, target = 0.5 * touch;
        if (d <= touch) {
            if (r.status != CLOSEST_SEPARATED) {
                r = body_distance(a, b, &cache); /* the normal, with the depth */
                out.queries++;
            }
            if (r.status != CLOSEST_SEPARATED || meeting(a, &ma, b, &mb, &r, touch)) {
                out.state = TOI_HIT;
                out.t = t;
                out.r = r;
                out.cache = cache;
                return out;
            }
            /* they graze: on, until they part or meet */
            target = 0.5 * d;
        }
        double dt = d > 0 ? sched_ca_time(a, &ma, b, &mb, d, r.normal, r.pa, r.pb, target) : 0;
        if (!(dt > 0)) {
            /* apart by less than rounding, not meeting: the time to move a contact
             * distance at their relative speed */
            double s = v3_len(v3_sub(ma.moves ? ma.v : v3(0, 0, 0), mb.moves ? mb.v : v3(0, 0, 0)));
            dt = touch / d_max(s + (ma.rate + mb.rate) * (A0->shape.r_out + B0->shape.r_out), 1e-3);
        }
        t += dt;
        if (!(t <= in->hi)) {
            out.t = t;
            return out;
        }
    }
    out.t = t; /* (a guard: searched again from here) */
    return out;
}
