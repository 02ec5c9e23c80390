/* sim.c: frames, internal steps and collisions in time (thesis 3.2.3, 3.3, 3.4.2;
 * design.md, "Dynamics").
 *
 * An internal step (thesis 3.4.2, steps 3 to 5): save every moving object's
 * state, fly the whole step, check the due pairs.  If some pair touches or
 * penetrates, each such pair is traced back in time to its first contact (toi.h);
 * the earliest is answered at its instant (its two objects flown back there), and
 * the rest of the step starts over from there.  So collisions are answered in the
 * order they happen, simultaneous ones one after another.  Each object flies from
 * its own saved state (step.h), which only a collision that changes it renews:
 * going back in time leaves the others' flights, and their pairs' predictions,
 * exact; and a pair's first contact depends on the two flights alone, so the
 * schedule (schedule.h) cannot change it.
 *
 * The answer (collide): the impulse (contact.h), then the contact state (rest.h):
 * a collision that leaves an object barely bouncing on a support below it puts it
 * at rest, or sliding (settle); slow collisions under gravity part at the
 * collision envelope's speed, and a stack passes blows from above down to its
 * support.  Each collision answered goes into the frame's events.
 */
#include "sim.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "pairs.h"
#include "rest.h"
#include "schedule.h"
#include "step.h"
#include "toi.h"
#include "tolerance.h"

/* A pair needs checking only when one of its objects moves. */
static bool pair_moves(const world *w, const pair *p)
{
    return w->bodies[p->a]->state == STATE_DYNAMIC || w->bodies[p->b]->state == STATE_DYNAMIC;
}

long sim_penetrations(world *w, sim_report report, void *ctx)
{
    if (pairs_update(w) != 0) return -1;
    long count = 0;
    for (long i = 0; i < w->pairs.n; i++) {
        pair *p = &w->pairs.p[i];
        const body *a = w->bodies[p->a], *b = w->bodies[p->b];
        closest_result r = pair_query(w, p, a, b);
        if (r.status == CLOSEST_PENETRATING && r.distance < -SIM_SEPARATION) {
            count++;
            if (report) report(ctx, a, b, -r.distance);
        }
    }
    return count;
}

/* The acceleration of body b, zero when it does not move. */
static vec3 still_accel(const world *w, const body *b)
{
    return b->state == STATE_DYNAMIC ? world_body_accel(w, b) : v3(0, 0, 0);
}

/* Moves the dynamic objects of the pair apart along n until they are sep apart
 * (they are gap apart now; a held one does not move), the lighter one more, so
 * that their centre of mass stays; when both move, their spins take back the
 * angular momentum the shift adds (s n x (va - vb)), so that it stays too. */
static void separate(body *a, body *b, vec3 n, double gap, double sep)
{
    double need = sep - gap;
    if (need <= 0) return;
    double ia = a->state == STATE_DYNAMIC && !a->held ? a->inv_mass : 0;
    double ib = b->state == STATE_DYNAMIC && !b->held ? b->inv_mass : 0;
    if (ia + ib == 0) return;
    double s = need / (ia + ib);
    a->x = v3_mad(a->x, n, s * ia);
    b->x = v3_mad(b->x, n, -s * ib);
    if (ia > 0 && ib > 0) {
        vec3 half = v3_scale(v3_cross(n, v3_sub(a->v, b->v)), 0.5 * s);
        a->L = v3_sub(a->L, half);
        b->L = v3_sub(b->L, half);
        body_update_w(a);
        body_update_w(b);
    }
}

/* A held body that cannot go on stops where it is, until the hand sets its
 * motion again (hold.h). */
static void hold_stop(body *h)
{
    h->hold_v = h->v = v3(0, 0, 0);
    body_set_angular_vel(h, v3(0, 0, 0));
}

/* The collision of pair p, one of whose objects is held (hold.h), at contact
 * point pt with restitution e: the held one has infinite mass and keeps its
 * motion, and the other is answered as if struck by a moving wall; where the
 * other cannot give way (static, held, or held by what it stands on or pinned
 * against a still object, along the blow), the held one stops. */
static void collide_held(world *w, pair *p, const closest_result *r, vec3 pt, double e)
{
    int hand = w->bodies[p->a]->held ? 1 : 2;
    int oi = hand == 1 ? p->b : p->a;
    body *a = w->bodies[p->a], *b = w->bodies[p->b], *o = w->bodies[oi];
    vec3 push = hand == 1 ? v3_neg(r->normal) : r->normal; /* the blow on the other */
    vec3 g = world_accel(w), up = v3_len2(g) > 0 ? v3_neg(v3_norm(g)) : v3(0, 0, 0), s;
    bool firm = body_is_static(o) || o->held || rest_pinned(w, oi, push, &s) ||
                (v3_dot(push, up) < -SIM_SUPPORT_COS && rest_holds(o, v3_neg(push), &s));
    if (firm) {
        hold_stop(hand == 1 ? a : b);
        return;
    }
    if (o->state == STATE_RESTING) rest_wake(w, oi);
    contact c = contact_respond(a, b, pt, r->normal, e, hand, v3(0, 0, 0));
    if (c.impulse > 0) {
        w->st.collisions++;
        world_event(w, &(sim_event){w->time, p->a, p->b, c.point, c.normal, c.impulse, c.speed});
    }
    if (r->distance < SIM_SEPARATION) separate(a, b, r->normal, r->distance, SIM_SEPARATION);
}

/* Answers the collision of pair p now: the impulse, the separation, the log; and
 * the thesis's contact state for an object that barely bounces off a support below
 * it. */
static void collide(world *w, pair *p)
{
    body *a = w->bodies[p->a], *b = w->bodies[p->b];
    /* where the time of impact stopped, when that is now: the same flights to the
     * same instant, so the same states */
    const pair_hit *h = &w->pairs.hits[p - w->pairs.p];
    closest_result r;
    if (h->t == w->time && p->toi_a == w->step.snap_id[p->a] && p->toi_b == w->step.snap_id[p->b]) {
        r = h->r;
        p->hit = h->cache;
    } else {
        r = pair_query_hit(w, p, a, b);
    }
    if (r.status == CLOSEST_INVALID) return;
    double scale = a->shape.r_out + b->shape.r_out;
    double tol = SIM_CONTACT_TOL * scale + d_max(0, -r.distance);
    vec3 pt = contact_point(a, b, &r, tol);
    /* the centre of the region moves apart, but a corner of it closes (a box
     * turning as it lands on an edge): that corner strikes, or nothing would stop
     * it */
    if (contact_closing_speed(a, b, pt, r.normal) <= 0) pt = contact_closing_corner(a, b, &r, tol, pt);
    double e = d_min(a->elasticity, b->elasticity);
    if (a->held || b->held) {
        collide_held(w, p, &r, pt, e);
        return;
    }
    vec3 g = world_accel(w);
    vec3 up = v3_len2(g) > 0 ? v3_neg(v3_norm(g)) : v3(0, 0, 0);
    /* a slow collision under gravity (the collision envelope of Mirtich and
     * Canny): the pair leaves at least fast enough to rise SIM_HOP against the
     * force that presses them together, or against gravity, so that an object
     * pivoting, rocking or turning against another collides every few
     * milliseconds, not every few microseconds */
    double press = v3_dot(v3_sub(still_accel(w, b), still_accel(w, a)), r.normal);
    double cs = contact_closing_speed(a, b, pt, r.normal);
    double leave = sqrt(2 * d_max(press, v3_len(g)) * SIM_HOP);
    bool slow = cs > 0 && cs < SIM_REST_SPEED;
    if (slow && e * cs < leave) e = leave / cs;
    /* in a stack, the object underneath passes a blow from above on to what holds
     * it (shock propagation): it moves only along its support, if at all */
    int held = 0;
    vec3 s = v3(0, 0, 0);
    if (press > 0 && v3_dot(r.normal, up) > SIM_SUPPORT_COS && rest_holds(b, r.normal, &s)) held = 2;
    if (press > 0 && v3_dot(r.normal, up) < -SIM_SUPPORT_COS && rest_holds(a, v3_neg(r.normal), &s)) held = 1;
    /* a sandwich: one of them pressed back against a still object it just struck */
    if (!held && rest_pinned(w, p->a, r.normal, &s)) held = 1;
    if (!held && rest_pinned(w, p->b, v3_neg(r.normal), &s)) held = 2;
    /* a resting object hit by a moving one takes part as a dynamic one */
    if (a->state == STATE_RESTING && b->state == STATE_DYNAMIC && held != 1) rest_wake(w, p->a);
    if (b->state == STATE_RESTING && a->state == STATE_DYNAMIC && held != 2) rest_wake(w, p->b);
    contact c = contact_respond(a, b, pt, r.normal, e, held, s);
    if (c.impulse > 0) {
        w->st.collisions++;
        world_event(w, &(sim_event){w->time, p->a, p->b, c.point, c.normal, c.impulse, c.speed});
        /* what struck a still object, for a sandwich */
        if (a->state == STATE_DYNAMIC && b->state != STATE_DYNAMIC) rest_strike(a, p->b, r.normal, w->time);
        if (b->state == STATE_DYNAMIC && a->state != STATE_DYNAMIC) rest_strike(b, p->a, v3_neg(r.normal), w->time);
    }
    /* the contact state: an object that barely bounces off a support under it rests
     * on it, or slides on it when it still moves along it */
    /* the pair is set apart, so that the step goes on and a later contact of
     * theirs (a rocking object's other corner) is found from a gap, not from
     * touching */
    bool apart = r.distance < SIM_SEPARATION;
    if (v3_len2(g) == 0) {
        if (apart) separate(a, b, r.normal, r.distance, SIM_SEPARATION);
        return;
    }
    bool settled = false;
    for (int k = 0; k < 2; k++) {
        body *m = k == 0 ? a : b, *sup = k == 0 ? b : a;
        int si = k == 0 ? p->b : p->a;
        /* from the support to m */
        bool face;
        vec3 n = rest_support_normal(sup, k == 0 ? r.fb : r.fa, k == 0 ? r.normal : v3_neg(r.normal),
                                     &face);
        /* a support: a static or resting object, or one that slides itself */
        if (m->state != STATE_DYNAMIC || (sup->state == STATE_DYNAMIC && sup->slide < 0)) continue;
        double vn = v3_dot(m->v, n);
        if (v3_dot(n, up) < SIM_SUPPORT_COS || vn > SIM_REST_SPEED) continue;
        int how = rest_settle(w, k == 0 ? p->a : p->b, si, n, face, k == 0 ? r.pb : r.pa, p,
                              v3_len(g), fmin(a->elasticity, b->elasticity));
        if (how == SETTLE_LAID) return; /* placed apart already */
        if (how == SETTLE_STANDS) settled = true;
    }
    if (apart || settled) separate(a, b, r.normal, r.distance, SIM_SEPARATION);
}

/* Checks pair i at the end of the step, t_end, for the step that began at now:
 * returns when it is next due, a time after t_end when it is apart, or the time
 * of its first contact when it penetrates.  Keeps in *first and *when the
 * earliest contact so far. */
static double check_pair(world *w, long i, double now, double t_end, pair **first, double *when)
{
    pair *p = &w->pairs.p[i];
    p->checked = HUGE_VAL;
    p->along = false;
    w->sched.parked[i] = false;
    if (!pair_moves(w, p)) return HUGE_VAL;
    /* a held object's pair is checked every step: no bound holds the hand */
    bool hand = w->bodies[p->a]->held || w->bodies[p->b]->held;
    if (w->set.collision_heap && !hand &&
        (rest_slides_clear(w, p->a, p->b) || rest_slides_clear(w, p->b, p->a)))
        return HUGE_VAL;
    /* found touching in this step from the same flights (flight numbers are new
     * each step), it touches still, and its first contact is known: no query, and
     * no far bound (it is never later than that contact, within the step) */
    bool known = p->toi_a == w->step.snap_id[p->a] && p->toi_b == w->step.snap_id[p->b];
    /* far apart: the bounding spheres' gap bounds the distance from below, and is
     * enough for a prediction beyond the frame (part of the schedule: without it
     * every pair gets its closest-feature check, as in the thesis's Table 5.3).
     * It is measured where the objects' flights start: a bound on how far they go
     * from there holds through a collision later in the step that turns them
     * back, so that such a collision leaves the pair's time as it is. */
    p->far = false;
    if (w->set.collision_heap && !known && !hand) {
        if (sched_boxes_apart(w, p->a, p->b)) { /* parked until a box is made again */
            w->sched.parked[i] = true;
            return HUGE_VAL;
        }
        const body *a = step_at_start(w, p->a), *b = step_at_start(w, p->b);
        bool turn_a, turn_b;
        double from = step_flights_start(w, p), gap = sched_bound_gap(a, b, &turn_a, &turn_b);
        double next = gap > 0 ? from + sched_predict_far(w, a, b, gap, turn_a, turn_b) : from;
        if (next - t_end >= w->set.time_step) {
            p->far = true;
            p->far_slide_a = a->slide >= 0 && a->slide_steady;
            p->far_slide_b = b->slide >= 0 && b->slide_steady;
            p->checked = from;
            p->jumped_a = a->jumped;
            p->jumped_b = b->jumped;
            p->speed_a = v3_len(a->v) + SCHED_SLACK;
            p->speed_b = v3_len(b->v) + SCHED_SLACK;
            return next;
        }
    }
    p->checked = t_end;
    p->speed_a = v3_len(w->bodies[p->a]->v);
    p->speed_b = v3_len(w->bodies[p->b]->v);
    const body *a = w->bodies[p->a], *b = w->bodies[p->b];
    closest_result r = {.status = CLOSEST_PENETRATING};
    if (!known) r = pair_query_apart(w, p, a, b);
    if (r.status != CLOSEST_PENETRATING) {
        if (!w->set.collision_heap) return HUGE_VAL; /* without the heap no time is kept */
        if (hand) { /* the next step's end */
            w->sched.bound[i].dist = 0;
            return nextafter(t_end, HUGE_VAL);
        }
        /* the bound from speeds, kept for a collision that changes an object, and
         * the one along the normal, later where they do not come on straight */
        double next = sched_predict_kept(w, a, b, r.distance, 0, 0, &w->sched.bound[i]);
        double along = sched_predict_along(w, a, b, r.distance, v3_neg(r.normal), r.pa, r.pb);
        p->along = along > next;
        return t_end + (p->along ? along : next);
    }
    w->sched.bound[i].dist = 0; /* touching: nothing left to keep (repredict) */
    /* the first contact is a function of the two flights alone, searched from
     * where the later of them starts, so that whenever the pair is found the
     * answer is the same (and is kept while both flights are) */
    if (!known) {
        double from = d_max(w->step.snap_t[p->a], w->step.snap_t[p->b]);
        toi_output o = toi_find(w, &(toi_input){p->a, p->b, p->hit, from, t_end});
        w->st.pair_checks += o.queries;
        if (o.state == TOI_HIT) w->pairs.hits[i] = (pair_hit){o.r, o.cache, o.t};
        else w->pairs.hits[i].t = NAN;
        p->toi = d_max(o.t, now);
        p->toi_a = w->step.snap_id[p->a];
        p->toi_b = w->step.snap_id[p->b];
    }
    /* the earliest; among equals the first pair, whatever order the schedule gave
     * them in, so that the heap changes nothing */
    if (!*first || p->toi < *when || (p->toi == *when && p < *first)) {
        *when = p->toi;
        *first = p;
    }
    return p->toi; /* checked again once the earliest is answered */
}

/* Checks the pairs due by t_end (every pair without the heap); returns the pair
 * that collides first within the step, its time in *when, or NULL.  A due pair
 * is popped and pushed back at once with its new time, unless that is within the
 * step (it touches): such pairs wait aside until the others are done. */
static pair *check_due(world *w, double now, double t_end, double *when)
{
    pair *first = NULL;
    *when = t_end;
    if (!w->set.collision_heap) {
        for (long i = 0; i < w->pairs.n; i++) check_pair(w, i, now, t_end, &first, when);
        return first;
    }
    long aside = 0, i;
    double next;
    while ((i = sched_top(w, &next)) >= 0 && next <= t_end) {
        if (i >= w->pairs.n) { /* an object's box ends: made again from its flight */
            int k = (int)(i - w->pairs.n);
            if (w->bodies[k]->held) { /* its box holds everything (hold_set) */
                sched_set(w, i, HUGE_VAL);
                continue;
            }
            bool moves = w->step.snap[k].state == STATE_DYNAMIC;
            sched_box_renew(w, k, step_at_start(w, k), moves ? w->step.snap_t[k] : next, next, t_end);
            continue;
        }
        w->st.heap_pops++;
        next = check_pair(w, i, now, t_end, &first, when);
        if (next <= t_end) {
            w->step.due[aside] = i;
            w->step.due_next[aside++] = next;
            next = HUGE_VAL;
        }
        sched_set(w, i, next);
    }
    for (long k = 0; k < aside; k++) sched_set(w, w->step.due[k], w->step.due_next[k]);
    return first;
}

/* True when body b, from the state given, flies h seconds without reaching the
 * speed limits, so that its centre moves by the plain v h + a h^2 / 2 and its
 * surface turns at the spin it has. */
static bool unlimited(const world *w, const body *b, double h)
{
    double acc = v3_len(world_body_accel(w, b));
    return b->state != STATE_DYNAMIC ||
           (v3_len(b->v) + acc * h < w->set.max_linear && v3_len(b->w) < w->set.max_angular);
}

/* A new time for near pair k of object i, which a collision at time t changed
 * from pre (moved by moved), from what is left of its distance then: the
 * distance when the pair was checked, less what the objects could close from the
 * check to t as the bound kept then assumed (they moved so until t), or, for a
 * check later than t (at the end of the step, with i's flight from before the
 * collision), less what they could have closed from t to the check; less the
 * move.  Object i moves on from t as it is now, and the other as it flies, no
 * faster than its speed where its flight starts plus what the force adds since.
 * Without a bound, the pair is due at t. */
static void repredict(world *w, long k, int i, const body *pre, double moved, double t)
{
    pair *q = &w->pairs.p[k];
    int j = q->a == i ? q->b : q->a;
    const body *o = step_at_start(w, j);
    double slack = o->state == STATE_DYNAMIC ? v3_len(world_body_accel(w, o)) * (t - w->step.snap_t[j]) : 0;
    double left = -1;
    if (q->checked <= t) {
        left = sched_left(&w->sched.bound[k], t - q->checked) - moved;
    } else if (unlimited(w, pre, q->checked - t) &&
               unlimited(w, o, q->checked - w->step.snap_t[j])) {
        double back = q->a == i ? sched_closing(w, pre, o, 0, slack, q->checked - t)
                                : sched_closing(w, o, pre, slack, 0, q->checked - t);
        left = w->sched.bound[k].dist - back - moved;
    }
    if (left <= 0) {
        sched_set(w, k, t);
        return;
    }
    const body *me = w->bodies[i];
    double next = q->a == i ? sched_predict_kept(w, me, o, left, 0, slack, &w->sched.bound[k])
                            : sched_predict_kept(w, o, me, left, slack, 0, &w->sched.bound[k]);
    q->checked = t;
    q->along = false;
    q->speed_a = v3_len((q->a == i ? me : o)->v) + (q->a == i ? 0 : slack);
    q->speed_b = v3_len((q->b == i ? me : o)->v) + (q->b == i ? 0 : slack);
    sched_set(w, k, t + next);
}

/* Makes due at time t the pairs of object i, which a collision changed from a to
 * b, that its new motion may bring together before their time.  A pair's time
 * came from a bound on its objects' motion from its check on: each no faster than
 * its speed then (speed_a, speed_b) plus what the force adds since, turning no
 * faster than then; or, for a far pair, turning any way at all (its bound takes
 * all of R - r at once, or a sphere that no turn changes) and moved at once by up
 * to SCHED_JUMP in all (body.jumped); or, for a near pair whose time came along
 * the normal (pair.along), from exactly the motions then.  Where b keeps within
 * that, the pair keeps its time.  A near pair that does not gets a new one from
 * its kept bound (repredict), unless the collision turned the object or moved it
 * more than a separation: it is due then.  Parked pairs wait on: the object's
 * box still holds it (sched_box_holds), or is made again from t, which parks
 * them or makes them due.  A held object's pairs (hold.h) are due at once. */
static void reschedule(world *w, int i, const body *a, const body *b, double t, double t_end)
{
    double acc = v3_len(world_body_accel(w, a)), moved = v3_len(v3_sub(a->x, b->x));
    bool turned = a->q.w != b->q.w || a->q.x != b->q.x || a->q.y != b->q.y || a->q.z != b->q.z;
    if (a->state != STATE_DYNAMIC || a->held || b->held ||
        (b->state == STATE_DYNAMIC && v3_len(world_body_accel(w, b)) > acc)) {
        sched_object_due(w, i, t);
        return;
    }
    /* its box holds, or is made again from here (its parked pairs wait on) */
    if (w->set.collision_heap && !sched_box_holds(w, i, b, t)) sched_box_renew(w, i, b, t, t, t_end);
    bool jolted = turned || moved > SIM_SEPARATION; /* beyond what a near bound keeps */
    double v = v3_len(b->v);
    bool spun = v3_len(b->L) > v3_len(a->L);
    for (long j = w->sched.obj_first[i]; j < w->sched.obj_first[i + 1]; j++) {
        long k = w->sched.obj_pairs[j];
        const pair *q = &w->pairs.p[k];
        if (w->bodies[w->sched.obj_other[j]]->held) { /* checked every step */
            if (q->next > t) sched_set(w, k, t);
            continue;
        }
        if (w->sched.parked[k]) continue;
        bool keep = q->checked <= t; /* found from speeds at an earlier instant */
        if (keep) keep = v <= (q->a == i ? q->speed_a : q->speed_b) + acc * (t - q->checked);
        if (keep && q->far)
            keep = w->bodies[q->a]->jumped - q->jumped_a + w->bodies[q->b]->jumped - q->jumped_b <=
                   SCHED_JUMP;
        else if (keep)
            keep = moved == 0 && !spun && !q->along;
        if (keep || q->next <= t) continue;
        if (!q->far && !jolted && q->checked < HUGE_VAL) repredict(w, k, i, a, moved, t);
        else sched_set(w, k, t);
    }
}

/* Answers the collision of pair p at time t, within the step that ends at t_end.
 * Only its two objects are flown there; the others stay at the end of the step,
 * where the next check wants them (settle flies the neighbours it looks at).  What
 * the answer changes flies on from t; what it leaves as it was flies back. */
static void answer(world *w, pair *p, double t, double t_end)
{
    assert(p->a < p->b && t >= w->time && t <= t_end);
    int ends[2] = {p->a, p->b};
    for (int k = 0; k < 2; k++) {
        int i = ends[k];
        if (w->step.snap[i].state == STATE_DYNAMIC) step_fly_into(w, i, t, w->bodies[i]);
        body_copy_state(&w->step.pre[i], w->bodies[i]);
    }
    for (int i = 0; i < w->n; i++) w->step.touched[i] = false;
    w->time = t;
    collide(w, p);
    rest_wake_unsupported(w, w->step.touched);
    for (int k = 0; k < 2; k++) {
        int i = ends[k];
        w->step.touched[i] = false;
        if (memcmp((char *)&w->step.pre[i] + offsetof(body, x), (char *)w->bodies[i] + offsetof(body, x),
                   sizeof(body) - offsetof(body, x)) == 0) {
            /* as it was: at the end of the step again */
            if (w->step.snap[i].state == STATE_DYNAMIC) step_fly_into(w, i, t_end, w->bodies[i]);
            continue;
        }
        /* what the collision moved it by at once (setting it apart, settling it) */
        w->bodies[i]->jumped += v3_len(v3_sub(body_com(w->bodies[i]), body_com(&w->step.pre[i])));
        step_renew(w, i, t);
        /* its motion changed: its pairs are due again, unless their times hold */
        reschedule(w, i, &w->step.pre[i], w->bodies[i], t, t_end);
    }
    for (int i = 0; i < w->n; i++) {
        if (!w->step.touched[i]) continue;
        body *b = w->bodies[i];
        if (w->step.snap[i].state == STATE_DYNAMIC) {
            /* a moving object that slides no more: where it is at t, with that */
            int slide = b->slide;
            step_fly_into(w, i, t, b);
            b->slide = slide;
        }
        step_renew(w, i, t);
    }
}

#ifdef VROC_VALIDATE
/* The validation build (make check runs it on every scene) checks after every
 * internal step what the simulation relies on and does not check as it goes: the
 * schedule's heap and marks, and every polyhedron's adjacency, planarity and
 * convexity (to 1e-9 of its size). */
static void validate(const world *w)
{
    if (w->sched.heap) assert(sched_check(w) == 0);
    for (int i = 0; i < w->n; i++) {
        const shape *s = &w->bodies[i]->shape;
        char err[256];
        if (s->hull) assert(poly_check(s->hull, 1e-9 * (1 + s->r_out), err, sizeof err) == 0);
    }
}
#endif

/* One internal step, from now to t_end (thesis 3.4.2, steps 3 to 5); its
 * scratch is in place (sim_prepare). */
static void internal_step(world *w, double t_end)
{
    double now = w->time;
    step_save(w, now);
    for (int n = 0;; n++) {
        step_fly_to_end(w, t_end);
        double when;
        pair *first = check_due(w, now, t_end, &when);
        if (!first || n >= SIM_MAX_COLLISIONS_PER_STEP) break;
        answer(w, first, when, t_end);
        now = when;
    }
    w->time = t_end;
    rest_check_slides(w);
#ifdef VROC_VALIDATE
    validate(w);
#endif
}

int sim_prepare(world *w)
{
    if (pairs_update(w) != 0 || (w->sched_dirty && sched_build(w, w->time) != 0) ||
        step_prepare(w, w->sched_dirty) != 0)
        return -1;
    w->sched_dirty = false;
    return 0;
}

/* The hook acts at world.time, where the internal step under way was cut; objects
 * resting on what it set moving wake.  Returns the next instant it asks for; one
 * that asks for the same instant again and again is let go after a while. */
static double hook_act(world *w, const sim_hook *hook, int *calls)
{
    hook->at(hook->ctx, w);
    rest_wake_unsupported(w, NULL);
    double tn = hook->next(hook->ctx, w);
    *calls = tn <= w->time ? *calls + 1 : 0;
    return *calls > SIM_MAX_COLLISIONS_PER_STEP ? HUGE_VAL : tn;
}

/* The internal step that ends at t_end, cut at each instant tn before it that the
 * hook asks for; returns the hook's next instant.  (Out of the frame's loop, so
 * that a frame the hook has nothing in costs one comparison a step.) */
static __attribute__((cold, noinline)) double hook_cut(world *w, const sim_hook *hook, double tn,
                                                      double t_end, int *calls)
{
    while (tn < t_end) {
        if (tn > w->time) internal_step(w, tn);
        tn = hook_act(w, hook, calls);
    }
    return tn;
}

int sim_frame(world *w, char *err, size_t errlen)
{
    return sim_frame_hooked(w, NULL, err, errlen);
}

int sim_frame_hooked(world *w, const sim_hook *hook, char *err, size_t errlen)
{
    long n = world_subframes(w);
    if (n > SIM_MAX_SUBFRAMES) {
        snprintf(err, errlen,
                 "time_step %g needs %ld internal steps per frame (limit %ld): raise "
                 "collision_dist or internal_step, or lower time_step",
                 w->set.time_step, n, SIM_MAX_SUBFRAMES);
        return -1;
    }
    if (sim_prepare(w) != 0) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double t0 = w->time, h = n > 0 ? w->set.time_step / (double)n : 0;
    w->nevents = 0;
    rest_wake_unsupported(w, NULL);
    /* the hook's next instant: the internal step is cut there, every object
     * brought to it, and what the hook changed is seen by the rest of the step
     * (step_save starts every flight afresh).  A frame it has nothing in runs as
     * if there were none. */
    int calls = 0;
    double tn = hook ? hook->next(hook->ctx, w) : HUGE_VAL;
    for (long k = 0; k < n; k++) {
        double t_end = w->time + h;
        if (tn < t_end) tn = hook_cut(w, hook, tn, t_end, &calls);
        internal_step(w, t_end);
        w->st.subframes++;
    }
    rest_frame_end(w);
    if (w->set.time_step != w->base_step || w->time_base + (double)w->base_frames * w->base_step != t0) {
        w->time_base = t0;
        w->base_step = w->set.time_step;
        w->base_frames = 0;
    }
    w->base_frames++;
    w->time = w->time_base + (double)w->base_frames * w->base_step;
    w->frame++;
    w->st.frames++;
    return 0;
}
