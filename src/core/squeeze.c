/* squeeze.c: what a held object pushes, and where it must stop (squeeze.h). */
#include "squeeze.h"

#include "pairs.h"
#include "retime.h"
#include "step.h"
#include "world.h"

int squeeze_reach(world *w, int *list, int n, double t)
{
    bool *mark = w->answer.mark;
    for (int k = 0; k < n; k++) mark[list[k]] = true;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        FOR_PAIRS_OF(w, i, link, p) {
            int o = link->other;
            const body *bo = w->bodies[o];
            if (mark[o] || !p->near || body_is_static(bo) || bo->held) continue;
            /* (o as it is at t, without touching its flight unless it is taken) */
            body at = *bo;
            if (step_moves(w, o)) step_fly(w, o, t, &at);
            const body *a = p->a == i ? w->bodies[i] : &at, *b = p->a == i ? &at : w->bodies[i];
            closest_result r = pair_query(w, p, a, b);
            if (r.status == CLOSEST_INVALID || r.distance > squeeze_gap(a, b)) continue;
            step_sync(w, o, t);
            mark[o] = true;
            list[n++] = o;
        }
    }
    for (int k = 0; k < n; k++) mark[list[k]] = false;
    return n;
}

void squeeze_hold_stop(world *w, int i, double t)
{
    body *b = w->bodies[i];
    step_sync(w, i, t);
    b->hold_v = b->v = v3(0, 0, 0);
    body_set_angular_vel(b, v3(0, 0, 0));
    retime_object(w, i, t);
}

bool squeeze_settle(world *w, impulse_row *rows, int nr, const int *list, int n, const bool *mobile)
{
    body **now = w->answer.now;
    double u[IMPULSE_MAX_ROWS], lambda[IMPULSE_MAX_ROWS];
    for (int r = 0; r < nr; r++) {
        rows[r].e = 0;
        u[r] = impulse_speed(&rows[r], now);
    }
    if (impulse_solve(rows, nr, now, mobile, u, lambda, w->answer.lcp) == 0) return true;
    /* pressed from every side, as rounding sees it: they stop where they are */
    for (int k = 0; k < n; k++) {
        body *b = w->bodies[list[k]];
        b->v = v3(0, 0, 0);
        body_set_angular_vel(b, v3(0, 0, 0));
    }
    return false;
}
