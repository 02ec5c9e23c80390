/* answer.h: answering the events of an internal step (thesis 3.2.2, 3.3.3 and
 * 3.4.2, step 5; design.md, "Dynamics"): a pair's first contact, and an object's
 * own event (a slide leaving its face, the end of a cluster's step).
 *
 * sim.c finds the events in the order they happen; each is answered here at its
 * own instant t, with every object it touches brought there (step_sync), and the
 * flights it changes started afresh from t (retime.h).  The speed limits
 * (max_linear, max_angular) apply to what a collision sets: a result they cut
 * loses energy, and is counted (sim_stats.speed_cuts, the first described in
 * first_cut) so that the caller can say so.  Each collision answered goes into
 * the frame's events (world.h).
 */
#ifndef VROC_ANSWER_H
#define VROC_ANSWER_H

#include <stdbool.h>

#include "body.h"
#include "friction.h"
#include "lcp.h"

typedef struct world world;

/* The scratch the answering works in (answer.c, and the clusters and rest it
 * calls: cluster.c, rest.c), sized by answer_prepare when the step is prepared,
 * so that no event allocates.  Each list and copy has the one user named here,
 * so that none is borrowed while another holds it. */
typedef struct {
    int *objects;     /* per object: the objects an event answers (answer_contact's
                       * component, answer_object's cluster; and the objects sim.c's
                       * start over woke) */
    int *cluster;     /* per object: one cluster's objects (answer_clusters',
                       * rest_frame_end's) */
    int *classify;    /* per object: rest_classify's work list */
    body *kicked;     /* each object's copy that cluster_kick kicks and flies */
    body *balanced;   /* each object's copy that rest_balanced pushes */
    body **now;       /* each object's state as a contact problem sees it (impulse.h):
                       * w->bodies[i], or its copy above while a kick or a balance
                       * works on it */
    bool *mark;       /* per object: marks, all false between uses (the objects
                       * reached, the mobile objects of a contact problem) */
    lcp_work *lcp;    /* room for the largest contact problem (lcp.h) */
    friction_work *fw; /* room for the largest one with friction (friction.h) */
    int cap;          /* objects the arrays have room for */
} answer_scratch;

void answer_init(answer_scratch *s);
void answer_free(answer_scratch *s);

/* Makes room for the world's objects and, when changed (a command changed
 * something) or when it grew, writes the copies afresh, so that frames allocate
 * nothing and touch no fresh memory (sim_prepare calls it).  Returns 0, or -1
 * when out of memory. */
int answer_prepare(world *w, bool changed);

/* Counts in the world's stats what a contact problem with friction met (object:
 * one of its objects, named by the first Painleve warning). */
void answer_count(world *w, friction_flags f, int object);

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
