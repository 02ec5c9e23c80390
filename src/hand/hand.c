/* hand.c: the hand-held tracker: its pose and clock, its rows, and what its
 * trigger and button do (hand.h).
 *
 * The hand's path: between two rows of a tracker file it moves and turns at
 * constant rates (tracker.h).  Each update of the hand (a row, a frame's start or
 * end, a statement, a tick of the wall clock, a row of a live feed) first glides it
 * along that path to the update's instant, counting what flying moved the head on
 * the way, then acts.  What it holds is carried by the core (hold.h): at each
 * update within a frame the hand gives the held object its motion up to the next
 * update, the hand's own when the object is where the hand has it (within
 * HAND_SYNC), or else the motion that brings it there by the next update (it was
 * stopped against something, or the hand went faster than the speed limits).
 * Where the hand jumps (a statement, a tick of the wall clock while time stands
 * still, a row of a live feed), what it holds sweeps towards its place in the
 * hand and stops at the first thing in its way (hold_sweep); the next frames
 * carry it on to the hand.
 *
 * A live source (the window's mouse) plays as a path of its own samples, each
 * added at a frame boundary as the row at the coming frame's end (hand.h), so
 * that it runs through the same code as a file; its rows are at the clock's own
 * times (start 0), which hand_log writes as they are, so that its log replays it
 * to the bit.  A row that rounding puts a hair off a frame's end acts at the end,
 * after the frame, as a row exactly there does, not within the frame.
 */
#include "hand.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/closest.h"
#include "core/hold.h"
#include "core/limits.h"
#include "core/sim.h"
#include "shell/outfile.h"

/* A held object this near the hand's place for it (m, and radians) is carried by
 * the hand's own motion. */
#define HAND_SYNC 1e-9

/* A row this near the clock (relative) is due: where a frame ends on the clock
 * and on simulated time may differ by rounding. */
#define HAND_CLOCK_ROUND 1e-12

hand_settings hand_settings_defaults(void)
{
    hand_settings s;
    memset(&s, 0, sizeof s);
    s.hand = v3(0, 0, 0);
    s.hand_rotate = (dir_amount){v3(1, 0, 0), 0};
    s.reach = 0.05;
    s.fly_speed = 1.0;
    s.panel = false;
    s.panel_at = v3(0, 0.5, -0.25);
    s.panel_rotate = (dir_amount){v3(1, 0, 0), 1.5707963267948966};
    return s;
}

void hand_init(hand *h, hand_say say, void *ctx)
{
    memset(h, 0, sizeof *h);
    h->set = hand_settings_defaults();
    h->p = h->set.hand;
    h->q = h->grip_q = q_identity();
    feed_init(&h->feed);
    h->held = h->last_held = h->make_current = -1;
    h->slider = PANEL_OFF;
    h->slid[0] = h->slid[1] = NAN;
    h->say = say;
    h->say_ctx = ctx;
}

void hand_free(hand *h)
{
    tracker_free(&h->path);
    feed_close(&h->feed);
    char ignored[8];
    hand_log_close(h, ignored, sizeof ignored); /* (checked before: shell_close_outputs) */
}

static void tell(hand *h, hand_message kind, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void tell(hand *h, hand_message kind, const char *fmt, ...)
{
    char msg[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (h->say) h->say(h->say_ctx, kind, msg);
}

quat hand_panel_q(const hand *h)
{
    return q_axis_angle(h->set.panel_rotate.dir, h->set.panel_rotate.amount);
}

/* show's hand and hand_rotate, from the pose (after the tracker moved it). */
static void show_pose(hand *h)
{
    vec3 axis;
    double angle;
    q_to_axis_angle(h->q, &axis, &angle);
    h->set.hand = h->p;
    h->set.hand_rotate = (dir_amount){axis, angle};
}

/* ---- the path ---- */

/* The simulated time of row k's instant, within the frame. */
static double row_sim(const hand *h, int k)
{
    return h->t0 + ((h->start + h->path.rows[k].t) - h->c0);
}

/* Row k's instant within the frame, where one a hair off the frame's end (by
 * rounding: the clock and simulated time are summed apart) is at the end. */
static double row_in_frame(const hand *h, int k)
{
    double t = row_sim(h, k);
    return fabs(t - h->tf) <= HAND_CLOCK_ROUND * (1 + fabs(h->tf)) ? h->tf : t;
}

/* True when row k is due: within a frame, at or before world.time; outside, at
 * or before the clock. */
static bool row_due(const hand *h, const world *w, int k)
{
    if (h->in_frame) return row_sim(h, k) <= w->time;
    return h->start + h->path.rows[k].t <= h->clock + HAND_CLOCK_ROUND * (1 + fabs(h->clock));
}

/* The way the hand points (+x in its own axes), integrated over T seconds from
 * orientation q while it turns at w: exactly, for a turn about one axis. */
static vec3 fly_path(quat q, vec3 w, double T)
{
    vec3 d = q_rotate(q, v3(1, 0, 0));
    double wl = v3_len(w), th = wl * T;
    if (th < 1e-12) return v3_scale(d, T);
    vec3 k = v3_scale(w, 1 / wl), par = v3_scale(k, v3_dot(k, d));
    vec3 perp = v3_sub(d, par);
    return v3_add(v3_add(v3_scale(par, T), v3_scale(perp, sin(th) / wl)),
                  v3_scale(v3_cross(k, d), (1 - cos(th)) / wl));
}

/* The hand glides on its path to clock c (counting what flying moves the head on
 * the way), without acting on rows. */
static void glide(hand *h, double c)
{
    double T = c - h->pose_clock;
    if (!(T > 0)) return;
    if (h->grip == GRIP_FLY) h->fly = v3_add(h->fly, v3_scale(fly_path(h->q, h->mw, T), h->set.fly_speed));
    h->pose_clock = c;
    if (h->playing && h->next > 0) {
        tracker_pose(&h->path, c - h->start, &h->p, &h->q);
        show_pose(h);
    }
}

/* The hand's velocity and angular velocity now: the path's derivative just
 * before now (at a row, the one before it), or from statements or the feed. */
static void velocity_now(const hand *h, vec3 *v, vec3 *wv)
{
    if (!h->playing) {
        *v = h->sv;
        *wv = h->sw;
        return;
    }
    int k = h->next - 1; /* the last row reached */
    if (k >= 0 && h->pose_clock == h->start + h->path.rows[k].t) k--;
    tracker_segment_rates(&h->path, k, v, wv);
}

/* The live source's rows still to come are dropped: the hand stays where it is,
 * and moves no more until told. */
static void live_drop(hand *h)
{
    if (!h->live) return;
    tracker_free(&h->path);
    h->playing = h->live = false;
    h->next = 0;
    h->mv = h->mw = v3(0, 0, 0);
}

/* ---- what the hand holds ---- */

/* Where the hand at (p, q) has what it holds: its origin and orientation. */
static void held_place(const hand *h, vec3 p, quat q, vec3 *x, quat *qo)
{
    *x = v3_add(p, q_rotate(q, h->grip_x));
    *qo = q_normalize(q_mul(q, h->grip_q));
}

/* Keeps the pose (x, q) of what the hand takes, relative to the hand now. */
static void grip_from(hand *h, vec3 x, quat q)
{
    h->grip_x = q_unrotate(h->q, v3_sub(x, h->p));
    h->grip_q = q_normalize(q_mul(q_conj(h->q), q));
}

static bool near_pose(const body *b, vec3 x, quat q)
{
    return v3_dist(b->x, x) <= HAND_SYNC && v3_len(tracker_turn(b->q, q)) <= HAND_SYNC;
}

/* Lets go of the held object as it moves (it is not thrown). */
static void drop(hand *h, world *w)
{
    if (h->grip == GRIP_OBJECT && h->held >= 0 && h->held < w->n) {
        body *b = w->bodies[h->held];
        hold_release(w, h->held, b->v, b->w);
    }
    h->held = -1;
    h->grip = h->set.trigger ? GRIP_NONE : GRIP_OFF;
}

/* True (and the hand lets go) when a command made the held object static. */
static bool held_gone(hand *h, world *w)
{
    if (!body_is_static(w->bodies[h->held])) return false;
    drop(h, w);
    return true;
}

/* The held object's motion until the next update at simulated time t1 (within a
 * frame): the hand's, or the way back to its place in the hand. */
static void carry(hand *h, world *w, double t1)
{
    if (h->grip != GRIP_OBJECT || held_gone(h, w)) return;
    body *b = w->bodies[h->held];
    vec3 x;
    quat q;
    held_place(h, h->p, h->q, &x, &q);
    double dt = t1 - w->time;
    if (near_pose(b, x, q) || !(dt > 0)) {
        hold_set(w, h->held, (hold_motion){h->p, dt > 0 ? h->mv : v3(0, 0, 0), dt > 0 ? h->mw : v3(0, 0, 0)});
        return;
    }
    /* its place at t1, reached in a straight line, turning the short way */
    vec3 p1 = v3_mad(h->p, h->mv, dt), c = body_com(b);
    quat q1 = tracker_turned(h->q, v3_scale(h->mw, dt));
    held_place(h, p1, q1, &x, &q);
    vec3 c1 = v3_add(x, q_rotate(q, b->shape.mass.com));
    hold_set(w, h->held, (hold_motion){c, v3_scale(v3_sub(c1, c), 1 / dt),
                                       v3_scale(tracker_turn(b->q, q), 1 / dt)});
}

/* The hand moved between frames: a held object waits for the next frame to be
 * carried to it, or, where the hand jumped (jump), sweeps there at once, and
 * stops at the first thing in its way (hold_sweep). */
static void follow(hand *h, world *w, bool jump)
{
    if (h->grip != GRIP_OBJECT || held_gone(h, w) || !jump) return;
    vec3 x;
    quat q;
    held_place(h, h->p, h->q, &x, &q);
    if (!near_pose(w->bodies[h->held], x, q)) hold_sweep(w, h->held, x, q);
    hold_set(w, h->held, (hold_motion){h->p, h->mv, h->mw});
}

/* The panel follows the hand that holds it, and a dragged slider takes the value
 * under the hand, which its setting gets at the end of the frame (or at once,
 * outside frames: apply_slider). */
static void panel_follow(hand *h)
{
    if (h->grip == GRIP_PANEL) {
        vec3 x, axis;
        quat q;
        double angle;
        held_place(h, h->p, h->q, &x, &q);
        q_to_axis_angle(q, &axis, &angle);
        /* within the limits of a position, as panel_at must be (core/limits.h) */
        const double m = LIM_POSITION_MAX;
        h->set.panel_at = v3(d_max(-m, d_min(m, x.x)), d_max(-m, d_min(m, x.y)), d_max(-m, d_min(m, x.z)));
        h->set.panel_rotate = (dir_amount){axis, angle};
    }
    if (h->grip == GRIP_SLIDER) {
        bool ts = h->slider == PANEL_TIME_STEP;
        h->slid[!ts] = panel_slider_value(h->set.panel_at, hand_panel_q(h), h->p, ts ? 0 : 0.001);
    }
}

/* The settings of the sliders moved since the last call take their values. */
static void apply_slider(hand *h, world *w)
{
    if (!isnan(h->slid[0])) w->set.time_step = h->slid[0];
    if (!isnan(h->slid[1])) w->set.collision_dist = h->slid[1];
    h->slid[0] = h->slid[1] = NAN;
}

/* The hand moved: what it holds follows, outside frames at once. */
static void moved(hand *h, world *w)
{
    panel_follow(h);
    if (h->in_frame) return;
    follow(h, w, h->jump);
    apply_slider(h, w);
}

/* How far point p is from body b's surface (0 inside it), or -1 when that cannot
 * be told (a body not built, or not finite). */
static double point_distance(const body *b, vec3 p)
{
    closest_proxy pt = {NULL, NULL, 0, v3(0, 0, 0), p, q_identity()};
    closest_proxy bp = shape_proxy(&b->shape, b->x, b->q);
    closest_result r = closest_distance_apart(&pt, &bp, NULL);
    if (r.status == CLOSEST_INVALID) return -1;
    return r.status == CLOSEST_SEPARATED ? r.distance : 0;
}

/* True when the hand may take body b: dynamic, built, not held. */
static bool graspable(const body *b)
{
    return !body_is_static(b) && !b->held && b->built;
}

/* The dynamic object nearest the hand whose surface is within reach (the hand
 * inside one is at 0), or -1. */
static int nearest(const hand *h, const world *w)
{
    int best = -1;
    double bd = HUGE_VAL;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (!graspable(b)) continue;
        double d = point_distance(b, h->p);
        if (d < 0) continue;
        if (d <= h->set.reach && d < bd) {
            bd = d;
            best = i;
        }
    }
    return best;
}

/* The hand takes object i where it is; it moves as the hand does from now. */
static void grab(hand *h, world *w, int i)
{
    body *b = w->bodies[i];
    h->grip = GRIP_OBJECT;
    h->held = h->last_held = h->make_current = i;
    grip_from(h, b->x, b->q);
    hold_set(w, i, (hold_motion){h->p, h->mv, h->mw});
}

/* The trigger goes down: a control, the panel, an object, or flying. */
static void press(hand *h, world *w)
{
    h->grip = GRIP_NONE;
    panel_part part = h->set.panel ? panel_hit(h->set.panel_at, hand_panel_q(h), h->p) : PANEL_OFF;
    if (part < PANEL_CONTROLS && !panel_control_of(part)->slider) {
        h->presses[part] = true;
    } else if (part < PANEL_CONTROLS) {
        h->grip = GRIP_SLIDER;
        h->slider = part;
        moved(h, w);
    } else if (part == PANEL_SHEET && h->set.select_mode) {
        h->grip = GRIP_PANEL;
        grip_from(h, h->set.panel_at, hand_panel_q(h));
    } else if (h->set.select_mode) {
        int i = nearest(h, w);
        if (i >= 0) grab(h, w, i);
    } else {
        h->grip = GRIP_FLY;
    }
}

/* The trigger goes up: a held object flies off with the hand's velocity at its
 * centre of mass, v + w x (c - p), and the hand's angular velocity. */
static void let_go(hand *h, world *w)
{
    if (h->grip == GRIP_OBJECT) {
        vec3 v, wv;
        velocity_now(h, &v, &wv);
        body *b = w->bodies[h->held];
        hold_release(w, h->held, v3_add(v, v3_cross(wv, v3_sub(body_com(b), h->p))), wv);
    }
    h->held = -1;
    h->grip = GRIP_OFF;
}

static void set_trigger(hand *h, world *w, bool down)
{
    if (down == h->set.trigger) return;
    h->set.trigger = down;
    if (down) press(h, w);
    else let_go(h, w);
}

/* The re-select button: 0, or -1 when nothing was held before. */
static int reselect(hand *h, world *w)
{
    if (h->last_held < 0) return -1;
    h->make_current = h->last_held;
    if (h->set.select_mode && h->set.trigger && h->grip == GRIP_NONE) {
        const body *b = w->bodies[h->last_held];
        double d = point_distance(b, h->p);
        if (d >= 0 && d <= h->set.reach && !body_is_static(b)) grab(h, w, h->last_held);
    }
    return 0;
}

static void set_button(hand *h, world *w, bool down, const char *from)
{
    if (down == h->button) return;
    h->button = down;
    if (down && reselect(h, w) != 0)
        tell(h, HAND_WARNING, "%s: the re-select button, with no object held before", from);
}

/* ---- the log ---- */

static bool same_row(const tracker_row *a, const tracker_row *b)
{
    return a->p.x == b->p.x && a->p.y == b->p.y && a->p.z == b->p.z && a->q.w == b->q.w &&
           a->q.x == b->q.x && a->q.y == b->q.y && a->q.z == b->q.z && a->trigger == b->trigger &&
           a->button == b->button;
}

/* A row of the hand now, when it changed since the last (or always). */
static void log_row(hand *h, bool always)
{
    if (!h->log) return;
    tracker_row r = {h->pose_clock - h->log_start, h->p, h->q, h->set.trigger, h->button};
    if (!always && h->have_logged && same_row(&r, &h->logged)) return;
    if (h->have_logged && r.t < h->logged.t) r.t = h->logged.t;
    /* a row that repeats the last to the bit, its time too, adds nothing (replayed,
     * it would only stop the hand for an instant between the two) */
    if (h->have_logged && r.t == h->logged.t && same_row(&r, &h->logged)) return;
    /* (the reason is the failing write's: a later flush may have none) */
    if (tracker_write_row(h->log, &r) < 0)
        outfile_failed(h->set.hand_log, errno, h->log_error, sizeof h->log_error);
    else
        outfile_flush(h->log, h->set.hand_log, h->log_error, sizeof h->log_error);
    if (h->log_error[0]) {
        char ignored[8];
        hand_log_close(h, ignored, sizeof ignored);
        return;
    }
    h->logged = r;
    h->have_logged = true;
}

int hand_log_open(hand *h, const char *path, char *err, size_t errlen)
{
    outfile o;
    if (outfile_begin(&o, path, OUTFILE_STREAM, err, errlen) != 0) return -1;
    /* the header and the hand now, checked (and the file put in its place) before
     * the old log is let go */
    tracker_row r = {0, h->p, h->q, h->set.trigger, h->button};
    int rc = fprintf(o.f, "%s\n", TRACKER_HEADER) < 0 || tracker_write_row(o.f, &r) < 0
                 ? outfile_failed(path, errno, err, errlen)
                 : outfile_place(&o, err, errlen);
    if (rc != 0) {
        outfile_abort(&o);
        return -1;
    }
    FILE *f = o.f;
    rc = outfile_close(h->log, h->set.hand_log, err, errlen);
    /* with no file playing the clock starts again at 0 with the log, so that the
     * log's times are the clock's own, and a live source's rows, at times of the
     * clock, are written as they were played (hand.h) */
    if (!(h->playing && !h->live)) {
        glide(h, h->clock); /* what flying moved the head, up to now */
        live_drop(h);
        h->clock = h->pose_clock = 0;
    }
    h->log = f;
    h->log_start = h->pose_clock;
    h->logged = r;
    h->have_logged = true;
    h->log_error[0] = '\0';
    snprintf(h->set.hand_log, sizeof h->set.hand_log, "%s", path);
    return rc;
}

int hand_log_close(hand *h, char *err, size_t errlen)
{
    int rc = outfile_close(h->log, h->set.hand_log, err, errlen);
    h->log = NULL;
    h->set.hand_log[0] = '\0';
    return rc;
}

bool hand_log_failed(hand *h, char *err, size_t errlen)
{
    if (!h->log_error[0]) return false;
    snprintf(err, errlen, "%s", h->log_error);
    h->log_error[0] = '\0';
    return true;
}

/* ---- rows ---- */

/* Acts on the file's rows that are due: the hand glides to each, takes its pose
 * (a jump only where rows share a time, or at the first), and its trigger and
 * button act then. */
static void act_rows(hand *h, world *w)
{
    while (h->playing && h->next < h->path.n && row_due(h, w, h->next)) {
        int k = h->next;
        const tracker_row *r = &h->path.rows[k];
        glide(h, h->start + r->t);
        if (h->pose_clock < h->start + r->t) h->pose_clock = h->start + r->t;
        if (h->clock < h->pose_clock) h->clock = h->pose_clock;
        h->p = r->p;
        h->q = r->q;
        show_pose(h);
        h->next = k + 1;
        tracker_segment_rates(&h->path, k, &h->mv, &h->mw);
        moved(h, w);
        set_trigger(h, w, r->trigger);
        set_button(h, w, r->button, h->live ? "the mouse" : h->set.tracker);
        log_row(h, false);
    }
}

int hand_tracker(hand *h, const char *path, char *err, size_t errlen)
{
    if (feed_is_fifo(path)) {
        tracker_feed f;
        feed_init(&f);
        if (feed_open(&f, path, err, errlen) != 0) return -1;
        hand_tracker_off(h);
        h->feed = f;
        h->have_last = false;
    } else {
        tracker_path tp;
        if (tracker_load(path, &tp, err, errlen) != 0) return -1;
        hand_tracker_off(h);
        h->path = tp;
        h->playing = true;
        h->next = 0;
        h->start = h->clock;
    }
    h->used = true;
    /* its full path, so that a saved world finds it from anywhere */
    char real[PATH_MAX];
    const char *name = realpath(path, real) && strlen(real) < sizeof h->set.tracker ? real : path;
    snprintf(h->set.tracker, sizeof h->set.tracker, "%.*s", (int)sizeof h->set.tracker - 1, name);
    return 0;
}

void hand_tracker_off(hand *h)
{
    tracker_free(&h->path);
    feed_close(&h->feed);
    h->playing = h->live = false;
    h->next = 0;
    h->mv = h->mw = h->sv = h->sw = v3(0, 0, 0);
    h->set.tracker[0] = '\0';
}

int hand_seek(hand *h, world *w, double t, char *err, size_t errlen)
{
    if (!h->playing || h->live) {
        if (t == 0) return 0; /* as show writes it */
        snprintf(err, errlen, "no tracker file plays (tracker = FILE names one)");
        return -1;
    }
    int k = 0;
    while (k < h->path.n && h->path.rows[k].t <= t) k++;
    h->next = k;
    h->start = h->clock - t;
    h->pose_clock = h->clock;
    if (k > 0) {
        tracker_pose(&h->path, t, &h->p, &h->q);
        show_pose(h);
        tracker_segment_rates(&h->path, k - 1, &h->mv, &h->mw);
        h->set.trigger = h->path.rows[k - 1].trigger;
        h->button = h->path.rows[k - 1].button;
        if (!h->set.trigger && h->grip != GRIP_OFF) drop(h, w);
        if (h->set.trigger && h->grip == GRIP_OFF) h->grip = GRIP_NONE;
    }
    h->used = true;
    return 0;
}

double hand_tracker_time(const hand *h)
{
    return h->playing && !h->live ? h->clock - h->start : 0;
}

/* ---- statements ---- */

void hand_move(hand *h, world *w, vec3 p, quat q)
{
    double dt = w->time - h->stmt_time;
    if (!h->playing) {
        h->sv = dt > 0 ? v3_scale(v3_sub(p, h->p), 1 / dt) : v3(0, 0, 0);
        h->sw = dt > 0 ? v3_scale(tracker_turn(h->q, q), 1 / dt) : v3(0, 0, 0);
    }
    h->stmt_time = w->time;
    h->p = p;
    h->q = q;
    h->used = true;
    h->jump = true;
    moved(h, w);
    log_row(h, false);
}

void hand_trigger(hand *h, world *w, bool down)
{
    h->used = true;
    set_trigger(h, w, down);
    log_row(h, false);
}

int hand_reselect(hand *h, world *w, char *err, size_t errlen)
{
    h->used = true;
    if (reselect(h, w) != 0) {
        snprintf(err, errlen, "no object has been held yet: the re-select button takes the last one the hand held");
        return -1;
    }
    return 0;
}

static const char *const grip_words[] = {"off", "none", "fly", NULL, "panel", NULL};

/* The grip a word of grip's names, with its slider; GRIP_OBJECT for any other
 * word (an object's name). */
static grip_kind grip_of_word(const char *what, panel_part *slider)
{
    grip_kind g = GRIP_OBJECT;
    *slider = PANEL_OFF;
    for (int k = 0; k < 6; k++)
        if (grip_words[k] && strcmp(what, grip_words[k]) == 0) g = (grip_kind)k;
    if (strcmp(what, "time_step") == 0) *slider = PANEL_TIME_STEP;
    if (strcmp(what, "collision_dist") == 0) *slider = PANEL_COLLISION_DIST;
    if (*slider != PANEL_OFF) g = GRIP_SLIDER;
    return g;
}

int hand_set_grip(hand *h, world *w, const char *what, bool quoted, char *err, size_t errlen)
{
    int i = -1;
    panel_part slider;
    grip_kind g = quoted ? GRIP_OBJECT : grip_of_word(what, &slider);
    if (quoted) slider = PANEL_OFF;
    if (g == GRIP_OBJECT) {
        i = world_find(w, what);
        if (i < 0) {
            snprintf(err, errlen, "no object named '%s' (grip takes off, none, fly, panel, time_step, "
                                  "collision_dist or an object's name)", what);
            return -1;
        }
        if (body_is_static(w->bodies[i])) {
            snprintf(err, errlen, "'%s' is static: the hand holds only dynamic objects", what);
            return -1;
        }
    }
    drop(h, w);
    h->used = true;
    h->set.trigger = g != GRIP_OFF;
    h->grip = g;
    h->slider = slider;
    if (g == GRIP_PANEL) grip_from(h, h->set.panel_at, hand_panel_q(h));
    if (g == GRIP_OBJECT) grab(h, w, i);
    return 0;
}

const char *hand_grip_word(const hand *h, const world *w, char buf[HAND_GRIP_TEXT])
{
    panel_part slider;
    switch (h->grip) {
    case GRIP_OBJECT:
        if (!(h->held >= 0 && h->held < w->n)) return "none";
        snprintf(buf, HAND_GRIP_TEXT, "%s", w->bodies[h->held]->name);
        if (grip_of_word(buf, &slider) != GRIP_OBJECT)
            snprintf(buf, HAND_GRIP_TEXT, "\"%s\"", w->bodies[h->held]->name);
        return buf;
    case GRIP_SLIDER: return panel_control_of(h->slider)->name;
    default: return grip_words[h->grip];
    }
}

void hand_set_clock(hand *h, double clock, double start)
{
    h->clock = h->pose_clock = clock;
    h->start = start;
}

void hand_clock_of(const hand *h, double *clock, double *start)
{
    *clock = h->clock;
    *start = h->playing ? h->start : 0;
}

int hand_set_row(hand *h, int n, char *err, size_t errlen)
{
    if (!h->playing) {
        if (n == 0) return 0; /* as show writes it */
        snprintf(err, errlen, "no tracker file plays (tracker = FILE names one)");
        return -1;
    }
    h->next = n = n < h->path.n ? n : h->path.n;
    tracker_segment_rates(&h->path, n - 1, &h->mv, &h->mw);
    if (n > 0) h->button = h->path.rows[n - 1].button;
    return 0;
}

int hand_row(const hand *h)
{
    return h->playing ? h->next : 0;
}

void hand_set_velocity(hand *h, vec3 v, double t)
{
    h->sv = v;
    h->stmt_time = t;
}

void hand_set_spin(hand *h, vec3 wv)
{
    h->sw = wv;
}

void hand_set_grip_pose(hand *h, const vec3 *x, const quat *q)
{
    if (x) h->grip_x = *x;
    if (q) h->grip_q = *q;
}

void hand_grip_pose(const hand *h, vec3 *x, quat *q)
{
    *x = h->grip_x;
    *q = h->grip_q;
}

int hand_set_last_held(hand *h, const world *w, const char *name, bool quoted, char *err, size_t errlen)
{
    bool none = !quoted && strcmp(name, "none") == 0;
    int i = none ? -1 : world_find(w, name);
    if (!none && (i < 0 || body_is_static(w->bodies[i]))) {
        snprintf(err, errlen,
                 i < 0 ? "no object named '%s'" : "'%s' is static: the hand holds only dynamic objects", name);
        return -1;
    }
    h->last_held = i;
    return 0;
}

void hand_let_go(hand *h, world *w, int i)
{
    if (h->grip == GRIP_OBJECT && h->held == i) drop(h, w);
}

void hand_object_deleted(hand *h, int i)
{
    if (h->held == i) {
        h->held = -1;
        h->grip = GRIP_NONE;
    } else if (h->held > i) {
        h->held--;
    }
    if (h->last_held == i) h->last_held = -1;
    else if (h->last_held > i) h->last_held--;
    if (h->make_current == i) h->make_current = -1;
    else if (h->make_current > i) h->make_current--;
}

/* ---- time ---- */

/* The next update within the frame: the next row's instant, or the frame's end. */
static double next_update(const hand *h)
{
    double t = h->tf;
    if (h->playing && h->next < h->path.n) t = d_min(t, row_in_frame(h, h->next));
    return t;
}

/* At a frame boundary, before the rows due there act: the live source's sample
 * becomes the row at the end of the coming frame, whose time on the clock is what
 * hand_frame_end will make it to the bit (sim_frame_end), so that it acts at that
 * end and the log writes it as it was.  The path starts with the hand where it is
 * now; a row still ahead is moved to where the frame now ends (time_step changed
 * since it was added). */
static void live_sample(hand *h, const world *w)
{
    if (!h->live_on || hand_tracked(h)) return;
    h->live_have_last = false; /* the next sample taken at once starts afresh */
    double end = h->clock + (sim_frame_end(w) - w->time);
    tracker_row *last = h->playing && h->live && h->path.n > 0 ? &h->path.rows[h->path.n - 1] : NULL;
    if (last && last->t > h->clock) {
        if (last->t != end) {
            last->t = end;
            if (h->next == h->path.n - 1) tracker_segment_rates(&h->path, h->next - 1, &h->mv, &h->mw);
        }
        return;
    }
    if (!last || last->t < h->clock) {
        tracker_free(&h->path);
        if (!h->live) h->set.tracker[0] = '\0'; /* a file that ended */
        h->playing = h->live = true;
        h->start = 0;
        h->next = 0;
        tracker_row now = {h->clock, h->p, h->q, h->set.trigger, h->button};
        if (tracker_append(&h->path, &now) != 0) {
            live_drop(h);
            return;
        }
    }
    tracker_row r = h->live_now;
    r.t = end;
    if (tracker_append(&h->path, &r) != 0) live_drop(h); /* (out of memory: the hand stays) */
    else h->live_taken++;
}

void hand_frame_begin(hand *h, world *w)
{
    hand_poll(h, w);
    live_sample(h, w);
    h->in_frame = false;
    h->jump = false;
    act_rows(h, w);
    h->in_frame = true;
    h->t0 = w->time;
    h->c0 = h->clock;
    h->tf = w->time + w->set.time_step;
    if (h->pose_clock < h->clock) glide(h, h->clock);
    carry(h, w, next_update(h));
}

double hand_hook_next(void *ctx, const world *w)
{
    (void)w;
    const hand *h = ctx;
    if (!h->playing || h->next >= h->path.n) return HUGE_VAL;
    double t = row_in_frame(h, h->next);
    return t < h->tf ? t : HUGE_VAL; /* (one at the frame's end acts after it) */
}

void hand_hook_at(void *ctx, world *w)
{
    hand *h = ctx;
    act_rows(h, w);
    carry(h, w, next_update(h));
}

void hand_frame_end(hand *h, world *w)
{
    double c = h->c0 + (w->time - h->t0);
    if (c > h->clock) h->clock = c;
    h->in_frame = false;
    h->jump = false;
    live_sample(h, w); /* before the rows at the boundary act, which look ahead */
    act_rows(h, w);
    glide(h, h->clock);
    moved(h, w);
    log_row(h, true);
}

void hand_wall(hand *h, world *w, double dt)
{
    if (!(dt > 0)) return;
    h->clock += dt;
    h->jump = true;
    act_rows(h, w);
    glide(h, h->clock);
    moved(h, w);
    log_row(h, false);
}

bool hand_busy(const hand *h)
{
    return (h->playing && h->next < h->path.n) || h->grip == GRIP_FLY;
}

int hand_feed_fd(const hand *h)
{
    return h->feed.fd;
}

typedef struct {
    hand *h;
    world *w;
} feed_ctx;

/* A row that acts as it comes (a live feed's, a live source's while time stands
 * still): the hand jumps there, and what it holds with it where nothing is in the
 * way; its velocity is the change from the row before (*last) over their times. */
static void jump_to(hand *h, world *w, const tracker_row *r, tracker_row *last, bool *have_last,
                    const char *from)
{
    double dt = *have_last ? r->t - last->t : 0;
    h->sv = dt > 0 ? v3_scale(v3_sub(r->p, last->p), 1 / dt) : v3(0, 0, 0);
    h->sw = dt > 0 ? v3_scale(tracker_turn(last->q, r->q), 1 / dt) : v3(0, 0, 0);
    *last = *r;
    *have_last = true;
    h->in_frame = false;
    h->jump = true;
    h->p = r->p;
    h->q = r->q;
    show_pose(h);
    moved(h, w);
    set_trigger(h, w, r->trigger);
    set_button(h, w, r->button, from);
    log_row(h, false);
}

static void feed_row(void *ctx, const tracker_row *r)
{
    hand *h = ((feed_ctx *)ctx)->h;
    jump_to(h, ((feed_ctx *)ctx)->w, r, &h->last, &h->have_last, h->feed.path);
}

static void feed_bad(void *ctx, const char *msg)
{
    tell(((feed_ctx *)ctx)->h, HAND_ERROR, "tracker: %s", msg);
}

void hand_poll(hand *h, world *w)
{
    if (h->feed.fd < 0) return;
    feed_ctx ctx = {h, w};
    char err[FEED_PATH_MAX + 128];
    h->in_frame = false;
    h->jump = true;
    feed_state s = feed_read(&h->feed, feed_row, feed_bad, &ctx, err, sizeof err);
    if (s == FEED_WAITING) return;
    if (s == FEED_ENDED)
        tell(h, HAND_WARNING, "tracker: the writer of '%s' went away: the live feed ends, and the hand stays where it is",
             h->feed.path);
    else
        tell(h, HAND_ERROR, "tracker: reading the live feed failed: %s", err);
    hand_tracker_off(h);
}

/* ---- a live source ---- */

void hand_live(hand *h, world *w, const tracker_row *now)
{
    (void)w;
    h->live_on = now != NULL;
    if (now) {
        h->live_now = *now;
        h->used = true;
    } else {
        live_drop(h);
    }
}

void hand_live_act(hand *h, world *w)
{
    if (!h->live_on || hand_tracked(h)) return;
    live_drop(h); /* the frames' path ends where the hand is */
    tracker_row r = h->live_now;
    r.t = h->clock;
    glide(h, h->clock);
    jump_to(h, w, &r, &h->live_last, &h->live_have_last, "the mouse");
    h->live_taken++;
}

long hand_live_taken(const hand *h)
{
    return h->live_taken;
}

bool hand_tracked(const hand *h)
{
    return (h->playing && !h->live && h->next < h->path.n) || h->feed.fd >= 0;
}

int hand_pick(const hand *h, const world *w, vec3 o, vec3 dir, double max, double *t)
{
    double tol = d_min(1e-4, 0.5 * h->set.reach), s = 0;
    if (!(tol > 1e-12)) tol = 1e-12;
    /* sphere tracing: no object is nearer the point than the least distance, so
     * the ray may go that far and meet none on the way */
    for (int it = 0; it < 256 && s <= max; it++) {
        vec3 p = v3_mad(o, dir, s);
        int best = -1;
        double bd = HUGE_VAL;
        for (int i = 0; i < w->n; i++) {
            if (!graspable(w->bodies[i])) continue;
            double d = point_distance(w->bodies[i], p);
            if (d >= 0 && d < bd) {
                bd = d;
                best = i;
            }
        }
        if (best < 0) return -1;
        if (bd <= tol) {
            *t = s;
            return best;
        }
        s += bd;
    }
    return -1;
}

/* ---- for the caller ---- */

panel_part hand_take_press(hand *h)
{
    for (int k = 0; k < PANEL_CONTROLS; k++) {
        if (h->presses[k]) {
            h->presses[k] = false;
            return (panel_part)k;
        }
    }
    return PANEL_OFF;
}

int hand_take_current(hand *h)
{
    int i = h->make_current;
    h->make_current = -1;
    return i;
}

vec3 hand_take_fly(hand *h)
{
    vec3 f = h->fly;
    h->fly = v3(0, 0, 0);
    return f;
}
