/* media.c: collisions to the sound engine, views to the movie, and the live stream
 * fed in real time (media.h). */
#include "media.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmt.h"
#include "hand/tracker.h"
#include "shell.h"
#include "sound/sound.h"
#include "view/movie.h"

/* A body as the frame found it: a movie's pictures within the frame are drawn
 * between this and where the frame leaves it. */
typedef struct {
    const body *b;
    vec3 x, v;
    quat q;
} media_start;

struct media {
    sound_engine *snd;
    double elapsed;     /* simulated seconds of the frames advanced since it was made */
    movie *mov;
    double mov_start;   /* elapsed time when the movie started */
    long mov_skipped;   /* pictures the movie left out (MOVIE_MAX_COPIES, Ctrl-C) */
    bool mov_told;      /* the movie's first frame cut to MOVIE_MAX_COPIES was warned of */
    sound_hit *hits;    /* the frame's collisions, as the engine hears them */
    long cap;
    media_start *start; /* each body when the frame began (media_frame_begin) */
    view_pose *poses;   /* where a picture within the frame draws them */
    int nstart, capstart;
};

/* The state, made on first need; NULL when out of memory. */
static media *media_get(shell *sh)
{
    if (sh->media) return sh->media;
    media *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    m->snd = sound_new();
    if (!m->snd) {
        free(m);
        return NULL;
    }
    sh->media = m;
    return m;
}

static sound_listener media_listener(const shell *sh)
{
    return (sound_listener){sh->view_set.head, sh->view_set.look_at, sh->view_set.up};
}

/* Opens the live stream the first time time runs at an interactive prompt with
 * `sound` not off; one warning where no server answers, and `sound` turns off. */
static void media_ask_server(shell *sh, media *m, const stmt *st, double t)
{
    char err[512];
    if (sound_live_open(m->snd, t, err, sizeof err) == 0) return;
    sh->sound_set.live = SOUND_LIVE_OFF;
    sh_warn(sh, st, "sound: no sound server answers (%s); sound is off", err);
}

/* The frame's collisions to the engine (frame [t0, t1] of elapsed time). */
static cmd_status media_sound_frame(shell *sh, media *m, const stmt *st, double t0, double t1)
{
    const world *w = &sh->w;
    if (w->nevents > m->cap) {
        sound_hit *h = realloc(m->hits, (size_t)w->nevents * sizeof *h);
        if (!h) return CMD_OK; /* no sound for this frame rather than none at all */
        m->hits = h;
        m->cap = w->nevents;
    }
    double start = w->time - (t1 - t0); /* the frame's start on the world's clock */
    for (long k = 0; k < w->nevents; k++) {
        const sim_event *e = &w->events[k];
        const body *a = w->bodies[e->a], *b = w->bodies[e->b];
        double t = t0 + (e->t - start);
        m->hits[k] = (sound_hit){.t = fmin(t1, fmax(t0, t)),
                                 .p = e->p,
                                 .j = e->j,
                                 .gain = sh->sound_set.collision_vol * a->volume * b->volume,
                                 .size = sqrt(a->shape.r_out * b->shape.r_out)};
    }
    sound_listener l = media_listener(sh);
    char err[2048];
    if (sound_frame(m->snd, &sh->sound_set, &l, m->hits, w->nevents, t0, t1,
                    sh->running ? shell_clock() : -1, err, sizeof err) != 0)
        return shell_output_failed(sh, st, "soundtrack", err); /* it is closed */
    return CMD_OK;
}

/* Finishes the movie, with the soundtrack's sound of its span if one is open,
 * reporting what fails (the movie, or the soundtrack as its sound is taken).
 * Returns 0, or -1 after an error. */
static int media_movie_close(shell *sh, media *m, const stmt *st)
{
    movie *mov = m->mov;
    m->mov = NULL;
    char err[2048];
    const char *wav = NULL;
    int rc = 0;
    if (sound_track_path(m->snd) && movie_frames(mov) > 0) {
        double t1 = m->mov_start + (double)(movie_frames(mov) + m->mov_skipped) * movie_period(mov);
        if (sound_flush(m->snd, m->elapsed, err, sizeof err) != 0) {
            sh_error(sh, st, "soundtrack: %s; soundtrack is now off", err);
            rc = -1;
        } else if (sound_track_excerpt(m->snd, m->mov_start, t1, movie_sound_path(mov), err,
                                       sizeof err) == 0) {
            wav = movie_sound_path(mov);
        } else {
            sh_error(sh, st, "movie: %s", err);
            rc = -1;
        }
    }
    /* a movie is its video and its sound, or nothing: the old file stays whole */
    char path[VIEW_PATH_MAX];
    snprintf(path, sizeof path, "%s", movie_path(mov));
    if (rc != 0) movie_abort(mov);
    else if (movie_close(mov, wav, err, sizeof err) != 0) {
        sh_error(sh, st, "movie: %s", err);
        rc = -1;
    }
    if (rc != 0) sh_error(sh, st, "movie: '%s' is not written, and what was there is kept", path);
    return rc;
}

void media_frame_begin(shell *sh)
{
    media *m = sh->media;
    if (!m || !m->mov) return;
    const world *w = &sh->w;
    m->nstart = 0;
    if (w->n > m->capstart) {
        media_start *ns = realloc(m->start, (size_t)w->n * sizeof *ns);
        view_pose *np = ns ? realloc(m->poses, (size_t)w->n * sizeof *np) : NULL;
        if (ns) m->start = ns;
        if (np) m->poses = np;
        if (!ns || !np) return; /* pictures as the frame ends, rather than none */
        m->capstart = w->n;
    }
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        m->start[i] = (media_start){b, b->x, b->v, b->q};
    }
    m->nstart = w->n;
}

/* Where the bodies are a fraction s into the frame of h seconds, from where it
 * found them to where it left them: the cubic through both places with both
 * velocities (exact for free flight under the force, a quadratic), and the
 * shorter turn between both orientations.  False when the bodies are not the
 * ones the frame began with. */
static bool media_between(const shell *sh, media *m, double s, double h)
{
    const world *w = &sh->w;
    if (m->nstart != w->n) return false;
    double s2 = s * s, s3 = s2 * s;
    double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        const media_start *a = &m->start[i];
        if (a->b != b) return false;
        vec3 x = v3_add(v3_add(v3_scale(a->x, h00), v3_scale(a->v, h10 * h)),
                        v3_add(v3_scale(b->x, h01), v3_scale(b->v, h11 * h)));
        /* (the tracker's slerp: a fraction s of the short turn from a to b) */
        m->poses[i] = (view_pose){x, tracker_turned(a->q, v3_scale(tracker_turn(a->q, b->q), s))};
    }
    return true;
}

/* The frame's pictures to the movie, movie_rate of them a second of simulated
 * time: picture k shows the time mov_start + (k + 1 + skipped) / movie_rate.
 * Those due within the frame [t0, t1] are drawn between its start and its end
 * (media_between); where a picture is due at the frame's end, or time_step is
 * shorter than a picture, the view after the frame is added as many times as
 * keeps video time with simulated time.  A frame gives at most MOVIE_MAX_COPIES
 * (one warning a movie says so), and fewer when Ctrl-C comes: the pictures left out are
 * skipped, so that later frames keep step. */
static cmd_status media_movie_frame(shell *sh, media *m, const stmt *st, double t0, double t1)
{
    double period = movie_period(m->mov), h = t1 - t0;
    long before = m->mov_skipped;
    long want = llround((t1 - m->mov_start) / period) - before;
    long cut = want - movie_frames(m->mov) - MOVIE_MAX_COPIES;
    if (cut > 0 && !m->mov_told) {
        m->mov_told = true;
        char a[32], b[32];
        sh_warn(sh, st, "movie: a frame of time_step = %s s would be %ld pictures at %s a second; "
                "it gets %d, and the movie skips the rest (its sound goes on, out of step from "
                "there)", fmt_num(a, h), want - movie_frames(m->mov), fmt_num(b, 1 / period),
                MOVIE_MAX_COPIES);
    }
    if (cut > 0) {
        want -= cut;
        m->mov_skipped += cut;
    }
    char err[2048];
    bool posed = false;
    shell_overlay(sh);
    /* the pictures within the frame */
    while (movie_frames(m->mov) < want && !shell_interrupted) {
        double s = (m->mov_start + (double)(movie_frames(m->mov) + before + 1) * period - t0) / h;
        if (!(s < 1 - 1e-9) || !media_between(sh, m, s > 0 ? s : 0, h)) break;
        if (view_render_posed(&sh->view, &sh->w, m->poses, &sh->view_set, err, sizeof err) != 0 ||
            movie_add(m->mov, sh->view, 1, err, sizeof err) != 0)
            goto failed;
        posed = true;
    }
    long copies = want - movie_frames(m->mov);
    if (copies <= 0) return CMD_OK;
    if (shell_interrupted) { /* (shell_advance says so) */
        m->mov_skipped += copies;
        return CMD_OK;
    }
    /* record has drawn this frame already, unless an eye the movie needs is missing */
    bool drawn = sh->view_set.record && !posed && view_pixels(sh->view, 0, NULL, NULL) &&
                 (!movie_needs_right(m->mov) || view_pixels(sh->view, 1, NULL, NULL));
    bool ok = drawn || view_render(&sh->view, &sh->w, &sh->view_set, err, sizeof err) == 0;
    /* in runs of ten, so that Ctrl-C stops a long one */
    const long run = 10;
    for (long done = 0; ok && done < copies; done += run) {
        if (shell_interrupted) {
            m->mov_skipped += copies - done;
            break;
        }
        ok = movie_add(m->mov, sh->view, copies - done < run ? copies - done : run, err, sizeof err) == 0;
    }
    if (ok) return CMD_OK;
failed:;
    /* the one rule for an output that fails (outfile.h); what finishing the
     * broken movie adds to it is no news */
    movie_abort(m->mov);
    m->mov = NULL;
    return shell_output_failed(sh, st, "movie", err);
}

cmd_status media_frame(shell *sh, const stmt *st)
{
    media *m = sh->media;
    bool ask = sh->running && sh->interactive && sh->sound_set.live != SOUND_LIVE_OFF &&
               !(m && sound_live_is_open(m->snd));
    if (!m && !ask) return CMD_OK;
    if (!m && !(m = media_get(sh))) return CMD_OK;
    double h = sh->w.set.time_step, t0 = m->elapsed, t1 = t0 + h;
    m->elapsed = t1;
    if (sh->sound_set.live == SOUND_LIVE_OFF || !sh->interactive) sound_live_close(m->snd);
    if (ask) media_ask_server(sh, m, st, t0);
    cmd_status r = CMD_OK;
    if (sound_active(m->snd)) r = media_sound_frame(sh, m, st, t0, t1);
    if (r == CMD_OK && m->mov) r = media_movie_frame(sh, m, st, t0, t1);
    return r;
}

double media_pump(shell *sh, double wait)
{
    media *m = sh->media;
    if (!m || !sound_live_is_open(m->snd)) return wait;
    char err[1024];
    double next = sound_pump(m->snd, shell_clock(), err, sizeof err);
    if (next == -2) { /* the stream is closed */
        sh->sound_set.live = SOUND_LIVE_OFF;
        shell_output_failed(sh, NULL, "sound", err); /* at the prompt: time goes on */
        return wait;
    }
    return next >= 0 && (wait < 0 || next < wait) ? next : wait;
}

int media_choose_sound(shell *sh, const char *name, char *err, size_t errlen)
{
    media *m = media_get(sh);
    if (!m) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    return sound_choose(m->snd, name, err, errlen);
}

/* The state for statement st of output what, made on first need: NULL, after
 * an error, when there is no memory for it. */
static media *media_for(shell *sh, const stmt *st, const char *what)
{
    media *m = media_get(sh);
    if (!m) sh_error(sh, st, "%s: out of memory", what);
    return m;
}

cmd_status media_soundtrack(shell *sh, const stmt *st, const char *path)
{
    if (!path && !sh->media) return CMD_OK; /* off, and nothing was on */
    media *m = media_for(sh, st, "soundtrack");
    if (!m) return CMD_ERROR;
    char err[2048];
    int rc = path ? sound_track_open(m->snd, path, m->elapsed, err, sizeof err)
                  : sound_track_close(m->snd, m->elapsed, err, sizeof err);
    if (rc == 0) return CMD_OK;
    sh_error(sh, st, "soundtrack: %s", err);
    return CMD_ERROR;
}

cmd_status media_movie(shell *sh, const stmt *st, const char *path)
{
    if (!path && !sh->media) return CMD_OK; /* off, and nothing was on */
    media *m = media_for(sh, st, "movie");
    if (!m) return CMD_ERROR;
    if (!path) return m->mov && media_movie_close(sh, m, st) != 0 ? CMD_ERROR : CMD_OK;
    char err[2048];
    movie *nm;
    if (movie_open(&nm, path, &sh->view_set, 1 / sh->view_set.movie_rate, err, sizeof err) != 0) {
        sh_error(sh, st, "movie: %s", err);
        return CMD_ERROR;
    }
    /* the new movie is open: the old one is finished after it, so that a bad new
     * path leaves the old movie going */
    int rc = m->mov ? media_movie_close(sh, m, st) : 0;
    m->mov = nm;
    m->mov_start = m->elapsed;
    m->mov_skipped = 0;
    m->mov_told = false;
    return rc == 0 ? CMD_OK : CMD_ERROR;
}

void media_live_off(shell *sh)
{
    if (sh->media) sound_live_close(sh->media->snd);
}

const char *media_soundtrack_path(const shell *sh)
{
    return sh->media ? sound_track_path(sh->media->snd) : NULL;
}

const char *media_movie_path(const shell *sh)
{
    return sh->media && sh->media->mov ? movie_path(sh->media->mov) : NULL;
}

bool media_live_on(const shell *sh)
{
    switch (sh->sound_set.live) {
    case SOUND_LIVE_ON: return true;
    case SOUND_LIVE_OFF: return false;
    default: return sh->interactive;
    }
}

int media_finish(shell *sh)
{
    media *m = sh->media;
    if (!m) return 0;
    char err[2048];
    int rc = 0;
    if (m->mov && media_movie_close(sh, m, NULL) != 0) rc = -1;
    if (sound_track_close(m->snd, m->elapsed, err, sizeof err) != 0) {
        sh_error(sh, NULL, "soundtrack: %s", err);
        rc = -1;
    }
    sound_live_close(m->snd);
    return rc;
}

void media_free(shell *sh)
{
    media *m = sh->media;
    if (!m) return;
    media_finish(sh);
    char err[256];
    sound_free(m->snd, m->elapsed, err, sizeof err);
    free(m->hits);
    free(m->start);
    free(m->poses);
    free(m);
    sh->media = NULL;
}
