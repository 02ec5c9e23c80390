/* edit.c: the changes a command makes to the world (edit.h). */
#include "edit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "friction.h"
#include "limits.h"
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

/* Object i's lasting contacts end. */
static void end_contacts(world *w, int i)
{
    for (long k = 0; k < w->pairs.n; k++) {
        pair *p = &w->pairs.p[k];
        if (p->a >= 0 && (p->a == i || p->b == i)) p->touching = false;
    }
}

/* Object i and every dynamic object pressed together with it move again, and find
 * their modes anew when time next runs; when `moved`, what i touches is found anew
 * too (its lasting contacts end).  (A scan of the pairs: the schedule's lists of
 * them may be out of date while commands run.) */
static void disturb(world *w, int i, bool moved)
{
    bool grew = true;
    w->bodies[i]->woken = true;
    while (grew) {
        grew = false;
        for (long k = 0; k < w->pairs.n; k++) {
            pair *p = &w->pairs.p[k];
            if (p->a < 0 || !p->touching || p->a >= w->n || p->b >= w->n) continue;
            body *a = w->bodies[p->a], *b = w->bodies[p->b];
            if (a->woken != b->woken) {
                body *o = a->woken ? b : a;
                if (!body_is_static(o)) {
                    o->woken = true;
                    grew = true;
                }
            }
        }
    }
    for (int k = 0; k < w->n; k++) {
        body *b = w->bodies[k];
        if (b->woken && b->state == STATE_RESTING) rest_wake(w, k);
    }
    if (!moved) return;
    w->bodies[i]->moved = true;
    end_contacts(w, i);
}

/* v, or v scaled down to length max when it is longer: for any finite v, since the
 * length is taken of v over its largest component (no square overflows).  A
 * length within rounding of max (a speed the simulation limited, saved and read
 * back) is left to the last bit. */
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
    /* the look or the sound of an object change nothing else */
    switch (off) {
    case offsetof(body, color):
        for (int k = 0; k < 3; k++) b->color[k] = (int)num[k];
        return 0;
    case offsetof(body, volume): b->volume = num[0]; return 0;
    case offsetof(body, elasticity):
        b->elasticity = num[0];
        disturb(w, i, false);
        return 0;
    case offsetof(body, friction):
        b->friction = num[0];
        disturb(w, i, false);
        return 0;
    case offsetof(body, rolling_friction):
        b->rolling_friction = num[0];
        disturb(w, i, false);
        return 0;
    case offsetof(body, v):
        b->v = limit_length(v, w->set.max_linear);
        disturb(w, i, false);
        return 0;
    case offsetof(body, w):
        body_set_angular_vel(b, limit_length(v, w->set.max_angular));
        disturb(w, i, false);
        return 0;
    case offsetof(body, mass):
        if (b->sp.kind == SHAPE_POLYHEDRON && (num[0] < 0) != b->sp.fixed) {
            /* a static polyhedron's open pieces are slabs, a moving one's hulls */
            double was = b->mass;
            b->sp.fixed = num[0] < 0;
            b->mass = num[0];
            if (rebuild(b, old, err, errlen) != 0) {
                b->mass = was;
                return -1;
            }
        }
        disturb(w, i, true);
        body_set_mass(b, num[0]);
        if (num[0] < 0) b->held = false; /* (the hand lets go: hold.h) */
        w->pairs.dirty = true; /* static objects have no pairs among themselves */
        return 0;
    case offsetof(body, x):
        disturb(w, i, true);
        b->x = v;
        return 0;
    case offsetof(body, rot_axis):
        disturb(w, i, true);
        body_set_rotation(b, v, num[3]);
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
    case offsetof(body, sp.scale): b->sp.scale = v; break;
    case offsetof(body, sp.thickness): b->sp.thickness = num[0]; break;
    default: snprintf(err, errlen, "no property at offset %zu", off); return -1;
    }
    if (rebuild(b, old, err, errlen) != 0) return -1;
    disturb(w, i, true);
    return 0;
}

int edit_source(world *w, int i, shape_source *src, char *err, size_t errlen)
{
    body *b = w->bodies[i];
    shape_params old = b->sp;
    b->sp.src = src;
    if (rebuild(b, old, err, errlen) != 0) {
        shape_source_release(src);
        return -1;
    }
    shape_source_release(old.src);
    disturb(w, i, true);
    return 0;
}

void edit_force(world *w, dir_amount force)
{
    /* rest and slides depend on the force */
    for (int i = 0; i < w->n; i++) {
        if (body_is_static(w->bodies[i])) continue;
        w->bodies[i]->woken = true;
        if (w->bodies[i]->state == STATE_RESTING) rest_wake(w, i);
    }
    w->set.force = force;
}

void edit_unpress(world *w, int i)
{
    disturb(w, i, false);
    end_contacts(w, i);
}

/* True when some component of v is beyond max (by magnitude). */
static bool beyond(vec3 v, double max)
{
    return fabs(v.x) > max || fabs(v.y) > max || fabs(v.z) > max;
}

bool edit_beyond_limits(const world *w, int i)
{
    const body *b = w->bodies[i];
    if (body_is_static(b)) return false;
    return beyond(b->x, LIM_POSITION_MAX) || beyond(b->v, LIM_SPEED_MAX) ||
           beyond(b->L, LIM_MOMENTUM_MAX);
}

void edit_rest_at_limits(world *w, int i)
{
    body *b = w->bodies[i];
    edit_unpress(w, i);
    const double m = LIM_POSITION_MAX;
    b->x = v3(d_max(-m, d_min(m, b->x.x)), d_max(-m, d_min(m, b->x.y)), d_max(-m, d_min(m, b->x.z)));
    b->v = b->w = b->L = v3(0, 0, 0);
    b->mode = MODE_FREE;
    b->slide_on = b->slide_face = -1;
    b->state = STATE_RESTING;
    /* placed: what it touches where it rests is found anew, and it wakes if so */
    b->moved = true;
    b->woken = false;
    edit_done(w);
}

void edit_delete(world *w, int i)
{
    for (long k = 0; k < w->pairs.n; k++) {
        pair *p = &w->pairs.p[k];
        if (p->a < 0 || !p->touching || (p->a != i && p->b != i)) continue;
        int o = p->a == i ? p->b : p->a;
        if (!body_is_static(w->bodies[o])) disturb(w, o, false);
    }
    world_delete(w, i);
}

void edit_exact_orientation(world *w, int i, quat q)
{
    body *b = w->bodies[i];
    if (memcmp(&b->q, &q, sizeof q) == 0)
        return; /* as it stands (an orientation typed with rotate, saved and read back) */
    q = q_as_unit(q);
    disturb(w, i, true);
    b->q = q;
    b->rot_given = false;
    body_set_angular_vel(b, b->w);
}

void edit_exact_velocity(world *w, int i, vec3 v)
{
    disturb(w, i, false);
    w->bodies[i]->v = v;
}

/* True when a and b are the same vector to the bit. */
static bool same_bits(vec3 a, vec3 b) { return memcmp(&a, &b, sizeof a) == 0; }

void edit_exact_momentum(world *w, int i, vec3 L)
{
    body *b = w->bodies[i];
    disturb(w, i, false);
    /* the angular velocity as it stands when it gives exactly L (one typed with
     * angular_vel, saved and read back), else the one L gives */
    bool as_typed = !body_is_static(b) && same_bits(m3_mulv(body_inertia_world(b), b->w), L);
    b->L = L;
    if (!as_typed) body_update_w(b);
}

void edit_exact_support(world *w, int i, int support, int face)
{
    body *b = w->bodies[i];
    b->slide_on = support;
    b->slide_face = face;
}

int edit_exact_contact(world *w, int i, body_mode mode, bool resting, char *err, size_t errlen)
{
    body *b = w->bodies[i];
    if (body_is_static(b)) {
        if (mode != MODE_FREE || resting) {
            snprintf(err, errlen, "'%s' is static: it neither slides, leans nor rests", b->name);
            return -1;
        }
        b->moved = b->woken = false; /* placed as saved */
        return 0;
    }
    if (mode == MODE_ROLL && !friction_ball(b)) {
        snprintf(err, errlen, "only a ball rolls: '%s' is not a sphere", b->name);
        return -1;
    }
    if (body_mode_on_face(mode)) {
        int support = b->slide_on, face = b->slide_face;
        const body *s = support >= 0 && support < w->n ? w->bodies[support] : NULL;
        int local;
        const poly *h = s && body_is_static(s) ? shape_face(&s->shape, face, &local) : NULL;
        if (!h) {
            const char *what = mode == MODE_SLIDE ? "a slide" : mode == MODE_STICK ? "mode = stick" : "mode = roll";
            snprintf(err, errlen, "%s needs slide_on, a static object, and slide_face, one of its "
                     "faces, before it", what);
            return -1;
        }
        b->slide_n = v3_norm(q_rotate(s->q, h->f[local].n));
    } else {
        b->slide_on = b->slide_face = -1;
    }
    b->mode = mode;
    b->state = resting ? STATE_RESTING : STATE_DYNAMIC;
    b->moved = b->woken = false;
    return 0;
}

int edit_exact_touching(world *w, int i, int j, char *err, size_t errlen)
{
    const body *a = w->bodies[i], *b = w->bodies[j];
    if (i == j || (body_is_static(a) && body_is_static(b))) {
        snprintf(err, errlen, "'%s' and '%s' cannot be in contact: %s", a->name, b->name,
                 i == j ? "the same object" : "both are static");
        return -1;
    }
    /* the pairs and the boxes of the objects as placed, then this contact's pair:
     * a lasting contact is kept a little way apart (SIM_HOVER), where the two
     * boxes need not meet, and the simulation keeps its pair whatever the boxes
     * say (pairs.h) */
    long k = -1;
    if (pairs_update(w) == 0 && pair_near(w, i, j) == 0) k = pair_index(w, i, j);
    if (k < 0) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    w->pairs.p[k].touching = true;
    return 0;
}

void edit_clock(world *w, double base, long frames)
{
    w->time_base = base;
    w->base_frames = frames;
    w->base_step = w->set.time_step;
    w->time = base + (double)frames * w->base_step;
}

void edit_done(world *w)
{
    w->sched_dirty = true;
}
