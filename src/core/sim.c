/* sim.c: frames, internal steps and their events (thesis 3.2.3, 3.3, 3.4.2;
 * design.md, "Dynamics").
 *
 * An internal step starts every moving object's flight afresh from where it is
 * (flight.h) and then answers the step's events in the order they happen, each at
 * its own instant:
 *  - a pair's first contact (toi.h: conservative advancement, so nothing is
 *    passed): the impulses of the colliding points and of every lasting contact of
 *    the objects pressed together with them, answered together (impulse.h), then
 *    the modes of all of them (rest.h);
 *  - a slide whose object's centre of mass leaves the face (rest.h): the object
 *    tips or pivots over the edge, or leaves it, as a cluster decides;
 *  - the end of a cluster's step (cluster.h).
 * Each event changes the flights of the objects it touches from its instant on;
 * every other object flies on as it did, and what was found of its pairs holds.
 * Events at the same instant are answered in a fixed order (pairs before objects,
 * each by index), and which pairs are searched (the heap's due ones, or all of
 * them) changes no answer: a search depends on its pair's flights alone.  The
 * frame ends with the thesis's rule of rest (rest_frame_end).  Each collision
 * answered goes into the frame's events.
 */
#include "sim.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "broad.h"
#include "cluster.h"
#include "contact.h"
#include "impulse.h"
#include "pairs.h"
#include "rest.h"
#include "schedule.h"
#include "step.h"
#include "toi.h"
#include "tolerance.h"

/* ------------------------------------------------------------ objects and pairs */

/* The contact distance of objects a and b. */
static double touch_of(const body *a, const body *b) { return toi_touch(a, b); }

/* True when pair p needs searching: one of its objects moves, and they are not
 * pressed together. */
static bool searched(const world *w, const pair *p)
{
    return !p->touching && (step_moves(w, p->a) || step_moves(w, p->b));
}

/* Pair k's cheap bound from time t, as its objects fly now (t itself for a held
 * object's: no bound foresees the hand). */
static double bound_from(world *w, long k, double t)
{
    pair *p = &w->pairs.p[k];
    if (!searched(w, p)) return HUGE_VAL;
    const body *a = step_flown(w, p->a, t, 1), *b = step_flown(w, p->b, t, 1);
    sched_move ma = step_move(w, p->a, a), mb = step_move(w, p->b, b);
    double dt = sched_sphere_time(a, &ma, b, &mb);
    return dt == HUGE_VAL ? dt : t + dt;
}

/* Object i's flight changed at time t: what was found of its pairs holds no
 * more; each gets its cheap bound. */
static void reschedule(world *w, int i, double t)
{
    FOR_PAIRS_OF(w, i, link, p) {
        p->toi_fa = p->toi_fb = -1;
        sched_set(w, sched_pair_id(&w->sched, link->slot), bound_from(w, link->slot, t));
    }
}

/* The pairs the broad phase made since the last call get their cheap bounds from
 * time t. */
static void schedule_fresh(world *w, double t)
{
    if (w->pairs.nfresh == 0) return;
    long n;
    const long *fresh = pairs_take_fresh(w, &n);
    for (long k = 0; k < n; k++)
        if (w->pairs.p[fresh[k]].a >= 0)
            sched_set(w, sched_pair_id(&w->sched, fresh[k]), bound_from(w, fresh[k], t));
}

/* Object i's own next event. */
static void set_event(world *w, int i, double t)
{
    w->step.event[i] = t;
    sched_set(w, sched_obj_id(i), t);
}

/* The broad phase holds moving object i, flying from time t, until the end of the
 * step (broad.h); same: on the motion of its last flight. */
static void hold_box(world *w, int i, double t, bool same)
{
    if (same && w->step.t_end <= w->broad.until[i]) return; /* (broad_hold's first test) */
    if (step_moves(w, i) && broad_hold(w, i, t, w->step.t_end, same) != 0) w->out_of_memory = true;
}

/* Object i flies on from time t as it is now (a slide: until it leaves its face). */
static void restart(world *w, int i, double t)
{
    step_start(w, i, t);
    const body *b = w->bodies[i];
    double ev = HUGE_VAL;
    if (step_moves(w, i) && b->mode == MODE_SLIDE) ev = rest_slide_exit(w, i, t);
    set_event(w, i, ev);
    hold_box(w, i, t, false);
    reschedule(w, i, t); /* (the pairs its box just made among them) */
    w->pairs.nfresh = 0;
}

/* The clusters among the n objects of list (their states at time t) start a step:
 * the kicks, then their flights until the step's end. */
static void begin_clusters(world *w, const int *list, int n, double t, double t_end)
{
    int *k_list = malloc((size_t)w->n * sizeof *k_list);
    if (!k_list) return;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        const body *b = w->bodies[i];
        /* (a cluster begun already has its step's end as its objects' event) */
        if (b->state != STATE_DYNAMIC || b->mode != MODE_GENERAL || w->step.event[i] != HUGE_VAL)
            continue;
        int m = rest_cluster(w, i, k_list);
        double h = cluster_kick(w, k_list, m, t, t_end);
        for (int j = 0; j < m; j++) {
            restart(w, k_list[j], t);
            set_event(w, k_list[j], t + h);
        }
    }
    free(k_list);
}

/* The speed limits, where a collision set a speed: |v| <= max_linear, |w| <=
 * max_angular (L scaled down). */
static bool limit_speeds(world *w, body *b)
{
    double vl = v3_len(b->v), wl = v3_len(b->w);
    bool cut = false;
    if (vl > w->set.max_linear) {
        b->v = v3_scale(b->v, w->set.max_linear / vl);
        cut = true;
    }
    if (wl > w->set.max_angular) {
        b->L = v3_scale(b->L, w->set.max_angular / wl);
        body_update_w(b);
        cut = true;
    }
    if (cut) world_cut(w, b, vl, wl, false);
    return cut;
}

/* The speed limits on the n objects of list; true when one was cut. */
static bool limit_all(world *w, const int *list, int n)
{
    bool cut = false;
    for (int j = 0; j < n; j++) cut = limit_speeds(w, w->bodies[list[j]]) || cut;
    return cut;
}

/* ------------------------------------------------------------ answering */

/* The rows of pair p's contact points (its objects in the states of w->bodies, r
 * their closest result, e the restitution of every row) appended to rows; the
 * count appended. */
static int rows_of(world *w, const pair *p, const closest_result *r, double e, impulse_row *rows,
                   int room)
{
    const body *A = w->bodies[p->a], *B = w->bodies[p->b];
    cpoint cp[16];
    double scale = A->shape.r_out + B->shape.r_out;
    int nc = contact_cpoints(A, B, r, SIM_CONTACT_TOL * scale, cp, 16), n = 0;
    for (int c = 0; c < nc && n < room; c++) {
        impulse_row *row = &rows[n++];
        row->p = cp[c].p == 0 ? p->a : p->b;
        row->q = cp[c].p == 0 ? p->b : p->a;
        row->e = e;
        cpoint_eval(&cp[c], w->bodies[row->p], w->bodies[row->q], &row->n, &row->at);
    }
    return n;
}

/* Held body i stops where it is at time t, until the hand sets its motion again
 * (hold.h): it met what cannot give way. */
static void hold_stop(world *w, int i, double t)
{
    body *b = w->bodies[i];
    step_sync(w, i, t);
    b->hold_v = b->v = v3(0, 0, 0);
    body_set_angular_vel(b, v3(0, 0, 0));
    restart(w, i, t);
}

/* Answers pair k's contact at time t: the impulses of its points and of every
 * lasting contact of the objects pressed together with them, answered together;
 * then the modes and flights of all of them.  A held object (hold.h) is not
 * moved by them: it pushes with its velocity as an infinite mass would, and stops
 * against a static or held object, or one that cannot give way. */
static void answer_contact(world *w, long k, double t, double t_end)
{
    pair *p = &w->pairs.p[k];
    int seeds[2], ns = 0, *list = w->step.list;
    bool ha = w->bodies[p->a]->held, hb = w->bodies[p->b]->held, hand = ha || hb;
    if (!body_is_static(w->bodies[p->a]) && !ha) seeds[ns++] = p->a;
    if (!body_is_static(w->bodies[p->b]) && !hb) seeds[ns++] = p->b;
    if (hand && ns == 0) {
        w->time = t;
        if (ha) hold_stop(w, p->a, t);
        if (hb) hold_stop(w, p->b, t);
        return;
    }
    int n = rest_component(w, seeds, ns, list);
    int *mine = malloc((size_t)(n > 0 ? n : 1) * sizeof *mine);
    if (!mine) return;
    memcpy(mine, list, (size_t)n * sizeof *mine);
    for (int j = 0; j < n; j++) step_sync(w, mine[j], t);
    int held = ha ? p->a : hb ? p->b : -1;
    if (hand) step_sync(w, held, t);
    w->time = t;
    /* the rows: the contact's own, then the lasting contacts' */
    impulse_row rows[IMPULSE_MAX_ROWS];
    const body *A = w->bodies[p->a], *B = w->bodies[p->b];
    double e = d_min(A->elasticity, B->elasticity);
    int own = rows_of(w, p, &w->pairs.hits[k].r, e, rows, IMPULSE_MAX_ROWS), nr = own;
    bool *mobile = w->step.mark;
    for (int j = 0; j < n; j++) mobile[mine[j]] = true;
    for (int j = 0; j < n; j++) {
        int i = mine[j];
        FOR_PAIRS_OF(w, i, link, o) {
            int other = link->other;
            if (!o->touching || o == p || (mobile[other] && other < i)) continue;
            closest_result r = pair_query(w, o, w->bodies[o->a], w->bodies[o->b]);
            nr += rows_of(w, o, &r, 0, rows + nr, IMPULSE_MAX_ROWS - nr);
        }
    }
    double u[IMPULSE_MAX_ROWS], lambda[IMPULSE_MAX_ROWS], closing = 0;
    double scale = 1 + A->shape.r_out + B->shape.r_out;
    for (int r = 0; r < nr; r++) {
        u[r] = impulse_speed(&rows[r], w->step.now);
        if (r < own) closing = d_max(closing, -u[r]);
        /* a rebound too slow to see is no rebound: they stay in contact */
        if (rows[r].e < 1 && rows[r].e * -u[r] < SIM_BOUNCE_SPEED) rows[r].e = 0;
        /* but nothing stays on a held object: it parts at that speed */
        if (hand && r < own && rows[r].e == 0) u[r] -= SIM_BOUNCE_SPEED;
    }
    bool solved = impulse_solve(rows, nr, w->step.now, mobile, u, lambda, w->step.lcp) == 0;
    if (!solved && own < nr) /* too many: the contact's own points alone */
        solved = impulse_solve(rows, own, w->step.now, mobile, u, lambda, w->step.lcp) == 0;
    if (solved && limit_all(w, mine, n)) {
        /* the limits must not turn a point back into its contact: those that would
         * approach again stop there */
        double u2[IMPULSE_MAX_ROWS], l2[IMPULSE_MAX_ROWS];
        for (int r = 0; r < nr; r++) {
            rows[r].e = 0;
            u2[r] = d_min(0, impulse_speed(&rows[r], w->step.now));
        }
        if (impulse_solve(rows, nr, w->step.now, mobile, u2, l2, w->step.lcp) == 0)
            for (int r = 0; r < nr; r++) lambda[r] += l2[r];
    }
    for (int j = 0; j < n; j++) mobile[mine[j]] = false;
    if (!solved && hand) hold_stop(w, held, t); /* what it pushes cannot give way */
    else if (!solved) w->st.restarts++;
    /* the event: the contact's own impulses */
    double j_sum = 0;
    vec3 at = v3(0, 0, 0);
    for (int r = 0; r < own && solved; r++) {
        j_sum += lambda[r];
        at = v3_mad(at, rows[r].at, lambda[r]);
    }
    if (j_sum > 0) {
        w->st.collisions++;
        vec3 nab = w->pairs.hits[k].r.normal; /* from b to a */
        world_event(w, &(sim_event){t, p->a, p->b, v3_scale(at, 1 / j_sum), nab, j_sum, closing});
    }
    /* they stay in contact where a point of theirs no longer moves apart (never
     * with a held object: each of its contacts is a collision) */
    p->hit = w->pairs.hits[k].cache;
    for (int r = 0; r < own && !hand; r++) {
        /* (a lossy contact that opens too slowly to see a rebound: none) */
        double open = rows[r].e < 1 || e < 1 ? SIM_BOUNCE_SPEED : 1e3 * SIM_SPEED_ROUND * scale;
        if (impulse_speed(&rows[r], w->step.now) <= open) p->touching = true;
    }
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) restart(w, mine[j], t);
    if (hand) restart(w, held, t);
    begin_clusters(w, mine, n, t, t_end);
    free(mine);
}

/* Answers object i's own event at time t: a slide leaving its face, or the end
 * of its cluster's step. */
static void answer_object(world *w, int i, double t, double t_end)
{
    int *list = w->step.list;
    body *b = w->bodies[i];
    w->time = t;
    if (b->mode == MODE_SLIDE) {
        /* over the edge: the cluster's steps decide what it does there */
        step_sync(w, i, t);
        b->mode = MODE_GENERAL;
        b->slide_on = -1;
        restart(w, i, t);
        begin_clusters(w, &i, 1, t, t_end);
        return;
    }
    int n = rest_cluster(w, i, list);
    int *mine = malloc((size_t)(n > 0 ? n : 1) * sizeof *mine);
    if (!mine) return;
    memcpy(mine, list, (size_t)n * sizeof *mine);
    for (int j = 0; j < n; j++) step_sync(w, mine[j], t);
    cluster_settle(w, mine, n);
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) restart(w, mine[j], t);
    if (t < t_end) begin_clusters(w, mine, n, t, t_end);
    free(mine);
}

/* ------------------------------------------------------------ finding the next */

typedef struct {
    double t;
    int kind;  /* 0 a pair's contact, 1 an object's event */
    long index;  /* the pair's slot, or the object */
    int a, b;    /* the pair's objects (an object's: itself twice) */
} next_event;

/* True when x comes before y: by time, pairs before objects, then by the objects'
 * indices (not the pairs' slots, which depend on when they were made). */
static bool earlier(const next_event *x, const next_event *y)
{
    if (x->t != y->t) return x->t < y->t;
    if (x->kind != y->kind) return x->kind < y->kind;
    if (x->a != y->a) return x->a < y->a;
    return x->b < y->b;
}

/* Pair k's contact, or object i's event, at time t. */
static next_event pair_event(const world *w, double t, long k)
{
    return (next_event){t, 0, k, w->pairs.p[k].a, w->pairs.p[k].b};
}

static next_event object_event(double t, int i) { return (next_event){t, 1, i, i, i}; }

/* Pair k's first contact in [t_step, t_end], searched from the later of its
 * flights' starts and the step's (or known from the same flights): its time, or
 * +inf with *again the time it must be searched again. */
static double search(world *w, long k, double t_step, double t_end, double *again)
{
    pair *p = &w->pairs.p[k];
    const flight *fa = &w->step.fl[p->a], *fb = &w->step.fl[p->b];
    *again = HUGE_VAL;
    if (p->toi_fa == fa->id && p->toi_fb == fb->id) {
        if (p->toi <= t_end) return p->toi;
        *again = p->next;
        return HUGE_VAL;
    }
    double from = t_step;
    if (step_moves(w, p->a)) from = d_max(from, fa->t0);
    if (step_moves(w, p->b)) from = d_max(from, fb->t0);
    /* no further than either flight lasts: an object's own event ends it */
    double to = d_min(t_end, d_min(w->step.event[p->a], w->step.event[p->b]));
    toi_output o = toi_find(w, &(toi_input){p->a, p->b, p->hit, from, d_max(from, to)});
    w->st.pair_checks += o.queries;
    p->toi_fa = fa->id;
    p->toi_fb = fb->id;
    if (o.state == TOI_HIT) {
        if (!p->near) w->st.late_pairs++;
#ifdef VROC_VALIDATE
        assert(p->near); /* the broad phase is never late */
#endif
        p->toi = o.t;
        w->pairs.hits[k] = (pair_hit){o.r, o.cache};
        return o.t;
    }
    p->toi = HUGE_VAL;
    *again = o.t;
    return HUGE_VAL;
}

/* The step's next event at or before t_end, or kind -1.  With the heap, only the
 * pairs due by then are searched, and only until what is found is earlier than
 * anything left; without it, every pair. */
static next_event find_next(world *w, double t_step, double t_end)
{
    next_event best = {HUGE_VAL, -1, -1, -1, -1};
    if (!w->set.collision_heap) {
        for (long k = 0; k < w->pairs.n; k++) {
            if (w->pairs.p[k].a < 0 || !searched(w, &w->pairs.p[k])) continue;
            double again, t = search(w, k, t_step, t_end, &again);
            next_event e = pair_event(w, t, k);
            if (t <= t_end && earlier(&e, &best)) best = e;
        }
        for (int i = 0; i < w->n; i++) {
            next_event e = object_event(w->step.event[i], i);
            if (e.t <= t_end && earlier(&e, &best)) best = e;
        }
        return best;
    }
    if (w->step.capdue < w->sched.nheap && step_reserve_due(w, w->sched.nheap) != 0) {
        w->out_of_memory = true;
        return best;
    }
    long aside = 0, i, nobj = w->sched.nobj;
    double next;
    while ((i = sched_top(w, &next)) >= 0 && next <= t_end && next <= best.t) {
        next_event e = object_event(next, (int)i);
        if (i >= nobj) {
            w->st.heap_pops++;
            double again;
            e = pair_event(w, search(w, i - nobj, t_step, t_end, &again), i - nobj);
            if (e.t > t_end) {
                sched_set(w, i, again);
                continue;
            }
        }
        if (earlier(&e, &best)) best = e;
        /* aside until the others are done (it stays due at its time) */
        w->step.due[aside] = i;
        w->step.due_next[aside++] = e.t;
        sched_set(w, i, HUGE_VAL);
    }
    for (long k = 0; k < aside; k++) sched_set(w, w->step.due[k], w->step.due_next[k]);
    return best;
}

/* ------------------------------------------------------------ steps and frames */

/* One internal step, from now to t_end (thesis 3.4.2, steps 3 to 5). */
static void internal_step(world *w, double t_end, bool fresh)
{
    double t = w->time;
    w->step.t_end = t_end;
    /* every moving object's flight starts afresh where it is (a free flight goes
     * on within a frame: the frame's start, where a save may be, is where it
     * starts), and its box holds it to the step's end */
    if (!fresh) /* what was searched for went no further than the last step */
        for (long k = 0; k < w->pairs.n; k++) w->pairs.p[k].toi_fa = w->pairs.p[k].toi_fb = -1;
    for (int i = 0; i < w->n; i++) {
        if (!step_moves(w, i)) continue;
        const body *b = w->bodies[i];
        if (fresh || b->mode != MODE_FREE || b->held || w->step.fl[i].kind != FLIGHT_FREE)
            step_start(w, i, t);
        double ev = b->mode == MODE_SLIDE ? rest_slide_exit(w, i, t) : HUGE_VAL;
        set_event(w, i, ev);
        if (w->step.t_end > w->broad.until[i]) hold_box(w, i, t, true); /* (its first test, here
                                                                        * without a call) */
    }
    schedule_fresh(w, t);
    /* clusters start their steps (their kicks change their flights) */
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (step_moves(w, i) && b->mode == MODE_GENERAL && w->step.event[i] == HUGE_VAL)
            begin_clusters(w, &i, 1, t, t_end);
    }
    for (int n = 0;; n++) {
        next_event e = find_next(w, t, t_end);
        if (e.kind < 0) break;
        if (n >= SIM_MAX_EVENTS_PER_STEP) {
            w->st.restarts++;
            break;
        }
        if (e.kind == 0) answer_contact(w, e.index, e.t, t_end);
        else answer_object(w, (int)e.index, e.t, t_end);
    }
    for (int i = 0; i < w->n; i++) step_sync(w, i, t_end);
    w->time = t_end;
#ifdef VROC_VALIDATE
    assert(w->sched.heap == NULL || sched_check(w) == 0);
    char why[256]; /* (what broke, for a debugger; test_broad reports it) */
    assert(broad_check(w, why, sizeof why) == 0);
    for (int i = 0; i < w->n; i++) {
        const shape *s = &w->bodies[i]->shape;
        char err[256];
        if (s->hull) assert(poly_check(s->hull, 1e-9 * (1 + s->r_out), err, sizeof err) == 0);
    }
#endif
}

/* Finds what each object the commands moved touches (within the contact distance),
 * and the modes of the objects they woke. */
static void find_contacts(world *w)
{
    bool any = false;
    for (int i = 0; i < w->n; i++) any = any || w->bodies[i]->moved || w->bodies[i]->woken;
    if (!any) return;
    for (long k = 0; k < w->pairs.n; k++) {
        pair *p = &w->pairs.p[k];
        if (p->a < 0 || !p->near) continue;
        body *a = w->bodies[p->a], *b = w->bodies[p->b];
        if ((!a->moved && !b->moved) || a->held || b->held) continue; /* (hold.h) */
        closest_result r = pair_query(w, p, a, b);
        if (r.status == CLOSEST_INVALID) continue;
        double touch = touch_of(a, b);
        if (r.distance <= touch && r.distance >= -touch) {
            p->touching = true;
            p->hit = p->cache;
            a->woken = b->woken = true;
        }
    }
    int *list = w->step.list, n = 0;
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (b->woken && !body_is_static(b)) {
            if (b->state == STATE_RESTING) rest_wake(w, i);
            list[n++] = i;
        }
        b->moved = b->woken = false;
    }
    int *mine = malloc((size_t)(n > 0 ? n : 1) * sizeof *mine);
    if (!mine) return;
    memcpy(mine, list, (size_t)n * sizeof *mine);
    rest_classify(w, mine, n);
    free(mine);
}

/* The pairs and the broad phase as the commands left the objects. */
static int update_pairs(world *w)
{
    if (pairs_update(w) != 0) return -1;
    return w->sched_dirty ? broad_commands(w) : 0;
}

/* After a change from outside the simulation (a statement, or the hook's at), the
 * objects standing at w->time: the boxes of what moved, what the moved objects
 * touch and the modes of the woken, then every flight, its box to t_end (the end
 * of the internal step: so a held body's pairs are found afresh whenever the hand
 * sets its motion), the schedule, and every pair's bound from now.  (The pairs
 * the boxes make meanwhile go straight into the schedule made after them.)
 * Returns 0, or -1 when out of memory. */
static int start_over(world *w, double t_end)
{
    if (update_pairs(w) != 0) return -1;
    find_contacts(w);
    w->step.t_end = t_end;
    for (int i = 0; i < w->n; i++) {
        step_start(w, i, w->time);
        w->step.event[i] = HUGE_VAL; /* (sched_build: every object's at +inf) */
        hold_box(w, i, w->time, false);
    }
    if (w->out_of_memory || sched_build(w, w->time) != 0) return -1;
    w->pairs.nfresh = 0; /* (every pair gets its bound below) */
    for (long k = 0; k < w->pairs.n; k++)
        if (w->pairs.p[k].a >= 0) sched_set(w, sched_pair_id(&w->sched, k), bound_from(w, k, w->time));
    w->sched_dirty = false;
    return 0;
}

int sim_prepare(world *w)
{
    if (update_pairs(w) != 0) return -1;
    bool changed = w->sched_dirty;
    if (step_prepare(w, changed) != 0) return -1;
    if (!changed) return 0;
    /* the boxes for the first internal step */
    long n = world_subframes(w);
    return start_over(w, w->time + (n > 0 ? w->set.time_step / (double)n : 0));
}

/* The hook acts at w->time, where the internal step under way was cut; what it
 * changed (edit_done marks it) starts over from there, as after a statement.
 * Returns the next instant it asks for; one that asks for the same instant again
 * and again is let go after SIM_MAX_EVENTS_PER_STEP calls. */
static double hook_act(world *w, const sim_hook *hook, double t_end, int *calls)
{
    hook->at(hook->ctx, w);
    if (w->sched_dirty && start_over(w, t_end) != 0) w->out_of_memory = true;
    double tn = hook->next(hook->ctx, w);
    *calls = tn <= w->time ? *calls + 1 : 0;
    return *calls > SIM_MAX_EVENTS_PER_STEP ? HUGE_VAL : tn;
}

/* The internal step that ends at t_end, cut at each instant tn before it that the
 * hook asks for; returns the hook's next instant.  (Out of the frame's loop, so
 * that a frame the hook has nothing in costs one comparison a step.) */
static __attribute__((cold, noinline)) double hook_cut(world *w, const sim_hook *hook, double tn,
                                                      double t_end, int *calls)
{
    while (tn < t_end) {
        if (tn > w->time) internal_step(w, tn, true);
        tn = hook_act(w, hook, t_end, calls);
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
    if (sim_prepare(w) != 0 || w->out_of_memory) {
        w->out_of_memory = false;
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double t0 = w->time, h = n > 0 ? w->set.time_step / (double)n : 0;
    w->nevents = 0;
    /* the hook's next instant: the internal step is cut there, and what the hook
     * changed is seen by the rest of the step.  A frame it has nothing in runs as
     * if there were none. */
    int calls = 0;
    double tn = hook ? hook->next(hook->ctx, w) : HUGE_VAL;
    for (long k = 0; k < n; k++) {
        double t_end = w->time + h;
        bool cut = tn < t_end;
        if (cut) tn = hook_cut(w, hook, tn, t_end, &calls);
        internal_step(w, t_end, k == 0 || cut);
        w->st.subframes++;
    }
    if (rest_frame_end(w) > 0) {
        for (int i = 0; i < w->n; i++) {
            if (w->bodies[i]->state != STATE_RESTING) continue;
            restart(w, i, w->time);
        }
    }
    if (w->set.time_step != w->base_step || w->time_base + (double)w->base_frames * w->base_step != t0) {
        w->time_base = t0;
        w->base_step = w->set.time_step;
        w->base_frames = 0;
    }
    w->base_frames++;
    w->time = w->time_base + (double)w->base_frames * w->base_step;
    /* the pairs' closest features only speed queries up, but where features are
     * equally close they pick which is reported: every frame starts from none, so
     * that a world read back from save (which has none) goes on to the bit */
    for (long k = 0; k < w->pairs.n; k++) w->pairs.p[k].cache.valid = w->pairs.p[k].hit.valid = false;
    /* and each object's w is the one its L and orientation give, as when read back */
    for (int i = 0; i < w->n; i++)
        if (!body_is_static(w->bodies[i])) body_update_w(w->bodies[i]);
    w->frame++;
    w->st.frames++;
    if (w->out_of_memory) { /* (a pair or a box could not be made on the way) */
        w->out_of_memory = false;
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    return 0;
}

long sim_penetrations(world *w, sim_report report, void *ctx)
{
    if (update_pairs(w) != 0) return -1;
    long count = 0;
    /* only near objects can meet: their pairs, in the order of a, then b */
    for (int i = 0; i < w->n; i++) {
        FOR_PAIRS_OF(w, i, link, p) {
            if (link->other < i || !p->near) continue;
            const body *a = w->bodies[p->a], *b = w->bodies[p->b];
            /* only what a command placed: the simulation's own states are its own */
            if (p->touching || (!a->moved && !b->moved)) continue;
            closest_result r = pair_query(w, p, a, b);
            if (r.status == CLOSEST_PENETRATING && r.distance < -touch_of(a, b)) {
                count++;
                if (report) report(ctx, a, b, -r.distance);
            }
        }
    }
    return count;
}
