/* sim.c: frames, internal steps, free flight, collisions in time and rest (thesis
 * 3.2.3, 3.3.3, 3.4.2; design.md, "Dynamics").
 *
 * Linear motion under a constant acceleration is integrated exactly, so a ball's
 * flight does not depend on the step length.  Rotation: the free rigid body's
 * energy H = sum_k pi_k^2 / (2 I_k) (pi the angular momentum in principal axes)
 * splits into three parts whose flows are exact rotations about one principal axis
 * each; composing them symmetrically (x/2, y/2, z, y/2, x/2) gives a second-order
 * method that leaves the world angular momentum untouched, whatever the inertia
 * tensor (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107, 1997).
 *
 * An internal step (thesis 3.4.2, steps 3 to 5): save every state, fly the whole
 * step, check the pairs.  If some pair touches or penetrates, each such pair is
 * bisected in time from the saved states to its first contact; the world goes back
 * to the saved states, flies to the earliest contact, answers it, and the rest of
 * the step starts over from there.  So collisions are answered in the order they
 * happen, simultaneous ones one after another, and the flight between them stays
 * exact.
 */
#include "sim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "log.h"
#include "schedule.h"

/* ------------------------------------------------------------ free flight */

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
    quat qp = q_mul(b->q, b->q_principal); /* principal axes to world */
    vec3 pi = q_unrotate(qp, b->L);        /* L in principal axes */
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

    if (v3_len2(b->L) != 0) {
        rotate_free(b, h);
        b->rot_given = false;
        body_update_w(b);
        double wl = v3_len(b->w);
        if (wl > max_angular) {
            b->L = v3_scale(b->L, max_angular / wl);
            body_update_w(b);
        }
    }
    /* the centre of mass moved by d; the origin follows the new orientation */
    b->x = v3_sub(v3_add(c0, d), q_rotate(b->q, b->shape.mass.com));
}

/* ------------------------------------------------------------ pairs */

int sim_update_pairs(world *w)
{
    if (!w->pairs_dirty) return 0;
    long n = world_pairs(w);
    if (n > w->cappairs) {
        pair *np = realloc(w->pairs, (size_t)n * sizeof *np);
        if (!np) return -1;
        w->pairs = np;
        w->cappairs = n;
    }
    long k = 0;
    for (int i = 0; i < w->n; i++) {
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            w->pairs[k++] = (pair){i, j, {{CLOSEST_NONE, 0}, {CLOSEST_NONE, 0}, false}, 0, -1};
        }
    }
    w->npairs = k;
    w->pairs_dirty = false;
    w->sched_dirty = true; /* the heap holds the old pairs */
    for (int i = 0; i < w->n; i++) w->bodies[i]->slide = -1; /* slide_pair is stale */
    return 0;
}

/* A pair needs checking only when one of its objects moves. */
static bool pair_moves(const world *w, const pair *p)
{
    return w->bodies[p->a]->state == STATE_DYNAMIC || w->bodies[p->b]->state == STATE_DYNAMIC;
}

static closest_result query(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = closest_query(a, b, &p->cache);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

long sim_penetrations(world *w, sim_report report, void *ctx)
{
    if (sim_update_pairs(w) != 0) return -1;
    long count = 0;
    for (long i = 0; i < w->npairs; i++) {
        pair *p = &w->pairs[i];
        const body *a = w->bodies[p->a], *b = w->bodies[p->b];
        closest_result r = query(w, p, a, b);
        if (r.status == CLOSEST_PENETRATING && r.distance < -SIM_SEPARATION) {
            count++;
            if (report) report(ctx, a, b, -r.distance);
        }
    }
    return count;
}

/* ------------------------------------------------------------ waking and rest */

/* A resting object moves again (its pairs are then made due by the caller, or by
 * the shell after a command). */
static void wake(world *w, int i)
{
    body *b = w->bodies[i];
    if (b->state == STATE_RESTING) {
        b->state = STATE_DYNAMIC;
        b->support = -1;
    }
}

/* The global acceleration as body b feels it: less the part that presses it onto
 * the support it slides on. */
static vec3 accel_of(const world *w, const body *b)
{
    vec3 a = world_accel(w);
    if (b->slide < 0) return a;
    double an = v3_dot(a, b->slide_n);
    return an < 0 ? v3_mad(a, b->slide_n, -an) : a;
}

void sim_wake_all(world *w)
{
    for (int i = 0; i < w->n; i++) wake(w, i);
}

void sim_wake_on(world *w, int i)
{
    for (int k = 0; k < w->n; k++) {
        body *b = w->bodies[k];
        if (b->state == STATE_RESTING && b->support == i) wake(w, k);
        if (b->slide == i) b->slide = -1;
    }
}

static void come_to_rest(body *b, int support)
{
    b->state = STATE_RESTING;
    b->slide = -1;
    b->support = support;
    b->v = v3(0, 0, 0);
    b->L = v3(0, 0, 0);
    b->w = v3(0, 0, 0);
}

/* Resting objects whose support left (deleted, or moving) wake up; chains of
 * resting objects wake in turn. */
static void wake_unsupported(world *w)
{
    bool changed = true;
    while (changed) {
        changed = false;
        for (int i = 0; i < w->n; i++) {
            body *b = w->bodies[i];
            const body *s = b->slide >= 0 ? w->bodies[b->slide] : NULL;
            if (s && s->state == STATE_DYNAMIC && s->slide < 0) b->slide = -1;
            if (b->state != STATE_RESTING) continue;
            if (b->support < 0 || w->bodies[b->support]->state == STATE_DYNAMIC) {
                wake(w, i);
                sched_object_due(w, i, w->time);
                changed = true;
            }
        }
    }
}

/* The frame rule (thesis 3.3.3): an object still sliding on a support at the end of
 * the frame, slower than the rest speed, rests on it. */
static void rest_still_objects(world *w)
{
    bool changed = true;
    while (changed) { /* a stack comes to rest from the bottom up */
        changed = false;
        for (int i = 0; i < w->n; i++) {
            body *b = w->bodies[i];
            if (b->state != STATE_DYNAMIC || b->slide < 0) continue;
            if (w->bodies[b->slide]->state == STATE_DYNAMIC) continue;
            double speed = v3_len(b->v) + v3_len(b->w) * b->shape.r_out;
            if (speed < SIM_REST_SPEED) {
                come_to_rest(b, b->slide);
                changed = true;
            }
        }
    }
}

/* ------------------------------------------------------------ collisions in time */

static int save_states(world *w)
{
    if (w->n > w->capsnap) {
        body *ns = realloc(w->snap, (size_t)w->n * sizeof *ns);
        if (!ns) return -1;
        w->snap = ns;
        w->capsnap = w->n;
    }
    for (int i = 0; i < w->n; i++) w->snap[i] = *w->bodies[i];
    return 0;
}

static void restore_states(world *w)
{
    for (int i = 0; i < w->n; i++) *w->bodies[i] = w->snap[i];
}

static void fly_all(world *w, double h)
{
    const settings *s = &w->set;
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (b->state == STATE_DYNAMIC)
            sim_flight(b, h, accel_of(w, b), s->max_linear, s->max_angular);
    }
}

/* A body's saved state flown for t seconds (shallow copy: shares the shape). */
static body flown(const world *w, int i, double t)
{
    body b = w->snap[i];
    if (b.state == STATE_DYNAMIC && t > 0)
        sim_flight(&b, t, accel_of(w, &b), w->set.max_linear, w->set.max_angular);
    return b;
}

/* First contact of pair p within [0, span] from the saved states, knowing that it
 * touches or penetrates at span: the latest time found at which it is apart. */
static double time_of_impact(world *w, pair *p, double span)
{
    double lo = 0, hi = span;
    closest_cache cache = p->cache;
    body a = flown(w, p->a, 0), b = flown(w, p->b, 0);
    closest_result r = closest_query(&a, &b, &cache);
    w->st.pair_checks++;
    if (r.status != CLOSEST_SEPARATED) return 0; /* touching already */
    while (hi - lo > SIM_TOI_TIME) {
        double mid = 0.5 * (lo + hi);
        a = flown(w, p->a, mid);
        b = flown(w, p->b, mid);
        r = closest_query(&a, &b, &cache);
        w->st.pair_checks++;
        if (r.status == CLOSEST_SEPARATED) {
            lo = mid;
            if (r.distance < 0.5 * SIM_SEPARATION) break;
        } else {
            hi = mid;
        }
    }
    return lo;
}

/* Moves the dynamic objects of the pair apart along n until they are sep apart
 * (they are gap apart now), the lighter one more. */
static void separate(body *a, body *b, vec3 n, double gap, double sep)
{
    double need = sep - gap;
    if (need <= 0) return;
    double ia = a->state == STATE_DYNAMIC ? a->inv_mass : 0;
    double ib = b->state == STATE_DYNAMIC ? b->inv_mass : 0;
    if (ia + ib == 0) return;
    a->x = v3_mad(a->x, n, need * ia / (ia + ib));
    b->x = v3_mad(b->x, n, -need * ib / (ia + ib));
}

/* Answers the collision of pair p now: the impulse, the separation, the log; and
 * the thesis's contact state for an object that barely bounces off a support below
 * it. */
static void collide(world *w, pair *p)
{
    body *a = w->bodies[p->a], *b = w->bodies[p->b];
    closest_result r = query(w, p, a, b);
    if (r.status == CLOSEST_INVALID) return;
    double scale = a->shape.r_out + b->shape.r_out;
    vec3 pt = contact_point(a, b, &r, 1e-6 * scale + fmax(0, -r.distance));
    double e = fmin(a->elasticity, b->elasticity);
    /* a resting object hit by a moving one takes part as a dynamic one */
    if (a->state == STATE_RESTING && b->state == STATE_DYNAMIC) wake(w, p->a);
    if (b->state == STATE_RESTING && a->state == STATE_DYNAMIC) wake(w, p->b);
    /* their motion changes: every pair of theirs is due again */
    sched_object_due(w, p->a, w->time);
    sched_object_due(w, p->b, w->time);
    contact c = contact_respond(a, b, pt, r.normal, e);
    if (c.impulse > 0) {
        w->st.collisions++;
        log_event(w, a, b, c.point, c.normal, c.impulse, c.speed);
    }
    /* the contact state: an object that barely bounces off a support under it rests
     * on it, or slides on it when it still moves along it */
    /* a pair that touches, or that touched without approaching (a glancing or
     * rotating contact), is set apart, so that the step goes on */
    bool apart = r.distance <= 0 || c.impulse == 0;
    vec3 g = world_accel(w);
    if (v3_len2(g) == 0) {
        if (apart) separate(a, b, r.normal, r.distance, SIM_SEPARATION);
        return;
    }
    vec3 up = v3_neg(v3_norm(g));
    bool settled = false;
    for (int k = 0; k < 2; k++) {
        body *m = k == 0 ? a : b, *s = k == 0 ? b : a;
        int si = k == 0 ? p->b : p->a;
        vec3 n = k == 0 ? r.normal : v3_neg(r.normal); /* from the support to m */
        /* a support: a static or resting object, or one that slides itself */
        if (m->state != STATE_DYNAMIC || (s->state == STATE_DYNAMIC && s->slide < 0)) continue;
        double vn = v3_dot(m->v, n);
        if (v3_dot(n, up) < 0.7 || vn > SIM_REST_SPEED) continue;
        if (!contact_stable(m, n, 1e-6 * scale)) continue;
        double speed = v3_len(m->v) + v3_len(m->w) * m->shape.r_out;
        if (speed < SIM_REST_SPEED && s->state != STATE_DYNAMIC) {
            come_to_rest(m, si);
        } else {
            m->slide = si;
            m->slide_n = n;
            m->slide_pair = p - w->pairs;
            if (vn > 0) m->v = v3_mad(m->v, n, -vn);
        }
        settled = true;
    }
    /* an object that barely moves against a support below it without standing on
     * it (rocking on an edge or a corner), and keeps colliding in this step, is set
     * a hop apart, so that gravity takes milliseconds, not microseconds, to bring
     * it back: the micro-collisions that turn it over stay few */
    double sep = SIM_SEPARATION;
    a->step_hits++;
    b->step_hits++;
    if (!settled && c.speed < SIM_REST_SPEED && fabs(v3_dot(r.normal, up)) > 0.7 &&
        (a->step_hits > SIM_HOP_AFTER || b->step_hits > SIM_HOP_AFTER))
        sep = SIM_HOP;
    if (apart || settled || sep > SIM_SEPARATION) separate(a, b, r.normal, r.distance, sep);
}

/* Sliding objects leave their support when they lift off, pass its edge, stop
 * standing stably on it or are thrown off it. */
static void check_slides(world *w)
{
    for (int i = 0; i < w->n; i++) {
        body *m = w->bodies[i];
        if (m->slide < 0) continue;
        if (m->state != STATE_DYNAMIC) {
            m->slide = -1;
            continue;
        }
        pair *p = &w->pairs[m->slide_pair];
        const body *s = w->bodies[m->slide];
        closest_result r = query(w, p, w->bodies[p->a], w->bodies[p->b]);
        vec3 n = p->a == i ? r.normal : v3_neg(r.normal);
        double scale = m->shape.r_out + s->shape.r_out;
        if (r.status != CLOSEST_SEPARATED || r.distance > 100 * SIM_SEPARATION ||
            v3_dot(n, m->slide_n) < 1 - 1e-6 || v3_dot(m->v, n) > SIM_REST_SPEED ||
            !contact_stable(m, n, 1e-6 * scale))
            m->slide = -1;
    }
}

static int due_room(world *w, long n)
{
    if (n <= w->capdue) return 0;
    long *d = realloc(w->due, (size_t)n * sizeof *d);
    if (d) w->due = d;
    double *dn = realloc(w->due_next, (size_t)n * sizeof *dn);
    if (dn) w->due_next = dn;
    if (!d || !dn) return -1;
    w->capdue = n;
    return 0;
}

/* The pairs to check at time t_end: with the heap, those due by then (taken out of
 * the way at +inf until their new time is known); without it, every pair. */
static long take_due(world *w, double t_end)
{
    long n = 0;
    if (!w->set.collision_heap) {
        for (long i = 0; i < w->npairs; i++) w->due[n++] = i;
        return n;
    }
    double next;
    long i;
    while ((i = sched_top(w, &next)) >= 0 && next <= t_end) {
        w->due[n++] = i;
        sched_set(w, i, HUGE_VAL);
        w->st.heap_pops++;
    }
    return n;
}

static void put_back(world *w, long n)
{
    if (!w->set.collision_heap) return;
    for (long k = 0; k < n; k++) sched_set(w, w->due[k], w->due_next[k]);
}

/* One internal step of h seconds (thesis 3.4.2, steps 3 to 5). */
static int internal_step(world *w, double h)
{
    double left = h, t0 = w->time, t_end = t0 + h;
    if (due_room(w, w->npairs) != 0) return -1;
    for (int i = 0; i < w->n; i++) w->bodies[i]->step_hits = 0;
    for (int n = 0; left > 0; n++) {
        if (save_states(w) != 0) return -1;
        fly_all(w, left);
        long ndue = take_due(w, t_end);
        pair *first = NULL;
        double when = left;
        for (long k = 0; k < ndue; k++) {
            pair *p = &w->pairs[w->due[k]];
            w->due_next[k] = HUGE_VAL;
            if (!pair_moves(w, p)) continue;
            closest_result r = query(w, p, w->bodies[p->a], w->bodies[p->b]);
            if (r.status != CLOSEST_PENETRATING) {
                w->due_next[k] = t_end + sched_predict(w, p, r.distance);
                continue;
            }
            double t = time_of_impact(w, p, left);
            w->due_next[k] = t0 + (h - left) + t; /* checked again once answered */
            /* the earliest; among equals the first pair, whatever order the
             * schedule gave them in, so that the heap changes nothing */
            if (!first || t < when || (t == when && p < first)) {
                when = t;
                first = p;
            }
        }
        /* the world goes back to answer a collision: what was predicted from the
         * states about to be dropped no longer holds (the speed limits make a
         * flight depend on where it is cut), so those pairs are due again then */
        if (first) {
            double tc = t0 + (h - left) + when;
            for (long k = 0; k < ndue; k++) w->due_next[k] = fmin(w->due_next[k], tc);
        }
        put_back(w, ndue);
        if (!first || n >= SIM_MAX_COLLISIONS_PER_STEP) break;
        restore_states(w);
        fly_all(w, when);
        left -= when;
        w->time = t0 + (h - left);
        collide(w, first);
        wake_unsupported(w);
    }
    w->time = t_end;
    check_slides(w);
    return 0;
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
    if (sim_update_pairs(w) != 0 || (w->sched_dirty && sched_build(w, w->time) != 0)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    w->sched_dirty = false;
    double t0 = w->time, h = n > 0 ? w->set.time_step / (double)n : 0;
    wake_unsupported(w);
    for (long k = 0; k < n; k++) {
        if (internal_step(w, h) != 0) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        w->st.subframes++;
    }
    rest_still_objects(w);
    if (w->set.time_step != w->base_step || w->time_base + (double)w->base_frames * w->base_step != t0) {
        w->time_base = t0;
        w->base_step = w->set.time_step;
        w->base_frames = 0;
    }
    w->base_frames++;
    w->time = w->time_base + (double)w->base_frames * w->base_step;
    w->frame++;
    w->st.frames++;
    log_trace_frame(w);
    return 0;
}
