/* step.c: the state of the simulation between its events (step.h).
 *
 * Everything here is allocated and written when time is about to run
 * (step_prepare), so that frames allocate nothing and touch no fresh memory.
 */
#include "step.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "friction.h"
#include "grow.h"
#include "world.h"

void step_init(step_state *s)
{
    memset(s, 0, sizeof *s);
}

static int step_copy(world *w, bool changed);

void step_free(step_state *s)
{
    free(s->fl);
    free(s->event);
    free(s->flown);
    free(s->flown_id);
    free(s->flown_t);
    free(s->due);
    free(s->due_next);
    step_init(s);
}

int step_prepare(world *w, bool changed)
{
    step_state *s = &w->step;
    bool ok = true;
    if (w->n > s->cap) {
        changed = true;
        s->fl = grow_resized(s->fl, sizeof *s->fl, w->n, &ok);
        s->event = grow_resized(s->event, sizeof *s->event, w->n, &ok);
        s->flown = grow_resized(s->flown, STEP_FLOWN_COPIES * sizeof *s->flown, w->n, &ok);
        s->flown_id = grow_resized(s->flown_id, STEP_FLOWN_COPIES * sizeof *s->flown_id, w->n, &ok);
        s->flown_t = grow_resized(s->flown_t, STEP_FLOWN_COPIES * sizeof *s->flown_t, w->n, &ok);
        if (!ok) return -1;
        s->cap = w->n;
    }
    /* the heap holds the pairs and the objects' own events */
    return step_reserve_due(w, w->pairs.n + w->n) != 0 ? -1 : step_copy(w, changed);
}

int step_reserve_due(world *w, long due)
{
    step_state *s = &w->step;
    bool ok = true;
    if (due > s->capdue) {
        due += due / 2;
        long *d = grow_resized(s->due, sizeof *d, due, &ok);
        double *dn = grow_resized(s->due_next, sizeof *dn, due, &ok);
        s->due = d;
        s->due_next = dn;
        if (!ok) return -1;
        /* written once now, so that the system maps its pages here and not in the
         * middle of a frame */
        memset(d, 0, (size_t)due * sizeof *d);
        memset(dn, 0, (size_t)due * sizeof *dn);
        s->capdue = due;
    }
    return 0;
}

/* Copies the objects into step_flown's copies when changed (step_prepare). */
static int step_copy(world *w, bool changed)
{
    step_state *s = &w->step;
    if (!changed) return 0;
    for (int i = 0; i < w->n; i++) {
        for (int k = 0; k < STEP_FLOWN_COPIES; k++) {
            s->flown[STEP_FLOWN_COPIES * i + k] = *w->bodies[i];
            s->flown_id[STEP_FLOWN_COPIES * i + k] = -1;
        }
        s->event[i] = HUGE_VAL;
        flight_start(&s->fl[i], w->bodies[i], FLIGHT_STILL, w->time, v3(0, 0, 0), v3(0, 0, 0),
                     s->flight_count++);
    }
    return 0;
}

bool step_moves(const world *w, int i)
{
    return w->bodies[i]->state == STATE_DYNAMIC;
}

void step_fly(const world *w, int i, double t, body *out)
{
    flight_at(&w->step.fl[i], w->bodies[i], t, out);
}

const body *step_flown(const world *w, int i, double t, int k)
{
    assert(k >= 0 && k < STEP_FLOWN_COPIES);
    if (!step_moves(w, i)) return w->bodies[i];
    const step_state *s = &w->step;
    long m = STEP_FLOWN_COPIES * i + k;
    body *b = &s->flown[m];
    if (s->flown_id[m] == s->fl[i].id && s->flown_t[m] == t) return b;
    step_fly(w, i, t, b);
    s->flown_id[m] = s->fl[i].id;
    s->flown_t[m] = t;
    return b;
}

void step_sync(world *w, int i, double t)
{
    if (step_moves(w, i)) flight_at(&w->step.fl[i], w->bodies[i], t, w->bodies[i]);
}

sched_move step_move(const world *w, int i, const body *o)
{
    const flight *f = &w->step.fl[i];
    sched_move m = {.moves = step_moves(w, i) && f->kind != FLIGHT_STILL, .reach = o->shape.r_out};
    if (!m.moves) return m;
    m.c = body_com(o);
    m.v = o->v;
    m.a = f->a;
    m.rate = f->rate;
    if (f->kind == FLIGHT_HELD) {
        m.held = true;
        m.reach += v3_len(v3_sub(m.c, o->hold_pivot));
        m.c = o->hold_pivot;
        m.v = o->hold_v;
    }
    return m;
}

void step_start(world *w, int i, double t)
{
    body *b = w->bodies[i];
    flight *f = &w->step.fl[i];
    long id = w->step.flight_count++;
    if (!step_moves(w, i)) {
        flight_start(f, b, FLIGHT_STILL, t, v3(0, 0, 0), v3(0, 0, 0), id);
        return;
    }
    if (b->held) {
        flight_start(f, b, FLIGHT_HELD, t, v3(0, 0, 0), v3(0, 0, 0), id);
        return;
    }
    if (body_mode_on_face(b->mode)) {
        const body *s = b->slide_on >= 0 ? w->bodies[b->slide_on] : NULL;
        if (b->mode == MODE_STICK) {
            flight_start(f, b, FLIGHT_STILL, t, v3(0, 0, 0), v3(0, 0, 0), id);
            return;
        }
        if (s && friction_mu(b, s) > 0) {
            /* in closed form; where the state has none, its event comes at once
             * (rest_face_stop: its mode is found anew) */
            vec3 lean;
            double hmax = d_max(0, w->step.t_end - t);
            face_motion m = friction_face(b, s, world_accel(w), b->slide_n, b->mode, hmax, &lean);
            if (m.mode == MODE_GENERAL)
                m = (face_motion){.mode = MODE_GENERAL, .a = v3(0, 0, 0), .axis = b->slide_n, .t_stop = 0};
            flight_kind k = b->mode == MODE_ROLL ? FLIGHT_ROLL : FLIGHT_SLIDE;
            flight_start_face(f, b, k, t, &m, b->slide_n, w->step.t_end, id);
            return;
        }
        flight_start(f, b, FLIGHT_SLIDE, t, world_body_accel(w, b), b->slide_n, id);
        return;
    }
    flight_start(f, b, FLIGHT_FREE, t, world_accel(w), v3(0, 0, 0), id);
}
