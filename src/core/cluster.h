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

/* The energy the n objects of list had before their cluster steps' kicks (less
 * what an instant had left them owing as the steps began: kick_record), when
 * each flew freely from its kick to that step's end at t, untouched on the
 * way (by an instant, which ends the step), neither held nor touching a held
 * object (which works on it); else NAN.  Before their kick records are
 * cleared. */
double cluster_owed(const world *w, const int *list, int n, double t);

/* cluster_settle, and then, when the objects owed energy (cluster_owed: not
 * NAN) and have more than that, the excess taken back from the motion the
 * contacts gave them over the step.  Contacts without friction do no work and
 * friction only takes, but a step's first kick lends the objects kinetic
 * energy (half its impulse times the speed it gives) that its last kicks take
 * back at the step's end, after they have turned: an object tipping over an
 * edge got back ~1e-4 of the loan too much every step (issue 35). */
void cluster_settle_owing(world *w, const int *list, int n, double owed);

/* The n objects of list, whose energy was `owed` before impulses that did no
 * work (frictionless contacts, e <= 1) changed their motion by their kick
 * records' dv and dL: what they have more than that (the impulses' error: a
 * step's kicks that lent energy and took back a different amount, or an
 * instant that ended a step with its loan) is taken back along that change,
 * so that what the impulses did not act on stays as it was (on a frictionless
 * floor, the motion along it and the spin about its normal; a free cluster's
 * momentum).  Along that change the kinetic energy is a parabola; the least
 * step down it that pays the excess is taken, or its vertex where the excess
 * is more than the parabola holds.  True when it took something (what it left
 * approaching is the caller's to stop). */
bool cluster_pay_excess(world *w, const int *list, int n, double owed);

/* What the n objects of list still have more than `owed` after
 * cluster_pay_excess and their stop, taken from all their motion, slowed by
 * as much as that takes, where it is less than half their kinetic energy
 * (the impulses' error is no more theirs than the rest of the motion's; a
 * free cluster's momentum is not kept there).  No point between two of them,
 * or on a static object, approaches that did not: each speed scales alike. */
void cluster_slow_excess(world *w, const int *list, int n, double owed);

/* What the n objects of list have more than they owed (after
 * cluster_pay_excess), left owing by those that have more than their kick
 * records' e0 (in proportion), for the steps that begin at t to take back
 * at their ends (cluster_kick takes it from its e0). */
void cluster_carry(world *w, const int *list, int n, double owed, double t);

/* How fast a point of b may close on what it is kept against between its
 * cluster's kicks, by the steps alone: as fast as its acceleration (the force's,
 * and its turn's, at most 2 w^2 R for a free body) changes its speed over a
 * step; 0 for a body not stepped as a cluster (resting, sliding, free), whose
 * lasting contacts are exact. */
double cluster_stepping_speed(const world *w, const body *b);

#endif
