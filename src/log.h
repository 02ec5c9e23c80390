/* log.h: the CSV logs a user asks for: `trace = FILE` and `events = FILE`.
 *
 * Columns are fixed by language.md; numbers are printed with 17 significant digits
 * so that every frame's state can be checked from outside exactly. */
#ifndef VROC_LOG_H
#define VROC_LOG_H

#include <stddef.h>

#include "world.h"

/* Opens path for the trace (truncating it), writes the header and one row per
 * object for the current state.  Closes a trace already open.  Returns 0, or -1
 * with a message in err (the previous trace is then left as it was). */
int log_trace_open(world *w, const char *path, char *err, size_t errlen);

/* Opens path for the collision events and writes the header; as above. */
int log_events_open(world *w, const char *path, char *err, size_t errlen);

void log_trace_close(world *w);
void log_events_close(world *w);

/* One trace row per object for the current frame (nothing when no trace is open). */
void log_trace_frame(world *w);

/* One event row: a collision of bodies a and b at point p with normal n (from b
 * to a), impulse magnitude j and closing speed s. */
void log_event(world *w, const body *a, const body *b, vec3 p, vec3 n, double j, double s);

/* The state word of a body: dynamic, static or resting. */
const char *log_state_name(body_state s);

#endif
