/* apart.c: no overlap left at a frame's end; the validation build's watch (apart.h). */
#include "apart.h"

#include <stdlib.h>

#include "closest.h"
#include "pairs.h"
#include "retime.h"
#include "step.h"
#include "world.h"

/* How freely object b moves when pushed apart: 1/m, or 0 when it does not. */
static double give(const body *b)
{
    return body_is_static(b) || b->held ? 0 : 1 / b->mass;
}

/* True when a and b cannot reach each other: their balls are apart. */
static bool balls_apart(const body *a, const body *b)
{
    double r = a->shape.r_out + b->shape.r_out;
    return v3_len2(v3_sub(body_com(a), body_com(b))) > r * r;
}

int apart_frame_end(world *w)
{
    int count = 0;
    bool *moved = w->answer.mark;
    for (int pass = 0; pass < APART_PASSES; pass++) {
        int now = 0;
        for (long k = 0; k < w->pairs.n; k++) {
            pair *p = &w->pairs.p[k];
            if (p->a < 0 || !p->near) continue;
            body *a = w->bodies[p->a], *b = w->bodies[p->b];
            double ga = give(a), gb = give(b);
            if (ga + gb == 0 || balls_apart(a, b)) continue;
            closest_result r = body_distance(a, b, NULL);
            if (r.status != CLOSEST_PENETRATING || !(r.distance < -APART_SLOP)) continue;
            /* the normal goes from b to a: a along it, b against it, until they touch */
            double depth = -r.distance;
            a->x = v3_mad(a->x, r.normal, depth * ga / (ga + gb));
            b->x = v3_mad(b->x, r.normal, -depth * gb / (ga + gb));
            moved[p->a] = ga > 0;
            moved[p->b] = gb > 0;
            now++;
        }
        count += now;
        if (now == 0) break;
    }
    for (int i = 0; i < w->n; i++) {
        if (!moved[i]) continue;
        moved[i] = false;
        retime_object(w, i, w->time);
    }
    w->st.separations += count;
    return count;
}

void apart_watch(world *w, double t)
{
    body *at = malloc(sizeof *at * (size_t)(w->n > 0 ? w->n : 1));
    if (!at) return;
    for (int i = 0; i < w->n; i++) {
        at[i] = *w->bodies[i];
        if (step_moves(w, i)) step_fly(w, i, t, &at[i]);
    }
    for (long k = 0; k < w->pairs.n; k++) {
        const pair *p = &w->pairs.p[k];
        if (p->a < 0 || !p->near || balls_apart(&at[p->a], &at[p->b])) continue;
        closest_result r = body_distance(&at[p->a], &at[p->b], NULL);
        if (r.status == CLOSEST_PENETRATING && -r.distance > w->st.deepest) {
            w->st.deepest = -r.distance;
            w->st.deepest_a = p->a;
            w->st.deepest_b = p->b;
        }
    }
    free(at);
}
