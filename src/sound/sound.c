/* sound.c: the engine: collisions to voices, the mixer's output to the soundtrack
 * and the live stream (sound.h). */
#include "sound.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sound/buf.h"
#include "sound/clip.h"
#include "sound/live.h"
#include "sound/mixer.h"
#include "sound/synth.h"
#include "sound/track.h"

/* Built-in sounds made for each pitch heard, a quarter semitone apart. */
#define SOUND_CACHE 64
#define SOUND_PITCH_STEPS 48 /* per octave */
/* The live stream's queue: rendered samples waiting for their wall-clock time. */
#define SOUND_QUEUE (2 * SOUND_RATE)

typedef struct {
    int kind, step;
    sound_buf *b;
} cached;

struct sound_engine {
    mixer *mix;
    bool active;           /* the mixer follows time (something takes its sound) */
    track *track;
    long track_start;      /* the sample the soundtrack's first is */
    live *live;
    int16_t *q;            /* ring of SOUND_QUEUE stereo samples for the live stream */
    long q_first, q_n;     /* the sample at the ring's head, samples held */
    long q_head;           /* index of the head in the ring */
    long sync_sample;      /* sample sync_sample is due at wall time sync_wall */
    double sync_wall;
    bool realtime;         /* the last frame ran in real time: its sound goes live */
    sound_buf *file;       /* the sound file chosen last, and its name */
    char file_name[SOUND_NAME_MAX];
    cached cache[SOUND_CACHE];
    int ncache;
    int16_t *out;          /* scratch for a render */
    long out_cap;
};

sound_settings sound_settings_defaults(void)
{
    sound_settings s;
    memset(&s, 0, sizeof s);
    snprintf(s.collision_sound, sizeof s.collision_sound, "click");
    s.collision_vol = 1.0;
    s.live = SOUND_LIVE_AUTO;
    return s;
}

long sound_sample(double t) { return llround(t * SOUND_RATE); }

sound_engine *sound_new(void)
{
    sound_engine *e = calloc(1, sizeof *e);
    if (!e) return NULL;
    e->mix = mixer_new();
    e->q = malloc(2 * sizeof *e->q * SOUND_QUEUE);
    if (!e->mix || !e->q) {
        mixer_free(e->mix);
        free(e->q);
        free(e);
        return NULL;
    }
    return e;
}

int sound_free(sound_engine *e, double t, char *err, size_t errlen)
{
    if (!e) return 0;
    int rc = sound_track_close(e, t, err, errlen);
    live_close(e->live);
    mixer_free(e->mix);
    free(e->q);
    free(e->out);
    sbuf_unref(e->file);
    for (int i = 0; i < e->ncache; i++) sbuf_unref(e->cache[i].b);
    free(e);
    return rc;
}

int sound_choose(sound_engine *e, const char *name, char *err, size_t errlen)
{
    if (strcmp(name, "off") == 0 || synth_find(name) >= 0) return 0;
    sound_buf *b = clip_load(name, err, errlen);
    if (!b) return -1;
    sbuf_unref(e->file);
    e->file = b;
    snprintf(e->file_name, sizeof e->file_name, "%s", name);
    return 0;
}

/* The built-in sound k for objects of the given size, made once per pitch step. */
static sound_buf *sound_builtin(sound_engine *e, int k, double size)
{
    int step = (int)lround(log2(synth_pitch((synth_kind)k, size)) * SOUND_PITCH_STEPS);
    for (int i = 0; i < e->ncache; i++)
        if (e->cache[i].kind == k && e->cache[i].step == step) return e->cache[i].b;
    sound_buf *b = synth_make((synth_kind)k, exp2((double)step / SOUND_PITCH_STEPS));
    if (!b) return NULL;
    if (e->ncache == SOUND_CACHE) { /* a full cache starts again */
        for (int i = 0; i < e->ncache; i++) sbuf_unref(e->cache[i].b);
        e->ncache = 0;
    }
    e->cache[e->ncache++] = (cached){k, step, b};
    return b;
}

/* What collision_sound names, for a collision of objects of the given size: NULL
 * for off (or a file not loaded). */
static sound_buf *sound_source(sound_engine *e, const char *name, double size)
{
    if (strcmp(name, "off") == 0) return NULL;
    int k = synth_find(name);
    if (k >= 0) return sound_builtin(e, k, size);
    if (e->file && strcmp(e->file_name, name) == 0) return e->file;
    return NULL;
}

bool sound_active(const sound_engine *e) { return e->track || e->live; }

/* Something now takes the sound: the mixer starts at t, silent. */
static void sound_wake(sound_engine *e, double t)
{
    if (e->active) return;
    mixer_reset(e->mix, sound_sample(t));
    e->active = true;
}

static void sound_sleep_if_idle(sound_engine *e)
{
    if (!sound_active(e)) e->active = false;
}

/* Appends n rendered samples (from sample first) to the live queue, dropping the
 * oldest when it is full. */
static void queue_push(sound_engine *e, long first, const int16_t *x, long n)
{
    if (e->q_n == 0) e->q_first = first;
    for (long k = 0; k < n; k++) {
        if (e->q_n == SOUND_QUEUE) {
            e->q_head = (e->q_head + 1) % SOUND_QUEUE;
            e->q_first++;
            e->q_n--;
        }
        long at = (e->q_head + e->q_n) % SOUND_QUEUE;
        e->q[2 * at] = x[2 * k];
        e->q[2 * at + 1] = x[2 * k + 1];
        e->q_n++;
    }
}

static void queue_drop(sound_engine *e, long n)
{
    if (n > e->q_n) n = e->q_n;
    e->q_head = (e->q_head + n) % SOUND_QUEUE;
    e->q_first += n;
    e->q_n -= n;
}

/* Renders up to sample upto into the soundtrack and the live queue.  Returns 0, or
 * 1 when the soundtrack failed (and was closed), with the message in err. */
static int sound_render(sound_engine *e, long upto, char *err, size_t errlen)
{
    long first = mixer_pos(e->mix), n = upto - first;
    if (!e->active || n <= 0) return 0;
    if (n > e->out_cap) {
        int16_t *o = realloc(e->out, 2 * (size_t)n * sizeof *o);
        if (!o) { /* nothing to render into: skip the time */
            mixer_reset(e->mix, upto);
            return 0;
        }
        e->out = o;
        e->out_cap = n;
    }
    mixer_render(e->mix, upto, e->out);
    int rc = 0;
    if (e->track) {
        long skip = e->track_start > first ? e->track_start - first : 0;
        if (skip < n && track_write(e->track, e->out + 2 * skip, n - skip, err, errlen) != 0) {
            char ignored[64]; /* (it failed: given up, the old file kept) */
            track_close(e->track, ignored, sizeof ignored);
            e->track = NULL;
            rc = 1;
        }
    }
    if (e->live && e->realtime) queue_push(e, first, e->out, n);
    sound_sleep_if_idle(e);
    return rc;
}

int sound_frame(sound_engine *e, const sound_settings *set, const sound_listener *l,
                const sound_hit *hits, long n, double t0, double t1, double wall, char *err,
                size_t errlen)
{
    if (!e->active) return 0;
    for (long i = 0; i < n; i++) {
        const sound_hit *h = &hits[i];
        sound_buf *b = sound_source(e, set->collision_sound, h->size);
        if (!b) continue;
        place_result pr = place_hit(l, h->p);
        double a = SOUND_REF_LEVEL * h->j * h->gain;
        long start[2];
        double gain[2];
        for (int ear = 0; ear < 2; ear++) {
            start[ear] = sound_sample(h->t + pr.delay[ear]);
            gain[ear] = a * pr.gain[ear];
        }
        mixer_add(e->mix, b, start, gain);
    }
    e->realtime = wall >= 0;
    if (e->realtime) {
        e->sync_sample = sound_sample(t0);
        e->sync_wall = wall;
    }
    return sound_render(e, sound_sample(t1) - MIXER_LOOKAHEAD, err, errlen);
}

int sound_flush(sound_engine *e, double t, char *err, size_t errlen)
{
    return sound_render(e, sound_sample(t), err, errlen) != 0 ? -1 : 0;
}

int sound_track_open(sound_engine *e, const char *path, double t, char *err, size_t errlen)
{
    track *nt;
    if (track_open(&nt, path, err, errlen) != 0) return -1;
    /* the old soundtrack ends at t, its voices going on into the new one */
    int rc = sound_flush(e, t, err, errlen);
    if (rc == 0 && track_close(e->track, err, errlen) != 0) rc = -1;
    e->track = nt;
    sound_wake(e, t);
    e->track_start = sound_sample(t);
    return rc;
}

int sound_track_close(sound_engine *e, double t, char *err, size_t errlen)
{
    if (!e->track) return 0;
    int rc = sound_flush(e, t, err, errlen);
    if (rc == 0) rc = track_close(e->track, err, errlen); /* (a failed flush closed it) */
    e->track = NULL;
    sound_sleep_if_idle(e);
    return rc;
}

const char *sound_track_path(const sound_engine *e)
{
    return e->track ? track_path(e->track) : NULL;
}

int sound_track_excerpt(sound_engine *e, double t0, double t1, const char *out, char *err,
                        size_t errlen)
{
    if (!e->track) {
        snprintf(err, errlen, "no soundtrack is being written");
        return -1;
    }
    long a = sound_sample(t0), z = sound_sample(t1);
    return track_excerpt(e->track, a - e->track_start, z - a, out, err, errlen);
}

int sound_live_open(sound_engine *e, double t, char *err, size_t errlen)
{
    if (e->live) return 0;
    if (live_open(&e->live, err, errlen) != 0) return -1;
    e->q_n = e->q_head = 0;
    sound_wake(e, t);
    return 0;
}

void sound_live_close(sound_engine *e)
{
    live_close(e->live);
    e->live = NULL;
    e->q_n = e->q_head = 0;
    sound_sleep_if_idle(e);
}

bool sound_live_is_open(const sound_engine *e) { return e->live != NULL; }

double sound_pump(sound_engine *e, double now, char *err, size_t errlen)
{
    if (!e->live || e->q_n == 0) return -1;
    /* sample k is due at sync_wall + (k - sync_sample) / rate */
    double head_due = e->sync_wall + (double)(e->q_first - e->sync_sample) / SOUND_RATE;
    if (head_due < now - LIVE_LATE_SECONDS) { /* late: skip to what is due now */
        queue_drop(e, (long)ceil((now - head_due) * SOUND_RATE));
        if (e->q_n == 0) return -1;
        head_due = e->sync_wall + (double)(e->q_first - e->sync_sample) / SOUND_RATE;
    }
    long n = (long)floor((now + LIVE_BUFFER_SECONDS - head_due) * SOUND_RATE);
    if (n > e->q_n) n = e->q_n;
    while (n > 0) { /* the ring in at most two runs */
        long run = SOUND_QUEUE - e->q_head < n ? SOUND_QUEUE - e->q_head : n;
        if (live_write(e->live, e->q + 2 * e->q_head, run, head_due, err, errlen) != 0) {
            sound_live_close(e);
            return -2;
        }
        queue_drop(e, run);
        head_due += (double)run / SOUND_RATE;
        n -= run;
    }
    if (e->q_n == 0) return -1;
    double wait = head_due - LIVE_BUFFER_SECONDS - now;
    return wait > 0.005 ? wait : 0.005;
}
