/* shell.c: the shell's state, statements run with their messages, and time
 * advanced with its logs and frames.
 *
 * A program (a file, a -c text, a line typed) is parsed whole, then its statements
 * run in turn through the command table; the first error stops it.  After every
 * statement the core is told that the world changed (edit_done).  Time advances
 * frame by frame: after each the shell writes the frame's events and trace rows,
 * the views' files when record is on, and gives the frame to the sound and the
 * movie (media.h).
 */
#include "shell.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/edit.h"
#include "core/limits.h"
#include "core/sim.h"
#include "view/view.h"
#include "fmt.h"
#include "media.h"
#include "viewer.h"

shell_settings shell_settings_defaults(void)
{
    shell_settings s;
    memset(&s, 0, sizeof s);
    s.random_box = v3(2, 2, 2);
    s.random_size[0] = 0.08;
    s.random_size[1] = 0.2;
    s.seed = 1;
    s.precision = FMT_SHORT;
    return s;
}

fmt_style shell_shown(const shell *sh) { return (fmt_style)sh->set.precision; }

double shell_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The hand's messages, about the statement running (hand.h). */
static void shell_hand_say(void *ctx, hand_message kind, const char *msg)
{
    shell *sh = ctx;
    if (kind == HAND_ERROR) {
        sh_error(sh, sh->running_st, "%s", msg);
        sh->hand_failed = true;
    } else if (kind == HAND_WARNING) {
        sh_warn(sh, sh->running_st, "%s", msg);
    } else {
        sh_info(sh, "%s", msg);
    }
}

void shell_init(shell *sh, FILE *out, FILE *err)
{
    memset(sh, 0, sizeof *sh);
    world_init(&sh->w);
    sh->view_set = view_settings_defaults();
    sh->set = shell_settings_defaults();
    sh->sound_set = sound_settings_defaults();
    sh->startup.sim = sh->w.set;
    sh->startup.view = sh->view_set;
    sh->startup.shell = sh->set;
    sh->startup.sound = sh->sound_set;
    sh->rng = sh->set.seed;
    sh->current = -1;
    sh->out = out;
    sh->err = err;
    hand_init(&sh->hand, shell_hand_say, sh);
    figures_init(&sh->figs, FIGURES_MAX_FRAMES, FIGURES_MAX_HEIGHTS);
}

cmd_status shell_close_logs(shell *sh, const stmt *st)
{
    char err[HAND_PATH_MAX + 512];
    cmd_status r = CMD_OK;
    if (log_trace_close(&sh->logs, err, sizeof err) != 0) {
        sh_error(sh, st, "trace: %s", err);
        r = CMD_ERROR;
    }
    if (log_events_close(&sh->logs, err, sizeof err) != 0) {
        sh_error(sh, st, "events: %s", err);
        r = CMD_ERROR;
    }
    if (hand_log_close(&sh->hand, err, sizeof err) != 0) {
        sh_error(sh, st, "hand_log: %s", err);
        r = CMD_ERROR;
    }
    return r;
}

cmd_status shell_close_outputs(shell *sh)
{
    cmd_status r = media_finish(sh) != 0 ? CMD_ERROR : CMD_OK; /* the movie, the soundtrack */
    return shell_close_logs(sh, NULL) != CMD_OK ? CMD_ERROR : r;
}

void shell_free(shell *sh)
{
    viewer_free(sh);
    shell_close_outputs(sh);
    media_free(sh);
    world_free(&sh->w);
    view_free(sh->view);
    sh->view = NULL;
    hand_free(&sh->hand);
    figures_free(&sh->figs);
}

/* ------------------------------------------------------------ messages */

/* A message while the prompt shows (the hand, between lines typed) starts on a
 * line of its own. */
static void break_line(shell *sh)
{
    if (sh->at_prompt && !sh->line_broken) {
        fputc('\n', sh->out);
        sh->line_broken = true;
    }
}

/* The message fmt, ap on f as one line, its bytes that are not printable text
 * escaped (fmt_escaped: a message may quote a file's bytes). */
static void put_line(FILE *f, const char *fmt, va_list ap)
{
    char small[512], *text = small;
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    if (n >= (int)sizeof small && (text = malloc((size_t)n + 1)) != NULL)
        vsnprintf(text, (size_t)n + 1, fmt, again);
    va_end(again);
    fmt_escaped(f, text ? text : small);
    fputc('\n', f);
    if (text != small) free(text);
}

static void vmsg(shell *sh, const stmt *st, const char *kind, const char *fmt, va_list ap)
{
    if (sh->progress) progress_hide(sh->progress);
    break_line(sh);
    fflush(sh->out);
    if (st && st->file) {
        fmt_escaped(sh->err, st->file);
        fprintf(sh->err, ":%d: %s: ", st->line, kind);
    } else {
        fprintf(sh->err, "%s: ", kind);
    }
    put_line(sh->err, fmt, ap);
    fflush(sh->err);
}

void sh_error(shell *sh, const stmt *st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(sh, st, "error", fmt, ap);
    va_end(ap);
}

void sh_warn(shell *sh, const stmt *st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(sh, st, "warning", fmt, ap);
    va_end(ap);
}

void sh_info(shell *sh, const char *fmt, ...)
{
    if (sh->quiet) return;
    if (sh->progress) progress_hide(sh->progress);
    break_line(sh);
    va_list ap;
    va_start(ap, fmt);
    put_line(sh->out, fmt, ap);
    va_end(ap);
}

/* ------------------------------------------------------------ running */

cmd_status shell_run_program(shell *sh, const program *p)
{
    for (int i = 0; i < p->n; i++) {
        sh->found_apart = false; /* the statement may move anything */
        const stmt *outer = sh->running_st;
        sh->running_st = &p->s[i];
        cmd_status r = p->s[i].cmd->run(sh, &p->s[i]);
        /* what the hand did: its buttons run after the statement */
        if (r == CMD_OK) r = shell_after_hand(sh);
        shell_check_cuts(sh, &p->s[i]); /* (a throw a statement made) */
        sh->running_st = outer;
        /* whatever a statement changed, the schedule's predictions start afresh */
        edit_done(&sh->w);
        if (r != CMD_OK) return r;
    }
    return CMD_OK;
}

/* How far along d the points a and b may both move and stay within the limits of
 * a position (core/limits.h): d, cut component by component. */
static double fly_room(double d, double a, double b)
{
    double lo = -LIM_POSITION_MAX - d_min(a, b), hi = LIM_POSITION_MAX - d_max(a, b);
    return d_max(lo, d_min(hi, d)); /* (lo <= 0 <= hi: a and b are within them now) */
}

cmd_status shell_after_hand(shell *sh)
{
    int i = hand_take_current(&sh->hand);
    if (i >= 0 && i < sh->w.n) sh->current = i;
    vec3 fly = hand_take_fly(&sh->hand), *h = &sh->view_set.head, *l = &sh->view_set.look_at;
    /* the head flies no further than the limits of a position: show and save
     * write it, and it must read back */
    vec3 room = v3(fly_room(fly.x, h->x, l->x), fly_room(fly.y, h->y, l->y), fly_room(fly.z, h->z, l->z));
    if ((room.x != fly.x || room.y != fly.y || room.z != fly.z) && !sh->fly_told) {
        sh->fly_told = true;
        sh_warn(sh, sh->running_st, "flying stops at the limits of a position: head and look_at "
                "stay within %g m of the origin in each coordinate", LIM_POSITION_MAX);
    }
    *h = v3_add(*h, room);
    *l = v3_add(*l, room);
    cmd_status r = CMD_OK;
    char err[HAND_PATH_MAX + 256];
    if (hand_log_failed(&sh->hand, err, sizeof err))
        r = shell_output_failed(sh, sh->running_st, "hand_log", err);
    panel_part k;
    while (r == CMD_OK && (k = hand_take_press(&sh->hand)) != PANEL_OFF)
        r = shell_run_text(sh, panel_control_of(k)->name, NULL);
    return r;
}

static lang_paths paths_of(const shell *sh) { return (lang_paths){NULL, sh->scene_dir, NULL}; }

static cmd_status run_parsed(shell *sh, program *p, const char *err)
{
    if (!p) {
        fflush(sh->out);
        fmt_escaped(sh->err, err);
        fputc('\n', sh->err);
        return CMD_ERROR;
    }
    cmd_status r = shell_run_program(sh, p);
    program_free(p);
    viewer_changed(sh); /* the window shows what the statements did */
    /* what the statements printed is checked like any file written */
    errno = 0;
    if (fflush(sh->out) != 0 || ferror(sh->out)) {
        sh_error(sh, NULL, "cannot write the standard output: %s", strerror(errno ? errno : EIO));
        clearerr(sh->out);
        if (r == CMD_OK) r = CMD_ERROR;
    }
    return r;
}

cmd_status shell_run_text_at(shell *sh, const char *text, const char *name, int line)
{
    char err[1024];
    lang_paths paths = paths_of(sh);
    program *p = lang_parse(text, strlen(text), name, line, &paths, 0, NULL, 0, err, sizeof err);
    return run_parsed(sh, p, err);
}

cmd_status shell_run_text(shell *sh, const char *text, const char *name)
{
    return shell_run_text_at(sh, text, name, 1);
}

cmd_status shell_run_file(shell *sh, const char *path)
{
    char err[1024];
    lang_paths paths = paths_of(sh);
    figures_clear(&sh->figs); /* a new run, as read starts one */
    /* level 1, as a file read at the prompt: one nesting limit for both */
    program *p = lang_parse_file(path, &paths, 1, NULL, 0, NULL, 0, err, sizeof err);
    return run_parsed(sh, p, err);
}

typedef struct {
    shell *sh;
    const stmt *st;
} pen_ctx;

static void report_penetration(void *ctx, const body *a, const body *b, double depth)
{
    pen_ctx *c = ctx;
    char d[32];
    sh_error(c->sh, c->st, "'%s' and '%s' interpenetrate by %s m", a->name, b->name,
             fmt_num(d, depth));
}

cmd_status shell_check_start(shell *sh, const stmt *st)
{
    pen_ctx ctx = {sh, st};
    long n = sim_penetrations(&sh->w, report_penetration, &ctx);
    if (n < 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    if (n > 0) {
        sh_error(sh, st, "time cannot run while objects interpenetrate: move them apart first");
        return CMD_ERROR;
    }
    if (sim_prepare(&sh->w) != 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    sh->found_apart = true;
    return CMD_OK;
}

cmd_status shell_output_failed(shell *sh, const stmt *st, const char *what, const char *err)
{
    sh_error(sh, st, "%s: %s; %s is now off%s", what, err, what,
             sh->stop_on_error ? ", time stopped" : "");
    return sh->stop_on_error ? CMD_ERROR : CMD_OK;
}

/* Writes what the frame just advanced gives the outputs: the events' and the
 * trace's rows, the views when record is on, then the frame's sound and movie
 * frames (media.h, which may reuse what record drew).  An output that fails is
 * turned off (shell_output_failed); returns CMD_ERROR when the run must stop. */
static cmd_status write_frame(shell *sh, const stmt *st)
{
    char err[1024], ignored[8];
    cmd_status r = CMD_OK;
    if (log_events_frame(&sh->logs, &sh->w, err, sizeof err) != 0) {
        log_events_close(&sh->logs, ignored, sizeof ignored);
        r = shell_output_failed(sh, st, "events", err);
    }
    if (r == CMD_OK && log_trace_frame(&sh->logs, &sh->w, err, sizeof err) != 0) {
        log_trace_close(&sh->logs, ignored, sizeof ignored);
        r = shell_output_failed(sh, st, "trace", err);
    }
    /* the hand and the panel, for whatever draws the frame: record, the movie */
    if (r == CMD_OK) shell_overlay(sh);
    if (r == CMD_OK && sh->view_set.record &&
        view_refresh(&sh->view, &sh->w, &sh->view_set, sh->w.frame, &sh->view_st, err,
                     sizeof err) != 0) {
        sh->view_set.record = false;
        r = shell_output_failed(sh, st, "record", err);
    }
    if (r == CMD_OK) r = media_frame(sh, st);
    return r;
}

/* True, after an error, when the next frame would take the clock past what
 * clock and frame may be set to (core/limits.h): a saved world would not read
 * back. */
static bool clock_full(shell *sh, const stmt *st)
{
    const world *w = &sh->w;
    char a[32], b[32];
    if (w->time + w->set.time_step > LIM_CLOCK_MAX) {
        sh_error(sh, st, "time cannot run past %s s (it is %s s): the limit of the clock",
                 fmt_num(a, LIM_CLOCK_MAX), fmt_num(b, w->time));
        return true;
    }
    if ((double)w->frame + 1 > LIM_FRAMES_MAX || (double)w->base_frames + 1 > LIM_CLOCK_MAX) {
        sh_error(sh, st, "time cannot run past frame %ld: the limit of the frame count", w->frame);
        return true;
    }
    return false;
}

/* What the frame took beyond the limits of a state (a fall of minutes, a force of
 * a thousand g) rests where it left them, with one warning each (edit.h): so that
 * every state save writes reads back. */
static void rest_beyond_limits(shell *sh, const stmt *st)
{
    world *w = &sh->w;
    for (int i = 0; i < w->n; i++) {
        if (!edit_beyond_limits(w, i)) continue;
        hand_let_go(&sh->hand, w, i);
        const body *b = w->bodies[i];
        vec3 x = b->x;
        bool far = fabs(x.x) > LIM_POSITION_MAX || fabs(x.y) > LIM_POSITION_MAX ||
                   fabs(x.z) > LIM_POSITION_MAX;
        char t[32], lim[32], why[160], p[3][32];
        fmt_num(t, w->time);
        if (far)
            snprintf(why, sizeof why, "a coordinate beyond %s m: translate = (%s, %s, %s)",
                     fmt_num(lim, LIM_POSITION_MAX), fmt_num(p[0], x.x), fmt_num(p[1], x.y),
                     fmt_num(p[2], x.z));
        else
            snprintf(why, sizeof why, "a velocity beyond %s m/s, or a spin beyond what the "
                     "limits give", fmt_num(lim, LIM_SPEED_MAX));
        edit_rest_at_limits(w, i);
        sh_warn(sh, st, "'%s' left the limits of a state at time = %s (%s): it rests where it left "
                "them, at translate = (%s, %s, %s)", b->name, t, why, fmt_num(p[0], b->x.x),
                fmt_num(p[1], b->x.y), fmt_num(p[2], b->x.z));
    }
}

/* Ctrl-C came while time advanced: at the prompt time stops there (CMD_OK); a
 * batch run stops there, as at an error. */
static cmd_status interrupted(shell *sh, const stmt *st)
{
    shell_interrupted = 0;
    char a[32];
    fmt_num(a, sh->w.time);
    if (!sh->stop_on_error) {
        sh_info(sh, "interrupted at time = %s", a);
        return CMD_OK;
    }
    sh_error(sh, st, "interrupted at time = %s", a);
    return CMD_ERROR;
}

/* The name of object i (an index the core reported), or "?". */
static const char *name_of(const shell *sh, int i)
{
    return i >= 0 && i < sh->w.n ? sh->w.bodies[i]->name : "?";
}

/* The world's first collision or throw whose result a speed limit cut (sim.h,
 * hold.h) warns, naming the object and the limit to raise: each such cut loses
 * energy. */
static void warn_speed_cut(shell *sh, const stmt *st)
{
    const sim_cut *c = &sh->w.st.first_cut;
    const char *limit = c->angular ? "max_angular" : "max_linear";
    const char *name = name_of(sh, c->object);
    sh_warn(sh, st,
            "%s = %g cut the %s a %s gave '%s' (%.3g %s): each such cut loses energy, and "
            "stats counts them (speed_cuts); raise %s to keep it",
            limit, c->limit, c->angular ? "spin" : "speed", c->thrown ? "throw" : "collision", name,
            c->speed, c->angular ? "rad/s" : "m/s", limit);
}

/* The world's first internal step whose events reached the guard's last resort
 * (guard.h) warns, naming the objects of the event at hand. */
static void warn_guard(shell *sh, const stmt *st)
{
    const sim_guard *g = &sh->w.st.first_guard;
    char t[32];
    fmt_num(t, g->t);
    char with[160] = "";
    if (g->b >= 0) snprintf(with, sizeof with, " and '%s'", name_of(sh, g->b));
    sh_warn(sh, st,
            "at time = %s the events of '%s'%s ran away (%ld in one step): %d object%s stopped "
            "where they were, so that nothing passes through anything; stats counts these (guards)",
            t, name_of(sh, g->a), with, sh->w.guard.max_events, g->stopped, g->stopped == 1 ? "" : "s");
}

void shell_check_cuts(shell *sh, const stmt *st)
{
    const sim_stats *s = &sh->w.st;
    if (s->guards < sh->guards_seen) sh->guards_seen = 0; /* a new world (restart) */
    if (sh->guards_seen == 0 && s->guards > 0) warn_guard(sh, st);
    sh->guards_seen = s->guards;
    if (s->speed_cuts < sh->cuts_seen) sh->cuts_seen = 0;
    if (sh->cuts_seen == 0 && s->speed_cuts > 0) warn_speed_cut(sh, st);
    sh->cuts_seen = s->speed_cuts;
    /* the world's first contact with friction that had no consistent answer */
    if (s->painleve < sh->painleve_seen) sh->painleve_seen = 0;
    if (sh->painleve_seen == 0 && s->painleve > 0) {
        int i = s->first_painleve;
        sh_warn(sh, st,
                "a contact of '%s' with friction had no consistent answer (Painleve): it was "
                "answered without friction there, and stats counts such contacts (painleve)",
                i >= 0 && i < sh->w.n ? sh->w.bodies[i]->name : "?");
    }
    sh->painleve_seen = s->painleve;
    /* each object that left the room, once */
    if (s->fallen < sh->fallen_seen) sh->fallen_seen = 0;
    if (s->fallen > sh->fallen_seen)
        for (int i = 0; i < sh->w.n; i++) {
            body *b = sh->w.bodies[i];
            if (b->fell != 1) continue;
            b->fell = 2;
            sh_warn(sh, st, "'%s' has fallen more than %d m below the lowest static object: it "
                            "falls on", b->name, SIM_FALL_DEPTH);
        }
    sh->fallen_seen = s->fallen;
}

/* shell_advance, with a status line when show (progress.h). */
static cmd_status advance(shell *sh, const stmt *st, long n, bool show)
{
    char err[1024];
    if (n > 0 && !sh->found_apart && shell_check_start(sh, st) != CMD_OK) return CMD_ERROR;
    double t0 = shell_clock();
    cmd_status r = CMD_OK;
    sim_hook hook = {hand_hook_next, hand_hook_at, &sh->hand};
    sh->hand_failed = false;
    if (n > 0 && sh->figs.n == 0) figures_record(&sh->figs, &sh->w); /* where the run starts */
    progress prog;
    if (show) {
        progress_begin(&prog, sh->err, n, t0);
        sh->progress = &prog;
    }
    for (long k = 0; k < n && r == CMD_OK; k++) {
        if (shell_interrupted) {
            r = interrupted(sh, st);
            break;
        }
        if (clock_full(sh, st)) {
            r = CMD_ERROR;
            break;
        }
        media_frame_begin(sh); /* a movie's pictures within the frame start here */
        /* the hand acts at its rows' instants within the frame (hand.h), and takes
         * the window's mouse at its boundaries (viewer.h) */
        viewer_sample(sh);
        hand_frame_begin(&sh->hand, &sh->w);
        int status = sim_frame_hooked(&sh->w, &hook, err, sizeof err);
        viewer_sample(sh);
        hand_frame_end(&sh->hand, &sh->w);
        shell_check_cuts(sh, st);
        if (status != 0) {
            sh_error(sh, st, "%s", err);
            r = CMD_ERROR;
            break;
        }
        rest_beyond_limits(sh, st);
        figures_record(&sh->figs, &sh->w);
        r = write_frame(sh, st);
        /* the panel's buttons pressed in the frame act at its end */
        if (r == CMD_OK && (shell_after_hand(sh) != CMD_OK || (sh->hand_failed && sh->stop_on_error)))
            r = CMD_ERROR;
        if (show) progress_tick(&prog, k + 1, sh->w.time, shell_clock());
        viewer_frame(sh, k + 1 == n || r != CMD_OK);
    }
    if (show) {
        progress_hide(&prog);
        sh->progress = NULL;
    }
    /* (a Ctrl-C the last frame's movie took) */
    if (r == CMD_OK && shell_interrupted) r = interrupted(sh, st);
    sh->wall_time += shell_clock() - t0;
    return r;
}

cmd_status shell_advance(shell *sh, const stmt *st, long n) { return advance(sh, st, n, false); }

cmd_status shell_run_frames(shell *sh, const stmt *st, long n)
{
    return advance(sh, st, n, sh->interactive || sh->verbose);
}

void *shell_setting_field(shell *sh, const command *c)
{
    return (void *)shell_setting_value(sh, c);
}

const void *shell_setting_value(const shell *sh, const command *c)
{
    switch (c->owner) {
    case OWN_SIM: return (const char *)&sh->w.set + c->off;
    case OWN_VIEW: return (const char *)&sh->view_set + c->off;
    case OWN_SHELL: return (const char *)&sh->set + c->off;
    case OWN_SOUND: return (const char *)&sh->sound_set + c->off;
    case OWN_HAND: return (const char *)&sh->hand.set + c->off;
    default: return NULL;
    }
}
