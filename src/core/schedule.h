/* schedule.h: when each pair could next touch, and the heap that orders it (thesis
 * 3.3.1).
 *
 * Each pair gets a lower bound on the time it could next touch, never late: from
 * the gap between the spheres about its objects' centres of mass that hold them
 * (or between one's sphere and the other's box, when one is much the larger)
 * against how fast their centres can close, |dv| t + |da| t^2 / 2 (a sphere about
 * the centre of mass stays put as the object turns), which needs no query; or,
 * after a query, from the gap along the normal between the closest points against
 * how fast the two surfaces can close along it: the centres' relative motion along
 * the normal exactly (v t + a t^2 / 2), and each surface's turn, at most |w|max R
 * and never beyond R (conservative advancement; Mirtich 1996).  The bounds hold
 * while the objects fly the flights they were found from.  Pairs sit in an indexed
 * binary heap keyed by their bound, with each object's own next event (a slide
 * leaving its face, the end of a cluster's step); an internal step takes from it
 * only what is due.
 */
#ifndef VROC_SCHEDULE_H
#define VROC_SCHEDULE_H

#include <stdbool.h>

#include "body.h"
#include "pairs.h"
#include "vmath.h"

typedef struct world world;

/* One object's motion as a bound sees it: at rest (moves false), or a point c
 * with velocity v and acceleration a, about which the object turns no faster than
 * rate, every point of it within reach of c: its centre of mass and r_out; or, for
 * a held body (hold.h, held true), the hand's pivot, about which it turns at a
 * constant w, and |c_m - pivot| + r_out. */
typedef struct {
    bool moves;
    vec3 c, v, a;
    double rate;
    double reach;
    bool held;
} sched_move;

/* The time from now, never late, before which objects a and b (moving as ma and
 * mb) cannot bring their distance d (> 0), closest at pa (on a) and pb (on b), n
 * the unit normal from b to a, down to `target` (0 <= target < d); HUGE_VAL when
 * they never can. */
double sched_ca_time(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                     double d, vec3 n, vec3 pa, vec3 pb, double target);

/* The same from the gap of their bounding spheres or boxes alone (no query):
 * 0 when those meet, or when either is held (its pairs are searched at once). */
double sched_sphere_time(const body *a, const sched_move *ma, const body *b, const sched_move *mb);

/* A gap no more than the distance of a and b: between the spheres about their
 * centres of mass that hold them, or, when one is much the larger (a floor, a
 * wall, a table), between the other's sphere and its bounding box.  A turn of
 * either object leaves a sphere as it is; *turn_a or *turn_b (when not NULL) says
 * whether the gap is to a's box or to b's, which turns with it. */
double sched_bound_gap(const body *a, const body *b, bool *turn_a, bool *turn_b);

/* An entry of the heap: its time, kept next to its id so that sifting reads no
 * pair.  Ids: object k's own next event is k; the pair in slot s is nobj + s. */
typedef struct {
    double next;
    long id;
} sched_entry;

/* The schedule's state, made by sched_build for the pairs of the moment, and kept
 * in step as pairs come and go (sched_add, sched_remove). */
typedef struct {
    sched_entry *heap;    /* a binary min-heap of (next, id) over the pairs and the
                           * objects (nheap entries), and after the last an end mark
                           * that no time precedes */
    long *heap_pos;       /* each id's place in it, -1 when out (apart from the
                           * pairs, so that sifting writes no pair) */
    long nheap, cap;      /* entries, and room for ids (and entries) */
    int nobj;             /* objects when it was built: pairs' ids start there */
} schedule;

/* An empty schedule (no heap: sched_build makes it). */
void sched_init(schedule *s);
void sched_free(schedule *s);

/* Builds the heap over every pair, all due at time t, and every object, with no
 * event of its own.  Returns 0, or -1 when out of memory. */
int sched_build(world *w, double t);

/* The id of the pair in slot s, and of object k's own event. */
static inline long sched_pair_id(const schedule *s, long slot) { return s->nobj + slot; }
static inline long sched_obj_id(int k) { return k; }

/* Sets entry id's time to next and restores the heap. */
void sched_set(world *w, long id, double next);

/* Adds the pair in slot s, due at next; removes it.  sched_add returns 0, or -1
 * when out of memory. */
int sched_add(world *w, long slot, double next);
void sched_remove(world *w, long slot);

/* The entry due first, or -1 for none; its time in *next. */
long sched_top(const world *w, double *next);

/* Checks the heap's invariants (for tests and the validation build): 0 when
 * they hold. */
int sched_check(const world *w);

#endif
