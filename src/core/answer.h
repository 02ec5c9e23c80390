/* answer.h: answering the events of an internal step (thesis 3.2.2, 3.3.3 and
 * 3.4.2, step 5; design.md, "Dynamics"): a pair's first contact, and an object's
 * own event (a slide leaving its face, the end of a cluster's step, where a
 * cluster may land on a new support point).
 *
 * sim.c finds the events in the order they happen; each is answered here at its
 * own instant t, with every object it touches brought there (step_sync), and the
 * flights it changes started afresh from t (retime.h).  Contacts, a pair's or a
 * landing's, are answered as an instant (instant.h): with every contact that
 * begins with them, in waves.  Each collision answered goes into the frame's
 * events (world.h).
 */
#ifndef VROC_ANSWER_H
#define VROC_ANSWER_H

#include <stdbool.h>

#include "body.h"
#include "friction.h"
#include "flight.h"
#include "instant.h"
#include "lcp.h"

typedef struct world world;
typedef struct row_work row_work;

/* The scratch the answering works in (answer.c, and the clusters and rest it
 * calls: cluster.c, rest.c), sized by answer_prepare when the step is prepared,
 * so that no event allocates.  Each list and copy has the one user named here,
 * so that none is borrowed while another holds it. */
/* The start kick of a cluster's step (cluster.h) that is under way: when it began
 * (t0), its length h (0: none under way), and the velocity and angular momentum
 * the kick gave the object (dv, dL). */
typedef struct {
    double t0, h;
    vec3 dv, dL;
} kick_record;

typedef struct {
    int *objects;     /* per object: the objects an event answers (answer_contact's
                       * component, answer_object's cluster; and the objects sim.c's
                       * start over woke) */
    int *cluster;     /* per object: one cluster's objects (answer_clusters',
                       * rest_frame_end's) */
    int *classify;    /* per object: rest_classify's work list */
    body *kicked;     /* each object's copy that cluster_kick kicks and flies, */
    flight *flights;  /*   and its flight when kicked */
    body *balanced;   /* each object's copy that rest_balanced pushes */
    body **now;       /* each object's state as a contact problem sees it (impulse.h):
                       * w->bodies[i], or its copy above while a kick or a balance
                       * works on it */
    bool *mark;       /* per object: marks, all false between uses (the objects
                       * reached, the mobile objects of a contact problem) */
    kick_record *kicks; /* per object: its cluster's step under way (cluster_kick) */
    long *landing;    /* per object: the pair whose new support point its cluster's
                       * step ends at (cluster_kick), or -1 */
    instant_seed *seeds; /* per object: the landings one cluster's step ends at */
    lcp_work *lcp;    /* room for the largest contact problem (lcp.h) */
    friction_work *fw; /* room for the largest one with friction (friction.h) */
    row_work *rw;     /* a cluster's problems (rows.h): grown to the largest
                       * cluster met, the only scratch a frame may grow */
    instant_work *instant; /* an instant's contacts and rows (instant.h) */
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
 * internal step that ends at t_end, as an instant (instant.h) that begins with
 * it. */
void answer_contact(world *w, long k, double t, double t_end);

/* Answers object i's own event at time t: a slide leaving its face (the object
 * goes over the edge as a cluster decides), or the end of its cluster's step:
 * where it ends at a landing, the instant of the new support points (instant.h);
 * else the last kicks, and the modes anew; then the next step unless t is
 * t_end. */
void answer_object(world *w, int i, double t, double t_end);

/* The clusters among the n objects of list (their states at time t) start a
 * step: the kicks, then their flights until the step's end (their own event). */
void answer_clusters(world *w, const int *list, int n, double t, double t_end);

#endif
