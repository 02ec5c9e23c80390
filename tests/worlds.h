/* worlds.h: building small worlds in unit tests (include after check.h). */
#ifndef VROC_TEST_WORLDS_H
#define VROC_TEST_WORLDS_H

#include <stdlib.h>

#include "core/tolerance.h"
#include "core/world.h"

/* A new object of the given kind with the thesis's defaults, built and added to w. */
static inline body *add(world *w, const char *name, shape_kind kind)
{
    body *b = malloc(sizeof *b);
    assert_non_null(b);
    body_init(b, name, kind);
    char err[256];
    assert_int_equal(body_build(b, err, sizeof err), 0);
    assert_true(world_add(w, b) >= 0);
    return b;
}

/* A static cube named name with half-extents size, built and added to w (at the
 * origin: place it with x). */
static inline body *add_static_box(world *w, const char *name, vec3 size)
{
    body *b = add(w, name, SHAPE_CUBE);
    b->sp.size = size;
    char err[256];
    assert_int_equal(body_build(b, err, sizeof err), 0);
    body_set_mass(b, -1);
    return b;
}

/* Builds b again after its shape parameters changed. */
static inline void rebuild(body *b)
{
    char err[256];
    assert_int_equal(body_build(b, err, sizeof err), 0);
}

/* A dynamic ball of radius r, built and added to w (at the origin). */
static inline body *add_ball(world *w, const char *name, double r)
{
    body *b = add(w, name, SHAPE_SPHERE);
    b->sp.radius = r;
    rebuild(b);
    return b;
}

/* A dynamic box with half-extents size, built and added to w (at the origin). */
static inline body *add_box(world *w, const char *name, vec3 size)
{
    body *b = add(w, name, SHAPE_CUBE);
    b->sp.size = size;
    rebuild(b);
    return b;
}

/* A uniform number in [lo, hi) from a 64-bit LCG: the same sequence everywhere. */
static inline double urand(unsigned long long *s, double lo, double hi)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*s >> 11) / 9007199254740992.0;
}

/* A shot of the thin-plate tests: an object of kind with sizes drawn from [0.05,
 * 0.3) m and superquadric exponents from [0.3, 2), rebuilt. */
static inline body *add_random_shot(world *w, shape_kind kind, unsigned long long *seed)
{
    body *b = add(w, "shot", kind);
    b->sp.radius = urand(seed, 0.05, 0.3);
    b->sp.size = v3(urand(seed, 0.05, 0.3), urand(seed, 0.05, 0.3), urand(seed, 0.05, 0.3));
    b->sp.a1 = urand(seed, 0.05, 0.3);
    b->sp.exp1 = urand(seed, 0.3, 2);
    b->sp.exp2 = urand(seed, 0.3, 2);
    rebuild(b);
    return b;
}

/* The limit of vanishing gaps (issue 34; instant.h) for a ball of mass m1 at
 * velocity *v1 that strikes a ball of mass m2 at *v2 lying on a floor (normal +z),
 * n the unit line of centres from the lower ball to the upper: each contact that
 * closes is answered in turn as the textbook impact of two bodies along their
 * normal (the balls along n with restitution e12, the lower ball on the floor
 * along z with e2f; a rebound slower than SIM_BOUNCE_SPEED none, for e < 1),
 * until neither closes.  The velocities after in *v1 and *v2, each contact's
 * impulses summed in *j12 and *j2f; returns the number of impacts (at most 8:
 * the instant's 4 n waves of n = 2 contacts).  The two never close at once in
 * the tests' set-ups: asserted. */
static inline int balls_on_floor(double m1, vec3 *v1, double m2, vec3 *v2, vec3 n, double e12,
                                 double e2f, double *j12, double *j2f)
{
    int waves = 0;
    *j12 = *j2f = 0;
    for (;;) {
        double c12 = -v3_dot(v3_sub(*v1, *v2), n), c2f = -v2->z;
        bool balls = c12 > 1e-12, floor = c2f > 1e-12;
        if (!balls && !floor) return waves;
        assert_false(balls && floor);
        assert_true(++waves <= 8);
        double c = balls ? c12 : c2f, e = balls ? e12 : e2f;
        if (e < 1 && e * c < SIM_BOUNCE_SPEED) e = 0;
        if (balls) {
            double j = (1 + e) * c / (1 / m1 + 1 / m2);
            *v1 = v3_mad(*v1, n, j / m1);
            *v2 = v3_mad(*v2, n, -j / m2);
            *j12 += j;
        } else {
            v2->z += (1 + e) * c;
            *j2f += m2 * (1 + e) * c;
        }
    }
}

#endif
