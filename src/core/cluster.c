/* cluster.c: a cluster's steps (cluster.h). */
#include "cluster.h"

#include <math.h>
#include <stdlib.h>

#include "answer.h"
#include "contact.h"
#include "friction.h"
#include "impulse.h"
#include "lcp.h"
#include "pairs.h"
#include "rows.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* Newton steps of the first kick, at most. */
#define CLUSTER_NEWTON 6

/* How fast a point that is in comes out (m/s). */
#define CLUSTER_RECOVER_SPEED 1e-3

/* A cluster's pressed points: the rows of its impulses, the points they follow
 * and their gaps when gathered (in `rows`, over row, cp and gap). */
typedef struct {
    impulse_row row[SIM_CLUSTER_ROWS];
    cpoint cp[SIM_CLUSTER_ROWS]; /* p and q renumbered as body indices */
    double gap[SIM_CLUSTER_ROWS];
    row_list rows;
    int np;                      /* the lasting contacts they come from */
    pair *pr[SIM_CLUSTER_ROWS];
} points;

/* The pressed points of the cluster's lasting contacts, its objects in the states
 * of w->bodies (each pair once). */
static void gather(world *w, const int *list, int n, points *pts, double reach)
{
    pts->rows = (row_list){pts->row, pts->cp, pts->gap, 0, SIM_CLUSTER_ROWS, false};
    pts->np = 0;
    bool *in = w->answer.mark;
    for (int k = 0; k < n; k++) in[list[k]] = true;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        FOR_PAIRS_OF(w, i, link, p) {
            int o = link->other;
            if (!p->touching || (in[o] && o < i)) continue;
            const body *A = w->bodies[p->a], *B = w->bodies[p->b];
            closest_result r = pair_query(w, p, A, B);
            if (r.status == CLOSEST_INVALID) continue;
            if (pts->np < SIM_CLUSTER_ROWS) pts->pr[pts->np++] = p;
            rows_add(&pts->rows, p, A, B, &r, d_max(tol_contact(A, B), reach), 0, w->bodies);
        }
    }
    for (int k = 0; k < n; k++) in[list[k]] = false;
}

/* The contact distance of point cp's pair. */
static double touch_at(const world *w, const cpoint *cp)
{
    return tol_touch(w->bodies[cp->p], w->bodies[cp->q]);
}

/* The fastest any point of the cluster moves (m/s). */
static double fastest(const world *w, const int *list, int n)
{
    double s = 0;
    for (int k = 0; k < n; k++) {
        const body *b = w->bodies[list[k]];
        s = d_max(s, v3_len(b->v) + v3_len(b->w) * b->shape.r_out);
    }
    return s;
}

/* The gap floor of a point at gap g0 now: kept at a hover's gap; one already
 * closer (or in, by the steps' rounding) goes no closer, and comes out slowly, so
 * as to add no bounce (over a step of h). */
static double floor_of(const world *w, const cpoint *cp, double g0, double h)
{
    const body *P = w->bodies[cp->p], *Q = w->bodies[cp->q];
    double hover = tol_hover(P, Q);
    return g0 >= hover ? hover : g0 >= 0 ? g0 : d_min(0, g0 + h * CLUSTER_RECOVER_SPEED);
}

/* The rows of pts (m of them) whose contacts' closest points at the step's end
 * (the objects' states there in bs) lie closer than the contact's points allow:
 * one more row for each, at those points (appended to pts, its floor and gap
 * written); returns how many. */
static int deepest_rows(world *w, points *pts, body **bs, double *floor_gap, double *gap, int m,
                        double h)
{
    int added = 0;
    for (int c = 0; c < pts->np && pts->rows.n < SIM_CLUSTER_ROWS; c++) {
        pair *p = pts->pr[c];
        const body *A = bs[p->a], *B = bs[p->b];
        closest_result r = pair_query_peek(w, p, A, B);
        if (r.status == CLOSEST_INVALID) continue;
        /* the least floor of its points, and the tolerance of their gaps */
        double least = HUGE_VAL, tol = 0;
        for (int k = 0; k < m; k++) {
            const cpoint *x = &pts->cp[k];
            if ((x->p == p->a && x->q == p->b) || (x->p == p->b && x->q == p->a)) {
                least = d_min(least, floor_gap[k]);
                tol = 1e-3 * touch_at(w, x);
            }
        }
        if (!(least < HUGE_VAL) || r.distance >= least - tol) continue;
        /* their points there (material points and features, so rows now): their
         * gaps now set their floors, and their gaps there what is left */
        int first = pts->rows.n, nc = rows_add(&pts->rows, p, A, B, &r, tol_contact(A, B), 0, w->bodies);
        for (int k = first; k < first + nc; k++) {
            const cpoint *x = &pts->cp[k];
            vec3 nn, at;
            floor_gap[k] = floor_of(w, x, pts->gap[k], h);
            gap[k] = cpoint_eval(x, bs[x->p], bs[x->q], &nn, &at) - floor_gap[k];
        }
        added += nc;
    }
    return added;
}

/* The cluster's objects (n of list) as copies in bs (their kicked copies),
 * kicked by impulses lam at the nr rows (and, with friction, by the rolling
 * resistance of the m points of pts at those impulses), then flown freely to
 * the step's end t + h. */
static void fly_kicked(world *w, const int *list, int n, const impulse_row *rows, int nr,
                       const double *lam, const points *rough, int m, double t, double h, body **bs)
{
    bool *mobile = w->answer.mark;
    vec3 g = world_accel(w);
    for (int k = 0; k < n; k++) {
        body *c = &w->answer.kicked[list[k]];
        *c = *w->bodies[list[k]];
        bs[list[k]] = c;
    }
    impulse_apply(rows, nr, bs, mobile, lam);
    if (rough) friction_roll(rough->row, m, bs, mobile, lam);
    for (int k = 0; k < n; k++) {
        body *c = bs[list[k]];
        flight f;
        flight_start(&f, c, FLIGHT_FREE, t, g, v3(0, 0, 0), 0);
        flight_at(&f, w->bodies[list[k]], t + h, c);
    }
}

/* The gap of each of the m points of pts at the step's end (the objects there in
 * bs), less its floor, into gap; true when every point is closed or open as its
 * impulse says (lam_n, every `stride`th of lam). */
static bool gaps_at_end(world *w, const points *pts, int m, body **bs, const double *floor_gap,
                        const double *lam, int stride, double *gap, vec3 *at)
{
    bool done = true;
    for (int k = 0; k < m; k++) {
        vec3 nn;
        gap[k] = cpoint_eval(&pts->cp[k], bs[pts->cp[k].p], bs[pts->cp[k].q], &nn, &at[k]) -
                 floor_gap[k];
        double tol = 1e-3 * touch_at(w, &pts->cp[k]);
        if ((lam[stride * k] > 0 && fabs(gap[k]) > tol) || gap[k] < -tol) done = false;
    }
    return done;
}

/* The first kicks of a step with friction at some point (cluster_kick's, over
 * the cones): at each point, its normal impulse keeps its gap at the step's end
 * as the frictionless kicks do, and its tangential impulse stops its slip at the
 * step's end, within its cone (friction.h), with rolling resistance beside. */
static void kick_rough(world *w, const int *list, int n, points *pts, double t, double h)
{
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    friction_work *fw = w->answer.fw;
    int m = pts->rows.n;
    double lam[3 * SIM_CLUSTER_ROWS], gap[SIM_CLUSTER_ROWS], floor_gap[SIM_CLUSTER_ROWS];
    vec3 at[SIM_CLUSTER_ROWS];
    for (int k = 0; k < 3 * m; k++) lam[k] = 0;
    for (int k = 0; k < m; k++) floor_gap[k] = floor_of(w, &pts->cp[k], pts->gap[k], h);
    friction_rows(pts->row, m, fw->rows);
    impulse_matrix(fw->rows, 3 * m, bs, mobile, fw->A);
    bool roll = false;
    for (int k = 0; k < m; k++) roll = roll || pts->row[k].roll > 0;
    friction_flags f = {false, false, false};
    for (int it = 0; it < CLUSTER_NEWTON; it++) {
        fly_kicked(w, list, n, fw->rows, 3 * m, lam, pts, m, t, h, bs);
        bool done = gaps_at_end(w, pts, m, bs, floor_gap, lam, 3, gap, at) && !(roll && it == 0);
        /* each point's slip at the step's end, where it is then */
        double slip[2 * SIM_CLUSTER_ROWS];
        for (int k = 0; k < m; k++)
            for (int j = 0; j < 2; j++) {
                impulse_row r = fw->rows[3 * k + 1 + j];
                r.at = at[k];
                slip[2 * k + j] = impulse_speed(&r, bs);
            }
        int added = done || it == CLUSTER_NEWTON - 1 ? deepest_rows(w, pts, bs, floor_gap, gap, m, h) : 0;
        for (int k = 0; k < n; k++) bs[list[k]] = w->bodies[list[k]];
        if (added > 0) {
            for (int k = 3 * m; k < 3 * (m + added); k++) lam[k] = 0;
            for (int k = m; k < m + added; k++) {
                vec3 nn;
                cpoint_eval(&pts->cp[k], w->answer.kicked + pts->cp[k].p, w->answer.kicked + pts->cp[k].q,
                            &nn, &at[k]);
                slip[2 * k] = slip[2 * k + 1] = 0;
            }
            m += added;
            friction_rows(pts->row, m, fw->rows);
            impulse_matrix(fw->rows, 3 * m, bs, mobile, fw->A);
            done = false;
        }
        if (done) break;
        /* Newton: gap / h + A (next - lam) >= 0 along the normals, the slips
         * + A (next - lam) along the tangents, over the cones */
        for (int k = 0; k < 3 * m; k++) {
            double s = k % 3 == 0 ? gap[k / 3] / h : slip[2 * (k / 3) + k % 3 - 1];
            for (int j = 0; j < 3 * m; j++) s -= fw->A[k * 3 * m + j] * lam[j];
            fw->q[k] = s;
        }
        for (int k = 0; k < m; k++) fw->mu[k] = pts->row[k].mu;
        for (int k = 0; k < 3 * m; k++) fw->z[k] = lam[k]; /* (from the last kicks) */
        int st = friction_cone_solve(m, fw->A, fw->q, fw->mu, fw->z, fw->w, &f.painleve);
        if (st < 0) {
            w->st.unsolved++; /* (the last kicks found stand) */
            break;
        }
        if (st > 0) f.unconverged = true;
        for (int k = 0; k < 3 * m; k++) lam[k] = fw->z[k];
    }
    impulse_apply(fw->rows, 3 * m, bs, mobile, lam);
    friction_roll(pts->row, m, bs, mobile, lam);
    answer_count(w, f, list[0]);
}

double cluster_kick(world *w, const int *list, int n, double t, double t_end)
{
    double h = d_min(SIM_CLUSTER_STEP, t_end - t);
    double s = fastest(w, list, n) + v3_len(world_accel(w)) * h;
    if (s * h > SIM_CLUSTER_MOVE) h = SIM_CLUSTER_MOVE / s;
    points pts;
    /* the points that could close within the step: its motion, twice over */
    gather(w, list, n, &pts, 2 * s * h);
    int m = pts.rows.n;
    if (m == 0 || !(h > 0)) return h;
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    for (int k = 0; k < n; k++) mobile[list[k]] = true;
    if (friction_any(pts.row, m)) {
        kick_rough(w, list, n, &pts, t, h);
        for (int k = 0; k < n; k++) mobile[list[k]] = false;
        return h;
    }
    double A[SIM_CLUSTER_ROWS * SIM_CLUSTER_ROWS], q[SIM_CLUSTER_ROWS], lam[SIM_CLUSTER_ROWS],
        next[SIM_CLUSTER_ROWS], wv[SIM_CLUSTER_ROWS], gap[SIM_CLUSTER_ROWS];
    impulse_matrix(pts.row, m, bs, mobile, A);
    for (int k = 0; k < m * m; k++) A[k] *= h;
    for (int k = 0; k < m; k++) lam[k] = 0;
    double floor_gap[SIM_CLUSTER_ROWS];
    for (int k = 0; k < m; k++) floor_gap[k] = floor_of(w, &pts.cp[k], pts.gap[k], h);
    for (int it = 0; it < CLUSTER_NEWTON; it++) {
        /* the gaps at the step's end after kicks lam: each object's copy kicked,
         * flown freely */
        fly_kicked(w, list, n, pts.row, m, lam, NULL, 0, t, h, bs);
        vec3 at[SIM_CLUSTER_ROWS];
        bool done = gaps_at_end(w, &pts, m, bs, floor_gap, lam, 1, gap, at);
        /* the points followed may miss where the objects meet at the step's end (a
         * curved side rolling over an edge brings its next facet): each contact's
         * own closest points there, when they are closer than its points allow,
         * are followed too */
        int added = done || it == CLUSTER_NEWTON - 1 ? deepest_rows(w, &pts, bs, floor_gap, gap, m, h) : 0;
        for (int k = 0; k < n; k++) bs[list[k]] = w->bodies[list[k]];
        if (added > 0) {
            for (int k = m; k < m + added; k++) lam[k] = 0;
            m += added;
            impulse_matrix(pts.row, m, bs, mobile, A);
            for (int k = 0; k < m * m; k++) A[k] *= h;
            done = false;
        }
        if (done) break;
        /* Newton: gaps + h A (next - lam) >= 0, complementary to next >= 0 */
        for (int k = 0; k < m; k++) {
            q[k] = gap[k];
            for (int j = 0; j < m; j++) q[k] -= A[k * m + j] * lam[j];
        }
        if (lcp_solve(m, A, q, next, wv, w->answer.lcp) != 0) {
            w->st.unsolved++; /* (the last kicks found stand) */
            break;
        }
        for (int k = 0; k < m; k++) lam[k] = next[k];
    }
    impulse_apply(pts.row, m, bs, mobile, lam);
    for (int k = 0; k < n; k++) mobile[list[k]] = false;
    return h;
}

void cluster_settle(world *w, const int *list, int n)
{
    points pts;
    gather(w, list, n, &pts, 0);
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    /* the touching points: those that stay in contact stop approaching */
    impulse_row rows[SIM_CLUSTER_ROWS];
    double u[SIM_CLUSTER_ROWS], lam[SIM_CLUSTER_ROWS];
    int m = 0;
    for (int k = 0; k < pts.rows.n; k++)
        if (pts.gap[k] <= touch_at(w, &pts.cp[k])) rows[m++] = pts.row[k];
    for (int k = 0; k < n; k++) mobile[list[k]] = true;
    for (int k = 0; k < m; k++) u[k] = impulse_speed(&rows[k], bs);
    if (m > 0 && friction_any(rows, m)) {
        friction_flags f = {false, false, false};
        if (friction_compress(rows, m, bs, mobile, u, lam, w->answer.fw, &f) != 0) w->st.unsolved++;
        answer_count(w, f, list[0]);
    } else if (m > 0 && impulse_solve(rows, m, bs, mobile, u, lam, w->answer.lcp) != 0) {
        w->st.unsolved++;
    }
    for (int k = 0; k < n; k++) mobile[list[k]] = false;
    /* the lasting contacts that opened end */
    for (int k = 0; k < n; k++) {
        int i = list[k];
        FOR_PAIRS_OF(w, i, link, p) {
            if (!p->touching) continue;
            const body *A = w->bodies[p->a], *B = w->bodies[p->b];
            closest_result r = pair_query_apart(w, p, A, B);
            /* (within the thickness of a contact, a rolling or rocking contact
             * holds: its points come and go as it turns) */
            double held = SIM_CONTACT_TOL * (1 + tol_size(A, B));
            if (r.status == CLOSEST_SEPARATED && r.distance > held) p->touching = false;
        }
    }
}
