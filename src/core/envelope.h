/* envelope.h: the first time two objects' points can close a gap along a normal,
 * each point's height bounded by a line in time (its height and rate now) plus a
 * quadratic common to all (what the bodies' accelerations and turns can take off):
 * the lower envelopes of the two sets of lines, summed (toi.c's points' bound).
 *
 * A hull of a few dozen vertices has its envelope found over all of them.  A
 * larger one's is walked instead: a vertex's height h0 + h1 t + y.(dh0 + t dh1) is
 * the hull's extent along a direction that turns with t, so the lowest vertex
 * moves from a vertex to one sharing a face with it (where two are lowest
 * together, the face between them is lowest).  The walk starts at the lowest
 * vertex now, found by a climb from a vertex near it (the pair's closest feature)
 * or down the hull's Dobkin-Kirkpatrick hierarchy (support.h) in time that grows
 * with the log of the vertex count, and reads only the faces about the vertices on
 * the envelope before the time it returns.  Both give the same envelope, to
 * rounding.
 */
#ifndef VROC_ENVELOPE_H
#define VROC_ENVELOPE_H

#include "closest.h"
#include "poly.h"
#include "vmath.h"

/* Hulls of at most this many vertices can be read vertex by vertex (without
 * closest data to walk them); it is also the most pieces a walked envelope holds
 * (where it would need more, the time it gives is where it stopped: early, never
 * late). */
#define ENV_FLAT_VERTICES 1024

/* Hulls of more than this many vertices (and closest data) are walked: reading
 * every vertex of a smaller one costs about as much as the walk's start. */
#define ENV_WALK_VERTICES 32

/* One object's points: vertex y (body frame) of hull is at height h0 + y.dh0
 * along the normal, and rises at h1 + y.dh1.  hull NULL: a single point of height
 * h0 and rate h1 (a ball's lowest).  feat: hull's closest data, to walk its
 * envelope (of more than ENV_WALK_VERTICES; needed above ENV_FLAT_VERTICES), or
 * NULL. */
typedef struct {
    double h0, h1;
    vec3 dh0, dh1;
    const poly *hull;
    const closest_hull *feat;
    int near; /* a vertex near the lowest now, where a walk starts looking for it
                 (a climb), or -1 (down the hull's hierarchy) */
} env_side;

/* The first time in [0, T) at which (lowest of a) + (lowest of b) + q t^2 can
 * come down to target + margin (computed in that order), backed off so that it is
 * never late; HUGE_VAL when not before T.  *reads (may be NULL) gets how many
 * vertices' lines it read (a walk's start, finding the lowest now, apart). */
double env_first_time(const env_side *a, const env_side *b, double q, double target,
                      double margin, double T, int *reads);

#endif
