/* panel.c: the tool panel's layout and hit testing (panel.h). */
#include "panel.h"

#include <math.h>
#include <stddef.h>

/* Buttons in a row at y = +0.0625, sliders at y = -0.03 and -0.09 (language.md). */
static const panel_control controls[PANEL_CONTROLS] = {
    {"stop", false, -0.16, 0.0625, 0.04, 0.04},
    {"start", false, -0.0533, 0.0625, 0.04, 0.04},
    {"step", false, 0.0533, 0.0625, 0.04, 0.04},
    {"select", false, 0.16, 0.0625, 0.04, 0.04},
    {"time_step", true, 0, -0.03, PANEL_SLIDER_END, 0.02},
    {"collision_dist", true, 0, -0.09, PANEL_SLIDER_END, 0.02},
};

const panel_control *panel_control_of(panel_part k)
{
    return k >= 0 && k < PANEL_CONTROLS ? &controls[k] : NULL;
}

/* p in the sheet's coordinates. */
static vec3 local(vec3 at, quat q, vec3 p)
{
    return q_unrotate(q, v3_sub(p, at));
}

panel_part panel_hit(vec3 at, quat q, vec3 p)
{
    vec3 l = local(at, q, p);
    if (!(fabs(l.z) <= PANEL_REACH && fabs(l.x) <= PANEL_HALF_W && fabs(l.y) <= PANEL_HALF_H))
        return PANEL_OFF;
    for (int k = 0; k < PANEL_CONTROLS; k++) {
        const panel_control *c = &controls[k];
        if (fabs(l.x - c->x) <= c->half_w && fabs(l.y - c->y) <= c->half_h) return (panel_part)k;
    }
    return PANEL_SHEET;
}

double panel_slider_value(vec3 at, quat q, vec3 p, double lo)
{
    double v = PANEL_SLIDER_MAX * (local(at, q, p).x + PANEL_SLIDER_END) / (2 * PANEL_SLIDER_END);
    return v < lo ? lo : v > PANEL_SLIDER_MAX ? PANEL_SLIDER_MAX : v;
}

double panel_slider_x(double v)
{
    if (!(v > 0)) v = 0;
    if (v > PANEL_SLIDER_MAX) v = PANEL_SLIDER_MAX;
    return v / PANEL_SLIDER_MAX * 2 * PANEL_SLIDER_END - PANEL_SLIDER_END;
}
