/* guard.c: steps whose events run away (guard.h). */
#include "guard.h"

#include <stdlib.h>

#include "body.h"
#include "grow.h"
#include "retime.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

void guard_init(guard_work *g)
{
    *g = (guard_work){SIM_CROWD_EVENTS, SIM_MAX_EVENTS_PER_STEP, NULL, NULL, NULL, 0, 0};
}

void guard_free(guard_work *g)
{
    free(g->events);
    free(g->crowded);
    free(g->counted);
    guard_init(g);
}

int guard_prepare(world *w)
{
    guard_work *g = &w->guard;
    if (w->n <= g->cap) return 0;
    bool ok = true;
    g->events = grow_resized(g->events, sizeof *g->events, w->n, &ok);
    g->crowded = grow_resized(g->crowded, sizeof *g->crowded, w->n, &ok);
    g->counted = grow_resized(g->counted, sizeof *g->counted, w->n, &ok);
    if (!ok) return -1;
    for (int i = g->cap; i < w->n; i++) {
        g->events[i] = 0;
        g->crowded[i] = false;
    }
    g->cap = w->n;
    return 0;
}

/* One more event of object i (dynamic) this step. */
static void count(world *w, int i)
{
    guard_work *g = &w->guard;
    if (g->events[i]++ == 0) g->counted[g->ncounted++] = i;
    if (g->events[i] == g->crowd_events) {
        g->crowded[i] = true;
        w->st.crowds++;
    }
}

/* Object i stops where it is at time t: nothing it touches approaches it. */
static void stop(world *w, int i, double t)
{
    body *b = w->bodies[i];
    step_sync(w, i, t);
    b->v = v3(0, 0, 0);
    body_set_angular_vel(b, v3(0, 0, 0));
    w->answer.kicks[i].h = 0; /* (no cluster kick of its is under way) */
    retime_object(w, i, t);
}

/* True when object i moves with what its contacts answer. */
static bool counts(const world *w, int i)
{
    return i >= 0 && !body_is_static(w->bodies[i]) && !w->bodies[i]->held;
}

bool guard_event(world *w, int a, int b, long n, double t)
{
    guard_work *g = &w->guard;
    if (n >= 2 * g->max_events) {
        w->st.overflows++;
        return false;
    }
    if (counts(w, a)) count(w, a);
    if (counts(w, b)) count(w, b);
    if (n != g->max_events) return true;
    /* the last resort */
    int stopped = 0;
    for (int k = 0; k < g->ncounted; k++) {
        int i = g->counted[k];
        if (!g->crowded[i] && i != a && i != b) continue;
        stop(w, i, t);
        stopped++;
    }
    if (w->st.guards++ == 0) w->st.first_guard = (sim_guard){t, a, b, stopped};
    return true;
}

void guard_step_end(world *w)
{
    guard_work *g = &w->guard;
    for (int k = 0; k < g->ncounted; k++) {
        g->events[g->counted[k]] = 0;
        g->crowded[g->counted[k]] = false;
    }
    g->ncounted = 0;
}
