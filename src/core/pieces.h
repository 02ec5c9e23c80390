/* pieces.h: bodies made of several convex pieces (a rigid union, shape.pieces > 1:
 * Mirtich 1998, V-Clip "on hierarchies of convex pieces"; Bullet's
 * btCompoundShape), as pairs see them.
 *
 * The distance of two bodies is the least over their pairs of pieces.  A pair
 * of bodies one of which has several pieces keeps a list of piece pairs, each
 * with its own closest-feature caches (piece_pair): those whose bounds meet.  A
 * static body's pieces are in the broad phase's static tree one by one, and its
 * word decides which of them are listed (broad.h); a moving body's pieces are all
 * listed, and a query skips each pair of pieces whose bounding spheres are
 * further apart than the nearest pair it has found, so that it costs only the
 * pieces near.  The result names its pieces (closest_result's ka and kb); the
 * pair's contact is every piece pair that touches, answered together (contact.h
 * gathers their points).  A body's own pieces never meet: they are one rigid
 * body.
 */
#ifndef VROC_PIECES_H
#define VROC_PIECES_H

#include <stdbool.h>

#include "body.h"
#include "closest.h"

/* Piece i of the pair's first object and j of its second, and the features of
 * its last query (c), of its pair's last contact (hit: where a search for the
 * next starts, as pairs.h's hit), and of the last contact a search found
 * (found: kept as hit when that contact is answered). */
typedef struct {
    int i, j;
    closest_cache c, hit, found;
    bool held;  /* in the lasting contact of its pair when a search began: that
                 * search leaves it out (toi.h) */
} piece_pair;

typedef struct {
    piece_pair *e;
    int n, cap;
} piece_pairs;

/* Which caches a query starts from and writes. */
typedef enum {
    PIECES_QUERY,  /* c, and back into c */
    PIECES_SEARCH, /* found, and back into found; the pairs held left out */
    PIECES_PEEK    /* c, and into nothing */
} pieces_use;

/* True when b is built of several pieces. */
static inline bool body_compound(const body *b) { return b->built && b->shape.pieces > 1; }

/* The distance between a and b (built, finite), the least over the piece pairs
 * of pp, or of every pair of their pieces when pp is NULL or empty (then with
 * no cache), computed as body_distance computes it (canonical order; depth as
 * there).  ka and kb name the pieces of the result. */
closest_result pieces_distance(const body *a, const body *b, piece_pairs *pp, pieces_use use,
                               bool depth);

/* The pairs of pieces a query of two bodies of several pieces met besides its
 * nearest (pieces_distance_near), for bounds on when each could meet: the
 * first PIECES_NEAR it queried, and no more than the distance of any other. */
#define PIECES_NEAR 8
typedef struct {
    closest_result r[PIECES_NEAR];
    int n;
    double others; /* HUGE_VAL when there is none */
} pieces_near;

/* pieces_distance, and those in *near (when not NULL). */
closest_result pieces_distance_near(const body *a, const body *b, piece_pairs *pp,
                                    pieces_use use, bool depth, pieces_near *near);

/* Marks held the piece pairs of pp (listed) within tol of each other (or in,
 * or not known), from their found caches: those whose bounds are further apart
 * are not queried. */
void pieces_hold(const body *a, const body *b, piece_pairs *pp, double tol);

/* The pairs of pieces of a and b, of pp (every pair when pp is NULL or empty),
 * within tol of each other (distance <= tol, with the depth), nearest first: at
 * most max written to out, the count returned.  No cache: for a contact's
 * points, each pair of pieces' own. */
int pieces_touching(const body *a, const body *b, const piece_pairs *pp, double tol,
                    closest_result *out, int max);

/* The distance from the ball of radius r about c to b (of any number of pieces):
 * the least over its pieces; <= 0 when they meet.  (To place objects clear of
 * a body of many pieces, whose outer sphere says little.) */
double pieces_ball_gap(const body *b, vec3 c, double r);

/* b seen as its piece k alone (its hull, features and box, one piece): b itself
 * when it has one piece, else *tmp made so. */
const body *pieces_view(const body *b, int k, body *tmp);

/* pp listed anew, with no memory: every piece of a (pieces) with the pieces of b
 * in bk (nb of them; every one when bk is NULL), in order.  Returns 0, or -1
 * when out of memory (pp is then empty). */
int pieces_list(piece_pairs *pp, const body *a, const body *b, const int *bk, int nb);

/* True when pp is what pieces_list (second: pieces of b in k) or
 * pieces_list_first (else: pieces of a in k) would make of the n pieces k. */
bool pieces_listed(const piece_pairs *pp, const body *a, const body *b, bool second, const int *k,
                   int n);

/* pp listed anew as every piece of b with the pieces of a in ak: the same with
 * the static body first. */
int pieces_list_first(piece_pairs *pp, const body *a, const body *b, const int *ak, int na);

/* Each piece pair's features as the given ones: hit from c (after a query that
 * found the pair touching), hit from found (a search's contact answered), or
 * none at all (a frame's start). */
void pieces_hit_from_query(piece_pairs *pp);
void pieces_hit_from_found(piece_pairs *pp);
void pieces_forget(piece_pairs *pp);

#endif
