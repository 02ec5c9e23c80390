/* place.c: a collision placed by the head pose (place.h). */
#include "place.h"

#include <math.h>

place_result place_hit(const sound_listener *l, vec3 p)
{
    place_result r;
    vec3 d = v3_sub(p, l->head);
    double dist = v3_len(d);
    if (!isfinite(dist)) dist = 0;
    r.dist = dist;
    vec3 right = v3_cross(v3_sub(l->look_at, l->head), l->up);
    double rl = v3_len(right), side = 0;
    if (rl > 1e-12 && dist > 1e-12 && isfinite(rl)) side = v3_dot(right, d) / (rl * dist);
    side = fmax(-1, fmin(1, side));
    double theta = asin(fabs(side));
    double itd = PLACE_HEAD_RADIUS / PLACE_SPEED * (theta + sin(theta));
    double g = 1.0 / fmax(dist, PLACE_MIN_DIST);
    int near = side >= 0 ? 1 : 0;
    double t = dist / PLACE_SPEED;
    r.delay[near] = fmax(0, t - 0.5 * itd);
    r.delay[1 - near] = t + 0.5 * itd;
    r.gain[near] = g;
    r.gain[1 - near] = g * (1 - 0.7 * fabs(side));
    return r;
}
