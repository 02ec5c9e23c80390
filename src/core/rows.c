/* rows.c: the rows of a pair's points of contact (rows.h). */
#include "rows.h"

#include "friction.h"

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
