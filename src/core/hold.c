/* hold.c: a body held by the hand: setting and ending its motion, and its flight
 * (hold.h; sim.c answers its collisions). */
#include "hold.h"

#include "rest.h"
#include "schedule.h"
#include "world.h"

/* Makes body i's pairs due now and its box hold everything, when the schedule is
 * the world's (within a frame, or between frames after one); otherwise the next
 * frame makes it anew. */
static void due_now(world *w, int i)
{
    if (!w->sched_dirty && !w->pairs.dirty && w->sched.obj_first) sched_object_due(w, i, w->time);
}

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
    rest_wake(w, i);
    b->slide = -1;
    b->held = true;
    b->hold_pivot = m.pivot;
    b->hold_v = m.v;
    body_set_angular_vel(b, m.w);
    b->v = v3_add(m.v, v3_cross(m.w, v3_sub(body_com(b), m.pivot)));
    due_now(w, i);
    return 0;
}

void hold_release(world *w, int i, vec3 v, vec3 wv)
{
    body *b = w->bodies[i];
    if (!b->held) return;
    b->held = false;
    b->hold_pivot = b->hold_v = v3(0, 0, 0);
    b->v = v;
    body_set_angular_vel(b, wv);
    due_now(w, i);
}

void hold_place(world *w, int i, vec3 x, quat q)
{
    body *b = w->bodies[i];
    vec3 c0 = body_com(b);
    b->x = x;
    b->q = q;
    b->rot_given = false;
    /* the pivot keeps its place relative to the body */
    if (b->held) b->hold_pivot = v3_add(b->hold_pivot, v3_sub(body_com(b), c0));
    body_set_angular_vel(b, b->w); /* L = I w in the new axes */
    due_now(w, i);
}

void hold_fly(body *b, double h)
{
    vec3 r = v3_sub(body_com(b), b->hold_pivot);
    double wl = v3_len(b->w);
    b->hold_pivot = v3_mad(b->hold_pivot, b->hold_v, h);
    if (wl > 0) {
        quat turn = q_axis_angle(b->w, wl * h);
        r = q_rotate(turn, r);
        b->q = q_normalize(q_mul(turn, b->q));
        b->rot_given = false;
    }
    vec3 c = v3_add(b->hold_pivot, r), com = b->shape.mass.com;
    b->x = c;
    if (com.x != 0 || com.y != 0 || com.z != 0) b->x = v3_sub(c, q_rotate(b->q, com));
    b->v = v3_add(b->hold_v, v3_cross(b->w, r));
    body_set_angular_vel(b, b->w);
}
