/* toi.c: the time of impact of a pair within an internal step (thesis 3.4.2,
 * step 4; design.md, "Dynamics").
 *
 * The search brackets the first contact between a time the pair is apart and one
 * it touches.  Each step tries the time the closest points would meet at their
 * present closing speed and acceleration (a Newton step, TOI_STEP of the way;
 * once the model has held, or from the start when it cannot overshoot, to a
 * quarter of SIM_SEPARATION short of contact), never earlier than the schedule's
 * bound allows a contact.  After a step that overshoots it halves the bracket
 * instead (a quarter after repeated overshoots), or, after a trusted step, first
 * tries TOI_BACK of it.  The objects fly from their flights' starts (step.h), so
 * the answer is a function of the two flights alone.
 */
#include "toi.h"

#include <assert.h>

#include <math.h>

#include "contact.h"
#include "flight.h"
#include "schedule.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* How far along the model's step a try goes: TOI_STEP while it is not trusted,
 * TOI_SURE once it has held or when it cannot overshoot; a step beyond TOI_TRUST
 * is trusted.  After a trusted step overshoots, TOI_BACK of it is tried. */
#define TOI_STEP 0.98
#define TOI_SURE 0.998
#define TOI_TRUST 0.99
#define TOI_BACK 0.9

static void swap_bodies(body **x, body **y)
{
    body *t = *x;
    *x = *y;
    *y = t;
}

/* The acceleration of body b's point p in free flight. */
static vec3 point_accel(const world *w, const body *b, vec3 p)
{
    if (b->state != STATE_DYNAMIC) return v3(0, 0, 0);
    if (v3_len2(b->w) == 0) return world_body_accel(w, b);
    flight_motion m = flight_motion_of(b, world_body_accel(w, b));
    return flight_point_accel(&m, p);
}

/* The first time at which one of polyhedron m's vertices, closing on the plane
 * through p with unit normal n (towards m) at its speed and acceleration along n
 * now (m moving as mm, the other object as mo), would have come within 1 - f of
 * its height above the plane (as the Newton step of toi_find, for every
 * vertex); HUGE_VAL when none comes down.  A turning object that has just struck
 * with one corner comes down next with another. */
static double vertex_plane_time(const body *m, const flight_motion *mm, const flight_motion *mo,
                                vec3 p, vec3 n, double f)
{
    const poly *h = m->shape.hull;
    double best = HUGE_VAL;
    for (int i = 0; i < h->nv; i++) {
        vec3 x = v3_add(m->x, q_rotate(m->q, h->v[i]));
        double height = v3_dot(v3_sub(x, p), n);
        double s = -v3_dot(v3_sub(flight_point_velocity(mm, x), flight_point_velocity(mo, x)), n);
        double c = -v3_dot(v3_sub(flight_point_accel(mm, x), flight_point_accel(mo, x)), n);
        double D = f * height;
        if (f > TOI_TRUST) D = d_max(D, height - 0.25 * SIM_SEPARATION);
        double disc = s * s + 2 * c * D;
        if (disc < 0 || !(s + sqrt(disc) > 0)) continue;
        best = d_min(best, 2 * D / (s + sqrt(disc)));
    }
    return best;
}

/* Body b (object i, flown) as it moves at that instant: a flight turns an object
 * at the angular momentum it starts with, and only its end is held to
 * max_angular, so the spin that moves it is the start's (a held body's spin is
 * its own).  b itself, or scratch
 * (a copy of object i) given that spin when it differs. */
static const body *moving(const world *w, int i, const body *b, body *scratch)
{
    vec3 L = w->step.snap[i].L;
    if (b->state != STATE_DYNAMIC || b->held || flight_spins_on_support(b) ||
        (L.x == b->L.x && L.y == b->L.y && L.z == b->L.z))
        return b;
    body_copy_state(scratch, b);
    scratch->L = L;
    body_update_w(scratch);
    return scratch;
}

/* True when object i's flight only shifts its shape: it does not move, is a
 * sphere, or does not spin.  Between two such shapes the plane that separates
 * their closest points moves with them, so the distance along its normal, which
 * the Newton step models exactly, is never more than the true one. */
static bool only_shifts(const world *w, int i)
{
    const body *s = &w->step.snap[i];
    if (s->state != STATE_DYNAMIC) return true;
    return w->bodies[i]->shape.p.kind == SHAPE_SPHERE || (s->L.x == 0 && s->L.y == 0 && s->L.z == 0);
}

toi_output toi_find(world *w, const toi_input *in)
{
    assert(in->a != in->b && in->lo <= in->hi);
    toi_output out = {.state = TOI_OVERLAPPED, .t = in->lo, .queries = 0};
    double lo = in->lo, hi = in->hi;
    closest_cache cache = in->cache;
    /* each object where the search stands, where it tries, where it tries back,
     * and its spin for the model: copies of it, of which only states are copied */
    body *A[STEP_COPIES], *B[STEP_COPIES];
    step_search_copies(w, in->a, lo, A);
    step_search_copies(w, in->b, lo, B);
    body *a = A[0], *b = B[0], *ta = A[1], *tb = B[1], *ba = A[2], *bb = B[2];
    closest_result r = body_distance_apart(a, b, &cache);
    out.queries++;
    if (r.status != CLOSEST_SEPARATED) return out; /* touching already */
    /* how far along the model's step to go: all the way when it cannot overshoot */
    double f = only_shifts(w, in->a) && only_shifts(w, in->b) ? TOI_SURE : TOI_STEP;
    int overshot = 0;  /* steps in a row that found the pair touching */
    while (hi - lo > SIM_TOI_TIME && r.distance >= 0.5 * SIM_SEPARATION) {
        const body *ma = moving(w, in->a, a, A[3]), *mb = moving(w, in->b, b, B[3]);
        double safe = lo + sched_predict_bodies(w, ma, mb, r.distance);
        double s = contact_closing_speed(ma, mb, v3_scale(v3_add(r.pa, r.pb), 0.5), r.normal);
        double c = v3_dot(v3_sub(point_accel(w, mb, r.pb), point_accel(w, ma, r.pa)), r.normal);
        /* s t + c t^2 / 2 = D, its least positive root, stably */
        double D = f * r.distance;
        /* once trusted, aim at the middle of where the search may stop */
        if (f > TOI_TRUST) D = d_max(D, r.distance - 0.25 * SIM_SEPARATION);
        double disc = s * s + 2 * c * D, t = 0.5 * (lo + hi);
        bool newton = !overshot && disc >= 0 && s + sqrt(disc) > 0;
        if (newton) t = lo + 2 * D / (s + sqrt(disc));
        /* just set apart after their own collision, a small polyhedron on the
         * other's face: the corner that comes down next, not only the closest */
        if (!overshot && r.distance <= 2 * SIM_SEPARATION) {
            double tv = HUGE_VAL;
            flight_motion fa = flight_motion_of(ma, world_body_accel(w, ma));
            flight_motion fb = flight_motion_of(mb, world_body_accel(w, mb));
            if (r.fb.kind == CLOSEST_FACE && a->shape.hull && a->shape.hull->nv <= SIM_PLANE_VERTICES)
                tv = vertex_plane_time(a, &fa, &fb, r.pb, r.normal, f);
            else if (r.fa.kind == CLOSEST_FACE && b->shape.hull &&
                     b->shape.hull->nv <= SIM_PLANE_VERTICES)
                tv = vertex_plane_time(b, &fb, &fa, r.pa, v3_neg(r.normal), f);
            if (tv < HUGE_VAL && (!newton || lo + tv < t)) {
                t = lo + tv;
                newton = true;
            }
        }
        t = d_max(t, safe);
        if (!(t < hi)) {
            newton = false;
            t = 0.5 * (d_max(lo, d_min(safe, hi)) + hi);
        }
        /* touching at every try: the contact is early in the bracket */
        if (overshot >= 2) t = d_min(t, lo + 0.25 * (hi - lo));
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        step_fly_at(w, in->a, t, ta);
        step_fly_at(w, in->b, t, tb);
        closest_result rt = body_distance_apart(ta, tb, &cache);
        out.queries++;
        if (rt.status != CLOSEST_SEPARATED) {
            /* a trusted step that just overshot: the contact is just short of it */
            double back = newton && f > TOI_TRUST ? lo + TOI_BACK * (t - lo) : -1;
            hi = t;
            overshot++;
            f = TOI_STEP;
            if (back > lo) {
                step_fly_at(w, in->a, back, ba);
                step_fly_at(w, in->b, back, bb);
                closest_result rb = body_distance_apart(ba, bb, &cache);
                out.queries++;
                if (rb.status != CLOSEST_SEPARATED) {
                    hi = back;
                } else {
                    overshot = 0;
                    lo = back;
                    swap_bodies(&a, &ba);
                    swap_bodies(&b, &bb);
                    r = rb;
                }
            }
        } else {
            /* where the model held (the rest is about what it left), trust it more */
            if (newton) f = rt.distance <= 2 * (1 - f) * r.distance ? TOI_SURE : TOI_STEP;
            overshot = 0;
            lo = t;
            swap_bodies(&a, &ta);
            swap_bodies(&b, &tb);
            r = rt;
        }
    }
    /* the answer, when it comes at lo, starts from here */
    out.state = TOI_HIT;
    out.t = lo;
    out.r = r;
    out.cache = cache;
    return out;
}
