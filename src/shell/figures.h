/* figures.h: what `plot` draws: the figures of each frame of the current run
 * (language.md, "The console beyond the thesis").
 *
 * The current run is what time did since the last restart or read.  After each
 * frame the shell records the world's time, its kinetic and potential energy,
 * its momentum and angular momentum (core/energy.h), and the height (z of the
 * origin) of every object, in a series per object name: an object made during
 * the run starts its series then, one deleted ends it, and one that comes back
 * goes on after a gap.  Recording only reads the world: it never changes a
 * trace.  At most max_frames frames are kept, and at most max_heights heights
 * in all (a world of many objects keeps fewer frames); past that the oldest
 * quarter is dropped, and `dropped` counts what went. */
#ifndef VROC_FIGURES_H
#define VROC_FIGURES_H

#include <stdbool.h>

#include "core/body.h"
#include "core/world.h"

/* The limits vroc records with: a million frames, 2^22 heights (32 MB, at most
 * twice that allocated as the series grow). */
#define FIGURES_MAX_FRAMES 1000000L
#define FIGURES_MAX_HEIGHTS (1L << 22)

typedef struct {
    long frame;
    double t;
    double kinetic, potential;
    vec3 momentum, angular_momentum;
} figure_row;

/* The heights of one object: z[k] belongs to row first + k (numbered from the
 * run's start); NaN where it was not there. */
typedef struct {
    char name[BODY_NAME_MAX];
    long first, n, cap;
    double *z;
} figure_series;

typedef struct {
    figure_row *rows;
    int n, cap;
    long dropped;          /* rows dropped from the front: rows[0] is row `dropped` */
    figure_series *series;
    int nseries, capseries;
    int *of_body;          /* the series of each body at the last row (a guess to check) */
    int capbody;
    long heights;          /* heights held in all series */
    long max_frames, max_heights;
    bool failed;           /* out of memory: nothing more is recorded this run */
} figures;

void figures_init(figures *f, long max_frames, long max_heights);
void figures_free(figures *f);

/* Forgets the run (restart, read). */
void figures_clear(figures *f);

/* Records w as it is now. */
void figures_record(figures *f, const world *w);

/* The series of the object named name, or NULL when it was never recorded. */
const figure_series *figures_series(const figures *f, const char *name);

#endif
