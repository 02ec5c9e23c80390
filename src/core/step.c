/* step.c: the internal step's state: where each object's flight starts, and the
 * copies and lists a step works on (thesis 3.4.2; sim.c uses them).
 *
 * Everything here is allocated and written when time is about to run
 * (step_prepare), so that frames allocate nothing and touch no fresh memory.
 */
#include "step.h"

#include <assert.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "flight.h"
#include "world.h"

void step_init(step_state *s)
{
    memset(s, 0, sizeof *s);
}

void step_free(step_state *s)
{
    free(s->snap);
    free(s->snap_t);
    free(s->snap_id);
    free(s->pre);
    free(s->scratch);
    free(s->end_id);
    free(s->touched);
    free(s->movers);
    free(s->due);
    free(s->due_next);
    step_init(s);
}

/* The array p resized to n elements of size elem; p itself, and ok set false, when
 * that fails. */
static void *resized(void *p, size_t elem, int n, bool *ok)
{
    void *q = realloc(p, (size_t)n * elem);
    if (!q) *ok = false;
    return q ? q : p;
}

/* end_id of an object that is where its flight starts (step_save made the
 * flight from it): the first flight to the end of the step needs no copy. */
#define END_AT_START (-2)

/* Within an internal step each object flies from its own starting state: snap[i]
 * at time snap_t[i], the start of the step, or the instant of the last collision
 * that changed it.  An object's place at time t is always one flight from there,
 * so a collision that sends the world back to an earlier instant leaves every
 * other object's flight, and so its pairs' predictions, exactly as they were. */
void step_save(world *w, double t)
{
    /* (a static object's start stays as copies set it: it never moves) */
    for (int k = 0; k < w->step.nmovers; k++) {
        int i = w->step.movers[k];
        /* what does not move is where it is: only its state is kept (flown) */
        if (w->bodies[i]->state == STATE_DYNAMIC) body_copy_state(&w->step.snap[i], w->bodies[i]);
        else w->step.snap[i].state = w->bodies[i]->state;
        w->step.snap_t[i] = t;
        w->step.snap_id[i] = w->step.flight_count++;
        w->step.end_id[i] = END_AT_START;
    }
}

/* Makes snap, pre and scratch copies of the objects that may move, so that within a
 * frame only their states need copying (nothing else changes while time runs;
 * static objects are read where they are).  The copies are made again only after
 * a command (changed, w->sched_dirty): between frames nothing else changes a
 * body but its state, which every step copies before it reads it. */
static int copies(world *w, bool changed)
{
    if (w->n > w->step.cap) {
        changed = true;
        bool ok = true;
        w->step.snap = resized(w->step.snap, sizeof *w->step.snap, w->n, &ok);
        w->step.pre = resized(w->step.pre, sizeof *w->step.pre, w->n, &ok);
        w->step.scratch = resized(w->step.scratch, STEP_COPIES * sizeof *w->step.scratch, w->n, &ok);
        w->step.snap_t = resized(w->step.snap_t, sizeof *w->step.snap_t, w->n, &ok);
        w->step.snap_id = resized(w->step.snap_id, sizeof *w->step.snap_id, w->n, &ok);
        w->step.end_id = resized(w->step.end_id, sizeof *w->step.end_id, w->n, &ok);
        w->step.touched = resized(w->step.touched, sizeof *w->step.touched, w->n, &ok);
        w->step.movers = resized(w->step.movers, sizeof *w->step.movers, w->n, &ok);
        if (!ok) return -1;
        w->step.cap = w->n;
    }
    if (!changed) return 0;
    w->step.nmovers = 0;
    for (int i = 0; i < w->n; i++) {
        if (!body_is_static(w->bodies[i])) {
            w->step.movers[w->step.nmovers++] = i;
            w->step.snap[i] = w->step.pre[i] = *w->bodies[i];
            for (int k = 0; k < STEP_COPIES; k++) w->step.scratch[STEP_COPIES * i + k] = *w->bodies[i];
        } else {
            /* a static object flies from nowhere before any step; its pre copy
             * is written here, not first in the middle of a frame (answer) */
            w->step.pre[i] = *w->bodies[i];
            w->step.snap[i].state = w->bodies[i]->state;
            w->step.snap_t[i] = -HUGE_VAL;
            w->step.snap_id[i] = w->step.flight_count++;
            w->step.end_id[i] = -1;
        }
    }
    return 0;
}

/* Flies out, a copy of moving body i where its flight starts, on to time t. */
void step_fly_on(const world *w, int i, double t, body *out)
{
    double dt = t - w->step.snap_t[i];
    if (dt > 0) flight_fly(out, dt, force_on(w->set.force, out), w->set.max_linear, w->set.max_angular);
}

/* Puts moving body i's state at time t in out, a copy of body i. */
void step_fly_into(const world *w, int i, double t, body *out)
{
    assert(w->step.snap[i].state == STATE_DYNAMIC && t >= w->step.snap_t[i]);
    body_copy_state(out, &w->step.snap[i]);
    step_fly_on(w, i, t, out);
}

/* Puts body i's state at time t in out, a copy of body i (what does not move is
 * there already). */
void step_fly_at(const world *w, int i, double t, body *out)
{
    if (w->step.snap[i].state == STATE_DYNAMIC) step_fly_into(w, i, t, out);
}

/* Body i at time t: itself when it does not move, else its scratch copy number
 * k, flown there. */
const body *step_flown(const world *w, int i, double t, int k)
{
    if (w->step.snap[i].state != STATE_DYNAMIC) return w->bodies[i];
    body *b = &w->step.scratch[STEP_COPIES * i + k];
    step_fly_into(w, i, t, b);
    return b;
}

/* The copies of body i a search works on, the first at time t: body i itself
 * when it does not move (nothing then changes them), else its scratch copies
 * (only the first flown: the others are written before they are read). */
void step_search_copies(world *w, int i, double t, body *out[STEP_COPIES])
{
    for (int k = 0; k < STEP_COPIES; k++)
        out[k] = w->step.snap[i].state == STATE_DYNAMIC ? &w->step.scratch[STEP_COPIES * i + k] : w->bodies[i];
    if (w->step.snap[i].state == STATE_DYNAMIC) step_fly_into(w, i, t, out[0]);
}

/* Body i where its flight starts (at snap_t[i]). */
const body *step_at_start(const world *w, int i)
{
    return w->step.snap[i].state == STATE_DYNAMIC ? &w->step.snap[i] : w->bodies[i];
}

/* The earlier start of the flights of pair p's moving objects. */
double step_flights_start(const world *w, const pair *p)
{
    bool ma = w->step.snap[p->a].state == STATE_DYNAMIC, mb = w->step.snap[p->b].state == STATE_DYNAMIC;
    if (ma && mb) return d_min(w->step.snap_t[p->a], w->step.snap_t[p->b]);
    return ma ? w->step.snap_t[p->a] : w->step.snap_t[p->b];
}

/* Every moving object to the end of the step, t_end: an object whose flight did
 * not change since it was last flown there is there already (answer flies back
 * there what it flew to a collision and left unchanged). */
void step_fly_to_end(world *w, double t_end)
{
    for (int k = 0; k < w->step.nmovers; k++) {
        int i = w->step.movers[k];
        if (w->step.snap[i].state != STATE_DYNAMIC || w->step.end_id[i] == w->step.snap_id[i]) continue;
        /* where its flight starts, as step_save left it, it flies on in place */
        if (w->step.end_id[i] != END_AT_START) body_copy_state(w->bodies[i], &w->step.snap[i]);
        step_fly_on(w, i, t_end, w->bodies[i]);
        w->step.end_id[i] = w->step.snap_id[i];
    }
}

/* Room for n pairs' due times. */
static int due_room(world *w, long n)
{
    if (n <= w->step.capdue) return 0;
    long *d = realloc(w->step.due, (size_t)n * sizeof *d);
    if (d) w->step.due = d;
    double *dn = realloc(w->step.due_next, (size_t)n * sizeof *dn);
    if (dn) w->step.due_next = dn;
    if (!d || !dn) return -1;
    /* written once now, so that the system maps its pages here and not in the
     * middle of a frame (see step_prepare) */
    memset(d, 0, (size_t)n * sizeof *d);
    memset(dn, 0, (size_t)n * sizeof *dn);
    w->step.capdue = n;
    return 0;
}

/* Object i flies on from time t as it is now. */
void step_renew(world *w, int i, double t)
{
    body_copy_state(&w->step.snap[i], w->bodies[i]);
    w->step.snap_t[i] = t;
    w->step.snap_id[i] = w->step.flight_count++;
}

int step_prepare(world *w, bool changed)
{
    if (copies(w, changed) != 0 || due_room(w, w->pairs.n) != 0) return -1;
    return 0;
}
