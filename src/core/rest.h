/* rest.h: the contact state of objects on their supports (thesis 3.3.3): rest,
 * slide, wake and settle.
 *
 * A body rests (STATE_RESTING, on body.support): it does not move and feels no
 * force until it is woken.  A body slides (body.slide, with the support's normal
 * slide_n): it flies under the force less the part that presses it onto the
 * support, while it stays on the support.  These functions decide when each
 * begins and ends; the simulation (sim.c) calls them around collisions and frames,
 * and the changes a command makes (edit.c) wake what they disturb.
 */
#ifndef VROC_REST_H
#define VROC_REST_H

#include <stdbool.h>

#include "body.h"
#include "closest.h"
#include "pairs.h"
#include "vmath.h"

typedef struct world world;

/* A resting object i moves again (its pairs are then made due by the caller). */
void rest_wake(world *w, int i);

/* Wakes every resting object (after a change of the global force). */
void rest_wake_all(world *w);

/* Wakes the objects resting on object i, and ends the slides on it (after a
 * command changed it; i = -1 for none). */
void rest_wake_on(world *w, int i);

/* Resting objects whose support left (deleted, or moving) wake up; chains of
 * resting objects wake in turn.  Sliding objects whose support moves on its own
 * slide no more.  Marks in touched (when not NULL) each object it changes. */
void rest_wake_unsupported(world *w, bool *touched);

/* The frame rule (thesis 3.3.3): an object still sliding on a still support at
 * the end of the frame, slower than SIM_REST_SPEED, rests on it (a stack from the
 * bottom up). */
void rest_frame_end(world *w);

/* What rest_settle did. */
enum {
    SETTLE_NONE,   /* nothing changed */
    SETTLE_STANDS, /* standing where it is: it still needs setting apart */
    SETTLE_LAID    /* turned onto its face and placed */
};

/* The contact state of body mi on support si after a collision that left it
 * barely moving away from the support (normal n from the support to it, face:
 * on a face of the support, support_pt a point of the support's surface, pair p,
 * g the global acceleration's size, e the pair's restitution): it rests, slides,
 * or is laid on the face it can stand on when its rocking could not tip it more
 * than SIM_SETTLE_ANGLE.  Returns SETTLE_NONE, SETTLE_STANDS or SETTLE_LAID. */
int rest_settle(world *w, int mi, int si, vec3 n, bool face, vec3 support_pt, pair *p, double g,
                double e);

/* True when body l, pressed from above along -n, is held by what it stands on: it
 * rests (it stays put: *s zero), or slides on a support whose normal *s is within
 * 45 degrees of n (it moves across *s only). */
bool rest_holds(const body *l, vec3 n, vec3 *s);

/* The normal n (from support s to the other object, as measured at their closest
 * points, f the feature of s) made exact when the contact is on a face of s: that
 * face's normal, so that an object sliding on the face keeps its height above it.
 * *face says whether it is. */
vec3 rest_support_normal(const body *s, closest_feature f, vec3 n, bool *face);

/* True when object i, pushed along toward (within 45 degrees), is pinned against
 * one of the last two still objects it struck a moment ago (SIM_PINNED_TIME):
 * then *s is that contact's normal, along which the blow passes on to the still
 * object (the object moves only across it). */
bool rest_pinned(world *w, int i, vec3 toward, vec3 *s);

/* Body x struck still object k along n (towards x) at time t (for rest_pinned). */
void rest_strike(body *x, int k, vec3 n, double t);

/* True when object mi slides on still support si in a way that cannot bring them
 * together until its motion changes: along the support, turning about the normal
 * only (or not at all, or a sphere about its centre). */
bool rest_slides_clear(const world *w, int mi, int si);

/* Sliding objects leave their support when they lift off, pass its edge, stop
 * standing stably on it or are thrown off it (at the end of an internal step). */
void rest_check_slides(world *w);

#endif
