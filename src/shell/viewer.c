/* viewer.c: the live window: drawing it, its keys, and the mouse as the head and
 * the hand (viewer.h). */
#include "viewer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "handlers.h"
#include "shell.h"
#include "view/window.h"

#define VIEWER_TICK 0.01       /* s: how often the prompt looks at an open window */
#define VIEWER_SAMPLE_GAP 0.015 /* s: the least wall time between the samples the hand
                                * takes while time stands still (its velocity is their
                                * change over it) */
#define ORBIT_TURN M_PI        /* a drag across the picture's height turns the head so far */
#define ORBIT_POLE 0.01        /* rad: the head stays this far from straight above or below */
#define WHEEL_STEP 1.1         /* a notch of the wheel: distance times or over this */
#define DEPTH_MIN 0.02         /* m: the nearest the hand's plane comes to the head */
#define HEAD_MIN 0.01          /* m: the nearest the head comes to look_at */
#define KEYS_MAX 16

struct viewer {
    window *win;
    bool dirty;             /* to be drawn again */
    double drawn_at;        /* wall clock of the last drawing */
    char said[1024];        /* the last drawing's error, said once */
    char title[96];
    stereo_mode mode;       /* the layout of the picture shown, */
    int eye_w, eye_h;       /*   its eyes' size */
    bool known;             /* the pointer has been on the picture, */
    double x, y;            /*   where it was last */
    bool left, right;       /* buttons held */
    long left_at, right_at; /* hand_live_taken when pressed (-1: no press waits): the
                             * button stays down for the hand until it took a sample */
    long released_at;       /* hand_live_taken when the left button went up */
    bool orbiting;          /* a left drag turns the head */
    bool panel_click;       /* outside select mode, a click on a control of the panel */
    bool had_hand;          /* the mouse had the hand when last looked at */
    double depth;           /* the hand's plane: metres in front of the head */
    int keys[KEYS_MAX], nkeys;
    bool close;             /* Escape or the close button, inside a statement */
    double sampled_at;      /* wall clock of the last sample taken at once */
};

bool viewer_is_open(const shell *sh) { return sh->viewer != NULL; }

/* ---- drawing ---- */

/* The picture's size for a layout of eyes of w x h. */
static void picture_size(stereo_mode m, int w, int h, int *pw, int *ph)
{
    *pw = m == STEREO_PAIR || m == STEREO_SBS ? 2 * w : w;
    *ph = h;
}

static void draw(shell *sh, viewer *v)
{
    char err[1024];
    int pw, ph, rc = -1;
    const view_settings *vs = &sh->view_set;
    v->dirty = false;
    v->drawn_at = shell_clock();
    shell_overlay(sh);
    if (view_render(&sh->view, &sh->w, vs, err, sizeof err) == 0) {
        const unsigned char *pic = view_picture(sh->view, vs->stereo, &pw, &ph);
        rc = pic ? window_show(v->win, pic, pw, ph, err, sizeof err) : -1;
        if (!pic) snprintf(err, sizeof err, "no picture was drawn");
    }
    if (rc == 0) {
        v->mode = vs->stereo;
        v->eye_w = vs->image_w;
        v->eye_h = vs->image_h;
        v->said[0] = '\0';
    } else if (strcmp(err, v->said) != 0) { /* once, not at every frame */
        snprintf(v->said, sizeof v->said, "%s", err);
        sh_warn(sh, NULL, "window: %s", err);
    }
    char a[32], title[sizeof v->title];
    snprintf(title, sizeof title, "vroc: time = %s%s", fmt_shown(a, sh->w.time, shell_shown(sh)),
             sh->running ? " (running)" : "");
    if (strcmp(title, v->title) != 0) {
        snprintf(v->title, sizeof v->title, "%s", title);
        window_title(v->win, title);
    }
}

static void close_window(shell *sh)
{
    viewer *v = sh->viewer;
    if (!v) return;
    hand_live(&sh->hand, &sh->w, NULL);
    window_close(v->win);
    free(v);
    sh->viewer = NULL;
}

cmd_status cmd_window(shell *sh, const stmt *st)
{
    if (st->num[0] == 0) {
        close_window(sh);
        return CMD_OK;
    }
    if (sh->viewer) return CMD_OK;
    viewer *v = calloc(1, sizeof *v);
    if (!v) {
        sh_error(sh, st, "window: out of memory");
        return CMD_ERROR;
    }
    char err[1024];
    int pw, ph;
    picture_size(sh->view_set.stereo, sh->view_set.image_w, sh->view_set.image_h, &pw, &ph);
    if (window_open(&v->win, "vroc", pw, ph, err, sizeof err) != 0) {
        sh_error(sh, st, "window: %s", err);
        free(v);
        return CMD_ERROR;
    }
    v->left_at = v->right_at = v->released_at = -1;
    sh->viewer = v;
    draw(sh, v);
    return CMD_OK;
}

void viewer_free(shell *sh) { close_window(sh); }

void viewer_changed(shell *sh)
{
    if (sh->viewer) draw(sh, sh->viewer);
}

/* ---- the mouse ---- */

static vec3 forward(const view_settings *vs) { return v3_norm(v3_sub(vs->look_at, vs->head)); }

/* The ray under the pointer, through the eye whose picture it is on.  False when
 * the head pose gives no view. */
static bool pointer_ray(const shell *sh, const viewer *v, vec3 *o, vec3 *d)
{
    const view_settings *vs = &sh->view_set;
    double px = v->x, py = v->y;
    int eye = 0;
    if (v->mode == STEREO_ANAGLYPH) eye = -1;
    if ((v->mode == STEREO_PAIR || v->mode == STEREO_SBS) && px >= v->eye_w) {
        eye = 1;
        px -= v->eye_w;
    }
    if (v->eye_w <= 0 || v->eye_h <= 0) return false;
    /* (image_size changed since: the same place on the new one) */
    px *= (double)vs->image_w / v->eye_w;
    py *= (double)vs->image_h / v->eye_h;
    char err[256];
    return view_ray(vs, eye, px, py, o, d, err, sizeof err) == 0;
}

/* Where the ray from o along d meets the panel's plane (in front of o): true, with
 * the point and the part of the panel there (PANEL_OFF off the sheet). */
static bool panel_under(const shell *sh, vec3 o, vec3 d, vec3 *hit, panel_part *part)
{
    const hand *h = &sh->hand;
    if (!h->set.panel) return false;
    quat q = hand_panel_q(h);
    vec3 n = q_rotate(q, v3(0, 0, 1));
    double dn = v3_dot(d, n);
    if (fabs(dn) < 1e-12) return false;
    double t = v3_dot(v3_sub(h->set.panel_at, o), n) / dn;
    if (!(t > 0)) return false;
    *hit = v3_mad(o, d, t);
    *part = panel_hit(h->set.panel_at, q, *hit);
    return true;
}

/* Where the pointer puts the hand: on the panel's plane while a slider is held,
 * on the sheet where the pointer is over it and nothing is held, else on the plane
 * facing the viewer at the hand's depth.  False where it puts it nowhere (the ray
 * along that plane). */
static bool pointer_point(const shell *sh, const viewer *v, vec3 *p)
{
    vec3 o, d, hit;
    panel_part part;
    if (!pointer_ray(sh, v, &o, &d)) return false;
    grip_kind g = sh->hand.grip;
    if (g != GRIP_OBJECT && g != GRIP_PANEL && panel_under(sh, o, d, &hit, &part) &&
        (g == GRIP_SLIDER || part != PANEL_OFF)) {
        *p = hit;
        return true;
    }
    const view_settings *vs = &sh->view_set;
    vec3 f = forward(vs);
    double df = v3_dot(d, f);
    if (!(df > 1e-9)) return false;
    *p = v3_mad(o, d, (v->depth - v3_dot(v3_sub(o, vs->head), f)) / df);
    return true;
}

/* True when the mouse is the hand now: select mode, or a click on the panel going
 * on, with no tracker file or feed having the hand. */
static bool has_hand(const shell *sh, const viewer *v)
{
    return v->known && !hand_tracked(&sh->hand) && (sh->hand.set.select_mode || v->panel_click);
}

/* Keeps the hand's plane where the hand is when the mouse takes it (the distance
 * to look_at where the hand is not in front of the head). */
static void take_hand(shell *sh, viewer *v)
{
    bool has = has_hand(sh, v);
    if (has && !v->had_hand) {
        const view_settings *vs = &sh->view_set;
        double d = v3_dot(v3_sub(sh->hand.p, vs->head), forward(vs));
        v->depth = d >= DEPTH_MIN ? d : v3_dist(vs->look_at, vs->head);
    }
    v->had_hand = has;
}

/* Turns the head about look_at: by ax about up, and up by ay, short of the poles. */
static void orbit(view_settings *vs, double ax, double ay)
{
    vec3 up = v3_norm(vs->up), v = v3_sub(vs->head, vs->look_at);
    double len = v3_len(v);
    if (!(len > 0) || !v3_finite(up)) return;
    v = q_rotate(q_axis_angle(up, ax), v);
    vec3 side = v3_cross(up, v);
    if (!(v3_len(side) > 1e-12 * len)) return;
    double c = v3_dot(v, up) / len;
    double el = acos(c > 1 ? 1 : c < -1 ? -1 : c); /* from straight above */
    double el2 = el - ay;
    el2 = el2 < ORBIT_POLE ? ORBIT_POLE : el2 > M_PI - ORBIT_POLE ? M_PI - ORBIT_POLE : el2;
    v = q_rotate(q_axis_angle(side, el2 - el), v);
    vs->head = v3_add(vs->look_at, v);
}

/* The left button went down at the pointer. */
static void press(shell *sh, viewer *v)
{
    hand *h = &sh->hand;
    vec3 o, d, hit;
    panel_part part = PANEL_OFF;
    bool ray = pointer_ray(sh, v, &o, &d);
    bool on_panel = ray && panel_under(sh, o, d, &hit, &part) && part != PANEL_OFF;
    if (!hand_tracked(h) && !h->set.select_mode && on_panel && part < PANEL_CONTROLS)
        v->panel_click = true;
    if (!has_hand(sh, v)) {
        v->orbiting = true;
        return;
    }
    take_hand(sh, v);
    v->left = true;
    v->left_at = hand_live_taken(h);
    if (!ray || on_panel || h->grip == GRIP_OBJECT) return;
    const view_settings *vs = &sh->view_set;
    double t;
    if (hand_pick(h, &sh->w, o, d, 1e4, &t) >= 0) /* the plane to the object under the pointer */
        v->depth = v3_dot(v3_sub(v3_mad(o, d, t), vs->head), forward(vs));
}

/* A key: its command now, or (inside a statement) what may act there. */
static void key(shell *sh, viewer *v, int k)
{
    if (k == WIN_KEY_ESCAPE) {
        v->close = true;
    } else if (!sh->at_prompt) { /* a statement runs: space stops it, the rest waits */
        if (k == ' ') shell_interrupted = 1;
        else if ((k == '.' || k == 'r') && v->nkeys < KEYS_MAX) v->keys[v->nkeys++] = k;
    } else if (v->nkeys < KEYS_MAX) {
        v->keys[v->nkeys++] = k;
    }
}

/* Reads what the user did in the window. */
static void pump(shell *sh, viewer *v)
{
    win_event e;
    hand *h = &sh->hand;
    while (window_poll(v->win, &e)) {
        switch (e.kind) {
        case WIN_CLOSE: v->close = true; break;
        case WIN_KEY: key(sh, v, e.key); break;
        case WIN_MOTION:
            if (v->orbiting && v->eye_h > 0) {
                double k = ORBIT_TURN / v->eye_h;
                orbit(&sh->view_set, -(e.x - v->x) * k, (e.y - v->y) * k);
            }
            v->x = e.x;
            v->y = e.y;
            v->known = true;
            /* the picture changes with the head, or with the hand where it takes
             * the mouse at once; while time runs the next frame shows the hand
             * (and drawing more often would only delay the frames) */
            if (v->orbiting || (has_hand(sh, v) && (!sh->running || !(sh->w.set.time_step > 0))))
                v->dirty = true;
            break;
        case WIN_BUTTON:
            v->x = e.x;
            v->y = e.y;
            v->known = true;
            if (e.button == 1 && e.down) {
                press(sh, v);
            } else if (e.button == 1) {
                if (v->left) v->released_at = hand_live_taken(h);
                v->left = v->orbiting = false;
            } else if (e.button == 3) {
                v->right = e.down && has_hand(sh, v);
                if (v->right) v->right_at = hand_live_taken(h);
            }
            v->dirty = true;
            break;
        case WIN_WHEEL:
            take_hand(sh, v);
            if (has_hand(sh, v)) {
                v->depth *= pow(WHEEL_STEP, e.wheel);
                if (v->depth < DEPTH_MIN) v->depth = DEPTH_MIN;
            } else {
                view_settings *vs = &sh->view_set;
                vec3 back = v3_sub(vs->head, vs->look_at);
                double len = v3_len(back), want = len * pow(WHEEL_STEP, -e.wheel);
                if (want < HEAD_MIN) want = HEAD_MIN;
                if (len > 0) vs->head = v3_mad(vs->look_at, back, want / len);
            }
            v->dirty = true;
            break;
        }
    }
}

/* The hand is given the mouse's sample, or told the mouse has it not; while time
 * stands still (act) it takes the sample at once. */
static void give(shell *sh, viewer *v, bool act)
{
    hand *h = &sh->hand;
    long taken = hand_live_taken(h);
    /* a click outside select mode ends once the hand took its release and let go */
    if (v->panel_click && !v->left && taken > v->released_at && !h->set.trigger) v->panel_click = false;
    take_hand(sh, v);
    tracker_row r = {0, h->p, h->q, false, false};
    if (!has_hand(sh, v) || !pointer_point(sh, v, &r.p)) {
        if (!has_hand(sh, v)) hand_live(h, &sh->w, NULL);
        return;
    }
    r.trigger = v->left || taken == v->left_at;
    r.button = v->right || taken == v->right_at;
    hand_live(h, &sh->w, &r);
    double now = shell_clock();
    bool still = !sh->running || !(sh->w.set.time_step > 0);
    if (act && still && now - v->sampled_at >= VIEWER_SAMPLE_GAP) {
        v->sampled_at = now;
        hand_live_act(h, &sh->w);
        shell_after_hand(sh); /* the object it took becomes current, the panel's buttons act */
        v->dirty = true;
    }
}

/* ---- the turns ---- */

void viewer_turn(shell *sh)
{
    viewer *v = sh->viewer;
    if (!v) return;
    pump(sh, v);
    for (int k = 0; k < v->nkeys && sh->viewer == v && !v->close; k++) {
        int c = v->keys[k];
        const char *cmd = c == ' ' ? (sh->running ? "stop" : "start") : c == '.' ? "step" : c == 'r' ? "refresh" : NULL;
        if (cmd) shell_run_text(sh, cmd, NULL);
    }
    if (sh->viewer != v) return; /* (a command closed it) */
    v->nkeys = 0;
    if (v->close) {
        close_window(sh);
        return;
    }
    give(sh, v, true);
    if (v->dirty) draw(sh, v);
}

double viewer_wait(const shell *sh, double wait)
{
    if (!sh->viewer) return wait;
    return wait < 0 || wait > VIEWER_TICK ? VIEWER_TICK : wait;
}

void viewer_sample(shell *sh)
{
    viewer *v = sh->viewer;
    if (!v) return;
    pump(sh, v);
    if (v->close) {
        close_window(sh);
        return;
    }
    give(sh, v, false);
}

void viewer_frame(shell *sh, bool last)
{
    viewer *v = sh->viewer;
    if (!v) return;
    v->dirty = true;
    if (last || shell_clock() - v->drawn_at >= 1.0 / VIEWER_FPS) draw(sh, v);
}
