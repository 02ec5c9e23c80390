/* sim.c: frames, internal steps and the order of their events (thesis 3.2.3,
 * 3.3, 3.4.2; design.md, "Dynamics").
 *
 * An internal step starts every moving object's flight afresh from where it is
 * (flight.h), then finds the step's events in the order they happen and has each
 * answered at its own instant (answer.h):
 *  - a pair's first contact (toi.h: conservative advancement, so nothing is
 *    passed), searched for the pairs the schedule says are due (schedule.h);
 *  - a slide whose object's centre of mass leaves the face (rest.h);
 *  - the end of a cluster's step (cluster.h).
 * Each event changes the flights of the objects it touches from its instant on
 * (retime.h); every other object flies on as it did, and what was found of its
 * pairs holds.  Events at the same instant are taken in a fixed order (pairs
 * before objects, each by index), but the first contact answered is an instant
 * that takes in every other contact beginning with it (instant.h: within the
 * contact distance and closing), so that the answer does not depend on that
 * order; and which pairs are searched (the heap's due ones, or all of them)
 * changes no answer: a search depends on its pair's flights alone.  The frame
 * ends with what overlaps moved apart (apart.h) and the thesis's rule of rest
 * (rest_frame_end).  As
 * Box2D's b2World_Step sits beside its contact_solver.c, this file keeps the
 * frame, the step and the loop over the events; answering them is answer.c's.
 */
#include "sim.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>

#include "answer.h"
#include "apart.h"
#include "broad.h"
#include "guard.h"
#include "instant.h"
#include "pairs.h"
#include "rest.h"
#include "retime.h"
#include "schedule.h"
#include "step.h"
#include "toi.h"
#include "tolerance.h"

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
    toi_output o = toi_find(w, &(toi_input){p->a, p->b, p->hit, from, d_max(from, to),
                                            pair_pieces(w, p)});
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
            if (w->pairs.p[k].a < 0 || !retime_searched(w, &w->pairs.p[k])) continue;
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
     * starts), and its box covers it to the step's end */
    if (!fresh) /* what was searched for went no further than the last step */
        for (long k = 0; k < w->pairs.n; k++) w->pairs.p[k].toi_fa = w->pairs.p[k].toi_fb = -1;
    for (int i = 0; i < w->n; i++) {
        if (!step_moves(w, i)) continue;
        const body *b = w->bodies[i];
        if (fresh || b->mode != MODE_FREE || b->held || w->step.fl[i].kind != FLIGHT_FREE)
            step_start(w, i, t);
        double ev = body_mode_on_face(b->mode) ? rest_slide_exit(w, i, t) : HUGE_VAL;
        retime_event(w, i, ev);
        /* (retime_box's first test, here without a call) */
        if (w->step.t_end > w->broad.until[i]) retime_box(w, i, t, true);
    }
    if (w->pairs.nfresh > 0) retime_fresh(w, t); /* (its own first test, without a call) */
    /* clusters start their steps (their kicks change their flights) */
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (step_moves(w, i) && b->mode == MODE_GENERAL && w->step.event[i] == HUGE_VAL)
            answer_clusters(w, &i, 1, t, t_end);
    }
    for (long n = 0;; n++) {
        next_event e = find_next(w, t, t_end);
        if (e.kind < 0) break;
        const pair *p = e.kind == 0 ? &w->pairs.p[e.index] : NULL;
        if (!guard_event(w, p ? p->a : (int)e.index, p ? p->b : -1, n, e.t)) break;
        if (e.kind == 0) answer_contact(w, e.index, e.t, t_end);
        else answer_object(w, (int)e.index, e.t, t_end);
#ifdef VROC_VALIDATE
        apart_watch(w, e.t); /* (st.deepest: that nothing passes into anything) */
#endif
    }
    guard_step_end(w);
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
        double touch = tol_touch(a, b);
        /* (placed closing: a collision, which its search finds at once) */
        if (r.distance <= touch && r.distance >= -touch && !instant_closing(w, p, &r)) {
            p->touching = true;
            pair_hit_from_query(w, p);
            a->woken = b->woken = true;
        }
    }
    int *woken = w->answer.objects, n = 0;
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (b->woken && !body_is_static(b)) {
            if (b->state == STATE_RESTING) rest_wake(w, i);
            woken[n++] = i;
        }
        b->moved = b->woken = false;
    }
    rest_classify(w, woken, n);
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
        retime_box(w, i, w->time, false);
    }
    if (w->out_of_memory || sched_build(w, w->time) != 0) return -1;
    w->pairs.nfresh = 0; /* (every pair gets its bound below) */
    for (long k = 0; k < w->pairs.n; k++)
        if (w->pairs.p[k].a >= 0) sched_set(w, sched_pair_id(&w->sched, k), retime_bound(w, k, w->time));
    w->sched_dirty = false;
    return 0;
}

int sim_prepare(world *w)
{
    if (update_pairs(w) != 0) return -1;
    bool changed = w->sched_dirty;
    if (step_prepare(w, changed) != 0 || answer_prepare(w, changed) != 0 || guard_prepare(w) != 0)
        return -1;
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

/* True when a frame starting at t0 counts on from the world's time base (the same
 * time_step, and t0 where the base's frames put it): its end is then the base's
 * next multiple, so that frames of 0.1 s end at 0.3, not 0.30000000000000004. */
static bool frame_continues(const world *w, double t0)
{
    return w->set.time_step == w->base_step &&
           w->time_base + (double)w->base_frames * w->base_step == t0;
}

double sim_frame_end(const world *w)
{
    if (!frame_continues(w, w->time)) return w->time + w->set.time_step;
    return w->time_base + (double)(w->base_frames + 1) * w->base_step;
}

/* The lowest point of static object b (along z): its hull's lowest vertex, or
 * its centre less its radius. */
static double lowest_of(const body *b)
{
    const poly *h = b->shape.hull;
    if (!h || h->nv == 0) return body_com(b).z - b->shape.r_out;
    double z = HUGE_VAL;
    for (int k = 0; k < h->nv; k++) z = d_min(z, b->x.z + q_rotate(b->q, h->v[k]).z);
    return z;
}

/* Marks the objects that fell more than SIM_FALL_DEPTH below the lowest point
 * of every static object (along z, as gravity pulls), each once (sim.h). */
static void mark_fallen(world *w)
{
    /* (the lowest point of a static object is no higher than its centre: only
     * an object that deep asks for the static objects' lowest points) */
    double centres = HUGE_VAL, deepest = HUGE_VAL;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (body_is_static(b)) centres = d_min(centres, body_com(b).z);
        else if (!b->fell) deepest = d_min(deepest, body_com(b).z);
    }
    if (!(centres < HUGE_VAL) || !(deepest < centres - SIM_FALL_DEPTH)) return;
    double lowest = HUGE_VAL;
    for (int i = 0; i < w->n; i++)
        if (body_is_static(w->bodies[i])) lowest = d_min(lowest, lowest_of(w->bodies[i]));
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (b->fell || body_is_static(b) || !(body_com(b).z < lowest - SIM_FALL_DEPTH)) continue;
        b->fell = 1;
        w->st.fallen++;
    }
}

/* True when nothing moves: every object static or resting, and no pair new
 * (a world at rest, which costs a frame nothing but its bookkeeping). */
static bool idle(const world *w)
{
    if (w->pairs.nfresh > 0) return false;
    for (int i = 0; i < w->n; i++)
        if (step_moves(w, i)) return false;
    return true;
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
    if (!hook && idle(w)) {
        /* nothing moves: the steps would find nothing, and leave only what
         * their searches remember reset, as here */
        if (n > 1)
            for (long k = 0; k < w->pairs.n; k++) w->pairs.p[k].toi_fa = w->pairs.p[k].toi_fb = -1;
        w->st.subframes += n;
        n = 0;
    }
    for (long k = 0; k < n; k++) {
        double t_end = w->time + h;
        bool cut = tn < t_end;
        if (cut) tn = hook_cut(w, hook, tn, t_end, &calls);
        internal_step(w, t_end, k == 0 || cut);
        w->st.subframes++;
    }
    /* a frame where nothing moved leaves nothing new to part or to fall */
    if (n > 0) {
        apart_frame_end(w);
        mark_fallen(w);
    }
    if (rest_frame_end(w) > 0) {
        for (int i = 0; i < w->n; i++) {
            if (w->bodies[i]->state != STATE_RESTING) continue;
            retime_object(w, i, w->time);
        }
    }
    if (!frame_continues(w, t0)) {
        w->time_base = t0;
        w->base_step = w->set.time_step;
        w->base_frames = 0;
    }
    w->base_frames++;
    w->time = w->time_base + (double)w->base_frames * w->base_step;
    /* the pairs' closest features only speed queries up, but where features are
     * equally close they pick which is reported: every frame starts from none, so
     * that a world read back from save (which has none) goes on to the bit */
    for (long k = 0; k < w->pairs.n; k++) pair_forget(w, &w->pairs.p[k]);
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
            if (r.status == CLOSEST_PENETRATING && r.distance < -tol_touch(a, b)) {
                count++;
                if (report) report(ctx, a, b, -r.distance);
            }
        }
    }
    return count;
}
