/* hand.h: the hand-held tracker and what it does: grab, carry, throw, re-select,
 * fly, and the virtual tool panel (thesis 1.3, 4.3, 4.5, Appendix A.1;
 * language.md, "The hand and the tool panel").
 *
 * The hand has a pose (position, and an orientation whose +x is where it points),
 * a trigger and a re-select button.  They come from statements, from a tracker file
 * replayed on the tracker clock, or from a live feed (feed.h).  The tracker clock
 * runs with simulated time while frames advance (the frame's hook: a row acts at
 * its exact instant, sim.h), and at the prompt while time stands still on the wall
 * clock (hand_wall), so that a recorded hand can press Start.
 *
 * The trigger going down: on a control of the panel (when shown), presses it; in
 * select mode, on the panel's sheet, grabs the panel; in select mode elsewhere, grabs
 * the dynamic object nearest the hand within reach (hold.h: it then moves with the
 * hand, keeping its pose relative to it); outside select mode, flies the head along
 * where the hand points.  Going up releases what is held: an object flies off with
 * the hand's velocity at its centre of mass and the hand's angular velocity.
 *
 * The hand writes no text: it reports through the say callback, and leaves the
 * panel's buttons (which do what their commands do) to its caller (hand_take_press).
 */
#ifndef VROC_HAND_H
#define VROC_HAND_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "core/vmath.h"
#include "core/world.h"
#include "feed.h"
#include "panel.h"
#include "tracker.h"

#define HAND_PATH_MAX 1024

/* The hand's settings, as show and save write them (the command table's OWN_HAND). */
typedef struct {
    vec3 hand;              /* position (follows the tracker) */
    dir_amount hand_rotate; /* orientation: axis and angle, radians */
    bool trigger;
    bool select_mode;
    double reach;           /* m, from an object's surface */
    double fly_speed;       /* m/s */
    bool panel;             /* shown and usable */
    vec3 panel_at;
    dir_amount panel_rotate;
    char tracker[HAND_PATH_MAX];
    char hand_log[HAND_PATH_MAX];
} hand_settings;

/* The start-up values: the hand at the origin pointing along +x, trigger up, select
 * mode off, reach 0.05 m, fly_speed 1 m/s, the panel off at (0, 0.5, -0.25) turned
 * by pi/2 about x (facing the default head), no tracker, no log. */
hand_settings hand_settings_defaults(void);

/* What the trigger is doing. */
typedef enum {
    GRIP_OFF,    /* up */
    GRIP_NONE,   /* down, doing nothing (a button pressed, nothing in reach) */
    GRIP_FLY,    /* down outside select mode: flying */
    GRIP_OBJECT, /* holding an object */
    GRIP_PANEL,  /* holding the panel */
    GRIP_SLIDER  /* dragging a slider */
} grip_kind;

/* Kinds of message the hand reports. */
typedef enum { HAND_ERROR, HAND_WARNING, HAND_INFO } hand_message;

typedef void (*hand_say)(void *ctx, hand_message kind, const char *msg);

typedef struct hand {
    hand_settings set;
    bool used;              /* some hand statement or tracker has run: drawn */
    vec3 p;                 /* the pose now */
    quat q;
    vec3 mv, mw;            /* how it moves from now on, until its next row */
    vec3 sv, sw;            /* its velocity from statements (change over time) */
    double stmt_time;       /* simulated time of the last statement that moved it */
    double clock;           /* the tracker clock, s */

    tracker_path path;      /* a tracker file playing, */
    bool playing;
    int next;               /*   the next row to act, */
    double start;           /*   the clock when it was named */
    tracker_feed feed;      /* or a live feed */
    tracker_row last;       /*   its last row (for the velocity) */
    bool have_last;

    bool jump;              /* outside frames: time stands still (follow) */
    bool in_frame;          /* a frame runs: t0 and c0 are its start in simulated */
    double t0, c0, tf;      /*   time and on the clock; tf its end */

    bool button;
    grip_kind grip;
    int held;               /* GRIP_OBJECT: the object */
    panel_part slider;      /* GRIP_SLIDER: which */
    vec3 grip_x;            /* what is held (object origin, or the panel's centre) */
    quat grip_q;            /*   in the hand's frame */
    int last_held;          /* for reselect, or -1 */
    int make_current;       /* an object to make current (hand_take_current), or -1 */
    bool presses[PANEL_CONTROLS]; /* buttons pressed, for the caller to run */
    double slid[2];         /* the values the sliders were dragged to, which their
                             * settings get at the end of the frame (NAN: none) */

    bool live;              /* the path playing is the live source's own (start 0:
                             * its rows are at times of the clock) */
    bool live_on;           /* a live source has the hand (hand_live) */
    tracker_row live_now;   /*   its pose and buttons now */
    tracker_row live_last;  /*   its last sample taken at once (hand_live_act) */
    bool live_have_last;
    long live_taken;        /*   samples the hand has taken from it */

    vec3 fly;               /* head movement not yet given (hand_take_fly) */
    double pose_clock;      /* the clock at which p and q are (fly counted up to it) */

    FILE *log;              /* hand_log */
    double log_start;
    char log_error[HAND_PATH_MAX + 256]; /* a row that did not reach it ("" none) */
    tracker_row logged;     /* the last row written */
    bool have_logged;

    hand_say say;
    void *say_ctx;
} hand;

void hand_init(hand *h, hand_say say, void *ctx);
/* Closes the feed and the log, frees the path. */
void hand_free(hand *h);

/* ---- statements (outside frames; w->time is now) ---- */

/* Moves the hand to p (hand = p) or turns it to q (hand_rotate): what it holds
 * sweeps after it at once, as far as nothing is in the way (hold_sweep).  Its velocity is the change over
 * the simulated time since the last such statement (zero when none passed). */
void hand_move(hand *h, world *w, vec3 p, quat q);

/* The trigger goes down or up (trigger = on/off). */
void hand_trigger(hand *h, world *w, bool down);

/* reselect: the object held last becomes current, and is grabbed again in select
 * mode with the trigger down and nothing held, when the hand can reach it.
 * Returns 0, or -1 with a message in err when nothing was held before. */
int hand_reselect(hand *h, world *w, char *err, size_t errlen);

/* tracker = path: a tracker file (checked whole) or a FIFO (a live feed).  Returns
 * 0, or -1 with a message in err (the old tracker stays). */
int hand_tracker(hand *h, const char *path, char *err, size_t errlen);
/* tracker = off: the hand stays where it is. */
void hand_tracker_off(hand *h);

/* tracker_time = t: the file's rows up to t are taken as played, without acting,
 * and the hand is where the file has it at t.  Returns 0, or -1 with a message. */
int hand_seek(hand *h, world *w, double t, char *err, size_t errlen);
/* The tracker clock's time in the file playing (0 without one). */
double hand_tracker_time(const hand *h);

/* hand_log = path / off, written and checked as every output (shell/outfile.h).
 * Open returns 0, or -1 with a message in err: the new file could not be written
 * (the old log stays), or the old log's last rows (the new one is open).  Close
 * returns 0, or -1 with a message when its last rows did not reach the file (it is
 * closed either way; nothing to close is 0). */
int hand_log_open(hand *h, const char *path, char *err, size_t errlen);
int hand_log_close(hand *h, char *err, size_t errlen);
/* True, with "cannot write 'PATH': REASON" in err, when a row written since the
 * last call did not reach the log: the log is then closed, and hand_log off (the
 * caller says so: shell_output_failed). */
bool hand_log_failed(hand *h, char *err, size_t errlen);

/* grip = what: sets the trigger down and what it holds without pressing, grabbing
 * or releasing anything (save writes it): off (the trigger up), none, fly, panel,
 * time_step, collision_dist, or an object's name; when quoted ("panel"), what is
 * an object's name whatever it is.  Returns 0, or -1 with a message. */
int hand_set_grip(hand *h, world *w, const char *what, bool quoted, char *err, size_t errlen);

/* Room for the text of grip's value: a name and its quotes. */
#define HAND_GRIP_TEXT (BODY_NAME_MAX + 2)
/* The value grip = would take for the hand now, in buf: one of its words, or the
 * held object's name, quoted when it is one of those words (an object named
 * panel is "panel"), so that it reads back as the object. */
const char *hand_grip_word(const hand *h, const world *w, char buf[HAND_GRIP_TEXT]);

/* The hand lets go of object i where it is, if it holds it (no throw): the
 * trigger stays down, holding nothing. */
void hand_let_go(hand *h, world *w, int i);

/* ---- the hand's exact state (save writes it after the tracker's place; each
 * sets what it names as it was, pressing, grabbing and moving nothing) ---- */

/* tracker_clock = (clock, start): the tracker clock, and its reading at the
 * playing file's time 0 (tracker_time is their difference). */
void hand_set_clock(hand *h, double clock, double start);
/* The clock and that reading, as hand_set_clock takes them. */
void hand_clock_of(const hand *h, double *clock, double *start);

/* tracker_row = n: the file's first n rows (all, when it has fewer) have acted:
 * the hand moves on from row n - 1 to row n, and its button is as row n - 1 says.
 * Returns 0, or -1 with a message when no file plays (but for n = 0). */
int hand_set_row(hand *h, int n, char *err, size_t errlen);
/* The rows that have acted (0 without a file). */
int hand_row(const hand *h);

/* hand_velocity = v t, hand_spin = wv: the velocity and angular velocity the
 * hand's statements gave it, the last of them at simulated time t. */
void hand_set_velocity(hand *h, vec3 v, double t);
void hand_set_spin(hand *h, vec3 wv);

/* grip_at = x, grip_orientation = q (either may be NULL): where what the hand
 * holds (an object or the panel) is in the hand's own axes; the next grab makes
 * them anew.  hand_grip_pose gives them. */
void hand_set_grip_pose(hand *h, const vec3 *x, const quat *q);
void hand_grip_pose(const hand *h, vec3 *x, quat *q);

/* last_held = NAME or none: the object the re-select button takes; quoted is
 * true when the name was written as a quoted string, which names an object even
 * if it reads "none".  Returns 0, or -1 with a message (no such dynamic object). */
int hand_set_last_held(hand *h, const world *w, const char *name, bool quoted, char *err, size_t errlen);

/* Object i was deleted: indices above it move down. */
void hand_object_deleted(hand *h, int i);

/* ---- time ---- */

/* A frame of w->set.time_step starts at w->time: rows due act, a live feed is read,
 * and what is held gets its motion.  The frame's hook (hand_hook) acts at its rows. */
void hand_frame_begin(hand *h, world *w);
/* The hook for sim_frame_hooked (ctx is the hand). */
double hand_hook_next(void *ctx, const world *w);
void hand_hook_at(void *ctx, world *w);
/* The frame ended at w->time: the clock moves on by the frame, rows at its end act,
 * a slider sets its setting, and the log gets a row. */
void hand_frame_end(hand *h, world *w);

/* At the prompt while time stands still: the clock moves on by dt seconds of the
 * wall clock, and the file's rows due act now. */
void hand_wall(hand *h, world *w, double dt);

/* A live feed's descriptor for select(), or -1. */
int hand_feed_fd(const hand *h);
/* Reads the live feed between frames: rows take effect as they come, and what the
 * hand holds sweeps after it, as far as nothing is in the way. */
void hand_poll(hand *h, world *w);

/* True when something moves on the tracker clock while time stands still (a
 * file still playing, or flying): the prompt should wake to call hand_wall. */
bool hand_busy(const hand *h);

/* ---- a live source: the window's mouse (shell/viewer.h) ----
 *
 * A live source follows the named pipe's rules, with its samples taken at frame
 * boundaries: at each boundary, before the rows due there act, its sample becomes
 * a row at the end of the coming frame, so that the hand moves to it in a straight
 * line over the frame, as between two rows of a file (a frame behind the source),
 * and its velocity is that segment's.  While time stands still, hand_live_act takes
 * the sample at once, as a row of a live feed.  hand_log writes the rows as they
 * act, at the clock's times, and the clock starts again at 0 when hand_log opens
 * with no file playing: so the log of a session whose time ran from the log's
 * opening, replayed as a tracker file from clock 0, moves the hand, and so the
 * world, to the bit as the source did. */

/* The live source's pose and buttons now (now->t is not used), or NULL when it does
 * not have the hand (a path of its rows still to come is dropped: the hand stays
 * where it is).  Between frames. */
void hand_live(hand *h, world *w, const tracker_row *now);

/* While time stands still: the hand takes the live source's sample now, at the
 * clock's time, as it takes a row of a live feed (it jumps there, and what it
 * holds sweeps after it, as far as nothing is in the way; its velocity is the change from the
 * sample before over the clock's time between them). */
void hand_live_act(hand *h, world *w);

/* How many samples of the live source the hand has taken so far. */
long hand_live_taken(const hand *h);

/* True when a tracker file with rows still to come, or a live feed, has the hand
 * (a live source then has not). */
bool hand_tracked(const hand *h);

/* The first dynamic object, not held, that the ray from o along the unit vector
 * dir meets within max metres (to within half of reach, and 1e-4 m at most), or
 * -1; *t is how far along the ray. */
int hand_pick(const hand *h, const world *w, vec3 o, vec3 dir, double max, double *t);

/* ---- what the caller does for the hand ---- */

/* The first button pressed since the last call (removed), or PANEL_OFF. */
panel_part hand_take_press(hand *h);
/* An object the hand made current (grabbed or re-selected), or -1 (removed). */
int hand_take_current(hand *h);
/* How far the head (and look_at) has flown since the last call (removed). */
vec3 hand_take_fly(hand *h);

/* The panel's orientation. */
quat hand_panel_q(const hand *h);

#endif
