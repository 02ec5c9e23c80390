/* retime.c: what follows when an object's flight changes (retime.h). */
#include "retime.h"

#include <math.h>

#include "broad.h"
#include "rest.h"
#include "schedule.h"
#include "world.h"

double retime_bound(world *w, long k, double t)
{
    pair *p = &w->pairs.p[k];
    if (!retime_searched(w, p)) return HUGE_VAL;
    const body *a = step_flown(w, p->a, t, 1), *b = step_flown(w, p->b, t, 1);
    sched_move ma = step_move(w, p->a, a), mb = step_move(w, p->b, b);
    double dt = sched_sphere_time(a, &ma, b, &mb);
    return dt == HUGE_VAL ? dt : t + dt;
}

/* Object i's flight changed at time t: what was found of its pairs holds no
 * more; each gets its cheap bound. */
static void retime_pairs(world *w, int i, double t)
{
    FOR_PAIRS_OF(w, i, link, p) {
        p->toi_fa = p->toi_fb = -1;
        sched_set(w, sched_pair_id(&w->sched, link->slot), retime_bound(w, link->slot, t));
    }
}

void retime_fresh(world *w, double t)
{
    if (w->pairs.nfresh == 0) return;
    long n;
    const long *fresh = pairs_take_fresh(w, &n);
    for (long k = 0; k < n; k++)
        if (w->pairs.p[fresh[k]].a >= 0)
            sched_set(w, sched_pair_id(&w->sched, fresh[k]), retime_bound(w, fresh[k], t));
}

void retime_box(world *w, int i, double t, bool same)
{
    if (same && w->step.t_end <= w->broad.until[i]) return; /* (broad_cover's first test) */
    if (step_moves(w, i) && broad_cover(w, i, t, w->step.t_end, same) != 0) w->out_of_memory = true;
}

void retime_object(world *w, int i, double t)
{
    step_start(w, i, t);
    const body *b = w->bodies[i];
    double ev = HUGE_VAL;
    if (step_moves(w, i) && body_mode_on_face(b->mode)) ev = rest_slide_exit(w, i, t);
    retime_event(w, i, ev);
    retime_box(w, i, t, false);
    retime_pairs(w, i, t); /* (the pairs its box just made among them) */
    w->pairs.nfresh = 0;
}
