/* edit.c: the changes a command makes to the world (edit.h). */
#include "edit.h"

#include <math.h>
#include <stdio.h>

#include "rest.h"

/* Builds body b again after its shape parameters changed from old; on failure
 * restores old and returns -1 with err. */
static int rebuild(body *b, shape_params old, char *err, size_t errlen)
{
    if (body_build(b, err, errlen) != 0) {
        b->sp = old;
        return -1;
    }
    return 0;
}

/* v, or v scaled down to length max when it is longer: for any finite v, since the
 * length is taken of v over its largest component (no square overflows).  A
 * length within rounding of max (a speed the simulation limited, saved and read
 * back) is left to the last bit; the flight's own limit is the same. */
static vec3 limit_length(vec3 v, double max)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (!(m > 0)) return v;
    vec3 u = v3(v.x / m, v.y / m, v.z / m);
    double l = v3_len(u); /* 1 to sqrt(3) */
    if (m <= max / l * (1 + 1e-12)) return v;
    return v3_scale(u, max / l);
}

int edit_property(world *w, int i, size_t off, const double *num, char *err, size_t errlen)
{
    body *b = w->bodies[i];
    vec3 v = v3(num[0], num[1], num[2]);
    shape_params old = b->sp;
    /* anything but the look or the sound of an object wakes it */
    if (off != offsetof(body, color) && off != offsetof(body, volume)) {
        if (b->state == STATE_RESTING) b->state = STATE_DYNAMIC;
        b->slide = -1;
    }
    /* objects resting on this one lose their support's old place */
    rest_wake_on(w, i);
    switch (off) {
    case offsetof(body, v): b->v = limit_length(v, w->set.max_linear); return 0;
    case offsetof(body, w): body_set_angular_vel(b, limit_length(v, w->set.max_angular)); return 0;
    case offsetof(body, elasticity): b->elasticity = num[0]; return 0;
    case offsetof(body, mass):
        body_set_mass(b, num[0]);
        w->pairs.dirty = true; /* static objects have no pairs among themselves */
        return 0;
    case offsetof(body, volume): b->volume = num[0]; return 0;
    case offsetof(body, x): b->x = v; return 0;
    case offsetof(body, rot_axis): body_set_rotation(b, v, num[3]); return 0;
    case offsetof(body, color):
        for (int k = 0; k < 3; k++) b->color[k] = (int)num[k];
        return 0;
    case offsetof(body, sp.radius): b->sp.radius = num[0]; break;
    case offsetof(body, sp.size): b->sp.size = v; break;
    case offsetof(body, sp.exp1): b->sp.exp1 = num[0]; break;
    case offsetof(body, sp.exp2): b->sp.exp2 = num[0]; break;
    case offsetof(body, sp.a1): b->sp.a1 = num[0]; break;
    case offsetof(body, sp.a2): b->sp.a2 = num[0]; break;
    case offsetof(body, sp.a3): b->sp.a3 = num[0]; break;
    case offsetof(body, sp.ures): b->sp.ures = (int)num[0]; break;
    case offsetof(body, sp.vres): b->sp.vres = (int)num[0]; break;
    default: snprintf(err, errlen, "no property at offset %zu", off); return -1;
    }
    return rebuild(b, old, err, errlen);
}

void edit_force(world *w, dir_amount force)
{
    rest_wake_all(w); /* rest depends on the force */
    w->set.force = force;
}

void edit_done(world *w)
{
    w->sched_dirty = true;
}
