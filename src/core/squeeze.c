/* squeeze.c: where a held object must stop (squeeze.h). */
#include "squeeze.h"

#include "retime.h"
#include "step.h"
#include "world.h"

void squeeze_hold_stop(world *w, int i, double t)
{
    body *b = w->bodies[i];
    step_sync(w, i, t);
    b->hold_v = b->v = v3(0, 0, 0);
    body_set_angular_vel(b, v3(0, 0, 0));
    retime_object(w, i, t);
}
