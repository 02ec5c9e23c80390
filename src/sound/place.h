/* place.h: where a collision is heard: its delay and loudness in each ear.
 *
 * The listener is the head pose of the views (head, look_at, up; language.md,
 * "Head, hand and views"), its right axis look_at - head crossed with up.  A sound
 * made at p reaches the centre of the head after |p - head| / 343 s, 1/r as loud
 * (r held at PLACE_MIN_DIST or more, so that a collision at the head is loud, not
 * infinite).  Its side, s = sin(azimuth) = the right axis . (p - head) / r, gives
 *   - an interaural time difference by Woodworth's spherical head (radius
 *     8.75 cm): ITD = a / c (theta + sin theta), theta = asin |s|, up to 0.66 ms,
 *     the near ear early by half of it and the far ear late by half;
 *   - an interaural level difference: the near ear at 1/r, the far ear at
 *     (1 - 0.7 |s|) / r, 10.5 dB quieter for a sound straight to the side.
 * Ear 0 is the left, ear 1 the right.  A head pose with no right axis (head at
 * look_at, or up along the view) hears everything straight ahead. */
#ifndef VROC_SOUND_PLACE_H
#define VROC_SOUND_PLACE_H

#include "core/vmath.h"

#define PLACE_SPEED 343.0     /* m/s, sound in air at 20 C */
#define PLACE_MIN_DIST 0.1    /* m */
#define PLACE_HEAD_RADIUS 0.0875

typedef struct {
    vec3 head, look_at, up;
} sound_listener;

typedef struct {
    double delay[2]; /* s, from the collision to each ear (>= 0) */
    double gain[2];  /* each ear's factor: 1/r for the near ear */
    double dist;     /* m, from the centre of the head */
} place_result;

place_result place_hit(const sound_listener *l, vec3 p);

#endif
