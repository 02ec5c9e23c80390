/* rest.h: the contact state of objects on their supports (thesis 3.3.3): how each
 * object pressed on others moves, and when it rests.
 *
 * Objects in lasting contact (pair.touching) are pressed together: the contact
 * forces, not collisions, keep them apart.  From its lasting contacts each
 * dynamic object gets its mode:
 *  - free: none;
 *  - sliding: one, on a face of a static object that holds it, a frictionless
 *    face pressed by the force with the object's centre of mass, projected along
 *    its normal, strictly inside the region they touch on (contact_holds); it then
 *    translates along the face under the rest of the force, turning about the
 *    normal only, until its centre of mass leaves the face (an exact event:
 *    rest_slide_exit), and on across a seam onto a coplanar face of another
 *    static object (rest_slide_on);
 *  - with friction on such a face, where mechanics has a closed form
 *    (friction_face): sliding along a line (a box flat on the face, a ball
 *    slipping), stuck, or rolling (a ball), each until its slip or its speed
 *    reaches zero, an exact event too (rest_face_stop), where it gets its mode
 *    anew; a box whose centre of pressure friction moves out of the region it
 *    stands on tips, and is general; a box sliding and spinning at once on a
 *    level face moves by friction over its face (facespin.h), a step of its
 *    integration at a time, each step's end an event, until both stop
 *    together;
 *  - general: anything else (tipping over an edge, pivoting on it, stacks and
 *    piles that move): its cluster (the objects pressed together with it) moves
 *    with the contact forces found as it goes (cluster.h).
 * At the end of a frame an object that is held (sliding on a level frictionless
 * face, or a cluster whose supports balance the force) and slower than
 * SIM_REST_SPEED rests (STATE_RESTING), and so does one stuck (keeping its mode
 * and support): it stays put and costs nothing until something moves it.
 */
#ifndef VROC_REST_H
#define VROC_REST_H

#include <stdbool.h>

#include "body.h"

typedef struct world world;

/* The objects pressed together with the seeds (n of them), through lasting
 * contacts between dynamic objects (static ones end it), the seeds first: written
 * to out (room for every object), their count returned.  Uses w->answer.mark. */
int rest_component(world *w, const int *seeds, int n, int *out);

/* The same, through the objects in MODE_GENERAL only: a cluster. */
int rest_cluster(world *w, int seed, int *out);

/* Gives each of the n objects of list (dynamic, their states at the same instant)
 * its mode from its lasting contacts, and makes general every dynamic object
 * pressed on a general one.  A resting object among them moves again. */
void rest_classify(world *w, const int *list, int n);

/* When object i, sliding or rolling on a face with its flight from time t, leaves
 * the face (its centre of mass passes the face's edge), or its closed-form
 * motion ends (flight.h's t_stop), whichever is first: an absolute time, or
 * +inf. */
double rest_slide_exit(const world *w, int i, double t);

/* When object i, on a face with friction, has its closed-form motion end (its
 * slip or its speed reaching zero: flight.h's t_stop) at the world's time, its
 * state there (synced to it): makes that end exact (a box or a rolling ball
 * still, a sliding ball rolling) and gives it its mode anew (it sticks, rolls,
 * slides on, or goes to a cluster); at the end of a step of a slide and spin
 * that goes on (FLIGHT_SPIN), nothing (its next step starts there), and where
 * no step could be taken (it tips) it is general.  False,
 * and nothing changed, when its event is not that end. */
bool rest_face_stop(world *w, int i);

/* Sliding object i (its state at the instant its centre of mass leaves its face)
 * goes on sliding onto a face of another static object that is coplanar with its
 * own within 1e-9 rad and 1e-9 m, and that its centre of mass is over or coming
 * onto (a seam between tiles): true when it does, its lasting contact moved to
 * that object, its speed unchanged.  False, and nothing changed, when there is
 * none. */
bool rest_slide_on(world *w, int i);

/* True when the supports of the n objects of list (at rest, or nearly) hold them
 * against the force: the contact forces can balance it, pushing only, with
 * rolling resistance's couples (up to c r N at each point that sticks) where
 * the objects would otherwise roll or tip. */
bool rest_balanced(world *w, const int *list, int n);

/* The frame rule: objects held by their supports and slower than SIM_REST_SPEED
 * rest.  Returns how many came to rest. */
int rest_frame_end(world *w);

/* Object i moves again (dynamic, free until classified). */
void rest_wake(world *w, int i);

#endif
