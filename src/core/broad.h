/* broad.h: the broad phase: which objects are near enough to need a pair
 * (thesis 2.1.3; design.md, "Broad phase").
 *
 * Each object has a box, fixed in the room, that covers it: a static object's
 * covers its shape as placed; a moving object's covers the sphere about its centre
 * of mass that holds it (a turn leaves that sphere as it is), swept along its
 * flight until a little past the end of the internal step, and fattened, so that
 * it is made again only every few steps.  Two objects (not both static) whose
 * boxes meet have a pair; when their boxes part, their pair ends (pairs.h).
 *
 * Never late: a moving object's box is checked to cover it until the end of the
 * internal step at each step's start and whenever its flight changes (an event:
 * a collision, a slide's end, a cluster's step), and made again, with the pairs
 * its new box meets, when it does not.  So at every instant of a step each object
 * is inside its box, and two objects can only come within the contact distance
 * (by which the boxes are widened) while their boxes meet: the pair exists before
 * its earliest possible contact, and its search starts no later than the flight
 * that brought its box to meet the other.  The boxes depend on the objects'
 * states and flights alone, so the heap on and off see the same pairs come and go.
 *
 * The moving objects' boxes sit in a dynamic bounding-volume tree (Box2D's
 * dynamic_tree.c, Bullet's btDbvt: insertion by the surface-area cost, AVL
 * rotations); the static objects' in a tree of their own, made when the pairs
 * are made and made again only by a command that moves a static object.  A
 * static object of several pieces (pieces.h) is in that tree piece by piece, each
 * with its own box: its pair with a moving object lists the pieces whose boxes
 * meet the moving one's (pair_near_pieces), and ends when none does, so that a
 * room of thousands of pieces costs only the pieces near each moving object.
 */
#ifndef VROC_BROAD_H
#define VROC_BROAD_H

#include <stdbool.h>
#include <stddef.h>

#include "vmath.h"

typedef struct world world;

typedef struct {
    vec3 lo, hi;
} aabb;

typedef struct {
    aabb box;
    int parent;
    int child[2];  /* child[0] < 0: a leaf */
    int height;    /* 0 for a leaf */
    int body;      /* a leaf's object */
} broad_node;

typedef struct {
    broad_node *node;
    int cap, root, free_list, count;
} broad_tree;

/* A box of the static tree: a static object's, or one piece's of a static object
 * of several (piece >= 0). */
typedef struct {
    int body, piece;
    aabb box;
} broad_item;

typedef struct {
    broad_tree moving;    /* the boxes of the objects that are not static */
    broad_tree fixed;     /* the static objects' boxes, and their pieces' (its
                           * leaves are items) */
    broad_item *item;     /* the static tree's boxes, by object, then piece */
    int nitem, capitem;
    int *first_item;      /* per object: its first item (static objects) */
    int *leaf;            /* per object: its node in its tree, or -1 */
    aabb *box;            /* per object: its box */
    double *until;        /* per object: its box covers it, on the motion it had when
                           * the box was last checked, until then (-inf: unknown) */
    int cap;              /* objects leaf and box have room for */
    int *stack, capstack; /* the trees' walks */
    int *found, nfound, capfound; /* the objects a query found */
    long refits;          /* boxes made again since the world was made */
    long since_build;     /* and since the trees were last built */
} broad_phase;

void broad_init(broad_phase *bp);
void broad_free(broad_phase *bp);

/* Makes every object's box and both trees anew, and the pairs of the boxes that
 * meet (pair_near).  Called by pairs_update with the pairs emptied.  Returns 0, or
 * -1 when out of memory. */
int broad_rebuild(world *w);

/* After commands ran (the objects stand still at w->time): every object whose
 * box no longer covers it gets a new one.  Returns 0 or -1. */
int broad_commands(world *w);

/* Moving object i flies its flight (w->step.fl[i]) from time t: its box is made
 * again, with the pairs it meets and the pairs it no longer meets ended, unless
 * it covers the object until t_end.  `same` says that the flight goes on with the
 * motion of the one before it (a new internal step's), so that what was found of
 * the last holds.  Returns 0, or -1 when out of memory. */
int broad_cover(world *w, int i, double t, double t_end, bool same);

/* Checks the broad phase (for tests and the validation build), objects at their
 * states in w->bodies: every object is inside its box, every two objects (not
 * both static) whose boxes meet have a near pair, and every near pair's boxes
 * meet or it is in lasting contact.  Examines every two objects: n^2.  Returns 0
 * when all holds, else -1 with what does not in err. */
int broad_check(const world *w, char *err, size_t errlen);

#endif
