/* track.h: the soundtrack file: 48 kHz, 16-bit, stereo WAV written with libsndfile.
 *
 * The header is kept true as the file grows (libsndfile rewrites it), so that the
 * file can be read while it is written: the movie reads its sound from it
 * (track_excerpt).  libsndfile writes through track.c's own calls, so that a
 * write that fails is "cannot write 'PATH': REASON" with the system's reason,
 * as every file vroc writes says it (shell/outfile.h). */
#ifndef VROC_SOUND_TRACK_H
#define VROC_SOUND_TRACK_H

#include <stddef.h>
#include <stdint.h>

typedef struct track track;

/* Creates (or replaces) the WAV file at path.  Returns 0, or -1 with a message in
 * err naming path and the reason. */
int track_open(track **t, const char *path, char *err, size_t errlen);

/* Appends n interleaved stereo samples.  Returns 0, or -1 with "cannot write
 * 'PATH': REASON" in err (a full disk, a file size limit). */
int track_write(track *t, const int16_t *x, long n, char *err, size_t errlen);

/* Samples written so far. */
long track_length(const track *t);

const char *track_path(const track *t);

/* Writes samples from .. from + n - 1 of the soundtrack into a new WAV file at out
 * (same format), with silence where the soundtrack has none (before 0, after its
 * end).  Returns 0, or -1 with a message. */
int track_excerpt(track *t, long from, long n, const char *out, char *err, size_t errlen);

/* Finishes the file (its last header) and closes it.  Returns 0, or -1 with
 * "cannot write 'PATH': REASON" (t is freed either way; NULL is fine). */
int track_close(track *t, char *err, size_t errlen);

#endif
