/* rows.c: the rows of a pair's points of contact (rows.h). */
#include "rows.h"

#include <stdlib.h>

#include "friction.h"
#include "grow.h"

int rows_add(row_list *l, const pair *p, const body *a, const body *b, const closest_result *r,
             double tol, double e, body *const *bs)
{
    cpoint cp[CONTACT_MAX_POINTS];
    int nc = contact_cpoints(a, b, p->pieces, r, tol, cp, CONTACT_MAX_POINTS), added = 0;
    for (int c = 0; c < nc; c++) {
        if (l->n == l->cap) {
            l->full = true;
            break;
        }
        /* (contact_cpoints numbers the sides 0 for a and 1 for b) */
        cpoint x = cp[c];
        x.p = cp[c].p == 0 ? p->a : p->b;
        x.q = cp[c].p == 0 ? p->b : p->a;
        impulse_row *row = &l->row[l->n];
        row->p = x.p;
        row->q = x.q;
        row->e = e;
        row->mu = friction_mu(bs[x.p], bs[x.q]);
        row->roll = friction_rolling(bs[x.p], bs[x.q]);
        double g = cpoint_eval(&x, bs[x.p], bs[x.q], &row->n, &row->at);
        if (l->cp) l->cp[l->n] = x;
        if (l->gap) l->gap[l->n] = g;
        l->n++;
        added++;
    }
    return added;
}

int rows_room(row_work *rw, int rows, int pairs)
{
    bool ok = true;
    if (rows > rw->cap) {
        long n = grow_doubled(rows, rw->cap);
        rw->row = grow_resized(rw->row, sizeof *rw->row, n, &ok);
        rw->cp = grow_resized(rw->cp, sizeof *rw->cp, n, &ok);
        rw->gap = grow_resized(rw->gap, sizeof *rw->gap, n, &ok);
        rw->sub = grow_resized(rw->sub, sizeof *rw->sub, n, &ok);
        rw->A = grow_resized(rw->A, sizeof *rw->A, n * n, &ok);
        rw->q = grow_resized(rw->q, sizeof *rw->q, n, &ok);
        rw->next = grow_resized(rw->next, sizeof *rw->next, n, &ok);
        rw->wv = grow_resized(rw->wv, sizeof *rw->wv, n, &ok);
        rw->u = grow_resized(rw->u, sizeof *rw->u, n, &ok);
        rw->gap_end = grow_resized(rw->gap_end, sizeof *rw->gap_end, n, &ok);
        rw->floor_gap = grow_resized(rw->floor_gap, sizeof *rw->floor_gap, n, &ok);
        rw->lam = grow_resized(rw->lam, sizeof *rw->lam, 3 * n, &ok);
        rw->slip = grow_resized(rw->slip, sizeof *rw->slip, 2 * n, &ok);
        rw->at = grow_resized(rw->at, sizeof *rw->at, n, &ok);
        rw->lcp = grow_resized(rw->lcp, 1, (long)lcp_work_size((int)n), &ok);
        /* (each array that moved has room for n; one that failed kept its old
         * room, so the room is n only when all did) */
        if (ok) rw->cap = (int)n;
    }
    if (ok && pairs > rw->cap_pairs) {
        long n = grow_doubled(pairs, rw->cap_pairs);
        rw->pr = grow_resized(rw->pr, sizeof *rw->pr, n, &ok);
        if (ok) rw->cap_pairs = (int)n;
    }
    return ok ? 0 : -1;
}

void rows_free(row_work *rw)
{
    free(rw->row);
    free(rw->cp);
    free(rw->gap);
    free(rw->sub);
    free(rw->A);
    free(rw->q);
    free(rw->next);
    free(rw->wv);
    free(rw->u);
    free(rw->gap_end);
    free(rw->floor_gap);
    free(rw->lam);
    free(rw->slip);
    free(rw->at);
    free(rw->pr);
    free(rw->lcp);
    *rw = (row_work){0};
}
