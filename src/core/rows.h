/* rows.h: where the objects of a pair in contact press, as the rows of a contact
 * problem (impulse.h): one row for each of the pair's points (contact.h).
 *
 * Written once for every caller that answers contacts: a collision and the
 * lasting contacts answered with it (answer.c), a cluster's kicks (cluster.c) and
 * the balance of objects at rest (rest.c).  Rows are gathered into a row_list, a
 * caller's arrays with their room.  A cluster's problems, which have as many rows
 * as its contacts have points (a hundred balls in a slot: hundreds), work in a
 * row_work, grown to the largest cluster met (rows_room) and kept, so that a
 * contact is never left out for want of room and a frame allocates only when a
 * cluster is larger than any before.
 */
#ifndef VROC_ROWS_H
#define VROC_ROWS_H

#include <stdbool.h>

#include "body.h"
#include "closest.h"
#include "contact.h"
#include "impulse.h"
#include "pairs.h"

/* Rows being gathered: room for cap of them in row, and in cp and gap when they
 * are not NULL. */
typedef struct {
    impulse_row *row;
    cpoint *cp;   /* NULL, or each row's point, its p and q the objects' indices */
    double *gap;  /* NULL, or each row's gap in the states it was evaluated in */
    int n, cap;
    bool full;    /* a point found no room */
} row_list;

/* Appends the rows of pair p: its points (contact_cpoints) with its objects in
 * the states a (object p->a's) and b (p->b's), r their closest result, the points
 * within tol of the contact plane; each row with restitution e and with its normal
 * and the point where it presses (cpoint_eval) taken with the objects in the
 * states bs (indexed by object).  Returns how many it appended; a point that
 * found no room sets l->full. */
int rows_add(row_list *l, const pair *p, const body *a, const body *b, const closest_result *r,
             double tol, double e, body *const *bs);

/* The scratch of a cluster's contact problems (answer_scratch; cluster.c,
 * rest.c), each array with room for cap rows (lam for three a row, slip two, A
 * cap x cap) and pr for cap_pairs pairs. */
typedef struct row_work {
    int cap, cap_pairs;
    impulse_row *row;  /* a cluster's points' rows (cluster.c's points), */
    cpoint *cp;        /*   their points, */
    double *gap;       /*   their gaps when gathered */
    impulse_row *sub;  /* some of them: the rows one problem solves */
    double *A, *q, *next, *wv, *u, *gap_end, *floor_gap, *lam, *slip;
    vec3 *at;
    pair **pr;         /* the lasting contacts the points come from */
    lcp_work *lcp;     /* lcp_work_size(cap) bytes */
} row_work;

/* Makes room in rw for at least rows rows and pairs pairs, keeping what the
 * arrays hold (A excepted: its rows are laid out by its size).  Returns 0, or -1
 * when out of memory (rw as it was). */
int rows_room(row_work *rw, int rows, int pairs);

/* Frees rw's arrays (rw itself is the caller's), leaving it empty. */
void rows_free(row_work *rw);

#endif
