/* body.h: one object of the world: its shape, its physical properties and its state.
 *
 * A body holds what the thesis's Tables A.1 to A.4 set (body_defaults gives their
 * defaults in one place) and the state the simulation advances.  The state is the
 * position of the object's origin x, its orientation q (body to world), the velocity v
 * of its centre of mass and its angular momentum L about the centre of mass in world
 * axes; the angular velocity w = I_world^-1 L is derived.  Keeping L as the state
 * is what makes free rotation conserve angular momentum for any inertia tensor.
 *
 * Exactness of `print`: the orientation and angular velocity a user typed are kept
 * as typed (rot_axis/rot_angle, w_given) until the simulation changes them, so that
 * print, save and read reproduce the same text to the last digit.
 */
#ifndef VROC_BODY_H
#define VROC_BODY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "closest.h"
#include "shape.h"
#include "vmath.h"

#define BODY_NAME_MAX 64

typedef enum { STATE_DYNAMIC, STATE_STATIC, STATE_RESTING } body_state;

/* How a dynamic body moves (rest.h): freely; sliding on a face of a still support
 * (translating along it, turning about its normal only; with friction, slipping
 * against it in closed form); pressed against others in ways that need the
 * contact forces found as it goes (a cluster: tipping, pivoting, stacks and
 * piles that move); stuck by friction on a face of a still support; or, a
 * ball, rolling on one without slipping.  (The order is the language's:
 * `mode = free|slide|general|stick|roll`.) */
typedef enum { MODE_FREE, MODE_SLIDE, MODE_GENERAL, MODE_STICK, MODE_ROLL } body_mode;

/* True for the modes of a body on a face of a still support (slide_on,
 * slide_face, slide_n hold it). */
static inline bool body_mode_on_face(body_mode m)
{
    return m == MODE_SLIDE || m == MODE_STICK || m == MODE_ROLL;
}

typedef struct body {
    char name[BODY_NAME_MAX];
    shape_params sp;   /* the parameters as set; the body owns sp.src */
    shape shape;       /* geometry built from sp */
    bool built;        /* shape is built and matches sp */
    int fell;          /* 1 once it has fallen more than SIM_FALL_DEPTH below the
                        * lowest static object (sim.c), 2 once that was told
                        * (the shell's warning), else 0 */

    double mass;       /* > 0 dynamic; < 0 static (infinite mass) */
    double elasticity; /* [0, 1] */
    double friction;   /* Coulomb's coefficient, >= 0 (friction.h) */
    double rolling_friction; /* rolling resistance, >= 0 (friction.h) */
    double volume;     /* loudness of collision sounds, >= 0 */
    int color[3];      /* 0..255 */

    /* inertia, derived from shape and mass */
    double inv_mass;   /* 0 for static objects */
    mat3 I_body;       /* inertia tensor about the com, body axes (mass-scaled) */
    mat3 I_body_inv;   /* its inverse (zero for static objects) */
    quat q_principal;  /* principal axes in body axes: I_body = P diag(I_princ) P^T */
    vec3 I_princ;      /* principal moments */

    /* state: from x to the end, what the simulation changes (body_copy_state) */
    vec3 x;            /* origin in world coordinates (translate) */
    quat q;            /* orientation, body to world */
    vec3 v;            /* velocity of the centre of mass */
    vec3 L;            /* angular momentum about the centre of mass, world axes */
    vec3 w;            /* angular velocity, world axes (derived from L, or as typed) */
    body_state state;
    /* held by the hand (hold.h): it moves as the hand sets it, not by forces */
    bool held;
    vec3 hold_pivot;   /* the point it turns about (the hand's) */
    vec3 hold_v;       /* that point's velocity; w is the body's own, constant */

    /* orientation as typed with `rotate`, valid while rot_given */
    vec3 rot_axis;
    double rot_angle;
    bool rot_given;

    body_mode mode;    /* how a dynamic body moves (sim.h): free, sliding, or in a
                        * cluster of bodies pressed together (general) */
    int slide_on;      /* on a face (body_mode_on_face): the static object, or -1, */
    int slide_face;    /*   the face of it, */
    vec3 slide_n;      /*   and that face's normal, towards this body */
    bool moved;        /* a command placed, turned, reshaped it or changed its mass
                        * since the simulation last ran: what it touches is found
                        * anew */
    bool woken;        /* a command changed its motion or what it presses on: its
                        * mode is found anew */
} body;

/* Copies src's state (x to the end) over dst's, for a dst that is a copy of the
 * same body: the simulation's copies of a body within a frame differ only there. */
static inline void body_copy_state(body *dst, const body *src)
{
    memcpy((char *)dst + offsetof(body, x), (const char *)src + offsetof(body, x),
           sizeof(body) - offsetof(body, x));
}

/* A fresh body of the given kind named name, with the thesis's defaults:
 * mass 1, elasticity 1, no friction (the thesis's), volume 1, colour (255,0,0), at the origin, identity
 * orientation, at rest; the shape is not built yet (body_build does it). */
void body_init(body *b, const char *name, shape_kind kind);

/* (Re)builds the shape and the inertia from sp and mass.  Keeps x, q, v and w
 * (L is recomputed from w).  Returns 0, or -1 with a message in err; on failure the
 * body keeps its previous shape. */
int body_build(body *b, char *err, size_t errlen);

/* Frees the shape and the polyhedron's source. */
void body_free(body *b);

/* Sets the mass (non-zero; negative: static) and recomputes the inertia, keeping
 * the angular velocity. */
void body_set_mass(body *b, double mass);

static inline bool body_is_static(const body *b) { return b->mass < 0; }

/* Centre of mass in world coordinates. */
static inline vec3 body_com(const body *b)
{
    vec3 c = b->shape.mass.com;
    if (c.x == 0 && c.y == 0 && c.z == 0) return b->x; /* every shape vroc builds */
    return v3_add(b->x, q_rotate(b->q, c));
}

/* The world inertia tensor R I_body R^T. */
mat3 body_inertia_world(const body *b);

/* Its inverse times v, without forming it: v turned to body axes, times the
 * inverse body tensor, turned back (zero for a static body). */
vec3 body_inertia_inv_mulv(const body *b, vec3 v);

/* Sets the angular velocity (world axes) as typed: w and L = I_world w. */
void body_set_angular_vel(body *b, vec3 w);

/* Sets the orientation from an axis and an angle as typed. */
void body_set_rotation(body *b, vec3 axis, double angle);

/* Recomputes w from L and q (after the simulation changed them). */
void body_update_w(body *b);

/* Kinetic energy (translational + rotational); 0 for static objects. */
double body_energy(const body *b);

/* Distance between bodies a and b from their shape, x and q (closest.h).  cache
 * (may be NULL) gives the features to start from and receives the new ones; for
 * bodies of several pieces it is not used: the least over every pair of their
 * pieces (pieces.h), each from none.  The
 * pair is computed in a canonical order (by name, then by address) so that
 * swapping a and b mirrors the result exactly (pa and pb, fa and fb swapped,
 * normal negated), also when the closest features are not unique.  A body whose
 * shape is not built, or with a non-finite x or q, gives status CLOSEST_INVALID,
 * distance NAN, and leaves the cache alone. */
closest_result body_distance(const body *a, const body *b, closest_cache *cache);

/* The same as closest_distance_apart: no penetration estimate. */
closest_result body_distance_apart(const body *a, const body *b, closest_cache *cache);

/* The canonical order of a pair (body_distance): by name, then by address. */
static inline bool body_before(const body *a, const body *b)
{
    int c = strcmp(a->name, b->name);
    if (c != 0) return c < 0;
    return (uintptr_t)a <= (uintptr_t)b;
}

/* A type name: "sphere", "cube", "superquadric", "polyhedron". */
const char *body_type_name(shape_kind kind);

#endif
