/* track.h: the soundtrack file: 48 kHz, 16-bit, stereo WAV, written beside its
 * path and put in its place when it is finished (shell/outfile.h).
 *
 * Its header is written by our own hand (track_header) and kept true as the file
 * grows, so that it can be read while it is written: the movie reads its sound
 * from it (track_excerpt).  A WAV file's sizes are 32-bit: beyond 4 GiB (6 h 12 min
 * of this sound) the file becomes RF64 (EBU Tech 3306), whose ds64 chunk holds
 * them in 64 bits; the 28 bytes it takes are kept from the start as a JUNK chunk,
 * so that the switch rewrites the header alone.  A write that fails is "cannot
 * write 'PATH': REASON" with the system's reason, as every file vroc writes says
 * it (shell/outfile.h); a soundtrack that fails leaves the old file at its path
 * whole and no part file. */
#ifndef VROC_SOUND_TRACK_H
#define VROC_SOUND_TRACK_H

#include <stddef.h>
#include <stdint.h>

typedef struct track track;

/* The header's length: RIFF (12), JUNK or ds64 (36), fmt (24), data's (8). */
#define TRACK_HEADER_BYTES 80

/* The largest RIFF size field, beyond which a file is RF64 (a RIFF chunk's size
 * is 32-bit). */
#define TRACK_RIFF_MAX 0xffffffffULL

/* The header of a file of frames stereo 16-bit frames: RIFF/WAVE when its RIFF
 * size (the file's length less 8) is at most riff_max (TRACK_RIFF_MAX; less in
 * the tests), else RF64 with the sizes in ds64 and 0xffffffff in the 32-bit
 * fields. */
void track_header(unsigned char out[TRACK_HEADER_BYTES], uint64_t frames, uint64_t riff_max);

/* Starts a WAV file that will replace path when it is finished.  Returns 0, or
 * -1 with a message in err naming path and the reason. */
int track_open(track **t, const char *path, char *err, size_t errlen);

/* Appends n interleaved stereo samples.  Returns 0, or -1 with "cannot write
 * 'PATH': REASON" in err (a full disk, a file size limit): the track is then
 * failed, and track_close gives it up. */
int track_write(track *t, const int16_t *x, long n, char *err, size_t errlen);

/* Samples written so far. */
long track_length(const track *t);

/* The path it will take. */
const char *track_path(const track *t);

/* Writes samples from .. from + n - 1 of the soundtrack into a new WAV file at out
 * (same format), with silence where the soundtrack has none (before 0, after its
 * end).  Returns 0, or -1 with a message (and nothing at out). */
int track_excerpt(track *t, long from, long n, const char *out, char *err, size_t errlen);

/* Finishes the file (its last header), closes it and puts it in its place.
 * Returns 0, or -1 with "cannot write 'PATH': REASON": then, as for a track that
 * failed before, the part file is removed and path left as it was (t is freed
 * either way; NULL is fine). */
int track_close(track *t, char *err, size_t errlen);

#endif
