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
 * An internal step (thesis 3.4.2, steps 3 to 5): save every moving object's
 * state, fly the whole step, check the due pairs.  If some pair touches or
 * penetrates, each such pair is traced back in time to its first contact; the
 * earliest is answered at its instant (its two objects flown back there), and the
 * rest of the step starts over from there.  So collisions are answered in the
 * order they happen, simultaneous ones one after another.  Each object flies from
 * its own saved state, which only a collision that changes it renews: going back
 * in time leaves the others' flights, and their pairs' predictions, exact; and a
 * pair's first contact depends on the two flights alone, so the schedule cannot
 * change it.
 *
 * Contact: a collision that leaves an object barely bouncing on a support below it
 * puts it at rest, or sliding (settle); slow collisions under gravity part at the
 * collision envelope's speed, and a stack passes blows from above down to its
 * support.
 */
#include "sim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "log.h"
#include "schedule.h"

/* ------------------------------------------------------------ free flight */

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

/* True when b slides on a support turning about the support's normal only (as
 * settling leaves it): then its flight keeps it so. */
static bool spins_on_support(const body *b)
{
    if (b->slide < 0 || v3_len2(b->L) == 0) return false;
    vec3 off = v3_mad(b->w, b->slide_n, -v3_dot(b->w, b->slide_n));
    return v3_len2(off) <= 1e-24 * v3_len2(b->w);
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

void sim_flight(body *b, double h, vec3 a, double max_linear, double max_angular)
{
    vec3 c0 = body_com(b);
    vec3 d = v3_add(v3_scale(b->v, h), v3_scale(a, 0.5 * h * h));
    vec3 v = v3_mad(b->v, a, h);
    double dl = v3_len(d), vl = v3_len(v);
    if (dl > max_linear * h) d = v3_scale(d, max_linear * h / dl);
    if (vl > max_linear) v = v3_scale(v, max_linear / vl);
    b->v = v;

    if (spins_on_support(b)) {
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

/* ------------------------------------------------------------ pairs */

/* The index of the pair of objects a and b (either order), or -1 when they have
 * none. */
static long pair_index(const world *w, int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    long lo = 0, hi = w->npairs;
    while (lo < hi) {
        long mid = lo + (hi - lo) / 2;
        const pair *p = &w->pairs[mid];
        if (p->a < a || (p->a == a && p->b < b)) lo = mid + 1;
        else hi = mid;
    }
    return lo < w->npairs && w->pairs[lo].a == a && w->pairs[lo].b == b ? lo : -1;
}

int sim_update_pairs(world *w)
{
    if (!w->pairs_dirty) return 0;
    long n = world_pairs(w);
    if (n > w->cappairs) {
        pair *np = realloc(w->pairs, (size_t)n * sizeof *np);
        if (np) w->pairs = np;
        pair_hit *nh = realloc(w->hits, (size_t)n * sizeof *nh);
        if (nh) w->hits = nh;
        if (!np || !nh) return -1;
        w->cappairs = n;
    }
    long k = 0;
    for (int i = 0; i < w->n; i++) {
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            w->hits[k].t = NAN;
            w->pairs[k++] = (pair){.a = i, .b = j, .toi_a = -1, .toi_b = -1};
        }
    }
    w->npairs = k;
    w->pairs_dirty = false;
    w->sched_dirty = true; /* the heap holds the old pairs */
    /* an object added or deleted elsewhere leaves a slide on a still support as
     * it was: its pair is found again (the pairs are in the order of a, then b).
     * A slide on a support that moves itself ends, as the schedule starts afresh. */
    for (int i = 0; i < w->n; i++) {
        body *m = w->bodies[i];
        if (m->slide < 0) continue;
        long at = -1;
        if (m->state == STATE_DYNAMIC && w->bodies[m->slide]->state != STATE_DYNAMIC)
            at = pair_index(w, i, m->slide);
        m->slide = at >= 0 ? m->slide : -1;
        m->slide_pair = at;
    }
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

/* query for the answer to a collision, from the features of the pair's last one */
static closest_result query_hit(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = closest_query(a, b, &p->hit);
    w->st.pair_checks++;
    if (r.restarted) w->st.restarts++;
    return r;
}

/* query for a check that needs only whether the pair is apart, and how far */
static closest_result query_apart(world *w, pair *p, const body *a, const body *b)
{
    closest_result r = closest_query_apart(a, b, &p->cache);
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
 * resting objects wake in turn.  Sliding objects whose support moves on its own
 * slide no more.  Marks in touched (when not NULL) each object it changes. */
static void wake_unsupported(world *w, bool *touched)
{
    bool changed = true;
    while (changed) {
        changed = false;
        for (int k = 0; k < w->nmovers; k++) { /* (a static object neither slides nor rests) */
            int i = w->movers[k];
            body *b = w->bodies[i];
            const body *s = b->slide >= 0 ? w->bodies[b->slide] : NULL;
            if (s && s->state == STATE_DYNAMIC && s->slide < 0) {
                b->slide = -1; /* the full force: its pairs' predictions change */
                sched_slide_ends(w, i, w->time);
                if (touched) touched[i] = true;
            }
            if (b->state != STATE_RESTING) continue;
            if (b->support < 0 || w->bodies[b->support]->state == STATE_DYNAMIC) {
                wake(w, i);
                sched_object_due(w, i, w->time);
                if (touched) touched[i] = true;
                changed = true;
            }
        }
    }
}

/* Makes due now the pairs of object i whose times hold only while it flies as it
 * did (pair.along), when it stops. */
static void along_due(world *w, int i)
{
    if (!w->obj_first) return;
    for (long j = w->obj_first[i]; j < w->obj_first[i + 1]; j++) {
        long k = w->obj_pairs[j];
        if (w->pairs[k].along && w->pairs[k].next > w->time) sched_set(w, k, w->time);
    }
}

/* The frame rule (thesis 3.3.3): an object still sliding on a support at the end of
 * the frame, slower than the rest speed, rests on it. */
static void rest_still_objects(world *w)
{
    bool changed = true;
    while (changed) { /* a stack comes to rest from the bottom up */
        changed = false;
        for (int k = 0; k < w->nmovers; k++) {
            int i = w->movers[k];
            body *b = w->bodies[i];
            if (b->state != STATE_DYNAMIC || b->slide < 0) continue;
            if (w->bodies[b->slide]->state == STATE_DYNAMIC) continue;
            double speed = v3_len(b->v) + v3_len(b->w) * b->shape.r_out;
            if (speed < SIM_REST_SPEED) {
                come_to_rest(b, b->slide);
                along_due(w, i);
                changed = true;
            }
        }
    }
}

/* ------------------------------------------------------------ collisions in time */

/* The array p resized to n elements of size elem; p itself, and ok set false, when
 * that fails. */
static void *resized(void *p, size_t elem, int n, bool *ok)
{
    void *q = realloc(p, (size_t)n * elem);
    if (!q) *ok = false;
    return q ? q : p;
}

/* end_id of an object that is where its flight starts (save_states made the
 * flight from it): the first flight to the end of the step needs no copy. */
#define END_AT_START (-2)

/* Within an internal step each object flies from its own starting state: snap[i]
 * at time snap_t[i], the start of the step, or the instant of the last collision
 * that changed it.  An object's place at time t is always one flight from there,
 * so a collision that sends the world back to an earlier instant leaves every
 * other object's flight, and so its pairs' predictions, exactly as they were. */
static void save_states(world *w, double t)
{
    /* (a static object's start stays as frame_states set it: it never moves) */
    for (int k = 0; k < w->nmovers; k++) {
        int i = w->movers[k];
        /* what does not move is where it is: only its state is kept (flown) */
        if (w->bodies[i]->state == STATE_DYNAMIC) body_copy_state(&w->snap[i], w->bodies[i]);
        else w->snap[i].state = w->bodies[i]->state;
        w->snap_t[i] = t;
        w->snap_id[i] = w->flight_count++;
        w->end_id[i] = END_AT_START;
    }
}

/* Copies of each object a time of impact or a settling works on: body i's are
 * scratch[SCRATCH i] to scratch[SCRATCH i + SCRATCH - 1]. */
#define SCRATCH 4

/* Makes snap, pre and scratch copies of the objects that may move, so that within a
 * frame only their states need copying (nothing else changes while time runs;
 * static objects are read where they are).  The copies are made again only after
 * a command (changed, w->sched_dirty): between frames nothing else changes a
 * body but its state, which every step copies before it reads it. */
static int frame_states(world *w, bool changed)
{
    if (w->n > w->capsnap) {
        changed = true;
        bool ok = true;
        w->snap = resized(w->snap, sizeof *w->snap, w->n, &ok);
        w->pre = resized(w->pre, sizeof *w->pre, w->n, &ok);
        w->scratch = resized(w->scratch, SCRATCH * sizeof *w->scratch, w->n, &ok);
        w->snap_t = resized(w->snap_t, sizeof *w->snap_t, w->n, &ok);
        w->snap_id = resized(w->snap_id, sizeof *w->snap_id, w->n, &ok);
        w->end_id = resized(w->end_id, sizeof *w->end_id, w->n, &ok);
        w->touched = resized(w->touched, sizeof *w->touched, w->n, &ok);
        w->movers = resized(w->movers, sizeof *w->movers, w->n, &ok);
        if (!ok) return -1;
        w->capsnap = w->n;
    }
    if (!changed) return 0;
    w->nmovers = 0;
    for (int i = 0; i < w->n; i++) {
        if (!body_is_static(w->bodies[i])) {
            w->movers[w->nmovers++] = i;
            w->snap[i] = w->pre[i] = *w->bodies[i];
            for (int k = 0; k < SCRATCH; k++) w->scratch[SCRATCH * i + k] = *w->bodies[i];
        } else {
            /* a static object flies from nowhere before any step; its pre copy
             * is written here, not first in the middle of a frame (answer) */
            w->pre[i] = *w->bodies[i];
            w->snap[i].state = w->bodies[i]->state;
            w->snap_t[i] = -HUGE_VAL;
            w->snap_id[i] = w->flight_count++;
            w->end_id[i] = -1;
        }
    }
    return 0;
}

/* Flies out, a copy of moving body i where its flight starts, on to time t. */
static void fly_on(const world *w, int i, double t, body *out)
{
    double dt = t - w->snap_t[i];
    if (dt > 0) sim_flight(out, dt, world_body_accel(w, out), w->set.max_linear, w->set.max_angular);
}

/* Puts moving body i's state at time t in out, a copy of body i. */
static void fly_into(const world *w, int i, double t, body *out)
{
    body_copy_state(out, &w->snap[i]);
    fly_on(w, i, t, out);
}

/* Puts body i's state at time t in out, a copy of body i (what does not move is
 * there already). */
static void fly_at(const world *w, int i, double t, body *out)
{
    if (w->snap[i].state == STATE_DYNAMIC) fly_into(w, i, t, out);
}

static void swap_bodies(body **x, body **y)
{
    body *t = *x;
    *x = *y;
    *y = t;
}

/* Body i at time t: itself when it does not move, else its scratch copy number
 * k, flown there. */
static const body *flown(const world *w, int i, double t, int k)
{
    if (w->snap[i].state != STATE_DYNAMIC) return w->bodies[i];
    body *b = &w->scratch[SCRATCH * i + k];
    fly_into(w, i, t, b);
    return b;
}

/* The copies of body i a search works on, the first at time t: body i itself
 * when it does not move (nothing then changes them), else its scratch copies
 * (only the first flown: the others are written before they are read). */
static void search_copies(world *w, int i, double t, body *out[SCRATCH])
{
    for (int k = 0; k < SCRATCH; k++)
        out[k] = w->snap[i].state == STATE_DYNAMIC ? &w->scratch[SCRATCH * i + k] : w->bodies[i];
    if (w->snap[i].state == STATE_DYNAMIC) fly_into(w, i, t, out[0]);
}

/* Body i where its flight starts (at snap_t[i]). */
static const body *at_start(const world *w, int i)
{
    return w->snap[i].state == STATE_DYNAMIC ? &w->snap[i] : w->bodies[i];
}

/* The earlier start of the flights of pair p's moving objects. */
static double flights_start(const world *w, const pair *p)
{
    bool ma = w->snap[p->a].state == STATE_DYNAMIC, mb = w->snap[p->b].state == STATE_DYNAMIC;
    if (ma && mb) return d_min(w->snap_t[p->a], w->snap_t[p->b]);
    return ma ? w->snap_t[p->a] : w->snap_t[p->b];
}

/* Every moving object to the end of the step, t_end: an object whose flight did
 * not change since it was last flown there is there already (answer flies back
 * there what it flew to a collision and left unchanged). */
static void fly_to_end(world *w, double t_end)
{
    for (int k = 0; k < w->nmovers; k++) {
        int i = w->movers[k];
        if (w->snap[i].state != STATE_DYNAMIC || w->end_id[i] == w->snap_id[i]) continue;
        /* where its flight starts, as save_states left it, it flies on in place */
        if (w->end_id[i] != END_AT_START) body_copy_state(w->bodies[i], &w->snap[i]);
        fly_on(w, i, t_end, w->bodies[i]);
        w->end_id[i] = w->snap_id[i];
    }
}

/* The acceleration of body b, zero when it does not move. */
static vec3 still_accel(const world *w, const body *b)
{
    return b->state == STATE_DYNAMIC ? world_body_accel(w, b) : v3(0, 0, 0);
}

/* How body b moves at that instant in free flight, for the velocity and the
 * acceleration of its points. */
typedef struct {
    vec3 c, v, w, a, dw; /* centre of mass, its velocity, spin, acceleration; dw/dt */
} flight_motion;

static flight_motion motion_of(const world *w, const body *b)
{
    flight_motion m = {body_com(b), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 0)};
    if (body_is_static(b) || b->state == STATE_RESTING) return m;
    m.v = b->v;
    m.w = b->w;
    if (b->state != STATE_DYNAMIC) return m;
    m.a = world_body_accel(w, b);
    if (v3_len2(b->w) != 0) m.dw = v3_neg(body_inertia_inv_mulv(b, v3_cross(b->w, b->L)));
    return m;
}

static vec3 motion_velocity(const flight_motion *m, vec3 p)
{
    return v3_add(m->v, v3_cross(m->w, v3_sub(p, m->c)));
}

/* The centre's acceleration, plus the centripetal part w x (w x r) and the
 * torque-free turn dw/dt x r, dw/dt = -I^-1 (w x L) (Euler's equations). */
static vec3 motion_accel(const flight_motion *m, vec3 p)
{
    vec3 r = v3_sub(p, m->c);
    return v3_add(m->a, v3_add(v3_cross(m->w, v3_cross(m->w, r)), v3_cross(m->dw, r)));
}

/* The acceleration of body b's point p in free flight. */
static vec3 point_accel(const world *w, const body *b, vec3 p)
{
    if (b->state != STATE_DYNAMIC) return v3(0, 0, 0);
    if (v3_len2(b->w) == 0) return world_body_accel(w, b);
    flight_motion m = motion_of(w, b);
    return motion_accel(&m, p);
}

/* A polyhedron of at most this many vertices is tried vertex by vertex by the
 * search after a strike (vertex_plane_time). */
#define SIM_PLANE_VERTICES 32

/* The first time at which one of polyhedron m's vertices, closing on the plane
 * through p with unit normal n (towards m) at its speed and acceleration along n
 * now (m moving as mm, the other object as mo), would have come within 1 - f of
 * its height above the plane (as the Newton step of time_of_impact, for every
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
        double s = -v3_dot(v3_sub(motion_velocity(mm, x), motion_velocity(mo, x)), n);
        double c = -v3_dot(v3_sub(motion_accel(mm, x), motion_accel(mo, x)), n);
        double D = f * height;
        if (f > 0.99) D = d_max(D, height - 0.25 * SIM_SEPARATION);
        double disc = s * s + 2 * c * D;
        if (disc < 0 || !(s + sqrt(disc) > 0)) continue;
        best = d_min(best, 2 * D / (s + sqrt(disc)));
    }
    return best;
}

/* Body b (object i, flown) as it moves at that instant: a flight turns an object
 * at the angular momentum it starts with, and only its end is held to
 * max_angular, so the spin that moves it is the start's.  b itself, or scratch
 * (a copy of object i) given that spin when it differs. */
static const body *moving(const world *w, int i, const body *b, body *scratch)
{
    vec3 L = w->snap[i].L;
    if (b->state != STATE_DYNAMIC || spins_on_support(b) ||
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
    const body *s = &w->snap[i];
    if (s->state != STATE_DYNAMIC) return true;
    return w->bodies[i]->shape.p.kind == SHAPE_SPHERE || (s->L.x == 0 && s->L.y == 0 && s->L.z == 0);
}

/* First contact of pair p within [lo, hi] (absolute times), knowing that it
 * touches or penetrates at hi: the latest time found at which it is apart, less
 * than SIM_SEPARATION / 2 apart or within SIM_TOI_TIME of a time it is not.  Each
 * step tries the time the closest points would meet at their present closing
 * speed and acceleration (a Newton step, 98% of the way; once the model has held,
 * or from the start when it cannot overshoot, to a quarter of SIM_SEPARATION
 * short of contact), never earlier than the schedule's bound allows a contact.  After a
 * step that overshoots it halves the bracket instead (a quarter after repeated
 * overshoots), or, after a 99.8% step, first tries 90% of it. */
static double time_of_impact(world *w, pair *p, double lo, double hi)
{
    closest_cache cache = p->hit;
    /* each object where the search stands, where it tries, where it tries back,
     * and its spin for the model: copies of it, of which only states are copied */
    body *A[SCRATCH], *B[SCRATCH];
    search_copies(w, p->a, lo, A);
    search_copies(w, p->b, lo, B);
    body *a = A[0], *b = B[0], *ta = A[1], *tb = B[1], *ba = A[2], *bb = B[2];
    closest_result r = closest_query_apart(a, b, &cache);
    w->st.pair_checks++;
    w->hits[p - w->pairs].t = NAN;
    if (r.status != CLOSEST_SEPARATED) return lo; /* touching already */
    /* how far along the model's step to go: all the way when it cannot overshoot */
    double f = only_shifts(w, p->a) && only_shifts(w, p->b) ? 0.998 : 0.98;
    int overshot = 0;  /* steps in a row that found the pair touching */
    while (hi - lo > SIM_TOI_TIME && r.distance >= 0.5 * SIM_SEPARATION) {
        const body *ma = moving(w, p->a, a, A[3]), *mb = moving(w, p->b, b, B[3]);
        double safe = lo + sched_predict_bodies(w, ma, mb, r.distance);
        double s = contact_closing_speed(ma, mb, v3_scale(v3_add(r.pa, r.pb), 0.5), r.normal);
        double c = v3_dot(v3_sub(point_accel(w, mb, r.pb), point_accel(w, ma, r.pa)), r.normal);
        /* s t + c t^2 / 2 = D, its least positive root, stably */
        double D = f * r.distance;
        /* once trusted, aim at the middle of where the search may stop */
        if (f > 0.99) D = d_max(D, r.distance - 0.25 * SIM_SEPARATION);
        double disc = s * s + 2 * c * D, t = 0.5 * (lo + hi);
        bool newton = !overshot && disc >= 0 && s + sqrt(disc) > 0;
        if (newton) t = lo + 2 * D / (s + sqrt(disc));
        /* just set apart after their own collision, a small polyhedron on the
         * other's face: the corner that comes down next, not only the closest */
        if (!overshot && r.distance <= 2 * SIM_SEPARATION) {
            double tv = HUGE_VAL;
            flight_motion fa = motion_of(w, ma), fb = motion_of(w, mb);
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
        fly_at(w, p->a, t, ta);
        fly_at(w, p->b, t, tb);
        closest_result rt = closest_query_apart(ta, tb, &cache);
        w->st.pair_checks++;
        if (rt.status != CLOSEST_SEPARATED) {
            /* a trusted step that just overshot: the contact is just short of it */
            double back = newton && f > 0.99 ? lo + 0.9 * (t - lo) : -1;
            hi = t;
            overshot++;
            f = 0.98;
            if (back > lo) {
                fly_at(w, p->a, back, ba);
                fly_at(w, p->b, back, bb);
                closest_result rb = closest_query_apart(ba, bb, &cache);
                w->st.pair_checks++;
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
            if (newton) f = rt.distance <= 2 * (1 - f) * r.distance ? 0.998 : 0.98;
            overshot = 0;
            lo = t;
            swap_bodies(&a, &ta);
            swap_bodies(&b, &tb);
            r = rt;
        }
    }
    /* the answer, when it comes at lo, starts from here */
    w->hits[p - w->pairs] = (pair_hit){r, cache, lo};
    return lo;
}

/* How far the sphere of radius r about c is outside b's bounding box (negative
 * inside it). */
static double box_gap(vec3 c, double r, const body *b)
{
    vec3 p = q_unrotate(b->q, v3_sub(c, b->x));
    vec3 lo = b->shape.box_lo, hi = b->shape.box_hi;
    /* how far p is outside the box along each axis (0 within it) */
    vec3 out = v3(p.x < lo.x ? lo.x - p.x : p.x > hi.x ? p.x - hi.x : 0,
                  p.y < lo.y ? lo.y - p.y : p.y > hi.y ? p.y - hi.y : 0,
                  p.z < lo.z ? lo.z - p.z : p.z > hi.z ? p.z - hi.z : 0);
    return v3_len(out) - r;
}

/* A gap no more than the distance of a and b: between the spheres about their
 * centres of mass that hold them, or, when one is much the larger (a floor, a
 * wall, a table), between the other's sphere and its bounding box.  A turn of
 * either object leaves a sphere as it is; *turn_a or *turn_b (when not NULL) says
 * whether the gap is to a's box or to b's, which turns with it. */
static double bound_gap(const body *a, const body *b, bool *turn_a, bool *turn_b)
{
    vec3 ca = body_com(a), cb = body_com(b);
    double ra = a->shape.r_out, rb = b->shape.r_out;
    double gap = v3_len(v3_sub(ca, cb)) - ra - rb;
    double box = ra > 2 * rb ? box_gap(cb, rb, a) : rb > 2 * ra ? box_gap(ca, ra, b) : gap;
    bool to_box = box > gap;
    if (turn_a) *turn_a = to_box && ra > 2 * rb;
    if (turn_b) *turn_b = to_box && rb > 2 * ra;
    return to_box ? box : gap;
}

/* Moves the dynamic objects of the pair apart along n until they are sep apart
 * (they are gap apart now), the lighter one more, so that their centre of mass
 * stays; when both move, their spins take back the angular momentum the shift
 * adds (s n x (va - vb)), so that it stays too. */
static void separate(body *a, body *b, vec3 n, double gap, double sep)
{
    double need = sep - gap;
    if (need <= 0) return;
    double ia = a->state == STATE_DYNAMIC ? a->inv_mass : 0;
    double ib = b->state == STATE_DYNAMIC ? b->inv_mass : 0;
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

/* True when b's surface stays where it is however b turns: a sphere about its
 * centre. */
static bool turns_in_place(const body *b)
{
    return b->sp.kind == SHAPE_SPHERE && v3_len2(b->shape.mass.com) == 0;
}

/* The contact state of body m on support s (index si, normal n from s to m, pair
 * p): it rests when still and its support is, else it slides. */
static void stand(world *w, body *m, const body *s, int si, vec3 n, bool face, const pair *p)
{
    double speed = v3_len(m->v) + v3_len(m->w) * m->shape.r_out;
    if (speed < SIM_REST_SPEED && s->state != STATE_DYNAMIC) {
        come_to_rest(m, si);
    } else {
        m->slide = si;
        m->slide_n = n;
        m->slide_pair = p - w->pairs;
        double vn = v3_dot(m->v, n);
        if (vn > 0) m->v = v3_mad(m->v, n, -vn);
        m->slide_steady = face && s->state != STATE_DYNAMIC &&
                        (v3_len2(m->L) == 0 || spins_on_support(m) || turns_in_place(m));
        m->slide_foot = contact_footprint(m, n, 1e-6 * (m->shape.r_out + s->shape.r_out));
    }
}

/* The contact state of body mi on support si after a collision that left it barely
 * moving away from the support (normal n from the support to it, support_pt a point
 * of the support's surface, pair p, g the global acceleration's size).
 *
 * A frictionless body that rocks on a face, an edge or a curved side with
 * restitution below 1 ends, after ever shorter and ever smaller rocks, lying on a
 * face it can stand on, with what the contact forces cannot change: its velocity
 * along the support and its angular momentum about the normal.  When the energy of
 * the rocking (the motion along n, the rotation beyond that spin, and the height
 * above the settled pose) could not tip it by more than SIM_SETTLE_ANGLE, that end
 * is taken at once, instead of thousands of micro-collisions.  A body standing on
 * the face already but rocking harder stands as it is.
 *
 * Returns SETTLE_NONE (nothing changed), SETTLE_STANDS (standing where it is: it
 * still needs setting apart) or SETTLE_LAID (turned onto its face and placed). */
enum { SETTLE_NONE, SETTLE_STANDS, SETTLE_LAID };

static int settle(world *w, int mi, int si, vec3 n, bool face, vec3 support_pt, pair *p, double g,
                  double e)
{
    body *m = w->bodies[mi];
    const body *s = w->bodies[si];
    double scale = m->shape.r_out + s->shape.r_out;
    bool stable = contact_stable(m, n, 1e-6 * scale);
    quat q = m->q;
    double height = 0;
    if (!stable && !contact_settle_pose(m, n, SIM_SETTLE_ANGLE, &q, &height)) return SETTLE_NONE;
    vec3 c = body_com(m);
    double vn = v3_dot(m->v, n), ln = v3_dot(m->L, n);
    double spin = ln * ln / v3_dot(n, m3_mulv(body_inertia_world(m), n));
    double rock = 0.5 * (v3_dot(m->w, m->L) - spin) * m->inv_mass + 0.5 * vn * vn;
    double above = stable ? 0 : v3_dot(v3_sub(c, support_pt), n) - height;
    double up = -v3_dot(v3_norm(world_accel(w)), n);
    bool calm = e < 1 && rock + g * up * above <= g * up * m->shape.r_out * (1 - cos(SIM_SETTLE_ANGLE));
    if (!calm && !stable) return SETTLE_NONE;
    if (!stable) {
        body keep = *m;
        c = v3_mad(c, n, height - v3_dot(v3_sub(c, support_pt), n) + 2 * SIM_SEPARATION);
        m->q = q;
        m->rot_given = false;
        m->x = v3_sub(c, q_rotate(q, m->shape.mass.com));
        closest_result r = query_hit(w, p, w->bodies[p->a], w->bodies[p->b]);
        vec3 rn = p->a == mi ? r.normal : v3_neg(r.normal);
        bool ok = r.status == CLOSEST_SEPARATED && r.distance < 4 * SIM_SEPARATION &&
                  v3_dot(rn, n) > 1 - 1e-6 && contact_stable(m, n, 1e-6 * scale);
        for (long j = w->obj_first[mi]; ok && j < w->obj_first[mi + 1]; j++) {
            pair *o = &w->pairs[w->obj_pairs[j]];
            if (o == p) continue;
            /* the other object where it is now (only the pair is flown to the
             * collision: see internal_step), unless it is clearly out of reach */
            const body *other = flown(w, o->a == mi ? o->b : o->a, w->time, 0);
            if (bound_gap(m, other, NULL, NULL) > SIM_SEPARATION) continue;
            closest_result ro = o->a == mi ? query(w, o, m, other) : query(w, o, other, m);
            if (ro.status != CLOSEST_SEPARATED || ro.distance < SIM_SEPARATION) ok = false;
        }
        if (!ok) {
            *m = keep;
            return SETTLE_NONE;
        }
    }
    if (calm) {
        m->v = v3_mad(m->v, n, -v3_dot(m->v, n));
        /* spin about n only, with the angular momentum about n it had */
        mat3 I = body_inertia_world(m);
        double omega = ln / v3_dot(n, m3_mulv(I, n));
        m->L = m3_mulv(I, v3_scale(n, omega));
        m->rot_given = false;
        body_update_w(m);
    }
    stand(w, m, s, si, n, face, p);
    return stable ? SETTLE_STANDS : SETTLE_LAID;
}

/* True when body l, pressed from above along -n, is held by what it stands on: it
 * rests (it stays put: *s zero), or slides on a support whose normal *s is within
 * 45 degrees of n (it moves across *s only). */
static bool holds(const body *l, vec3 n, vec3 *s)
{
    *s = v3(0, 0, 0);
    if (l->state == STATE_RESTING) return true;
    if (l->state != STATE_DYNAMIC || l->slide < 0 || v3_dot(l->slide_n, n) < 0.7) return false;
    *s = l->slide_n;
    return true;
}

/* The normal n (from support s to the other object, as measured at their closest
 * points, f the feature of s) made exact when the contact is on a face of s: that
 * face's normal, so that an object sliding on the face keeps its height above it
 * (a measured normal a hair off would carry it slowly into the face or off it). */
static vec3 support_normal(const body *s, closest_feature f, vec3 n, bool *face)
{
    *face = false;
    if (f.kind != CLOSEST_FACE || !s->shape.hull) return n;
    vec3 fn = v3_norm(q_rotate(s->q, s->shape.hull->f[f.index].n));
    *face = v3_dot(fn, n) > 1 - 1e-6;
    return *face ? fn : n;
}

/* True when object i, pushed along toward (within 45 degrees), is pinned against
 * the still object it struck a moment ago that its pinned_by[slot] names (see
 * SIM_PINNED_TIME): then *s is that contact's normal, along which the blow
 * passes on to the still object (the object moves only across it). */
static bool pinned_by(world *w, int i, int slot, vec3 toward, vec3 *s)
{
    const body *x = w->bodies[i];
    int k = x->pinned_by[slot];
    if (x->state != STATE_DYNAMIC || k < 0 || k >= w->n || w->bodies[k]->state == STATE_DYNAMIC ||
        w->time - x->pinned_t[slot] > SIM_PINNED_TIME || v3_dot(x->pinned_n[slot], toward) > -0.7)
        return false;
    for (long j = w->obj_first[i]; j < w->obj_first[i + 1]; j++) {
        pair *o = &w->pairs[w->obj_pairs[j]];
        if (o->a != k && o->b != k) continue;
        closest_result r = query_apart(w, o, w->bodies[o->a], w->bodies[o->b]);
        if (r.status == CLOSEST_PENETRATING || r.distance > SIM_PINNED_GAP) return false;
        *s = x->pinned_n[slot];
        return true;
    }
    return false;
}

/* The same for either of the last two still objects i struck. */
static bool pinned(world *w, int i, vec3 toward, vec3 *s)
{
    return pinned_by(w, i, 0, toward, s) || pinned_by(w, i, 1, toward, s);
}

/* Body x struck still object k along n (towards x) at time t: kept in the slot
 * that holds k already, or else in the older one. */
static void strike(body *x, int k, vec3 n, double t)
{
    int slot = x->pinned_by[1] == k || (x->pinned_by[0] != k && x->pinned_t[1] < x->pinned_t[0]);
    x->pinned_by[slot] = k;
    x->pinned_n[slot] = n;
    x->pinned_t[slot] = t;
}

/* Answers the collision of pair p now: the impulse, the separation, the log; and
 * the thesis's contact state for an object that barely bounces off a support below
 * it. */
static void collide(world *w, pair *p)
{
    body *a = w->bodies[p->a], *b = w->bodies[p->b];
    /* where the time of impact stopped, when that is now: the same flights to the
     * same instant, so the same states */
    const pair_hit *h = &w->hits[p - w->pairs];
    closest_result r;
    if (h->t == w->time && p->toi_a == w->snap_id[p->a] && p->toi_b == w->snap_id[p->b]) {
        r = h->r;
        p->hit = h->cache;
    } else {
        r = query_hit(w, p, a, b);
    }
    if (r.status == CLOSEST_INVALID) return;
    double scale = a->shape.r_out + b->shape.r_out;
    double tol = 1e-6 * scale + d_max(0, -r.distance);
    vec3 pt = contact_point(a, b, &r, tol);
    /* the centre of the region moves apart, but a corner of it closes (a box
     * turning as it lands on an edge): that corner strikes, or nothing would stop
     * it */
    if (contact_closing_speed(a, b, pt, r.normal) <= 0) pt = contact_closing_corner(a, b, &r, tol, pt);
    double e = d_min(a->elasticity, b->elasticity);
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
    if (press > 0 && v3_dot(r.normal, up) > 0.7 && holds(b, r.normal, &s)) held = 2;
    if (press > 0 && v3_dot(r.normal, up) < -0.7 && holds(a, v3_neg(r.normal), &s)) held = 1;
    /* a sandwich: one of them pressed back against a still object it just struck */
    if (!held && pinned(w, p->a, r.normal, &s)) held = 1;
    if (!held && pinned(w, p->b, v3_neg(r.normal), &s)) held = 2;
    /* a resting object hit by a moving one takes part as a dynamic one */
    if (a->state == STATE_RESTING && b->state == STATE_DYNAMIC && held != 1) wake(w, p->a);
    if (b->state == STATE_RESTING && a->state == STATE_DYNAMIC && held != 2) wake(w, p->b);
    contact c = contact_respond(a, b, pt, r.normal, e, held, s);
    if (c.impulse > 0) {
        w->st.collisions++;
        log_event(w, a, b, c.point, c.normal, c.impulse, c.speed);
        /* what struck a still object, for a sandwich */
        if (a->state == STATE_DYNAMIC && b->state != STATE_DYNAMIC) strike(a, p->b, r.normal, w->time);
        if (b->state == STATE_DYNAMIC && a->state != STATE_DYNAMIC) strike(b, p->a, v3_neg(r.normal), w->time);
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
        body *m = k == 0 ? a : b, *s = k == 0 ? b : a;
        int si = k == 0 ? p->b : p->a;
        /* from the support to m */
        bool face;
        vec3 n = support_normal(s, k == 0 ? r.fb : r.fa, k == 0 ? r.normal : v3_neg(r.normal), &face);
        /* a support: a static or resting object, or one that slides itself */
        if (m->state != STATE_DYNAMIC || (s->state == STATE_DYNAMIC && s->slide < 0)) continue;
        double vn = v3_dot(m->v, n);
        if (v3_dot(n, up) < 0.7 || vn > SIM_REST_SPEED) continue;
        int how = settle(w, k == 0 ? p->a : p->b, si, n, face, k == 0 ? r.pb : r.pa, p, v3_len(g),
                         fmin(a->elasticity, b->elasticity));
        if (how == SETTLE_LAID) return; /* placed apart already */
        if (how == SETTLE_STANDS) settled = true;
    }
    if (apart || settled) separate(a, b, r.normal, r.distance, SIM_SEPARATION);
}


/* True when object mi slides on a still support si, not towards it, turning
 * about its normal only (or not at all, or a sphere about its centre).  The plane between them at their
 * closest points separates them; mi moves along it and its surface keeps its
 * height above it, so the pair cannot collide until mi's motion changes, which
 * makes the pair due again. */
static bool slides_clear(const world *w, int mi, int si)
{
    const body *m = w->bodies[mi];
    return m->state == STATE_DYNAMIC && m->slide == si && w->bodies[si]->state != STATE_DYNAMIC &&
           v3_dot(m->v, m->slide_n) >= -1e-12 && /* (rounding: 1e-7 m in a day) */
           (v3_len2(m->L) == 0 || spins_on_support(m) || turns_in_place(m));
}

/* True when object i slides on a face of a still box in a way that keeps it
 * there: as slides_clear allows, along the face, the normal one of the box's
 * axes, and what it stands on within the face's sides (the circle of its
 * footprint, body.slide_foot, which no turn about the normal changes; a ball's
 * is its centre, over the face the face is nearest).  Then the contact is as it
 * was, and needs no query: the rest of it is further from the face's plane. */
static bool on_the_face(const world *w, int i)
{
    const body *m = w->bodies[i], *s = w->bodies[m->slide];
    if (s->sp.kind != SHAPE_CUBE || !slides_clear(w, i, m->slide) ||
        v3_dot(m->v, m->slide_n) > 1e-12) /* rising off it */
        return false;
    vec3 n = q_unrotate(s->q, m->slide_n), p = q_unrotate(s->q, v3_sub(body_com(m), s->x));
    double r = m->slide_foot;
    vec3 lo = s->shape.box_lo, hi = s->shape.box_hi;
    if (fabs(n.x) > 1 - 1e-9)
        return p.y - r >= lo.y && p.y + r <= hi.y && p.z - r >= lo.z && p.z + r <= hi.z;
    if (fabs(n.y) > 1 - 1e-9)
        return p.x - r >= lo.x && p.x + r <= hi.x && p.z - r >= lo.z && p.z + r <= hi.z;
    if (fabs(n.z) > 1 - 1e-9)
        return p.x - r >= lo.x && p.x + r <= hi.x && p.y - r >= lo.y && p.y + r <= hi.y;
    return false;
}

/* Sliding objects leave their support when they lift off, pass its edge, stop
 * standing stably on it or are thrown off it. */
static void check_slides(world *w)
{
    for (int k = 0; k < w->nmovers; k++) {
        int i = w->movers[k];
        body *m = w->bodies[i];
        if (m->slide < 0) continue;
        if (m->state != STATE_DYNAMIC) {
            m->slide = -1;
            continue;
        }
        if (on_the_face(w, i)) continue;
        pair *p = &w->pairs[m->slide_pair];
        const body *s = w->bodies[m->slide];
        closest_result r = query_apart(w, p, w->bodies[p->a], w->bodies[p->b]);
        vec3 n = p->a == i ? r.normal : v3_neg(r.normal);
        double scale = m->shape.r_out + s->shape.r_out;
        /* turning about the normal only (or not at all), it stands as it stood */
        bool turned = v3_len2(m->L) != 0 && !spins_on_support(m);
        if (r.status != CLOSEST_SEPARATED || r.distance > 100 * SIM_SEPARATION ||
            v3_dot(n, m->slide_n) < 1 - 1e-6 || v3_dot(m->v, n) > SIM_REST_SPEED ||
            (turned && !contact_stable(m, n, 1e-6 * scale))) {
            m->slide = -1; /* the full force: its pairs' predictions change */
            sched_slide_ends(w, i, w->time);
        }
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
    /* written once now, so that the system maps its pages here and not in the
     * middle of a frame (see sim_prepare) */
    memset(d, 0, (size_t)n * sizeof *d);
    memset(dn, 0, (size_t)n * sizeof *dn);
    w->capdue = n;
    return 0;
}

/* Checks pair i at the end of the step, t_end, for the step that began at now:
 * returns when it is next due, a time after t_end when it is apart, or the time
 * of its first contact when it penetrates.  Keeps in *first and *when the
 * earliest contact so far. */
static double check_pair(world *w, long i, double now, double t_end, pair **first, double *when)
{
    pair *p = &w->pairs[i];
    p->checked = HUGE_VAL;
    p->along = false;
    w->parked[i] = false;
    if (!pair_moves(w, p)) return HUGE_VAL;
    if (w->set.collision_heap && (slides_clear(w, p->a, p->b) || slides_clear(w, p->b, p->a)))
        return HUGE_VAL;
    /* found touching in this step from the same flights (flight numbers are new
     * each step), it touches still, and its first contact is known: no query, and
     * no far bound (it is never later than that contact, within the step) */
    bool known = p->toi_a == w->snap_id[p->a] && p->toi_b == w->snap_id[p->b];
    /* far apart: the bounding spheres' gap bounds the distance from below, and is
     * enough for a prediction beyond the frame (part of the schedule: without it
     * every pair gets its closest-feature check, as in the thesis's Table 5.3).
     * It is measured where the objects' flights start: a bound on how far they go
     * from there holds through a collision later in the step that turns them
     * back, so that such a collision leaves the pair's time as it is. */
    p->far = false;
    if (w->set.collision_heap && !known) {
        if (sched_boxes_apart(w, p->a, p->b)) { /* parked until a box is made again */
            w->parked[i] = true;
            return HUGE_VAL;
        }
        const body *a = at_start(w, p->a), *b = at_start(w, p->b);
        bool turn_a, turn_b;
        double from = flights_start(w, p), gap = bound_gap(a, b, &turn_a, &turn_b);
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
    if (!known) r = query_apart(w, p, a, b);
    if (r.status != CLOSEST_PENETRATING) {
        if (!w->set.collision_heap) return HUGE_VAL; /* without the heap no time is kept */
        /* the bound from speeds, kept for a collision that changes an object, and
         * the one along the normal, later where they do not come on straight */
        double next = sched_predict_kept(w, a, b, r.distance, 0, 0, &w->bound[i]);
        double along = sched_predict_along(w, a, b, r.distance, v3_neg(r.normal), r.pa, r.pb);
        p->along = along > next;
        return t_end + (p->along ? along : next);
    }
    w->bound[i].dist = 0; /* touching: nothing left to keep (repredict) */
    /* the first contact is a function of the two flights alone, searched from
     * where the later of them starts, so that whenever the pair is found the
     * answer is the same (and is kept while both flights are) */
    if (!known) {
        double from = d_max(w->snap_t[p->a], w->snap_t[p->b]);
        p->toi = d_max(time_of_impact(w, p, from, t_end), now);
        p->toi_a = w->snap_id[p->a];
        p->toi_b = w->snap_id[p->b];
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
        for (long i = 0; i < w->npairs; i++) check_pair(w, i, now, t_end, &first, when);
        return first;
    }
    long aside = 0, i;
    double next;
    while ((i = sched_top(w, &next)) >= 0 && next <= t_end) {
        if (i >= w->npairs) { /* an object's box ends: made again from its flight */
            int k = (int)(i - w->npairs);
            bool moves = w->snap[k].state == STATE_DYNAMIC;
            sched_box_renew(w, k, at_start(w, k), moves ? w->snap_t[k] : next, next, t_end);
            continue;
        }
        w->st.heap_pops++;
        next = check_pair(w, i, now, t_end, &first, when);
        if (next <= t_end) {
            w->due[aside] = i;
            w->due_next[aside++] = next;
            next = HUGE_VAL;
        }
        sched_set(w, i, next);
    }
    for (long k = 0; k < aside; k++) sched_set(w, w->due[k], w->due_next[k]);
    return first;
}

/* Object i flies on from time t as it is now. */
static void renew_flight(world *w, int i, double t)
{
    body_copy_state(&w->snap[i], w->bodies[i]);
    w->snap_t[i] = t;
    w->snap_id[i] = w->flight_count++;
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
    pair *q = &w->pairs[k];
    int j = q->a == i ? q->b : q->a;
    const body *o = at_start(w, j);
    double slack = o->state == STATE_DYNAMIC ? v3_len(world_body_accel(w, o)) * (t - w->snap_t[j]) : 0;
    double left = -1;
    if (q->checked <= t) {
        left = sched_left(&w->bound[k], t - q->checked) - moved;
    } else if (unlimited(w, pre, q->checked - t) &&
               unlimited(w, o, q->checked - w->snap_t[j])) {
        double back = q->a == i ? sched_closing(w, pre, o, 0, slack, q->checked - t)
                                : sched_closing(w, o, pre, slack, 0, q->checked - t);
        left = w->bound[k].dist - back - moved;
    }
    if (left <= 0) {
        sched_set(w, k, t);
        return;
    }
    const body *me = w->bodies[i];
    double next = q->a == i ? sched_predict_kept(w, me, o, left, 0, slack, &w->bound[k])
                            : sched_predict_kept(w, o, me, left, slack, 0, &w->bound[k]);
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
 * them or makes them due. */
static void reschedule(world *w, int i, const body *a, const body *b, double t, double t_end)
{
    double acc = v3_len(world_body_accel(w, a)), moved = v3_len(v3_sub(a->x, b->x));
    bool turned = a->q.w != b->q.w || a->q.x != b->q.x || a->q.y != b->q.y || a->q.z != b->q.z;
    if (a->state != STATE_DYNAMIC ||
        (b->state == STATE_DYNAMIC && v3_len(world_body_accel(w, b)) > acc)) {
        sched_object_due(w, i, t);
        return;
    }
    /* its box holds, or is made again from here (its parked pairs wait on) */
    if (w->set.collision_heap && !sched_box_holds(w, i, b, t)) sched_box_renew(w, i, b, t, t, t_end);
    bool jolted = turned || moved > SIM_SEPARATION; /* beyond what a near bound keeps */
    double v = v3_len(b->v);
    bool spun = v3_len(b->L) > v3_len(a->L);
    for (long j = w->obj_first[i]; j < w->obj_first[i + 1]; j++) {
        long k = w->obj_pairs[j];
        const pair *q = &w->pairs[k];
        if (w->parked[k]) continue;
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
    int ends[2] = {p->a, p->b};
    for (int k = 0; k < 2; k++) {
        int i = ends[k];
        if (w->snap[i].state == STATE_DYNAMIC) fly_into(w, i, t, w->bodies[i]);
        body_copy_state(&w->pre[i], w->bodies[i]);
    }
    for (int i = 0; i < w->n; i++) w->touched[i] = false;
    w->time = t;
    collide(w, p);
    wake_unsupported(w, w->touched);
    for (int k = 0; k < 2; k++) {
        int i = ends[k];
        w->touched[i] = false;
        if (memcmp((char *)&w->pre[i] + offsetof(body, x), (char *)w->bodies[i] + offsetof(body, x),
                   sizeof(body) - offsetof(body, x)) == 0) {
            /* as it was: at the end of the step again */
            if (w->snap[i].state == STATE_DYNAMIC) fly_into(w, i, t_end, w->bodies[i]);
            continue;
        }
        /* what the collision moved it by at once (setting it apart, settling it) */
        w->bodies[i]->jumped += v3_len(v3_sub(body_com(w->bodies[i]), body_com(&w->pre[i])));
        renew_flight(w, i, t);
        /* its motion changed: its pairs are due again, unless their times hold */
        reschedule(w, i, &w->pre[i], w->bodies[i], t, t_end);
    }
    for (int i = 0; i < w->n; i++) {
        if (!w->touched[i]) continue;
        body *b = w->bodies[i];
        if (w->snap[i].state == STATE_DYNAMIC) {
            /* a moving object that slides no more: where it is at t, with that */
            int slide = b->slide;
            fly_into(w, i, t, b);
            b->slide = slide;
        }
        renew_flight(w, i, t);
    }
}

/* One internal step of h seconds (thesis 3.4.2, steps 3 to 5); its scratch is
 * in place (sim_prepare). */
static void internal_step(world *w, double h)
{
    double now = w->time, t_end = now + h;
    save_states(w, now);
    for (int n = 0;; n++) {
        fly_to_end(w, t_end);
        double when;
        pair *first = check_due(w, now, t_end, &when);
        if (!first || n >= SIM_MAX_COLLISIONS_PER_STEP) break;
        answer(w, first, when, t_end);
        now = when;
    }
    w->time = t_end;
    check_slides(w);
}

int sim_prepare(world *w)
{
    if (sim_update_pairs(w) != 0 || (w->sched_dirty && sched_build(w, w->time) != 0) ||
        frame_states(w, w->sched_dirty) != 0 || due_room(w, w->npairs) != 0)
        return -1;
    w->sched_dirty = false;
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
    if (sim_prepare(w) != 0) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double t0 = w->time, h = n > 0 ? w->set.time_step / (double)n : 0;
    wake_unsupported(w, NULL);
    for (long k = 0; k < n; k++) {
        internal_step(w, h);
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
