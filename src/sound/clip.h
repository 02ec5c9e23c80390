/* clip.h: a sound file as a collision sound (`collision_sound = FILE`).
 *
 * Any format libsndfile reads; its channels are averaged to mono, it is resampled
 * to 48 kHz with libsamplerate (sinc, medium quality) and normalised to a peak of
 * 1, so that a file obeys the same loudness rule as the built-in sounds
 * (language.md, "Sound and movies"). */
#ifndef VROC_SOUND_CLIP_H
#define VROC_SOUND_CLIP_H

#include <stddef.h>

#include "buf.h"

/* The longest sound file a collision may play, in seconds, and the largest file
 * read (shell/infile.h). */
#define CLIP_MAX_SECONDS 60
#define CLIP_MAX_BYTES (64L * 1024 * 1024)

/* Reads the sound file at path.  Returns the sound, or NULL with a message in err
 * that names the path and says why: missing or unreadable, a folder, larger than
 * CLIP_MAX_BYTES, a pipe nothing came through, empty, not a sound file libsndfile
 * knows, longer than CLIP_MAX_SECONDS, a sample that is NaN or infinite, or out of
 * memory. */
sound_buf *clip_load(const char *path, char *err, size_t errlen);

#endif
