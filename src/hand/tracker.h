/* tracker.h: the tracker-file format: rows of the hand's pose and buttons in time,
 * read whole from a file or one by one from a live feed, written by hand_log, and
 * the hand's path between rows (language.md, "The hand and the tool panel").
 *
 * A file is CSV with the header `time,x,y,z,qw,qx,qy,qz,trigger,button`; `#`
 * starts a comment line, blank lines are skipped.  time is seconds on the tracker
 * clock, in non-decreasing order; the quaternion (scalar first) turns hand
 * coordinates into world coordinates and must be a unit one to 1e-6 (it is
 * normalised within that); trigger and button are 0 or 1.  Between rows the
 * hand moves at constant rates: its position linearly, its orientation by slerp,
 * which is a turn about one axis at a constant angular velocity.  So the path's
 * derivative is exact; at a row, the derivative is the one just before it.
 */
#ifndef VROC_TRACKER_H
#define VROC_TRACKER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "core/vmath.h"

#define TRACKER_HEADER "time,x,y,z,qw,qx,qy,qz,trigger,button"

/* The caps of a tracker file (shell/infile.h): its size, and its lines' length, a
 * live feed's too (a row of ten numbers to the bit is under 300 bytes). */
#define TRACKER_MAX_BYTES (64L * 1024 * 1024)
#define TRACKER_LINE_MAX 1024

/* One row: the hand at time t. */
typedef struct {
    double t;
    vec3 p;
    quat q;
    bool trigger, button;
} tracker_row;

/* The rows of a file, in order. */
typedef struct {
    tracker_row *rows;
    int n, cap;
} tracker_path;

/* What a line of a tracker file is. */
typedef enum { TRACKER_SKIP, TRACKER_HEADER_LINE, TRACKER_DATA } tracker_line;

/* The kind of a line (its newline removed): a comment or blank line is skipped;
 * the header; anything else is data. */
tracker_line tracker_line_kind(const char *line);

/* Reads a data line into row, checked against the limits every statement has
 * (core/limits.h): time from 0 to LIM_CLOCK_MAX, each of x, y, z within
 * LIM_POSITION_MAX.  Returns 0, or -1 with the problem in err (no place: the
 * caller knows it). */
int tracker_parse_row(const char *line, tracker_row *row, char *err, size_t errlen);

/* Reads the file at path whole into out (which it initialises), within the caps
 * above: every line is checked, rows in non-decreasing time, each at the same time
 * as the row before (a jump) or at least LIM_TIME_MIN after it (rows nearer in
 * time would give the hand any speed).  Returns 0, or -1 with "path:line: problem"
 * (or "path: problem") in err and out empty. */
int tracker_load(const char *path, tracker_path *out, char *err, size_t errlen);

void tracker_free(tracker_path *tp);

/* Adds row r at the end of the path (in time order: the caller's care).  Returns
 * 0, or -1 when out of memory (the path unchanged). */
int tracker_append(tracker_path *tp, const tracker_row *r);

/* The hand at time t on the path: before the first row, the first row's pose;
 * between rows k and k+1 interpolated; at or after the last, the last. */
void tracker_pose(const tracker_path *tp, double t, vec3 *p, quat *q);

/* The velocity and angular velocity (world axes) on the path from row k to row
 * k+1: zero when they share a time, or when k is not such a pair. */
void tracker_segment_rates(const tracker_path *tp, int k, vec3 *v, vec3 *w);

/* The rotation that turns a into b the short way, as a rotation vector (axis
 * times angle, radians). */
vec3 tracker_turn(quat a, quat b);

/* The orientation a turned by the rotation vector r (world axes): the
 * orientation a hand reaches from a turning at r / T for T seconds. */
quat tracker_turned(quat a, vec3 r);

/* The check of a row's time t against the time before of the row before it:
 * 0, or -1 with the problem in err when they are nearer than LIM_TIME_MIN but not
 * equal. */
int tracker_check_spacing(double before, double t, char *err, size_t errlen);

/* Writes row as a line of the format (17 significant digits, so that it reads
 * back to the bit); fprintf's count, negative when the write failed. */
int tracker_write_row(FILE *f, const tracker_row *row);

#endif
