/* sound.h: the sound layer: collision sounds mixed into a soundtrack and the live
 * stream (thesis 4.3, 7.3; language.md, "Sound and movies").
 *
 * The shell owns the settings (sound_settings, like the views' view_settings) and
 * one engine, which it gives each frame's collisions (sound_frame).  The engine
 * counts time in samples at 48 kHz of *elapsed* simulated time, which the shell
 * keeps: every frame adds its time_step, whatever `restart` or `read` do to the
 * world's clock, so that the soundtrack runs on as time does.  Sample n is elapsed
 * time n / 48000.
 *
 * Each collision starts one voice (mixer.h) at the sample of its time plus the
 * travel to each ear (place.h), playing the built-in sound (synth.h, pitched by the
 * objects' size) or the sound file (clip.h), with the amplitude
 *
 *     SOUND_REF_LEVEL * impulse * collision_vol * volume_a * volume_b * (1 / r)
 *
 * for a sound of peak 1: an impulse of 1 N s heard from 1 m with all volumes 1
 * peaks at a quarter of full scale in the nearer ear, before the limiter.
 *
 * Sound is mixed only while somewhere takes it: a soundtrack (track.h) or the live
 * stream (live.h).  Each frame renders up to MIXER_LOOKAHEAD samples before its end
 * (the limiter looks that far ahead); the rest follows with the next frame, or at
 * once with sound_flush.  Results of the simulation never depend on any of it: the
 * engine only reads what the frame reports. */
#ifndef VROC_SOUND_SOUND_H
#define VROC_SOUND_SOUND_H

#include <stdbool.h>
#include <stddef.h>

#include "core/vmath.h"
#include "sound/place.h"

/* Longest collision_sound, with its final NUL. */
#define SOUND_NAME_MAX 1024
/* The peak of 1 N s heard from 1 m with all volumes 1. */
#define SOUND_REF_LEVEL 0.25

/* `sound`: live output.  AUTO (the start-up value) means on at an interactive
 * prompt if a server answers when time first runs there, else off. */
typedef enum { SOUND_LIVE_AUTO, SOUND_LIVE_ON, SOUND_LIVE_OFF } sound_live_mode;

/* The sound settings (language.md, "Sound and movies"). */
typedef struct {
    char collision_sound[SOUND_NAME_MAX]; /* click, knock, bell, off, or a file */
    double collision_vol;                 /* master loudness, >= 0 */
    sound_live_mode live;                 /* `sound` */
} sound_settings;

/* The start-up values: click, collision_vol 1, live AUTO. */
sound_settings sound_settings_defaults(void);

/* One collision as the engine hears it. */
typedef struct {
    double t;     /* elapsed simulated time, s */
    vec3 p;       /* the contact point */
    double j;     /* impulse magnitude, N s */
    double gain;  /* collision_vol * volume_a * volume_b */
    double size;  /* m: how big the two objects are (the pitch of built-in sounds) */
} sound_hit;

typedef struct sound_engine sound_engine;

/* A silent engine at elapsed time 0, or NULL when out of memory. */
sound_engine *sound_new(void);
/* Finishes the soundtrack at elapsed time t (see sound_track_close), closes the
 * live stream and frees e (NULL is fine).  Returns 0, or -1 with a message. */
int sound_free(sound_engine *e, double t, char *err, size_t errlen);

/* Checks and, for a file, loads what `collision_sound = name` names: click, knock,
 * bell, off, or a sound file.  Returns 0, or -1 with a message (the sound in use
 * stays). */
int sound_choose(sound_engine *e, const char *name, char *err, size_t errlen);

/* The collisions of the frame of elapsed time [t0, t1] (the hits' times within
 * it).  wall: the wall-clock time (s, monotonic) at which t0 is due in real time,
 * or < 0 when time is not running in real time.  Returns 0; or when the
 * soundtrack cannot be written, 1 (it is then closed) with "cannot write 'PATH':
 * REASON" in err.  (The live stream fails in sound_pump.) */
int sound_frame(sound_engine *e, const sound_settings *set, const sound_listener *l,
                const sound_hit *hits, long n, double t0, double t1, double wall, char *err,
                size_t errlen);

/* Renders everything up to elapsed time t, the end of the last frame, with no
 * look-ahead past it.  Returns 0, or -1 when the soundtrack cannot be written
 * (it is then closed), with the message in err. */
int sound_flush(sound_engine *e, double t, char *err, size_t errlen);

/* True when sound is being mixed: a soundtrack or the live stream is open. */
bool sound_active(const sound_engine *e);

/* Starts writing the soundtrack to path from elapsed time t (a WAV file, 48 kHz,
 * 16-bit stereo); one already open is finished at t.  Returns 0, or -1 with a
 * message: either the new file could not be made (then the soundtrack open
 * before, if any, goes on), or it was and the one open before could not be
 * finished (the message names that one). */
int sound_track_open(sound_engine *e, const char *path, double t, char *err, size_t errlen);

/* Finishes the soundtrack at elapsed time t (nothing when none is open).  Returns
 * 0, or -1 with "cannot write 'PATH': REASON"; it is closed either way. */
int sound_track_close(sound_engine *e, double t, char *err, size_t errlen);

/* The soundtrack's path, or NULL when none is open. */
const char *sound_track_path(const sound_engine *e);

/* Writes the soundtrack's sound of elapsed time [t0, t1) into a new WAV file at out,
 * with silence where the soundtrack has none.  Returns 0, or -1 with a message. */
int sound_track_excerpt(sound_engine *e, double t0, double t1, const char *out, char *err,
                        size_t errlen);

/* Opens the live stream at elapsed time t (live.h: no autospawn, no hang).
 * Returns 0, or -1 with the reason. */
int sound_live_open(sound_engine *e, double t, char *err, size_t errlen);
void sound_live_close(sound_engine *e);
bool sound_live_is_open(const sound_engine *e);

/* Sends the live stream what is due by wall-clock time now + LIVE_BUFFER_SECONDS,
 * and drops what is more than 0.1 s late.  Returns the seconds until it should be
 * called again, or -1 when nothing waits; on a failed stream, -2 with the reason
 * in err (it is then closed). */
double sound_pump(sound_engine *e, double now, char *err, size_t errlen);

/* The sample of elapsed time t. */
long sound_sample(double t);

#endif
