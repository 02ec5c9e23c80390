/* mixer.h: voices mixed into one stereo stream, through a limiter that never clips.
 *
 * Time is counted in samples at 48 kHz from the mixer's start.  A voice plays a
 * shared sound (buf.h) from its own start sample in each ear, with its own gain
 * in each ear (place.h gives both).  Rendering sums the voices in double
 * precision and passes the sum through a look-ahead peak limiter:
 *
 *   - each sample needs the gain r[n] = min(1, MIXER_CEILING / max(|left|, |right|));
 *   - the gain applied is G[n] = min(G[n-1] recovering towards 1 with a 50 ms time
 *     constant, min over k in 0..L of r[n+k] + k / L), L = MIXER_LOOKAHEAD samples:
 *     it ramps down over at most 1 ms before a loud sample, and is never above r[n],
 *     so no output sample exceeds the ceiling (-1 dBFS), whatever the sum;
 *   - below the ceiling G stays 1: the output is the sum itself.
 * Both channels share the gain, so the image does not move.  The limiter looks
 * MIXER_LOOKAHEAD samples past the last one rendered: the caller renders up to
 * L samples before the end of what it knows, or flushes with what it knows.
 *
 * At most MIXER_VOICES voices play at once; a new voice then takes the place of
 * the quietest if it is louder, else it is not played.  Voices quieter than a
 * 16-bit step are not played at all.  So thousands of collisions in a frame cost
 * a bounded time and memory, and the limiter keeps them from clipping. */
#ifndef VROC_SOUND_MIXER_H
#define VROC_SOUND_MIXER_H

#include <stdint.h>

#include "buf.h"

#define MIXER_VOICES 512
#define MIXER_LOOKAHEAD 48            /* samples: 1 ms */
#define MIXER_CEILING 0.8912509381337456 /* -1 dBFS */

typedef struct mixer mixer;

/* A mixer at sample 0 with no voice, or NULL when out of memory. */
mixer *mixer_new(void);
void mixer_free(mixer *m);

/* The next sample mixer_render will produce. */
long mixer_pos(const mixer *m);

/* Plays b from sample start[e] in ear e with gain[e] (e = 0 left, 1 right).  A voice
 * that would start before mixer_pos is moved later, whole, to start there. */
void mixer_add(mixer *m, sound_buf *b, const long start[2], const double gain[2]);

/* Renders samples mixer_pos .. upto - 1 into out as interleaved 16-bit stereo
 * (left, right), 2 values per sample, and advances mixer_pos to upto.  Returns the
 * number of samples (0 when upto <= mixer_pos). */
long mixer_render(mixer *m, long upto, int16_t *out);

/* The sum before the limiter of samples from .. from + n - 1, interleaved, into
 * out (for tests and the reference loudness; nothing advances). */
void mixer_peek(const mixer *m, long from, long n, double *out);

/* Drops every voice and moves to sample pos, the limiter at rest. */
void mixer_reset(mixer *m, long pos);

/* Voices playing. */
int mixer_voices(const mixer *m);

#endif
