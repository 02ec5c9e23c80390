/* hold.c: a body held by the hand: setting and ending its motion (hold.h; its
 * flight is flight.c's FLIGHT_HELD, and sim.c answers its collisions). */
#include "hold.h"

#include "edit.h"
#include "rest.h"
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
