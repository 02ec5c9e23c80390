/* rows.h: where the objects of a pair in contact press, as the rows of a contact
 * problem (impulse.h): one row for each of the pair's points (contact.h).
 *
 * Written once for every caller that answers contacts: a collision and the
 * lasting contacts answered with it (answer.c), a cluster's kicks (cluster.c) and
 * the balance of objects at rest (rest.c).  Rows are gathered into a row_list, a
 * caller's arrays with their room, so that none is allocated.
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

#endif
