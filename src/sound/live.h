/* live.h: collisions played live through the sound server (PulseAudio's simple
 * API, libpulse-simple; PipeWire serves the same API).
 *
 * live_open first asks whether a server answers, with the asynchronous API, no
 * autospawn (PA_CONTEXT_NOAUTOSPAWN: no server is ever started by accident) and a
 * bound of LIVE_ASK_SECONDS, so that a machine without a server costs a failed
 * connect, not a hang; then it opens the playback stream with pa_simple on the
 * server that answered: 48 kHz 16-bit stereo, a target buffer of
 * LIVE_BUFFER_SECONDS.
 *
 * pa_simple_write blocks until the server takes the samples, and a server can
 * keep a new stream waiting (an idle null sink, for one, sleeps up to 2 s before
 * it first reads), so a thread of its own does the writing: live_write only
 * hands samples over and never waits.  Each run of samples carries the wall-clock
 * time it is due; the thread drops what is more than LIVE_LATE_SECONDS late when
 * its turn comes, so that a stalled server costs a gap, not a delay that lasts. */
#ifndef VROC_SOUND_LIVE_H
#define VROC_SOUND_LIVE_H

#include <stddef.h>
#include <stdint.h>

#define LIVE_ASK_SECONDS 1.0
#define LIVE_BUFFER_SECONDS 0.04
#define LIVE_LATE_SECONDS 0.1

typedef struct live live;

/* Connects to the sound server ($PULSE_SERVER, else the default one) and starts
 * the writing thread.  Returns 0, or -1 with the reason in err (no server
 * answers, it refused the stream). */
int live_open(live **l, char *err, size_t errlen);

/* Hands over n interleaved stereo samples, the first due at wall-clock time due
 * (s, monotonic), to be played after those handed over before.  Never blocks.
 * Returns 0, or -1 when the stream has failed, with "cannot write to the sound
 * server 'ADDRESS': REASON" in err. */
int live_write(live *l, const int16_t *x, long n, double due, char *err, size_t errlen);

/* Stops the thread and closes the stream at once, dropping what is buffered
 * (NULL is fine). */
void live_close(live *l);

/* Seconds on the monotonic clock (the clock `due` is on). */
double live_clock(void);

#endif
