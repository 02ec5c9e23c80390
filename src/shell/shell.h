/* shell.h: runs statements against the world: dispatch, messages, time.
 *
 * The shell owns the world, the settings of the views, of the sound and its own,
 * the current object, the logs, the off-screen view, and the sound and movie
 * being made (media.h).  Input comes from files (parsed whole before running),
 * from -c, from a terminal through GNU readline (with real-time running while
 * the user types: prompt.c), or line by line from a pipe.  Handlers
 * (the cmd_*.c files) report through sh_error / sh_warn / sh_info so that every
 * message carries its file and line.
 */
#ifndef VROC_SHELL_H
#define VROC_SHELL_H

#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>

#include "commands.h"
#include "figures.h"
#include "fmt.h"
#include "core/world.h"
#include "hand/hand.h"
#include "lang.h"
#include "log.h"
#include "progress.h"
#include "sound/sound.h"
#include "view/view.h"

/* Longest path a setting of the shell's holds, with its final NUL. */
#define SHELL_PATH_MAX 1024

/* The settings the shell owns: where `random` places objects. */
typedef struct {
    vec3 random_box;        /* half-extents of the box random objects go in */
    double random_size[2];  /* the least and the most of each random object's largest
                             * half-extent (a sphere's radius) */
    unsigned long seed;     /* of random's sequence */
    int precision;          /* how numbers are shown to a person (fmt_style) */
} shell_settings;

/* The start-up values: random_box (2, 2, 2), random_size (0.08, 0.2), seed 1,
 * precision short. */
shell_settings shell_settings_defaults(void);

typedef struct shell {
    world w;
    view_settings view_set;
    shell_settings set;
    sound_settings sound_set;
    hand hand;             /* the hand-held tracker and the tool panel */
    struct {               /* what restart returns to: defaults and -o */
        sim_settings sim;
        view_settings view;
        shell_settings shell;
        sound_settings sound;
    } startup;
    shell_logs logs;       /* trace and events */
    figures figs;          /* the current run's figures, for plot */
    view *view;            /* off-screen context, created on first need */
    view_stats view_st;    /* what drawing has cost */
    struct media *media;   /* sound and movie (media.h), made on first need */
    struct viewer *viewer; /* the live window (viewer.h), or NULL when closed */
    double wall_time;      /* seconds spent advancing time */
    bool running;          /* `start` given and not stopped */
    int current;           /* index of the current object, or -1 */
    long made;             /* objects made since restart: the next takes colour `made`
                            * of the palette (view_palette) */
    const stmt *running_st; /* the statement running (for the hand's messages) */
    bool hand_failed;      /* the hand reported an error since it began */
    bool interactive;      /* a terminal with readline */
    bool quiet;            /* -q */
    bool verbose;          /* -v: progress in batch too */
    progress *progress;    /* the status line of the run going on, or NULL */
    bool stop_on_error;    /* -b, or input that is not a terminal */
    FILE *out, *err;
    const char *scene_dir; /* installed scenes folder */
    unsigned long long rng; /* state of `random`, reset by seed */
    bool at_prompt;        /* readline shows the prompt and a line being typed: a
                            * message first breaks the line (line_broken), and
                            * the prompt is drawn again after it (prompt.c) */
    bool line_broken;
    bool found_apart;      /* shell_check_start found no overlap since the last
                            * statement began: time may run on unchecked */
    long cuts_seen;        /* the world's speed_cuts when last looked at
                            * (shell_check_cuts), */
    long painleve_seen;    /*   its painleve, */
    long fallen_seen;      /*   its fallen */
    long guards_seen;      /*   and its guards (the event guard's last resort) */
    bool fly_told;         /* flying was stopped at the limits, and said so */
} shell;

/* Set by the SIGINT handler; long operations (run, start, random, reading a pipe,
 * a frame's many pictures in a movie) stop when it is set, and what acts on it
 * clears it. */
extern volatile sig_atomic_t shell_interrupted;

/* Ctrl-C (SIGINT) sets shell_interrupted from now on, in batch runs too (main);
 * a second Ctrl-C before the first was taken ends vroc at once. */
void shell_catch_sigint(void);

void shell_init(shell *sh, FILE *out, FILE *err);
void shell_free(shell *sh);

/* Parses text named name (NULL: typed at the prompt; "-c": the command line)
 * and runs it.  Returns CMD_QUIT on quit, CMD_ERROR on the first error (after
 * printing it; later statements of that text do not run), else CMD_OK. */
cmd_status shell_run_text(shell *sh, const char *text, const char *name);

/* Parses the file at path whole and runs it, as `read` does from the prompt. */
cmd_status shell_run_file(shell *sh, const char *path);

/* Runs a parsed program, stopping at the first error (or quit). */
cmd_status shell_run_program(shell *sh, const program *p);

/* Refuses to let time run while objects interpenetrate (thesis 3.4.2, step 1):
 * names every such pair with its depth.  The check queries every pair, so it is
 * made once per statement: the frames start advances in real time between
 * statements are not checked again (nothing but the simulation moved). */
cmd_status shell_check_start(shell *sh, const stmt *st);

/* Advances n frames (honouring Ctrl-C); writes the logs' rows after each, and the
 * views when record is on. */
cmd_status shell_advance(shell *sh, const stmt *st, long n);

/* shell_advance for `run`: at an interactive prompt, or with -v, a run that lasts
 * shows its progress (progress.h). */
cmd_status shell_run_frames(shell *sh, const stmt *st, long n);

/* The one rule for an output that could not be written (outfile.h): trace,
 * events, the recorded frames, and any file written as time runs.  The caller has
 * turned the output `what` off; this says so, with err ("cannot write 'PATH':
 * REASON").  At the prompt time goes on without it (CMD_OK); a batch run
 * (stop_on_error) stops there (CMD_ERROR, and vroc exits 1). */
cmd_status shell_output_failed(shell *sh, const stmt *st, const char *what, const char *err);

/* Finishes the movie and the soundtrack (media.h) and closes the logs, checking
 * their last writes: at the end of the program, before shell_free.  Returns
 * CMD_ERROR (after saying why) when one failed. */
cmd_status shell_close_outputs(shell *sh);

/* Closes the logs (trace, events, hand_log), checking their last writes, as the
 * end of the program and restart (st) do; the movie and soundtrack go on.
 * Returns CMD_ERROR (after saying why) when one failed. */
cmd_status shell_close_logs(shell *sh, const stmt *st);

/* The world's first collision or throw whose result a speed limit cut (st.speed_cuts
 * grew from 0 since the last look) warns once, naming the object and the limit
 * to raise; later ones are only counted (stats: speed_cuts).  So does the first
 * step whose events reached the event guard's last resort (st.guards: guard.h),
 * naming the objects. */
void shell_check_cuts(shell *sh, const stmt *st);

/* Messages about statement st (NULL: no location). */
void sh_error(shell *sh, const stmt *st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void sh_warn(shell *sh, const stmt *st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* An informational line on the output, silenced by -q. */
void sh_info(shell *sh, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Seconds on the monotonic clock (wall time). */
double shell_clock(void);

/* After the hand acted (a statement, a frame, a tick of the wall clock): the object
 * it grabbed or re-selected becomes current, the head flies as it flew, a hand_log
 * row that failed turns hand_log off (shell_output_failed), and the panel's
 * buttons it pressed run as their commands.  Returns CMD_ERROR when the log's
 * failure stops the run, else what the buttons' commands returned (CMD_OK when
 * none). */
cmd_status shell_after_hand(shell *sh);

/* The hand and the panel as the views draw them (view_settings.overlay), from the
 * hand now: called before each drawing. */
void shell_overlay(shell *sh);

/* The address of setting c's field (a FORM_SETTING) in its owner's settings. */
void *shell_setting_field(shell *sh, const command *c);
const void *shell_setting_value(const shell *sh, const command *c);

/* How numbers are shown to a person now (`precision`). */
fmt_style shell_shown(const shell *sh);

/* How many numbers the random sequence has drawn since seed was set (what
 * random_draws restores). */
unsigned long long shell_random_draws(const shell *sh);

/* Statements text (named name for messages) parsed and run from line `line` on. */
cmd_status shell_run_text_at(shell *sh, const char *text, const char *name, int line);

/* The interactive loop on a terminal (readline) or the line loop on a pipe
 * (prompt.c). */
int shell_loop(shell *sh);

#endif
