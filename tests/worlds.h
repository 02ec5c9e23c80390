/* worlds.h: building small worlds in unit tests (include after check.h). */
#ifndef VROC_TEST_WORLDS_H
#define VROC_TEST_WORLDS_H

#include <stdlib.h>

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

#endif
