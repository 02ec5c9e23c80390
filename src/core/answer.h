/* answer.h: answering the events of an internal step (thesis 3.2.2, 3.3.3 and
 * 3.4.2, step 5; design.md, "Dynamics"): a pair's first contact, and an object's
 * own event (a slide leaving its face, the end of a cluster's step).
 *
 * sim.c finds the events in the order they happen; each is answered here at its
 * own instant t, with every object it touches brought there (step_sync), and the
 * flights it changes started afresh from t (retime.h).  The speed limits
 * (max_linear, max_angular) apply to what a collision sets.  Each collision
 * answered goes into the frame's events (world.h).
 */
#ifndef VROC_ANSWER_H
#define VROC_ANSWER_H

typedef struct world world;

/* Answers pair k's contact (found by its search, pairs.hits[k]) at time t, in the
 * internal step that ends at t_end: the impulses of its points and of every
 * lasting contact of the objects pressed together with them, answered together;
 * then the modes and flights of all of them.  A held object (hold.h) is not moved
 * by them: it pushes with its velocity as an infinite mass would, and stops
 * against a static or held object, or one that cannot give way. */
void answer_contact(world *w, long k, double t, double t_end);

/* Answers object i's own event at time t: a slide leaving its face (the object
 * goes over the edge as a cluster decides), or the end of its cluster's step
 * (the last kicks, the modes anew, and the next step unless t is t_end). */
void answer_object(world *w, int i, double t, double t_end);

/* The clusters among the n objects of list (their states at time t) start a
 * step: the kicks, then their flights until the step's end (their own event). */
void answer_clusters(world *w, const int *list, int n, double t, double t_end);

#endif
