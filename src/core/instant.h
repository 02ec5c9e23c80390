/* instant.h: contacts that begin at one instant, answered together in waves
 * (thesis 3.2.2, extended to many contacts at once; design.md, "Dynamics").
 *
 * An instant starts from contacts found at one time t (a pair's first contact,
 * found by its search; the landing of a cluster's new support point: answer.h),
 * among any set of bodies, and takes in every contact of the bodies it sets
 * moving: their lasting contacts, and their pairs within the contact distance.
 * An object struck within the first half of its cluster's step joins with the
 * share of the step's start kick not yet spent taken back (cluster.h: the kick
 * is the contact forces' impulse over half the step, given at its start), unless
 * the kicks themselves made the instant.  It is answered as in the limit of
 * vanishing gaps:
 *  - a wave solves together the contacts that approach (impulse.h: each point
 *    with Newton's restitution, the impulses of least norm), so that parallel
 *    contacts (a plank dropped on two supports, a ball into a groove) are one
 *    problem, with an answer that is symmetric when the set-up is, whatever the
 *    order the objects were made in;
 *  - the next wave takes the contacts of the bodies the last one set moving, so
 *    that a chain struck at one end (a touching cradle, a stack) passes the blow
 *    along, as with gaps between them;
 *  - the waves end when no contact approaches; after 4 n waves of n contacts,
 *    one last solve of them all with no restitution ends the instant (a ball
 *    pinched between two walls, a lossy stack whose waves would halve for ever),
 *    counted in sim_stats.waves_cut.
 * A point's restitution is its pair's (the lesser elasticity of the two), none
 * for a rebound slower than SIM_BOUNCE_SPEED when that is below 1 or the pair has
 * friction (it loses energy as it slips), and none for a
 * lasting contact closing no faster than its cluster's own steps can make it
 * (cluster.h: the kicks keep it closed, and only a contact that approaches
 * faster than that joins a wave).  Then the speed limits (max_linear,
 * max_angular: a result they cut loses energy and is counted in
 * sim_stats.speed_cuts), one event for each contact that took an impulse, the
 * contacts that stay closed, and the modes and flights of every object the
 * instant touched and of those pressed together with them.  A held object
 * (hold.h) is moved by none of it: it pushes with its velocity, as an infinite
 * mass, and stops against a static or held object, or one that cannot give way.
 */
#ifndef VROC_INSTANT_H
#define VROC_INSTANT_H

#include <stdbool.h>

#include "closest.h"

typedef struct world world;
typedef struct pair pair;

/* A contact that begins an instant: pair `slot`, its objects closest as r at
 * the instant (r of p->a against p->b), and the features its next search is to
 * start from. */
typedef struct {
    long slot;
    closest_result r;
    closest_cache hit;
} instant_seed;

/* The room an instant works in (instant.c), made by instant_prepare. */
typedef struct instant_work instant_work;

/* Makes room for n objects (and, the first time, for the contacts and rows of an
 * instant) in *iw: 0, or -1 when out of memory. */
int instant_prepare(instant_work **iw, int n);
void instant_free(instant_work *iw);

/* Answers the n seeds, found at time t in the internal step that ends at t_end,
 * as one instant (above), with every object they touch brought to t; then the
 * modes, flights and clusters of every object it touched. */
void instant_answer(world *w, const instant_seed *seeds, int n, double t, double t_end);

/* True when some point of pair p (its objects in their states now, r their
 * closest result) closes faster than a lasting contact of theirs would by a
 * cluster's own steps: a collision, not a contact to keep closed. */
bool instant_closing(world *w, const pair *p, const closest_result *r);

#endif
