/* schedule.h: the collision heap (thesis 3.3.1).
 *
 * Each pair gets the earliest time it could possibly collide: its distance, less
 * what rotation can bring the surfaces closer ((R - r) of each rotating object, or
 * |w| R t when that is smaller), against the farthest vroc's own integrator can
 * carry the two centres of mass towards each other (|v| t + |a| t^2 / 2, and never
 * more than max_linear t).  Pairs sit in an indexed binary heap keyed by that time;
 * an internal step checks only the pairs that are due.  A near pair's time may
 * instead come from the motion along the normal between its closest points
 * (sched_predict_along), later where the objects do not come on straight; such a
 * time holds only while both fly on as they did.  A collision that changes
 * an object's motion gives its near pairs new times from the bounds they were
 * found with (sched_bound), or makes them due (sim.c, reschedule).  In front of
 * the far pairs, a broad phase: each object has a box that holds it for a while
 * (sched_box), and a pair whose boxes do not meet waits outside the heap's order
 * until one of them is made again.
 */
#ifndef VROC_SCHEDULE_H
#define VROC_SCHEDULE_H

#include <stdbool.h>

#include "body.h"
#include "pairs.h"
#include "vmath.h"

typedef struct world world;

/* Time (s, from now) before which pair p, its objects distance d apart now, cannot
 * collide; 0 when d <= 0, HUGE_VAL when neither object moves. */
double sched_predict(const world *w, const pair *p, double d);

/* The same for objects a and b in the states given (not necessarily the world's). */
double sched_predict_bodies(const world *w, const body *a, const body *b, double d);

/* How far (m), in all, collisions may move a far pair's objects at once (setting
 * them apart, settling them onto a face: body.jumped) before the pair's time from
 * sched_predict_far must be found again. */
#define SCHED_JUMP 5e-3

/* Speed (m/s) a far pair's bound gives each moving object beyond its own. */
#define SCHED_SLACK 0.1

/* A bound for objects a and b, a gap d apart in the states given, that holds
 * whatever their spins become, while their speeds stay within SCHED_SLACK of what
 * they are in those states plus what the force adds, whatever their directions
 * (the whole force, whether or not the object slides, unless its slide is steady:
 * body.slide_steady; so a slide that ends leaves the time as it was), and
 * through moves at once of up to SCHED_JUMP in all: so that a collision that
 * turns an object back, spins it faster, speeds it up a little, sets it a hair
 * apart or lays it on a face leaves the pair's time as it was.  turn_a and turn_b say whether a turn of
 * that object can close the gap; each that can turns its surface by all of its
 * R - r at once.  (A gap between spheres about the centres of mass that hold the
 * objects, or from such a sphere to a still object, no turn changes.)  It is
 * earlier than sched_predict's by little when d is large. */
double sched_predict_far(const world *w, const body *a, const body *b, double d, bool turn_a,
                         bool turn_b);

/* One moving object's part of a bound, as a function of the time t since it was
 * found: its centre goes at most s t + acc t^2 / 2 until t_lin, then vmax t; its
 * surface turns about the centre by at most rate t until t_rot, then cap. */
typedef struct {
    double s, acc, vmax, t_lin;
    double rate, cap, t_rot;
} sched_reach;

/* A near pair's prediction as it was made: the distance then and the bound on how
 * far its n moving objects could close it since. */
typedef struct sched_bound {
    double dist;
    sched_reach r[2];
    int n;
} sched_bound;

/* sched_predict_bodies for objects whose speeds may exceed those of the states
 * given by slack_a and slack_b (m/s; the states may be earlier than the instant
 * the time is counted from); the bound it used is kept in *keep. */
double sched_predict_kept(const world *w, const body *a, const body *b, double d, double slack_a,
                          double slack_b, sched_bound *keep);

/* How far objects a and b, in the states given (speeds up to slack_a and slack_b
 * more), could close their distance in t seconds: the bound sched_predict_kept
 * predicts with. */
double sched_closing(const world *w, const body *a, const body *b, double slack_a, double slack_b,
                   double t);

/* What is left of a kept bound's distance t seconds after it was found, while
 * its objects moved as it assumed: a lower bound on the pair's distance then
 * (negative when they may touch). */
double sched_left(const sched_bound *k, double t);

/* A later time than sched_predict's where the objects do not come on straight
 * at each other: a and b, distance d apart, closest at points pa and pb, n the
 * unit normal from a to b.  The plane through the gap at right angles to n
 * separates them; along n each centre flies its parabola exactly (v.n t + a.n t^2
 * / 2, while its speed stays under max_linear), and each surface turns out from
 * its centre at most as far as R and at w_max R.  Beyond the time that speed
 * could reach max_linear nothing is promised: the time returned is no later.
 * The bound holds only while both objects fly as they fly now, with no slack:
 * any change to either's motion must make the pair's time again (sim.c). */
double sched_predict_along(const world *w, const body *a, const body *b, double d, vec3 n, vec3 pa,
                           vec3 pb);

/* A gap no more than the distance of a and b: between the spheres about their
 * centres of mass that hold them, or, when one is much the larger (a floor, a
 * wall, a table), between the other's sphere and its bounding box.  A turn of
 * either object leaves a sphere as it is; *turn_a or *turn_b (when not NULL) says
 * whether the gap is to a's box or to b's, which turns with it. */
double sched_bound_gap(const body *a, const body *b, bool *turn_a, bool *turn_b);

/* The broad phase in front of the far pairs: each object's box, fixed in the
 * world, holds the object from time `from` until `until`.  A still object's holds
 * it where it is, until it moves (until is +inf).  A moving object's holds the
 * sphere about its centre of mass that holds it, turned any way, wherever the
 * bound of sched_predict_far lets the centre go: no faster than speed plus acc
 * for each second since from, and moved at once by collisions by up to
 * SCHED_JUMP in all (body.jumped since jumped).  While two objects' boxes do not
 * meet they cannot touch, and their pair is parked: its time is +inf, and it is
 * not checked, until one of the boxes is made again.  A box is made again when it
 * ends (its entry in the heap comes due), or when its object leaves the bound:
 * a collision beyond it (sched_box_holds), a slide whose lesser acceleration it
 * counted that ends, a wake, a command. */
typedef struct sched_box {
    vec3 lo, hi;
    double from, until;
    double speed, acc, jumped;
} sched_box;

/* How far (m) a moving object's box reaches beyond the sphere that holds it:
 * larger boxes last longer, smaller ones meet fewer others. */
#define SCHED_BOX_REACH 0.25

/* An entry of the heap: a pair's time, kept next to its index so that sifting
 * reads no pair; or the time an object's box ends. */
typedef struct {
    double next;
    long pair;            /* a pair, or npairs + k for object k's box */
} sched_entry;

/* The schedule's state, made by sched_build for the pairs of the moment. */
typedef struct {
    sched_entry *heap;    /* a binary min-heap of (next, pair) over the pairs and
                           * the objects' boxes (nheap entries), and after the last
                           * an end mark that no time precedes */
    long *heap_pos;       /* each entry's place in it (apart from the pairs, so that
                           * sifting writes no pair) */
    long nheap;
    sched_box *box;       /* each object's box */
    bool *parked;         /* each pair's: its time is +inf because its objects'
                           * boxes do not meet; it waits until one of them is made
                           * again (apart from the pairs, so that a box's renewal
                           * reads no pair) */
    sched_bound *bound;   /* each near pair's bound, as its time was found */
    long *obj_first;      /* the pairs of object k: obj_pairs[obj_first[k] .. */
    long *obj_pairs;      /*   obj_first[k + 1] - 1], */
    int *obj_other;       /*   and the other object of each */
} schedule;

/* An empty schedule (no heap: sched_build makes it). */
void sched_init(schedule *s);
void sched_free(schedule *s);

/* Builds the heap over every pair, all due at time t, and over every object's
 * box, none made yet (they meet every box) and all ending at t; and the lists of
 * each object's pairs.  Returns 0, or -1 when out of memory. */
int sched_build(world *w, double t);

/* Sets entry i's time to next and restores the heap: pair i's, or, for i >=
 * npairs, the end of object i - npairs's box.  A pair given a time is parked no
 * more. */
void sched_set(world *w, long i, double next);

/* The entry due first (pair, or npairs + k for object k's box), or -1 for none;
 * its time in *next. */
long sched_top(const world *w, double *next);

/* Makes object k's box anew from o, object k at time from (where its flight
 * starts), to last beyond t_end: parks its pairs whose boxes no longer meet, and
 * makes due at t its parked pairs whose boxes meet now. */
void sched_box_renew(world *w, int k, const body *o, double from, double t, double t_end);

/* True when object k's box still holds it as b, its state since time t. */
bool sched_box_holds(const world *w, int k, const body *b, double t);

/* True when the boxes of objects a and b do not meet. */
bool sched_boxes_apart(const world *w, int a, int b);

/* Makes every pair of object k due at time t (sooner only: a pair already due
 * earlier keeps its time), and its box end at t (it meets every box until it is
 * made again). */
void sched_object_due(world *w, int k, double t);

/* The same when object k's slide ends, and with it the part of the force its
 * support took: for its near pairs, and for the far ones whose times counted that
 * slide's lesser acceleration (pair.far_slide_a, far_slide_b); the other far ones
 * counted the whole force, and keep their times.  Its box ends, as its pairs
 * come due, when it counted that acceleration; else its parked pairs stay so. */
void sched_slide_ends(world *w, int k, double t);

/* Checks the heap's invariants (for tests): 0 when they hold. */
int sched_check(const world *w);

#endif
