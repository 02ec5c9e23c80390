/* force.h: the global force (Table A.5's `force`, `gravity`) as each body feels it.
 *
 * The force is a uniform acceleration on every dynamic body.  A body sliding on a
 * support (rest.h) feels it less the part that presses it onto the support.
 */
#ifndef VROC_FORCE_H
#define VROC_FORCE_H

#include "body.h"
#include "hold.h"
#include "vmath.h"

/* The acceleration of force f: f.dir / |f.dir| * f.amount (zero when none).
 * Inline, as is the next: the schedule and every flight ask for it. */
static inline vec3 force_accel(dir_amount f)
{
    /* a unit direction (gravity's (0, 0, -1)) needs no square root: the same to
     * the bit as normalising it */
    if (v3_len2(f.dir) == 1) return v3_scale(f.dir, f.amount);
    return v3_scale(v3_norm(f.dir), f.amount);
}

/* The acceleration of force f as body b feels it: less the part that presses it
 * onto the support it slides on.  A held body (hold.h) feels none: its centre of
 * mass accelerates only as it turns about the hand. */
static inline vec3 force_on(dir_amount f, const body *b)
{
    if (b->held) return hold_accel(b);
    vec3 a = force_accel(f);
    if (b->slide < 0) return a;
    double an = v3_dot(a, b->slide_n);
    return an < 0 ? v3_mad(a, b->slide_n, -an) : a;
}

#endif
