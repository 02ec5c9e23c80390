/* log.h: the CSV logs a user asks for: `trace = FILE` and `events = FILE`.
 *
 * Columns are fixed by language.md; numbers are printed with 17 significant digits
 * so that every frame's state can be checked from outside exactly.  The core
 * reports each frame's collisions in world.events; the shell writes them here
 * after the frame, with the trace's rows, and checks that they were written
 * (outfile.h). */
#ifndef VROC_LOG_H
#define VROC_LOG_H

#include <stddef.h>
#include <stdio.h>

#include "core/world.h"

/* Longest path of a log, with its final NUL. */
#define LOG_PATH_MAX 1024

typedef struct {
    FILE *trace;          /* `trace = FILE`, or NULL */
    char trace_path[LOG_PATH_MAX];
    FILE *events;         /* `events = FILE`, or NULL */
    char events_path[LOG_PATH_MAX];
} shell_logs;

/* The trace's columns (language.md): frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,
 * wx,wy,wz,state,ke, ke being the body's kinetic energy (energy.h; 0 when static),
 * appended after state so that readers of the older columns read on.
 *
 * Opens path for the trace (truncating it), writes the header and one row per
 * object of w for the current state, and checks that they were written
 * (outfile.h).  Closes a trace already open.  Returns 0, or -1 with a message in
 * err: the new file could not be written (the previous trace is then left as it
 * was), or the previous trace's last rows (the new one is open). */
int log_trace_open(shell_logs *l, const world *w, const char *path, char *err, size_t errlen);

/* Opens path for the collision events and writes the header; as above. */
int log_events_open(shell_logs *l, const char *path, char *err, size_t errlen);

/* Close the log (nothing when none is open).  Return 0, or -1 with a message in
 * err when its last rows could not be written; it is closed either way. */
int log_trace_close(shell_logs *l, char *err, size_t errlen);
int log_events_close(shell_logs *l, char *err, size_t errlen);

/* One trace row per object for the current frame (nothing when no trace is open).
 * Returns 0, or -1 with "cannot write 'PATH': REASON" in err when the rows did not
 * reach the file; the caller then closes the log (shell_output_failed). */
int log_trace_frame(shell_logs *l, const world *w, char *err, size_t errlen);

/* One event row per collision of the last frame, w->events (nothing when no events
 * log is open); as log_trace_frame. */
int log_events_frame(shell_logs *l, const world *w, char *err, size_t errlen);

/* The state word of a body: dynamic, static or resting. */
const char *log_state_name(body_state s);

/* The state word of body b: held (by the hand), or its state's. */
const char *log_body_state(const body *b);

#endif
