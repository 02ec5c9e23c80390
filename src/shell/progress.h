/* progress.h: a status line while a long `run` works (language.md, "The console
 * beyond the thesis").
 *
 * At an interactive prompt (and in batch with -v), a run that has taken more
 * than PROGRESS_AFTER seconds shows one line on standard error: the frame, the
 * simulated time, frames per second of wall time and the time left, redrawn a
 * few times a second in place (\r) and erased when the run ends.  Where standard
 * error is not a terminal (-v into a log) it is written as a whole line once a
 * second instead, and nothing is erased.  Messages printed meanwhile hide it
 * first (progress_hide); the next tick draws it again. */
#ifndef VROC_PROGRESS_H
#define VROC_PROGRESS_H

#include <stdbool.h>
#include <stdio.h>

#define PROGRESS_AFTER 0.5  /* s of wall time before the line first shows */
#define PROGRESS_EVERY 0.25 /* s between redraws on a terminal */
#define PROGRESS_LOG 1.0    /* s between lines into a file */

typedef struct {
    FILE *out;
    bool tty;          /* out is a terminal: one line redrawn in place */
    long n;            /* frames asked for */
    double start;      /* wall clock when the run began */
    double next;       /* wall clock of the next drawing */
    bool shown;        /* a line is on the terminal now */
} progress;

/* Begins a run of n frames at wall clock now, the line going to out. */
void progress_begin(progress *p, FILE *out, long n, double now);

/* After frame k (1 to n) at simulated time t, wall clock now: draws when due. */
void progress_tick(progress *p, long k, double t, double now);

/* Erases the line if one shows (a message follows, or the run ended). */
void progress_hide(progress *p);

#endif
