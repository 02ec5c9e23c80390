/* panel.h: the virtual tool panel's layout and where the hand touches it (thesis
 * Appendix A.1.2; language.md, "The hand and the tool panel").
 *
 * The panel is a 0.45 x 0.25 m sheet in its own x-y plane (x to the right, y up,
 * its front facing +z), placed at `at` and turned by q.  Its upper half holds four
 * 0.08 m square buttons, Stop, Start, Step and Select; its lower half two sliders
 * along x from -0.18 (value 0) to +0.18 (value 2), time_step and collision_dist.
 * The hand touches a control when it is within 0.02 m of the sheet's plane and over
 * the control (a slider's band is 0.04 m tall about its line).  The panel is no part
 * of the simulation: nothing collides with it.
 */
#ifndef VROC_PANEL_H
#define VROC_PANEL_H

#include <stdbool.h>

#include "core/vmath.h"

typedef enum {
    PANEL_STOP,
    PANEL_START,
    PANEL_STEP,
    PANEL_SELECT,
    PANEL_TIME_STEP,      /* the sliders */
    PANEL_COLLISION_DIST,
    PANEL_CONTROLS,       /* how many controls there are */
    PANEL_SHEET = PANEL_CONTROLS, /* the sheet outside every control */
    PANEL_OFF             /* not on the sheet */
} panel_part;

#define PANEL_HALF_W 0.225
#define PANEL_HALF_H 0.125
#define PANEL_REACH 0.02        /* how near the sheet's plane the hand presses */
#define PANEL_SLIDER_END 0.18   /* the sliders run from x = -0.18 to +0.18 */
#define PANEL_SLIDER_MAX 2.0    /* the value at +0.18 */

/* One control: a button (its square) or a slider (its band), in the sheet's
 * coordinates, and the command word it stands for. */
typedef struct {
    const char *name;     /* stop, start, step, select, time_step, collision_dist */
    bool slider;
    double x, y;          /* centre */
    double half_w, half_h;
} panel_control;

/* Control k (k < PANEL_CONTROLS). */
const panel_control *panel_control_of(panel_part k);

/* Where the hand's point p (world) is on the panel at `at`, turned by q. */
panel_part panel_hit(vec3 at, quat q, vec3 p);

/* The value of a slider under p: 2 (x + 0.18) / 0.36 in the sheet's x, clamped to
 * [lo, 2]. */
double panel_slider_value(vec3 at, quat q, vec3 p, double lo);

/* The sheet's x at which a slider shows value v (clamped to [0, 2]). */
double panel_slider_x(double v);

#endif
