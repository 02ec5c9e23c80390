/* limits.h: the ranges of the values a command may give the world, under which
 * every later computation stays finite.
 *
 * The shell refuses a value outside them (its command table names them); the
 * core assumes them.  What they keep finite, with room to spare (doubles reach
 * 1.8e308; the smallest normal one is 2.2e-308):
 *
 *   inertia      m r^2 <= 1e9 * 1e8 = 1e17 kg m^2, and >= 1e-9 * 1e-12 = 1e-21;
 *                the shapes' volumes and second moments before the mass scales
 *                them, r^3 and r^5, stay within 1e-30 .. 1e20
 *   momentum     m v <= 1e9 * 1e4, angular I w <= 1e17 * 1e4 = 1e21, whose
 *                square the free rotation takes: 1e42
 *   energy       m v^2 <= 1e17 J, I w^2 <= 1e25 J
 *   reach        speed x time: 1e4 m/s over a frame of 1e3 s, 1e7 m, and a
 *                position of 1e6 m: their squares (distances) stay below 1e15
 *   steps        time_step / h, h = collision_dist / (2 max_linear) or
 *                internal_step: at most 1e3 / (1e-6 / 2e4) = 2e13, a count a long
 *                holds; a frame that needs more than SIM_MAX_SUBFRAMES is refused
 *                when it is run (sim.h)
 *
 * Sizes run from a micrometre to ten kilometres, masses from a microgram to a
 * million tonnes, speeds to 10 km/s: far beyond any scene of the thesis.  At the
 * far edge of positions rounding comes near: a double resolves 1.2e-10 m at
 * 1e6 m, an eighth of the contact distance (SIM_TOUCH, tolerance.h).  A velocity or an angular velocity
 * may be any finite vector: edit.h limits it to max_linear or max_angular as it
 * is set.
 */
#ifndef VROC_LIMITS_H
#define VROC_LIMITS_H

/* lengths (m): radius, size, a1..a3, collision_dist, ipd (which may also be 0) */
#define LIM_LENGTH_MIN 1e-6
#define LIM_LENGTH_MAX 1e4
/* coordinates of a point (m): translate, head, look_at, hand, and of a direction
 * (rotate's axis, force's direction, up), which must be at least LIM_DIR_MIN long
 * so that it has a direction to the last bit */
#define LIM_POSITION_MAX 1e6
#define LIM_DIR_MIN 1e-6
/* |mass| (kg); a negative mass makes an object static */
#define LIM_MASS_MIN 1e-9
#define LIM_MASS_MAX 1e9
/* speed limits: max_linear (m/s), max_angular (rad/s) */
#define LIM_SPEED_MAX 1e4
#define LIM_SPIN_MAX 1e4
/* times (s): time_step, internal_step, each 0 (halt, automatic) or in range */
#define LIM_TIME_MIN 1e-6
#define LIM_TIME_MAX 1e3
/* |force| (m/s^2), about a thousand g */
#define LIM_ACCEL_MAX 1e4
/* |angle| (rad) of rotate and hand_rotate */
#define LIM_ANGLE_MAX 1e6
/* superquadric exponents: from a box's (near 0) to far past the pinched shapes
 * above 2, whose collision shape is their tessellation's hull */
#define LIM_EXP_MIN 1e-3
#define LIM_EXP_MAX 100
/* friction and rolling_friction: far past any real surface's */
#define LIM_FRICTION_MAX 1e3
/* loudness: volume, collision_vol (1 is the default, 1e3 is 60 dB louder) */
#define LIM_LOUD_MAX 1e3
/* random_box half-extents (m) */
#define LIM_RANDOM_BOX_MIN 1e-4
/* random_size (m): each of random's objects has half-extents from 0.6 to 1 times
 * the size drawn, so that they stay within the lengths above */
#define LIM_RANDOM_SIZE_MIN 1e-5
/* exact state (save): angular momentum (kg m^2/s), as I w above; the clock's base
 * time (s) and frame counts, which a double holds exactly below 2^53 */
#define LIM_MOMENTUM_MAX 1e21
#define LIM_CLOCK_MAX 1e12
#define LIM_FRAMES_MAX 1e15

#endif
