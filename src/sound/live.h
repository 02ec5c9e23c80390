/* live.h: collisions played live through the sound server (PulseAudio's simple
 * API, libpulse-simple; PipeWire serves the same API).
 *
 * live_open first asks whether a server answers, with the asynchronous API, no
 * autospawn (PA_CONTEXT_NOAUTOSPAWN: no server is ever started by accident) and a
 * bound of LIVE_ASK_SECONDS, so that a machine without a server costs a failed
 * connect, not a hang; then it opens the playback stream with pa_simple on the
 * server that answered.  The stream is 48 kHz 16-bit stereo, its target buffer
 * LIVE_BUFFER_SECONDS: what is written plays that soon (sound.h keeps to it). */
#ifndef VROC_SOUND_LIVE_H
#define VROC_SOUND_LIVE_H

#include <stddef.h>
#include <stdint.h>

#define LIVE_ASK_SECONDS 1.0
#define LIVE_BUFFER_SECONDS 0.04

typedef struct live live;

/* Connects to the sound server ($PULSE_SERVER, else the default one).  Returns 0,
 * or -1 with the reason in err (no server answers, it refused the stream). */
int live_open(live **l, char *err, size_t errlen);

/* Plays n interleaved stereo samples after those written before.  Returns 0, or -1
 * with the reason when the server has gone. */
int live_write(live *l, const int16_t *x, long n, char *err, size_t errlen);

/* Closes the stream at once, dropping what is buffered (NULL is fine). */
void live_close(live *l);

#endif
