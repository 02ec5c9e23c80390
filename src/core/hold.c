/* hold.c: a body held by the hand: setting and ending its motion (hold.h; its
 * flight is flight.c's FLIGHT_HELD, and sim.c answers its collisions). */
#include "hold.h"

#include <math.h>
#include <stdlib.h>

#include "closest.h"
#include "edit.h"
#include "rest.h"
#include "tolerance.h"
#include "world.h"

int hold_set(world *w, int i, hold_motion m)
{
    body *b = w->bodies[i];
    if (body_is_static(b)) return -1;
    /* the speed limits: |w| first, then the centre's |v| + |w| r */
    double wl = v3_len(m.w);
    if (wl > w->set.max_angular) m.w = v3_scale(m.w, w->set.max_angular / wl);
    double r = v3_len(v3_sub(body_com(b), m.pivot));
    double s = v3_len(m.v) + v3_len(m.w) * r;
    if (s > w->set.max_linear) {
        m.v = v3_scale(m.v, w->set.max_linear / s);
        m.w = v3_scale(m.w, w->set.max_linear / s);
    }
    if (!b->held) edit_unpress(w, i);
    rest_wake(w, i);
    b->held = true;
    b->hold_pivot = m.pivot;
    b->hold_v = m.v;
    body_set_angular_vel(b, m.w);
    b->v = v3_add(m.v, v3_cross(m.w, v3_sub(body_com(b), m.pivot)));
    edit_done(w);
    return 0;
}

void hold_release(world *w, int i, vec3 v, vec3 wv)
{
    body *b = w->bodies[i];
    if (!b->held) return;
    b->held = false;
    b->hold_pivot = b->hold_v = v3(0, 0, 0);
    /* a throw is held to the speed limits, as a collision is (a hand that moved
     * at a limit may give rounding's worth more: that is not a cut) */
    double vl = v3_len(v), wl = v3_len(wv);
    bool cut_v = vl > w->set.max_linear * (1 + 1e-12), cut_w = wl > w->set.max_angular * (1 + 1e-12);
    if (cut_v) v = v3_scale(v, w->set.max_linear / vl);
    if (cut_w) wv = v3_scale(wv, w->set.max_angular / wl);
    /* counted as a collision's cut is (answer.c), the world's first described */
    sim_cut c = {i, !cut_v, cut_v ? vl : wl, cut_v ? w->set.max_linear : w->set.max_angular, true};
    if ((cut_v || cut_w) && w->st.speed_cuts++ == 0) w->st.first_cut = c;
    b->v = v;
    body_set_angular_vel(b, wv);
    edit_done(w);
}

int hold_exact(world *w, int i, vec3 pivot, vec3 v)
{
    body *b = w->bodies[i];
    if (!b->held) return -1;
    b->hold_pivot = pivot;
    b->hold_v = v;
    edit_done(w);
    return 0;
}

void hold_place(world *w, int i, vec3 x, quat q)
{
    body *b = w->bodies[i];
    vec3 c0 = body_com(b);
    b->x = x;
    b->q = q;
    b->rot_given = false;
    if (b->held) b->hold_pivot = v3_add(b->hold_pivot, v3_sub(body_com(b), c0));
    body_set_angular_vel(b, b->w); /* L = I w in the new axes */
    edit_done(w);
}

/* ---- the sweep of a jump ---- */

/* Steps a sweep may take: each goes as far as the nearest object allows, so an
 * approach takes a few; one that grazes along a face at the hover gap would take
 * a step per gap, and stops where it is after this many. */
#define HOLD_SWEEP_STEPS 1000

/* The straight path of a jump: the centre of mass from c0 by dc, the orientation
 * from q0 about axis by angle, both in proportion to s in [0, 1]. */
typedef struct {
    vec3 c0, dc, axis, com;
    quat q0;
    double angle;
} sweep_path;

static void sweep_pose(const sweep_path *sp, double s, body *out)
{
    out->q = s == 0 || sp->angle == 0 ? sp->q0 : q_normalize(q_mul(q_axis_angle(sp->axis, s * sp->angle), sp->q0));
    out->x = v3_sub(v3_mad(sp->c0, sp->dc, s), q_rotate(out->q, sp->com));
}

/* The distance from moved to each of the n candidates (status: -1 overlapping). */
static bool sweep_gaps(const world *w, const body *moved, const int *cand, int n, double *d)
{
    for (int k = 0; k < n; k++) {
        closest_result r = body_distance_apart(moved, w->bodies[cand[k]], NULL);
        if (r.status == CLOSEST_INVALID || r.status == CLOSEST_PENETRATING) return false;
        d[k] = r.status == CLOSEST_SEPARATED ? r.distance : 0;
    }
    return true;
}

/* The distance from point p to the segment from a by ab. */
static double segment_distance(vec3 p, vec3 a, vec3 ab)
{
    double l2 = v3_dot(ab, ab), s = l2 > 0 ? v3_dot(v3_sub(p, a), ab) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return v3_dist(p, v3_mad(a, ab, s));
}

double hold_sweep(world *w, int i, vec3 x1, quat q1)
{
    body *b = w->bodies[i];
    sweep_path sp = {body_com(b), v3(0, 0, 0), v3(1, 0, 0), b->shape.mass.com, b->q, 0};
    quat r = q_mul(q1, q_conj(b->q));
    if (r.w < 0) r = (quat){-r.w, -r.x, -r.y, -r.z}; /* the short way */
    q_to_axis_angle(r, &sp.axis, &sp.angle);
    sp.dc = v3_sub(v3_add(x1, q_rotate(q1, sp.com)), sp.c0);
    /* a point of it moves at most this far for each unit of s */
    double len = v3_len(sp.dc) + fabs(sp.angle) * b->shape.r_out;
    if (!(len > 0)) return 1;
    /* what the path comes near: its ball, swept, meets theirs */
    int *cand = malloc(sizeof *cand * (size_t)w->n);
    double *d = malloc(sizeof *d * 2 * (size_t)w->n), *d1 = d ? d + w->n : NULL;
    if (!cand || !d) {
        free(cand);
        free(d);
        return 0;
    }
    int n = 0;
    for (int j = 0; j < w->n; j++) {
        const body *o = w->bodies[j];
        if (j == i || !o->built) continue;
        double reach = b->shape.r_out + o->shape.r_out + tol_contact(b, o);
        if (segment_distance(body_com(o), sp.c0, sp.dc) <= reach) cand[n++] = j;
    }
    body moved = *b;
    double s = 0, gmin = HUGE_VAL;
    for (int k = 0; k < n; k++) gmin = d_min(gmin, tol_hover(b, w->bodies[cand[k]]));
    /* from where it is: nothing to sweep against, or already in something */
    bool ok = sweep_gaps(w, &moved, cand, n, d);
    for (int step = 0; ok && s < 1 && step < HOLD_SWEEP_STEPS; step++) {
        /* conservative advancement: no point comes nearer anything than its gap,
         * or, from within the gap, by more than the smallest gap */
        double slack = HUGE_VAL;
        for (int k = 0; k < n; k++) slack = d_min(slack, d[k] - tol_hover(b, w->bodies[cand[k]]));
        double s1 = d_min(1, s + d_max(slack, gmin) / len);
        sweep_pose(&sp, s1, &moved);
        if (!sweep_gaps(w, &moved, cand, n, d1)) break;
        /* stopped by what it closes on within half its gap (an advance to the
         * gap itself may land a rounding short of it) */
        bool blocked = false;
        for (int k = 0; k < n; k++)
            blocked = blocked || (d1[k] < 0.5 * tol_hover(b, w->bodies[cand[k]]) && d1[k] < d[k]);
        if (blocked) break;
        s = s1;
        for (int k = 0; k < n; k++) d[k] = d1[k];
    }
    free(cand);
    free(d);
    if (s > 0) {
        sweep_pose(&sp, s, &moved);
        hold_place(w, i, moved.x, moved.q);
    }
    return s;
}
