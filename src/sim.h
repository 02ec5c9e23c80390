/* sim.h: advancing simulated time (thesis 3.2.3 and 3.4.2).
 *
 * A frame of time_step is cut into world_subframes() equal internal steps.  Within
 * an internal step every dynamic body flies freely under the global acceleration:
 * linear motion exactly (x += v h + a h^2/2, v += a h), rotation by a symmetric
 * splitting about the principal axes that keeps the angular momentum L exactly and
 * the energy to O(h^2) (Dullweber, Leimkuhler and McLachlan 1997), then the speed
 * limits max_linear and max_angular.
 */
#ifndef VROC_SIM_H
#define VROC_SIM_H

#include <stddef.h>

#include "world.h"

/* Most internal steps one frame may take; more is an error asking for fewer. */
#define SIM_MAX_SUBFRAMES 1000000L

/* Advances the world by one frame.  Returns 0, or -1 with a message in err when the
 * settings ask for more than SIM_MAX_SUBFRAMES internal steps (nothing moves then).
 * With time_step 0 nothing moves and the frame still counts. */
int sim_frame(world *w, char *err, size_t errlen);

/* Free flight of one dynamic body over h seconds under acceleration a, then the
 * speed limits. */
void sim_flight(body *b, double h, vec3 a, double max_linear, double max_angular);

#endif
