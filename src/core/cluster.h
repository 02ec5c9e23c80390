/* cluster.h: objects pressed together that move with the contact forces found as
 * they go: tipping over an edge, pivoting on it, stacks and piles that move (the
 * general mode of rest.h).
 *
 * A cluster steps by short steps of free flight (exact: flight.h), with kicks at
 * each end that keep its closed contact points closed (RATTLE, Andersen 1983;
 * Hairer, Lubich and Wanner, "Geometric Numerical Integration", VII.1): at a
 * step's start, the impulses that make every closed point's gap at the step's
 * end zero or positive (pushing only, zero where the gap is open: a
 * complementarity problem, solved by Newton's method over the exact flights); at
 * its end, the impulses that stop every touching point approaching.  The contact
 * forces so do no work, the energy stays within the square of the step, and a
 * contact opens where its push would have to pull: a ball pivoting on a table's
 * edge leaves it where the textbook says.  Between the kicks the objects fly, so
 * collisions with anything else are found as for any other flight.
 *
 * Only points already closed are kept closed: those within twice the hover gap,
 * or within the contact's thickness and closing no faster than the steps
 * themselves close them (cluster_stepping_speed).  A new support point (a box
 * rocking onto its other edge, a tipping block landing flat, a polygon rolling
 * onto its next facet) is open until it lands: the step ends where it first
 * reaches twice the hover gap, and the landing is a collision with the pair's
 * elasticity (answer.h, instant.h).
 */
#ifndef VROC_CLUSTER_H
#define VROC_CLUSTER_H

#include "body.h"

typedef struct world world;

/* The first kicks of a step of the cluster's n objects (their states at time t):
 * applied to their states.  Returns the step's length (until t_end at most): to
 * where an open point lands, if one does, its pair then noted as the landing of
 * its objects (answer_scratch.landing). */
double cluster_kick(world *w, const int *list, int n, double t, double t_end);

/* The last kicks of the step (the objects' states at its end): the frictionless
 * points the steps keep closed, and touching ones, no longer approach (RATTLE's second
 * kick, on every closed point: one left approaching, as a point kept at the hover
 * gap above the contact distance was, carries into the next step the speed the
 * force gave it over this one, and the kicks made energy of it, a pile's
 * contacts sinking and coming out again); lasting contacts whose gaps opened
 * end. */
void cluster_settle(world *w, const int *list, int n);

/* How fast a point of b may close on what it is kept against between its
 * cluster's kicks, by the steps alone: as fast as its acceleration (the force's,
 * and its turn's, at most 2 w^2 R for a free body) changes its speed over a
 * step; 0 for a body not stepped as a cluster (resting, sliding, free), whose
 * lasting contacts are exact. */
double cluster_stepping_speed(const world *w, const body *b);

#endif
