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

/* Sweeps of a crowd's cone solve (past FRICTION_MAX_POINTS) in a Newton step,
 * at most: each Newton step's solve starts from the last one's kicks, so that
 * the sweeps go on across them, and the kick is done on its gaps, not on the
 * slips.  The slot of 100 rough balls (test_pressure) rests after 9 frames and
 * 65 s of processor time with 15; with 30, after 11 frames and 107 s of wall
 * time against 78 s (on a loaded machine). */
#define CLUSTER_CROWD_SWEEPS 15

/* The forcing of newton_rough's inexact Newton: each step but the last solves
 * its cone problem until a sweep changes the speeds by no more than this times
 * the largest gap error over the step (a speed); the kicks kept are solved to
 * FRICTION_TOL.  The closed box of 50 rough objects (issue 35, seed 2) took
 * 15.5 s of processor time for 20 frames with every step to FRICTION_TOL, and
 * 8.6 s with 0.1. */
#define CLUSTER_FORCING 0.1

/* How fast a point that is in comes out (m/s). */
#define CLUSTER_RECOVER_SPEED 1e-3

/* A cluster's points: the rows of its impulses, the points they follow and
 * their gaps when gathered (in `rows`, over row, cp and gap); the closed ones
 * first (nclosed), which the kicks keep closed, then the open ones, which land
 * (cluster.h).  The arrays are the answer scratch's row_work (rows.h), grown to
 * hold every point of the cluster (room). */
typedef struct {
    impulse_row *row;
    cpoint *cp;                  /* p and q renumbered as body indices */
    double *gap;
    row_list rows;
    int nclosed;
    bool rough;                  /* some point has friction: the kicks are 3 a
                                  * point, along the normal and two tangents
                                  * (friction.h), with rolling resistance */
    int np;                      /* the lasting contacts they come from */
    pair **pr;
} points;

/* Makes room for `rows` more points and `pairs` more pairs than pts holds, and
 * points pts at the scratch anew (it may have moved).  False when out of memory:
 * then a point that finds no room sets pts->rows.full, which the caller counts
 * as a problem not answered (stats: unsolved), never silently. */
static bool room(world *w, points *pts, int rows, int pairs)
{
    row_work *rw = w->answer.rw;
    bool ok = rows_room(rw, pts->rows.n + rows, pts->np + pairs) == 0;
    pts->row = pts->rows.row = rw->row;
    pts->cp = pts->rows.cp = rw->cp;
    pts->gap = pts->rows.gap = rw->gap;
    pts->rows.cap = rw->cap;
    pts->pr = rw->pr;
    return ok;
}

/* The pressed points of the cluster's lasting contacts, its objects in the states
 * of w->bodies (each pair once). */
static void gather(world *w, const int *list, int n, points *pts, double reach)
{
    pts->rows = (row_list){0};
    pts->np = pts->nclosed = 0;
    pts->rough = false;
    room(w, pts, 0, 0);
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
            room(w, pts, CONTACT_MAX_POINTS, 1);
            if (pts->np < w->answer.rw->cap_pairs) pts->pr[pts->np++] = p;
            rows_add(&pts->rows, p, A, B, &r, d_max(tol_contact(A, B), reach), 0, w->bodies);
        }
    }
    for (int k = 0; k < n; k++) in[list[k]] = false;
    if (pts->rows.full) w->st.unsolved++;
}

/* The contact distance of point cp's pair. */
static double touch_at(const world *w, const cpoint *cp)
{
    return tol_touch(w->bodies[cp->p], w->bodies[cp->q]);
}

/* The gap at which a point of cp's pair lands: twice the hover gap at which the
 * kicks keep closed points, so that those never land. */
static double land_at(const world *w, const cpoint *cp)
{
    return 2 * tol_hover(w->bodies[cp->p], w->bodies[cp->q]);
}

double cluster_stepping_speed(const world *w, const body *b)
{
    if (body_is_static(b) || b->state != STATE_DYNAMIC || b->mode != MODE_GENERAL) return 0;
    double spin = v3_len(b->w);
    return (v3_len(world_body_accel(w, b)) + 2 * spin * spin * b->shape.r_out) * SIM_CLUSTER_STEP;
}

/* True when point k of pts (its gap when gathered, the objects in the states of
 * w->bodies) is closed: within the landing gap, or within the contact's thickness
 * and closing no faster than the cluster's own steps close it. */
static bool closed(const world *w, const points *pts, int k)
{
    const cpoint *x = &pts->cp[k];
    const body *P = w->bodies[x->p], *Q = w->bodies[x->q];
    double g = pts->gap[k], land = land_at(w, x);
    if (g <= land) return true;
    if (g > d_max(tol_contact(P, Q), land)) return false;
    double closing = -impulse_speed(&pts->row[k], w->bodies);
    return closing <= tol_speed(P, Q) + cluster_stepping_speed(w, P) + cluster_stepping_speed(w, Q);
}

/* True when point k of pts is closed and closes no faster than the cluster's own
 * steps close it: one the steps keep closed, not one landing. */
static bool kept(const world *w, const points *pts, int k)
{
    const cpoint *x = &pts->cp[k];
    const body *P = w->bodies[x->p], *Q = w->bodies[x->q];
    double closing = -impulse_speed(&pts->row[k], w->bodies);
    return closed(w, pts, k) &&
           closing <= tol_speed(P, Q) + cluster_stepping_speed(w, P) + cluster_stepping_speed(w, Q);
}

/* Sorts the points of pts from `from` on into closed and open: the closed ones
 * to follow pts->nclosed (which grows by them), the open ones after. */
static void sort_closed(const world *w, points *pts, int from)
{
    for (int k = from; k < pts->rows.n; k++) {
        if (!closed(w, pts, k)) continue;
        int c = pts->nclosed++;
        impulse_row row = pts->row[c];
        cpoint cp = pts->cp[c];
        double gap = pts->gap[c];
        pts->row[c] = pts->row[k], pts->cp[c] = pts->cp[k], pts->gap[c] = pts->gap[k];
        pts->row[k] = row, pts->cp[k] = cp, pts->gap[k] = gap;
    }
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

/* Kicks lam at the m closed points of pts applied to the mobile bodies of bs:
 * one a point, or with friction three (normal, tangents: the rows of
 * friction_rows, in the friction scratch) and the rolling resistance's couples
 * at those impulses. */
static void apply_kicks(world *w, const points *pts, int m, body **bs, const double *lam)
{
    if (!pts->rough) {
        impulse_apply(pts->row, m, bs, w->answer.mark, lam);
        return;
    }
    /* (past FRICTION_MAX_POINTS in the crowd's room, which newton_rough made) */
    impulse_row *rows = friction_rows_in(w->answer.fw, pts->row, m);
    if (rows) impulse_apply(rows, 3 * m, bs, w->answer.mark, lam);
    friction_roll(pts->row, m, bs, w->answer.mark, lam);
}

/* The cluster's n objects of list kicked by lam at the m closed points of pts at
 * time t: their flights from there, in w->answer.flights. */
static void kick_flights(world *w, const int *list, int n, const points *pts, int m,
                         const double *lam, double t)
{
    body **bs = w->answer.now;
    for (int k = 0; k < n; k++) {
        body *c = &w->answer.kicked[list[k]];
        *c = *w->bodies[list[k]];
        bs[list[k]] = c;
    }
    apply_kicks(w, pts, m, bs, lam);
    for (int k = 0; k < n; k++) {
        flight_start(&w->answer.flights[list[k]], bs[list[k]], FLIGHT_FREE, t, world_accel(w),
                     v3(0, 0, 0), 0);
        bs[list[k]] = w->bodies[list[k]];
    }
}

/* Those flights at time t: the objects' copies, in w->answer.kicked, referenced
 * by w->answer.now. */
static void fly_kicked(world *w, const int *list, int n, double t)
{
    body **bs = w->answer.now;
    for (int k = 0; k < n; k++) {
        body *c = &w->answer.kicked[list[k]];
        flight_at(&w->answer.flights[list[k]], w->bodies[list[k]], t, c);
        bs[list[k]] = c;
    }
}

/* True when point x is one of pair p's. */
static bool of_pair(const cpoint *x, const pair *p)
{
    return (x->p == p->a && x->q == p->b) || (x->p == p->b && x->q == p->a);
}

/* True when an open point of pts of pair p is in at the step's end (the objects'
 * states there in bs). */
static bool open_in(const points *pts, const pair *p, body *const *bs)
{
    for (int k = pts->nclosed; k < pts->rows.n; k++) {
        const cpoint *x = &pts->cp[k];
        vec3 nn, at;
        if (of_pair(x, p) && cpoint_eval(x, bs[x->p], bs[x->q], &nn, &at) <= 0) return true;
    }
    return false;
}

/* The closed points of pts (m of them) whose contacts' closest points at the
 * step's end (the objects' states there in bs) lie closer than the contact's
 * closed points allow (or than its landing gap, with none): the points there
 * (material points and features, so rows now) are added to pts; the closed ones
 * among them follow the closed points (their floors and gaps written in the
 * scratch's floor_gap and gap_end, which may move with the room made), and
 * their count is returned. */
static int deepest_rows(world *w, points *pts, body **bs, double h)
{
    row_work *rw = w->answer.rw;
    int m = pts->nclosed, added = 0;
    for (int c = 0; c < pts->np; c++) {
        pair *p = pts->pr[c];
        const body *A = bs[p->a], *B = bs[p->b];
        closest_result r = pair_query_peek(w, p, A, B, false);
        if (r.status == CLOSEST_INVALID) continue;
        if (r.status != CLOSEST_SEPARATED) {
            /* in: by an open point, which lands within the step (landing_time),
             * or else by a point not followed, found with the depth */
            if (open_in(pts, p, bs)) continue;
            r = pair_query_peek(w, p, A, B, true);
            if (r.status == CLOSEST_INVALID) continue;
        }
        /* the least floor of its closed points, and the tolerance of their gaps */
        double least = 2 * tol_hover(A, B), tol = 1e-3 * tol_touch(A, B);
        bool any = false;
        for (int k = 0; k < m; k++) {
            const cpoint *x = &pts->cp[k];
            if (of_pair(x, p)) {
                least = any ? d_min(least, rw->floor_gap[k]) : rw->floor_gap[k];
                any = true;
            }
        }
        if (r.distance >= least - tol) continue;
        /* their gaps now set their floors, and their gaps there what is left */
        int first = pts->rows.n;
        if (!room(w, pts, CONTACT_MAX_POINTS, 0)) w->st.unsolved++;
        rows_add(&pts->rows, p, A, B, &r, tol_contact(A, B), 0, w->bodies);
        int before = pts->nclosed;
        sort_closed(w, pts, first);
        for (int k = before; k < pts->nclosed; k++) {
            const cpoint *x = &pts->cp[k];
            vec3 nn, at;
            rw->floor_gap[k] = floor_of(w, x, pts->gap[k], h);
            rw->gap_end[k] = cpoint_eval(x, bs[x->p], bs[x->q], &nn, &at) - rw->floor_gap[k];
        }
        added += pts->nclosed - before;
    }
    return added;
}

/* The least gap of the open points of pts at the step's end (the objects' states
 * in bs) less their landing gaps: the first to land, in *which. */
static double least_open(const world *w, const points *pts, body *const *bs, int *which)
{
    double least = HUGE_VAL;
    for (int k = pts->nclosed; k < pts->rows.n; k++) {
        const cpoint *x = &pts->cp[k];
        vec3 nn, at;
        double g = cpoint_eval(x, bs[x->p], bs[x->q], &nn, &at) - land_at(w, x);
        if (g < least) {
            least = g;
            *which = k;
        }
    }
    return least;
}

/* When an open point lands within the step of h from t, kicked by lam at the
 * closed points: the time it first reaches its landing gap (by bisection over the
 * kicked flights, to between a quarter of that gap and it), and the point in
 * *which; else t + h, and -1. */
static double landing_time(world *w, const int *list, int n, const points *pts, const double *lam,
                           double t, double h, int *which)
{
    *which = -1;
    if (pts->rows.n == pts->nclosed) return t + h;
    body **bs = w->answer.now;
    int k;
    kick_flights(w, list, n, pts, pts->nclosed, lam, t);
    fly_kicked(w, list, n, t + h);
    double lo = t, hi = t + h, g = least_open(w, pts, bs, &k);
    if (g <= 0) {
        *which = k;
        while (g < -0.75 * land_at(w, &pts->cp[*which])) {
            double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            fly_kicked(w, list, n, mid);
            double gm = least_open(w, pts, bs, &k);
            if (gm > 0) {
                lo = mid;
            } else {
                hi = mid;
                g = gm;
                *which = k;
            }
        }
    }
    for (int j = 0; j < n; j++) bs[list[j]] = w->bodies[list[j]];
    return hi;
}

/* Open point k of pts lands: its pair is noted as the landing of its objects
 * (answer_scratch.landing). */
static void note_landing(world *w, const points *pts, int k)
{
    const cpoint *x = &pts->cp[k];
    long slot = pair_index(w, x->p, x->q);
    if (slot < 0) return;
    if (!body_is_static(w->bodies[x->p])) w->answer.landing[x->p] = slot;
    if (!body_is_static(w->bodies[x->q])) w->answer.landing[x->q] = slot;
}

/* newton's kicks with friction at some point (lam, the scratch's: three a
 * point): at each closed point, its normal kick keeps its gap at the step's end
 * as the frictionless kicks do, and its tangential kick stops its slip at the
 * step's end, within its cone (friction.h), with rolling resistance beside.
 * Past FRICTION_MAX_POINTS (a crowd) the cone problem is solved in blocks
 * (friction_crowd_solve).  False, the kicks as they were, when there is no room
 * for the problem: the caller answers it without friction. */
static bool newton_rough(world *w, const int *list, int n, points *pts, double t, double h)
{
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    friction_work *fw = w->answer.fw;
    row_work *rw = w->answer.rw;
    int m = pts->nclosed;
    for (int k = 0; k < m; k++) rw->floor_gap[k] = floor_of(w, &pts->cp[k], pts->gap[k], h);
    if (friction_matrix(fw, pts->row, m, bs, mobile) != 0) return false;
    friction_problem P = friction_problem_of(fw, m);
    bool roll = false;
    for (int k = 0; k < pts->rows.n; k++) roll = roll || pts->row[k].roll > 0;
    friction_flags f = {false, false, false};
    bool fits = true;
    double loose = 0; /* the last solve's tolerance past FRICTION_TOL's (a speed) */
    for (int it = 0; it < CLUSTER_NEWTON; it++) {
        kick_flights(w, list, n, pts, m, rw->lam, t);
        fly_kicked(w, list, n, t + h);
        bool done = !(roll && it == 0); /* (the couples act at solved impulses) */
        double off = 0; /* the largest gap error (as done judges them) */
        for (int k = 0; k < m; k++) {
            vec3 nn;
            rw->gap_end[k] = cpoint_eval(&pts->cp[k], bs[pts->cp[k].p], bs[pts->cp[k].q], &nn, &rw->at[k]) -
                             rw->floor_gap[k];
            double tol = 1e-3 * touch_at(w, &pts->cp[k]), g = rw->gap_end[k];
            if ((rw->lam[3 * k] > 0 && fabs(g) > tol) || g < -tol) done = false;
            off = d_max(off, rw->lam[3 * k] > 0 ? fabs(g) : -g);
            /* its slip at the step's end, where it is then */
            for (int j = 0; j < 2; j++) {
                impulse_row r = P.rows[3 * k + 1 + j];
                r.at = rw->at[k];
                rw->slip[2 * k + j] = impulse_speed(&r, bs);
            }
        }
        int added = done || it == CLUSTER_NEWTON - 1 ? deepest_rows(w, pts, bs, h) : 0;
        if (added > 0) {
            for (int k = 3 * m; k < 3 * (m + added); k++) rw->lam[k] = 0;
            for (int k = m; k < m + added; k++) {
                vec3 nn;
                cpoint_eval(&pts->cp[k], bs[pts->cp[k].p], bs[pts->cp[k].q], &nn, &rw->at[k]);
                rw->slip[2 * k] = rw->slip[2 * k + 1] = 0;
            }
        }
        for (int k = 0; k < n; k++) bs[list[k]] = w->bodies[list[k]];
        if (added > 0) {
            m += added;
            if (friction_matrix(fw, pts->row, m, bs, mobile) != 0) {
                fits = false;
                break;
            }
            P = friction_problem_of(fw, m);
            done = false;
        }
        /* (kicks that keep the gaps from a loose solve: solved once more to
         * FRICTION_TOL, so that the slips the kicks leave are as exact) */
        bool again = done && loose > 0;
        if (again) done = false;
        if (done || m == 0) break;
        /* Newton: gap / h + A (next - lam) >= 0 along the normals, the slips
         * + A (next - lam) along the tangents, over the cones */
        if (m > FRICTION_MAX_POINTS) friction_crowd_mulv(&fw->crowd, m, rw->lam, P.w);
        for (int k = 0; k < 3 * m; k++) {
            double s = k % 3 == 0 ? rw->gap_end[k / 3] / h : rw->slip[2 * (k / 3) + k % 3 - 1];
            if (m > FRICTION_MAX_POINTS) s -= P.w[k];
            else
                for (int j = 0; j < 3 * m; j++) s -= fw->A[k * 3 * m + j] * rw->lam[j];
            P.q[k] = s;
        }
        for (int k = 0; k < m; k++) P.mu[k] = pts->row[k].mu;
        for (int k = 0; k < 3 * m; k++) P.z[k] = rw->lam[k]; /* (from the last kicks) */
        /* inexact Newton: a step whose kicks the next one corrects need its
         * cone problem solved only to a fraction of the gap error (as a
         * speed); the last step's (after which none follows) to FRICTION_TOL */
        loose = it < CLUSTER_NEWTON - 1 && added == 0 && !again ? CLUSTER_FORCING * off / h : 0;
        int st = friction_solve(fw, m, CLUSTER_CROWD_SWEEPS, loose, &f.painleve);
        if (st < 0) {
            w->st.unsolved++; /* (the last kicks found stand) */
            break;
        }
        if (st > 0) f.unconverged = true;
        for (int k = 0; k < 3 * m; k++) rw->lam[k] = P.z[k];
    }
    answer_count(w, f, list[0]);
    return fits;
}

/* The kicks (the scratch's lam) at the closed points of pts (more of them as
 * deepest_rows finds them, their kicks from 0) that keep them at their floors at
 * the end of a step of h from t, by Newton's method over the exact flights
 * (cluster.h), from lam as given (with friction: newton_rough; where there is
 * no room for its cone problem, along the normals alone, from then on). */
static void newton(world *w, const int *list, int n, points *pts, double t, double h)
{
    row_work *rw = w->answer.rw;
    if (pts->rough) {
        if (newton_rough(w, list, n, pts, t, h)) return;
        for (int k = 0; k < pts->nclosed; k++) rw->lam[k] = rw->lam[3 * k];
        pts->rough = false;
    }
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    int m = pts->nclosed;
    impulse_matrix(pts->row, m, bs, mobile, rw->A);
    for (int k = 0; k < m * m; k++) rw->A[k] *= h;
    for (int k = 0; k < m; k++) rw->floor_gap[k] = floor_of(w, &pts->cp[k], pts->gap[k], h);
    for (int it = 0; it < CLUSTER_NEWTON; it++) {
        /* the gaps at the step's end after kicks lam: each object's copy kicked,
         * flown freely */
        kick_flights(w, list, n, pts, m, rw->lam, t);
        fly_kicked(w, list, n, t + h);
        bool done = true;
        for (int k = 0; k < m; k++) {
            vec3 nn, at;
            rw->gap_end[k] = cpoint_eval(&pts->cp[k], bs[pts->cp[k].p], bs[pts->cp[k].q], &nn, &at) -
                             rw->floor_gap[k];
            double tol = 1e-3 * touch_at(w, &pts->cp[k]), g = rw->gap_end[k];
            if ((rw->lam[k] > 0 && fabs(g) > tol) || g < -tol) done = false;
        }
        /* the points followed may miss where the objects meet at the step's end (a
         * curved side rolling over an edge brings its next facet): each contact's
         * own closest points there, when they are closer than its points allow,
         * are followed too (or land, when they are open now) */
        int added = done || it == CLUSTER_NEWTON - 1 ? deepest_rows(w, pts, bs, h) : 0;
        for (int k = 0; k < n; k++) bs[list[k]] = w->bodies[list[k]];
        if (added > 0) {
            for (int k = m; k < m + added; k++) rw->lam[k] = 0;
            m += added;
            impulse_matrix(pts->row, m, bs, mobile, rw->A);
            for (int k = 0; k < m * m; k++) rw->A[k] *= h;
            done = false;
        }
        if (done || m == 0) break;
        /* Newton: gaps + h A (next - lam) >= 0, complementary to next >= 0 */
        for (int k = 0; k < m; k++) {
            rw->q[k] = rw->gap_end[k];
            for (int j = 0; j < m; j++) rw->q[k] -= rw->A[k * m + j] * rw->lam[j];
        }
        /* (a crowd's hundreds of points: from the last kicks' clamped points,
         * which the next kicks mostly share, for fewer pivots) */
        int st;
        if (m > IMPULSE_MAX_ROWS) {
            for (int k = 0; k < m; k++) rw->next[k] = rw->lam[k];
            st = lcp_solve_warm(m, rw->A, rw->q, rw->next, rw->wv, rw->lcp);
        } else {
            st = lcp_solve(m, rw->A, rw->q, rw->next, rw->wv, rw->lcp);
        }
        if (st != 0) {
            w->st.unsolved++; /* (the last kicks found stand) */
            break;
        }
        for (int k = 0; k < m; k++) rw->lam[k] = rw->next[k];
    }
}

double cluster_kick(world *w, const int *list, int n, double t, double t_end)
{
    for (int k = 0; k < n; k++) {
        w->answer.landing[list[k]] = -1;
        w->answer.kicks[list[k]].h = 0;
    }
    double h = d_min(SIM_CLUSTER_STEP, t_end - t);
    double s = fastest(w, list, n) + v3_len(world_accel(w)) * h;
    if (s * h > SIM_CLUSTER_MOVE) h = SIM_CLUSTER_MOVE / s;
    points pts;
    /* the points that could close within the step: its motion, twice over */
    gather(w, list, n, &pts, 2 * s * h);
    sort_closed(w, &pts, 0);
    if (pts.rows.n == 0 || !(h > 0)) return h;
    pts.rough = friction_any(pts.row, pts.rows.n);
    bool *mobile = w->answer.mark;
    for (int k = 0; k < n; k++) mobile[list[k]] = true;
    row_work *rw = w->answer.rw;
    for (int k = 0; k < 3 * pts.nclosed; k++) rw->lam[k] = 0;
    newton(w, list, n, &pts, t, h);
    /* an open point that lands within the step ends it there (answer.h), with the
     * kicks found again for the shorter step, so that no closed point is below
     * its floor there; with them it lands by the step's end, or a hair after
     * (then early in the next step) */
    int which;
    for (int again = 0; again < 3; again++) {
        double land = landing_time(w, list, n, &pts, rw->lam, t, h, &which);
        if (which < 0) break;
        bool found_again = land < t + h;
        h = land - t;
        if (again > 0 && !found_again) break;
        newton(w, list, n, &pts, t, h);
    }
    if (which >= 0) note_landing(w, &pts, which);
    /* the kicks, and what they gave each object (answer.h: an instant within
     * the step takes back the share not yet spent) */
    kick_record *rec = w->answer.kicks;
    for (int k = 0; k < n; k++) {
        const body *b = w->bodies[list[k]];
        rec[list[k]] = (kick_record){t, h, b->v, b->L};
    }
    apply_kicks(w, &pts, pts.nclosed, w->answer.now, rw->lam);
    for (int k = 0; k < n; k++) {
        const body *b = w->bodies[list[k]];
        kick_record *r = &rec[list[k]];
        r->dv = v3_sub(b->v, r->dv);
        r->dL = v3_sub(b->L, r->dL);
        mobile[list[k]] = false;
    }
    return h;
}

void cluster_settle(world *w, const int *list, int n)
{
    points pts;
    gather(w, list, n, &pts, 0);
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    /* the touching points, and the frictionless ones the steps keep closed:
     * they stop approaching (not a landing one, whose approach is a collision).
     * Stopping the kept points is what keeps a frictionless pile from gaining
     * energy (they would close in at every step's end).  At a rough point it is
     * not done: the friction solve there sticks points 1e-8 m apart, and the
     * next steps' cone solves then failed to converge (Bounce's first 100
     * frames: 148 unconverged solves and 4.4 times the instructions). */
    row_work *rw = w->answer.rw;
    impulse_row *rows = rw->sub;
    int m = 0;
    for (int k = 0; k < pts.rows.n; k++)
        if (pts.gap[k] <= touch_at(w, &pts.cp[k]) || (pts.row[k].mu == 0 && kept(w, &pts, k)))
            rows[m++] = pts.row[k];
    for (int k = 0; k < n; k++) mobile[list[k]] = true;
    for (int k = 0; k < m; k++) rw->u[k] = impulse_speed(&rows[k], bs);
    if (m > 0 && friction_any(rows, m)) {
        friction_flags f = {false, false, false};
        if (friction_compress(rows, m, bs, mobile, rw->u, rw->lam, w->answer.fw, &f) != 0)
            w->st.unsolved++;
        answer_count(w, f, list[0]);
    } else if (m > 0 &&
               impulse_solve_in(rows, m, bs, mobile, rw->u, rw->lam, rw->lcp, rw->A, rw->q, rw->wv) != 0) {
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
