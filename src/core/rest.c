/* rest.c: the thesis's contact state (3.3.3): resting, sliding, waking and
 * settling, and what a stack passes on to its support.
 *
 * A collision that leaves an object barely bouncing on a support below it puts it
 * at rest, or sliding on it (settle); a resting object feels no gravity and wakes
 * when hit or when its support moves away; a sliding object feels the force less
 * the part its support takes, and leaves the support when it lifts off, passes an
 * edge or stops standing on it.  A stack passes blows from above down to its
 * support (holds), and an object pressed back against a still object it just
 * struck passes them on to it (pinned).
 */
#include "rest.h"

#include <assert.h>

#include <math.h>

#include "contact.h"
#include "flight.h"
#include "schedule.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* A resting object moves again (its pairs are then made due by the caller, or by
 * the shell after a command). */
void rest_wake(world *w, int i)
{
    body *b = w->bodies[i];
    if (b->state == STATE_RESTING) {
        b->state = STATE_DYNAMIC;
        b->support = -1;
    }
}

void rest_wake_all(world *w)
{
    for (int i = 0; i < w->n; i++) rest_wake(w, i);
}

void rest_wake_on(world *w, int i)
{
    for (int k = 0; k < w->n; k++) {
        body *b = w->bodies[k];
        if (b->state == STATE_RESTING && b->support == i) rest_wake(w, k);
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
void rest_wake_unsupported(world *w, bool *touched)
{
    bool changed = true;
    while (changed) {
        changed = false;
        for (int k = 0; k < w->step.nmovers; k++) { /* (a static object neither slides nor rests) */
            int i = w->step.movers[k];
            body *b = w->bodies[i];
            const body *s = b->slide >= 0 ? w->bodies[b->slide] : NULL;
            if (s && s->state == STATE_DYNAMIC && s->slide < 0) {
                b->slide = -1; /* the full force: its pairs' predictions change */
                sched_slide_ends(w, i, w->time);
                if (touched) touched[i] = true;
            }
            if (b->state != STATE_RESTING) continue;
            if (b->support < 0 || w->bodies[b->support]->state == STATE_DYNAMIC) {
                rest_wake(w, i);
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
    if (!w->sched.obj_first) return;
    for (long j = w->sched.obj_first[i]; j < w->sched.obj_first[i + 1]; j++) {
        long k = w->sched.obj_pairs[j];
        if (w->pairs.p[k].along && w->pairs.p[k].next > w->time) sched_set(w, k, w->time);
    }
}

void rest_frame_end(world *w)
{
    bool changed = true;
    while (changed) { /* a stack comes to rest from the bottom up */
        changed = false;
        for (int k = 0; k < w->step.nmovers; k++) {
            int i = w->step.movers[k];
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
        m->slide_pair = p - w->pairs.p;
        double vn = v3_dot(m->v, n);
        if (vn > 0) m->v = v3_mad(m->v, n, -vn);
        m->slide_steady = face && s->state != STATE_DYNAMIC &&
                        (v3_len2(m->L) == 0 || flight_spins_on_support(m) || turns_in_place(m));
        m->slide_foot = contact_footprint(m, n, SIM_CONTACT_TOL * (m->shape.r_out + s->shape.r_out));
    }
}

/* A frictionless body that rocks on a face, an edge or a curved side with
 * restitution below 1 ends, after ever shorter and ever smaller rocks, lying on a
 * face it can stand on, with what the contact forces cannot change: its velocity
 * along the support and its angular momentum about the normal.  When the energy of
 * the rocking (the motion along n, the rotation beyond that spin, and the height
 * above the settled pose) could not tip it by more than SIM_SETTLE_ANGLE, that end
 * is taken at once, instead of thousands of micro-collisions.  A body standing on
 * the face already but rocking harder stands as it is. */
int rest_settle(world *w, int mi, int si, vec3 n, bool face, vec3 support_pt, pair *p, double g,
                double e)
{
    assert(mi != si && (p->a == mi || p->b == mi) && (p->a == si || p->b == si));
    body *m = w->bodies[mi];
    const body *s = w->bodies[si];
    double scale = m->shape.r_out + s->shape.r_out;
    bool stable = contact_stable(m, n, SIM_CONTACT_TOL * scale);
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
        closest_result r = pair_query_hit(w, p, w->bodies[p->a], w->bodies[p->b]);
        vec3 rn = p->a == mi ? r.normal : v3_neg(r.normal);
        bool ok = r.status == CLOSEST_SEPARATED && r.distance < 4 * SIM_SEPARATION &&
                  v3_dot(rn, n) > 1 - SIM_PARALLEL && contact_stable(m, n, SIM_CONTACT_TOL * scale);
        for (long j = w->sched.obj_first[mi]; ok && j < w->sched.obj_first[mi + 1]; j++) {
            pair *o = &w->pairs.p[w->sched.obj_pairs[j]];
            if (o == p) continue;
            /* the other object where it is now (only the pair is flown to the
             * collision: see internal_step), unless it is clearly out of reach */
            const body *other = step_flown(w, o->a == mi ? o->b : o->a, w->time, 0);
            if (sched_bound_gap(m, other, NULL, NULL) > SIM_SEPARATION) continue;
            closest_result ro = o->a == mi ? pair_query(w, o, m, other) : pair_query(w, o, other, m);
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
bool rest_holds(const body *l, vec3 n, vec3 *s)
{
    *s = v3(0, 0, 0);
    if (l->state == STATE_RESTING) return true;
    if (l->state != STATE_DYNAMIC || l->slide < 0 || v3_dot(l->slide_n, n) < SIM_SUPPORT_COS) return false;
    *s = l->slide_n;
    return true;
}

/* The normal n (from support s to the other object, as measured at their closest
 * points, f the feature of s) made exact when the contact is on a face of s: that
 * face's normal, so that an object sliding on the face keeps its height above it
 * (a measured normal a hair off would carry it slowly into the face or off it). */
vec3 rest_support_normal(const body *s, closest_feature f, vec3 n, bool *face)
{
    *face = false;
    if (f.kind != CLOSEST_FACE || !s->shape.hull) return n;
    vec3 fn = v3_norm(q_rotate(s->q, s->shape.hull->f[f.index].n));
    *face = v3_dot(fn, n) > 1 - SIM_PARALLEL;
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
        w->time - x->pinned_t[slot] > SIM_PINNED_TIME || v3_dot(x->pinned_n[slot], toward) > -SIM_SUPPORT_COS)
        return false;
    for (long j = w->sched.obj_first[i]; j < w->sched.obj_first[i + 1]; j++) {
        pair *o = &w->pairs.p[w->sched.obj_pairs[j]];
        if (o->a != k && o->b != k) continue;
        closest_result r = pair_query_apart(w, o, w->bodies[o->a], w->bodies[o->b]);
        if (r.status == CLOSEST_PENETRATING || r.distance > SIM_PINNED_GAP) return false;
        *s = x->pinned_n[slot];
        return true;
    }
    return false;
}

/* The same for either of the last two still objects i struck. */
bool rest_pinned(world *w, int i, vec3 toward, vec3 *s)
{
    return pinned_by(w, i, 0, toward, s) || pinned_by(w, i, 1, toward, s);
}

/* Body x struck still object k along n (towards x) at time t: kept in the slot
 * that holds k already, or else in the older one. */
void rest_strike(body *x, int k, vec3 n, double t)
{
    int slot = x->pinned_by[1] == k || (x->pinned_by[0] != k && x->pinned_t[1] < x->pinned_t[0]);
    x->pinned_by[slot] = k;
    x->pinned_n[slot] = n;
    x->pinned_t[slot] = t;
}

/* True when object mi slides on a still support si, not towards it, turning
 * about its normal only (or not at all, or a sphere about its centre).  The
 * plane between them at their closest points separates them; mi moves along it and its surface keeps its
 * height above it, so the pair cannot collide until mi's motion changes, which
 * makes the pair due again. */
bool rest_slides_clear(const world *w, int mi, int si)
{
    const body *m = w->bodies[mi];
    return m->state == STATE_DYNAMIC && m->slide == si && w->bodies[si]->state != STATE_DYNAMIC &&
           v3_dot(m->v, m->slide_n) >= -SIM_SPEED_ROUND &&
           (v3_len2(m->L) == 0 || flight_spins_on_support(m) || turns_in_place(m));
}

/* True when object i slides on a face of a still box in a way that keeps it
 * there: as rest_slides_clear allows, along the face, the normal one of the box's
 * axes, and what it stands on within the face's sides (the circle of its
 * footprint, body.slide_foot, which no turn about the normal changes; a ball's
 * is its centre, over the face the face is nearest).  Then the contact is as it
 * was, and needs no query: the rest of it is further from the face's plane. */
static bool on_the_face(const world *w, int i)
{
    const body *m = w->bodies[i], *s = w->bodies[m->slide];
    if (s->sp.kind != SHAPE_CUBE || !rest_slides_clear(w, i, m->slide) ||
        v3_dot(m->v, m->slide_n) > SIM_SPEED_ROUND) /* rising off it */
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
void rest_check_slides(world *w)
{
    for (int k = 0; k < w->step.nmovers; k++) {
        int i = w->step.movers[k];
        body *m = w->bodies[i];
        if (m->slide < 0) continue;
        if (m->state != STATE_DYNAMIC) {
            m->slide = -1;
            continue;
        }
        if (on_the_face(w, i)) continue;
        pair *p = &w->pairs.p[m->slide_pair];
        const body *s = w->bodies[m->slide];
        closest_result r = pair_query_apart(w, p, w->bodies[p->a], w->bodies[p->b]);
        vec3 n = p->a == i ? r.normal : v3_neg(r.normal);
        double scale = m->shape.r_out + s->shape.r_out;
        /* turning about the normal only (or not at all), it stands as it stood */
        bool turned = v3_len2(m->L) != 0 && !flight_spins_on_support(m);
        if (r.status != CLOSEST_SEPARATED || r.distance > 100 * SIM_SEPARATION ||
            v3_dot(n, m->slide_n) < 1 - SIM_PARALLEL || v3_dot(m->v, n) > SIM_REST_SPEED ||
            (turned && !contact_stable(m, n, SIM_CONTACT_TOL * scale))) {
            m->slide = -1; /* the full force: its pairs' predictions change */
            sched_slide_ends(w, i, w->time);
        }
    }
}
