/* energy.c: the mechanical energy and momenta of bodies and of the world
 * (energy.h). */
#include "energy.h"

energy_sum energy_of_body(const world *w, const body *b)
{
    energy_sum e = {0};
    if (body_is_static(b)) return e;
    vec3 c = body_com(b);
    e.linear = 0.5 * b->mass * v3_len2(b->v);
    e.rotational = 0.5 * v3_dot(b->w, b->L);
    e.potential = -b->mass * v3_dot(world_accel(w), c);
    e.momentum = v3_scale(b->v, b->mass);
    e.angular_momentum = v3_add(v3_cross(c, e.momentum), b->L);
    return e;
}

energy_sum energy_of_world(const world *w)
{
    energy_sum sum = {0};
    for (int i = 0; i < w->n; i++) {
        energy_sum e = energy_of_body(w, w->bodies[i]);
        sum.linear += e.linear;
        sum.rotational += e.rotational;
        sum.potential += e.potential;
        sum.momentum = v3_add(sum.momentum, e.momentum);
        sum.angular_momentum = v3_add(sum.angular_momentum, e.angular_momentum);
    }
    return sum;
}
