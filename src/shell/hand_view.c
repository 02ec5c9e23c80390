/* hand_view.c: what the views draw of the hand and the tool panel (view.h's
 * view_overlay), made from the hand and the panel's layout (hand/panel.h). */
#include <stdio.h>

#include "shell.h"

/* The pictures of the buttons, in panel_part's order. */
static const view_icon icons[PANEL_CONTROLS] = {VIEW_ICON_STOP, VIEW_ICON_START, VIEW_ICON_STEP,
                                                VIEW_ICON_SELECT, VIEW_ICON_NONE, VIEW_ICON_NONE};

void shell_overlay(shell *sh)
{
    const hand *h = &sh->hand;
    view_overlay *o = &sh->view_set.overlay;
    o->hand = h->used;
    o->hand_p = h->p;
    o->hand_q = h->q;
    o->panel = h->set.panel;
    o->panel_at = h->set.panel_at;
    o->panel_q = hand_panel_q(h);
    o->half_w = PANEL_HALF_W;
    o->half_h = PANEL_HALF_H;
    o->ncontrols = PANEL_CONTROLS;
    for (int k = 0; k < PANEL_CONTROLS; k++) {
        const panel_control *c = panel_control_of((panel_part)k);
        view_control *v = &o->controls[k];
        *v = (view_control){c->slider, c->x, c->y, c->half_w, c->half_h, "", icons[k], 0, false};
        double value = k == PANEL_TIME_STEP ? sh->w.set.time_step : sh->w.set.collision_dist;
        if (c->slider) {
            v->knob = c->x + panel_slider_x(value);
            snprintf(v->label, sizeof v->label, "%s %.3g", c->name, value);
        } else {
            snprintf(v->label, sizeof v->label, "%s", c->name);
        }
    }
    o->controls[PANEL_START].lit = sh->running;
    o->controls[PANEL_STOP].lit = !sh->running;
    o->controls[PANEL_SELECT].lit = h->set.select_mode;
}
