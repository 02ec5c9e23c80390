/* rest.c: the contact state of objects on their supports (rest.h; thesis 3.3.3). */
#include "rest.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "contact.h"
#include "friction.h"
#include "impulse.h"
#include "pairs.h"
#include "rows.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* ---- who presses on whom ---- */

/* Walks the lasting contacts of object i: pr the pair, oth the other object. */
#define FOR_TOUCHING(w, i, pr, oth)                                                        \
    FOR_PAIRS_OF(w, i, link_, pr)                                                         \
        for (int oth = link_->other; pr && pr->touching; pr = NULL)

/* The objects reached from the seeds through lasting contacts, to objects that
 * qualify (dynamic; general when general_only). */
static int reach(world *w, const int *seeds, int n, int *out, bool general_only)
{
    bool *mark = w->answer.mark;
    int m = 0;
    for (int k = 0; k < n; k++) {
        if (mark[seeds[k]]) continue;
        mark[seeds[k]] = true;
        out[m++] = seeds[k];
    }
    for (int k = 0; k < m; k++) {
        int i = out[k];
        FOR_TOUCHING(w, i, p, o) {
            const body *b = w->bodies[o];
            if (mark[o] || body_is_static(b)) continue;
            if (general_only && (b->state != STATE_DYNAMIC || b->mode != MODE_GENERAL)) continue;
            mark[o] = true;
            out[m++] = o;
        }
    }
    for (int k = 0; k < m; k++) mark[out[k]] = false;
    return m;
}

int rest_component(world *w, const int *seeds, int n, int *out)
{
    return reach(w, seeds, n, out, false);
}

int rest_cluster(world *w, int seed, int *out)
{
    return reach(w, &seed, 1, out, true);
}

void rest_wake(world *w, int i)
{
    body *b = w->bodies[i];
    if (b->state == STATE_RESTING) b->state = STATE_DYNAMIC;
    b->mode = MODE_FREE;
    b->slide_on = -1;
}

/* ---- sliding ---- */

/* A slide on a face of the mover's own is levelled when it is at most this far
 * off flat (radians): the region they touch on is found within SIM_CONTACT_TOL. */
#define REST_LEVEL_TILT 1e-3

/* A lossy slide starts from at most this deep in (relative to the sizes, as
 * SIM_CONTACT_TOL), and from on the face. */
#define REST_LEVEL_DEPTH 1e-4

/* A slide goes on across a seam, onto a face of another static object, when the
 * two faces are coplanar within this angle (rad) and this offset (m); a centre of
 * mass on the seam that is short of the new face by no more than REST_SEAM_GAP
 * and moves onto it is over it. */
#define REST_SEAM_ANGLE 1e-9
#define REST_SEAM_GAP 1e-9

/* A point's height inside one edge of a face, in the face's plane, as it moves:
 * g0 + g1 tau + g2 tau^2 at tau from now. */
typedef struct {
    double g0, g1, g2;
} edge_gap;

/* The height of point c inside edge k of face F of hull h of static s (n the
 * face's normal), for a point moving at v with acceleration a.  (Inlined: a
 * slide's exit is asked for at every internal step.) */
static inline __attribute__((always_inline)) edge_gap gap_to_edge(const body *s, const poly *h,
                                                                  const poly_face *F, int k,
                                                                  vec3 n, vec3 c, vec3 v, vec3 a)
{
    vec3 p0 = v3_add(s->x, q_rotate(s->q, h->v[h->face_vert[F->first + k]]));
    vec3 p1 = v3_add(s->x, q_rotate(s->q, h->v[h->face_vert[F->first + (k + 1) % F->count]]));
    vec3 in = v3_norm(v3_cross(n, v3_sub(p1, p0))); /* into the face, across this edge */
    return (edge_gap){v3_dot(in, v3_sub(c, p0)), v3_dot(in, v), 0.5 * v3_dot(in, a)};
}

/* True when a point at g is past its edge: outside it, and not coming onto the
 * face across it from within REST_SEAM_GAP (a seam's other side). */
static bool past_edge(edge_gap g)
{
    if (g.g0 > 0) return false;
    bool entering = g.g1 > 0 || (g.g1 == 0 && g.g2 > 0);
    return !(entering && g.g0 >= -REST_SEAM_GAP);
}

/* Makes m, touching face `face` (normal n) of static s with friction (r the
 * closest result of m against s, thick the contact's thickness), move on it in
 * closed form (friction_face), if it nearly does already: its speed along n
 * and its turning that the closed form has not (a box's, a ball's about n and
 * across its line) are below tol, and are dropped (which adds no energy); on a
 * slope, a drift across the slope's line below tol is dropped too.  A box is
 * laid flat on the face, and must keep its centre of pressure inside the region
 * they touch on, or it tips (the clusters then take it).  True when it did. */
static bool try_face(world *w, body *m, const body *s, int si, int face, vec3 n,
                     const closest_result *r, double thick, double tol)
{
    body t = *m;
    double R = t.shape.r_out;
    if (fabs(v3_dot(t.v, n)) > tol) return false;
    vec3 g = world_accel(w), gt = v3_mad(g, n, -v3_dot(g, n));
    vec3 v = v3_mad(t.v, n, -v3_dot(t.v, n));
    if (v3_len(gt) > SIM_ACCEL_ROUND * (1 + R)) {
        vec3 down = v3_norm(gt), across = v3_mad(v, down, -v3_dot(v, down));
        if (v3_len(across) <= tol) v = v3_sub(v, across);
    }
    if (v3_len(v) <= SIM_SPEED_ROUND * (1 + R)) v = v3(0, 0, 0);
    t.v = v;
    double hover = tol_hover(m, s);
    t.x = v3_mad(t.x, n, hover - r->distance);
    int local;
    const poly *hf = shape_face(&s->shape, face, &local);
    vec3 on = v3_add(s->x, q_rotate(s->q, hf->v[hf->face_vert[hf->f[local].first]]));
    if (!friction_ball(&t)) {
        double wn = v3_dot(t.w, n);
        if (v3_len(v3_mad(t.w, n, -wn)) * R > tol) return false;
        body_set_angular_vel(&t, v3(0, 0, 0));
        if (!contact_level(&t, s, face, REST_LEVEL_TILT, hover)) return false;
        /* a spin about n is kept on a face of its own that the support's
         * holds wherever it turns (the circle its corners sweep inside): in
         * closed form at rest on a face centrally symmetric on a level face
         * (friction_face), else by friction over the face (facespin.h, level
         * or inclined), where it is above tol (below it, it is dropped, as
         * before that form) */
        bool inside = true, level = v3_len(gt) <= SIM_ACCEL_ROUND * (1 + R);
        const poly_face *F = &hf->f[local];
        for (int k = 0; k < F->count && inside; k++)
            inside = gap_to_edge(s, hf, F, k, n, body_com(&t), v, v3(0, 0, 0)).g0 > R;
        if (inside && wn != 0 && (fabs(wn) * R > tol || (level && v3_len(v) == 0 && contact_face_arm(&t, n) > 0)))
            body_set_angular_vel(&t, v3_scale(n, wn));
        else if (fabs(wn) * R > tol) return false;
    } else {
        if (fabs(v3_dot(t.w, n)) * R > tol) return false;
        vec3 wp = v3_mad(t.w, n, -v3_dot(t.w, n));
        if (v3_len(v) > 0) {
            vec3 e = v3_norm(v3_cross(n, v)), off = v3_mad(wp, e, -v3_dot(wp, e));
            if (v3_len(off) * R > tol) return false;
            wp = v3_scale(e, v3_dot(wp, e));
        }
        body_set_angular_vel(&t, wp);
    }
    t.rot_given = false;
    vec3 lean;
    face_motion fm = friction_face(&t, s, g, n, MODE_FREE, -1, &lean);
    if (fm.mode == MODE_GENERAL) return false;
    if (!friction_ball(&t)) {
        /* the centre of pressure, h lean from under the centre of mass (h its
         * height over the face) */
        int f2;
        double h = v3_dot(v3_sub(body_com(&t), on), n);
        if (!contact_holds_at(&t, s, r, thick, v3_scale(lean, h), &f2)) return false;
    }
    if (fm.mode == MODE_STICK) {
        t.v = v3(0, 0, 0);
        body_set_angular_vel(&t, v3(0, 0, 0));
    }
    body_copy_state(m, &t);
    m->mode = fm.mode;
    m->slide_on = si;
    m->slide_n = n;
    m->slide_face = face;
    return true;
}

/* Makes m slide on face `face` of static s, if that face holds it (see rest.h):
 * true when it did.  p the pair. */
static bool try_slide(world *w, int mi, int si, pair *p)
{
    body *m = w->bodies[mi];
    const body *s = w->bodies[si];
    double size = 1 + tol_size(m, s);
    bool rough = friction_mu(m, s) > 0;
    closest_result r = mi == p->a ? pair_query(w, p, m, s) : pair_query(w, p, s, m);
    if (r.status == CLOSEST_INVALID) return false;
    if (mi != p->a) closest_mirror(&r);
    double e = d_min(m->elasticity, s->elasticity);
    double thick = SIM_CONTACT_TOL * size, deep = e < 1 ? REST_LEVEL_DEPTH * size : thick;
    if (r.distance > thick || r.distance < -deep) return false;
    int face;
    if (!contact_holds(m, s, &r, thick, &face)) {
        return false;
    }
    int local;
    const poly *hf = shape_face(&s->shape, face, &local);
    vec3 n = v3_norm(q_rotate(s->q, hf->f[local].n));
    /* pressed onto the face, moving along it, turning about its normal only */
    if (!(v3_dot(world_accel(w), n) < -tol_accel(m, s))) return false;
    /* its centre of mass over the face, as rest_slide_exit sees it: else the
     * slide would end where it begins, and begin again (on a seam of two pieces
     * of one body, a centre of mass on the edge of the face the contact names) */
    const poly_face *F = &hf->f[local];
    for (int k = 0; k < F->count; k++)
        if (past_edge(gap_to_edge(s, hf, F, k, n, body_com(m), m->v, world_accel(w)))) return false;
    /* a lossy contact ends a rocking too slow to see as a rebound would (impulse's
     * SIM_BOUNCE_SPEED): it lands flat */
    double tol = e < 1 || rough ? SIM_BOUNCE_SPEED : 1e3 * tol_speed(m, s);
    if (rough) return try_face(w, m, s, si, face, n, &r, thick, tol);
    vec3 w_off = v3_mad(m->w, n, -v3_dot(m->w, n));
    if (fabs(v3_dot(m->v, n)) > tol || v3_len(w_off) * m->shape.r_out > tol) {
        return false;
    }
    /* flat on the face, so that a turn about its normal lifts no corner and sinks
     * none */
    double hover = tol_hover(m, s);
    m->x = v3_mad(m->x, n, hover - r.distance);
    contact_level(m, s, face, REST_LEVEL_TILT, hover);
    m->mode = MODE_SLIDE;
    m->slide_on = si;
    m->slide_n = n;
    m->slide_face = face;
    m->v = v3_mad(m->v, n, -v3_dot(m->v, n));
    body_set_angular_vel(m, v3_scale(n, v3_dot(m->w, n)));
    m->rot_given = false;
    return true;
}

void rest_classify(world *w, const int *list, int n)
{
    int *work = w->answer.classify, nw = 0;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        body *b = w->bodies[i];
        if (body_is_static(b) || b->held) continue; /* (a held one: free, hold.h) */
        if (b->state == STATE_RESTING) b->state = STATE_DYNAMIC;
        int count = 0, other = -1;
        pair *touch = NULL;
        FOR_TOUCHING(w, i, p, o) {
            count++;
            other = o;
            touch = p;
        }
        b->slide_on = -1;
        if (count == 0) b->mode = MODE_FREE;
        else if (count == 1 && body_is_static(w->bodies[other]) && try_slide(w, i, other, touch)) {
        } else {
            b->mode = MODE_GENERAL;
            work[nw++] = i;
        }
    }
    /* whatever presses on a general object is general with it */
    for (int k = 0; k < nw; k++) {
        int i = work[k];
        FOR_TOUCHING(w, i, p, o) {
            body *b = w->bodies[o];
            if (body_is_static(b) || (b->state == STATE_DYNAMIC && b->mode == MODE_GENERAL)) continue;
            b->state = STATE_DYNAMIC;
            b->mode = MODE_GENERAL;
            b->slide_on = -1;
            work[nw++] = o;
        }
    }
}

/* The first tau > 0 at which g0 + g1 tau + g2 tau^2 (g0 >= 0) turns negative, or
 * HUGE_VAL. */
static double first_below(double g0, double g1, double g2)
{
    if (g2 == 0) return g1 < 0 ? -g0 / g1 : HUGE_VAL;
    double r1, r2, best = HUGE_VAL;
    if (!quad_roots(g2, g1, g0, &r1, &r2)) return HUGE_VAL;
    if (r1 > 0) best = r1;
    if (r2 > 0 && r2 < best) best = r2;
    return best;
}

double rest_slide_exit(const world *w, int i, double t)
{
    const body *m = w->bodies[i];
    if (m->state != STATE_DYNAMIC || !body_mode_on_face(m->mode) || m->slide_on < 0) return HUGE_VAL;
    const flight *f = &w->step.fl[i];
    if (f->kind != FLIGHT_SLIDE && f->kind != FLIGHT_ROLL && f->kind != FLIGHT_SPIN) return HUGE_VAL;
    /* a spinning one's face stays on the support's while its centre of mass
     * keeps its reach from the edges (try_face); its path is bounded by the
     * parabola of its step's mean acceleration */
    double keep = f->kind == FLIGHT_SPIN ? m->shape.r_out : 0;
    const body *s = w->bodies[m->slide_on];
    int face;
    const poly *h = shape_face(&s->shape, m->slide_face, &face);
    if (!h) return HUGE_VAL;
    double h0 = t - f->t0;
    /* (it goes no further once it stops: its stop is its event) */
    double left = f->t_stop - h0, stop = f->t_stop < HUGE_VAL ? d_max(t, f->t0 + f->t_stop) : HUGE_VAL;
    if (left < 0) h0 = f->t_stop;
    vec3 c = v3_add(f->c0, v3_add(v3_scale(f->v0, h0), v3_scale(f->a, 0.5 * h0 * h0)));
    vec3 v = left > 0 ? v3_mad(f->v0, f->a, h0) : v3(0, 0, 0), n = m->slide_n;
    vec3 a = left > 0 ? f->a : v3(0, 0, 0);
    const poly_face *F = &h->f[face];
    double best = HUGE_VAL;
    for (int k = 0; k < F->count; k++) {
        edge_gap g = gap_to_edge(s, h, F, k, n, c, v, a);
        g.g0 -= keep;
        if (past_edge(g)) return t; /* over the edge already */
        best = d_min(best, first_below(d_max(g.g0, 0), g.g1, g.g2));
    }
    return best == HUGE_VAL || best > left ? stop : d_min(stop, t + best);
}

bool rest_face_stop(world *w, int i)
{
    body *m = w->bodies[i];
    const flight *f = &w->step.fl[i];
    if (!(f->t_stop < HUGE_VAL) || w->time < f->t0 + f->t_stop) return false;
    /* a spinning one's step: it goes on from the next (retime_object), or,
     * where none could be taken, it tips: the clusters take it */
    if (f->kind == FLIGHT_SPIN && f->step.more) return true;
    /* on a slope steeper than friction holds, its spin gone (below 1e-9 m/s
     * at its reach): dropped, it slides on down in closed form */
    if (f->kind == FLIGHT_SPIN && f->step.slides && !f->step.tips) {
        body_set_angular_vel(m, v3(0, 0, 0));
        m->rot_given = false;
        rest_classify(w, &i, 1);
        return true;
    }
    if (f->kind == FLIGHT_SPIN && f->step.tips) {
        m->mode = MODE_GENERAL;
        m->slide_on = -1;
        return true;
    }
    /* where the closed form ended, exactly: a box, or a rolling ball, still; a
     * sliding ball rolling */
    if (f->closed) {
        if (m->mode == MODE_SLIDE && friction_ball(m))
            body_set_angular_vel(m, v3_scale(v3_cross(m->slide_n, m->v), 1 / m->shape.r_out));
        else {
            m->v = v3(0, 0, 0);
            body_set_angular_vel(m, v3(0, 0, 0));
        }
        m->rot_given = false;
    }
    rest_classify(w, &i, 1);
    return true;
}

bool rest_slide_on(world *w, int i)
{
    body *m = w->bodies[i];
    int from = m->slide_on;
    /* (a spinning one leaves its face where its reach does: the clusters take
     * it there) */
    if (w->step.fl[i].kind == FLIGHT_SPIN) return false;
    const body *s = w->bodies[from];
    int local;
    const poly *h = shape_face(&s->shape, m->slide_face, &local);
    if (!h) return false;
    vec3 n = m->slide_n, c = body_com(m), a = w->step.fl[i].a;
    vec3 on = v3_add(s->x, q_rotate(s->q, h->v[h->face_vert[h->f[local].first]]));
    FOR_PAIRS_OF(w, i, link, p) {
        const body *o = w->bodies[link->other];
        const poly *ho = o->shape.hull;
        /* (not across the seams of a body of several pieces: it leaves its face
         * and lands on the next as on another object) */
        if (link->other == from || !body_is_static(o) || !ho || o->sp.kind == SHAPE_SPHERE ||
            body_compound(o))
            continue;
        /* its face that way: coplanar with this one */
        int face = contact_facing(o, n);
        const poly_face *F = &ho->f[face];
        vec3 n2 = v3_norm(q_rotate(o->q, F->n));
        vec3 on2 = v3_add(o->x, q_rotate(o->q, ho->v[ho->face_vert[F->first]]));
        if (!(v3_dot(n2, n) > 0) || v3_len(v3_cross(n2, n)) > REST_SEAM_ANGLE ||
            fabs(v3_dot(v3_sub(on2, on), n)) > REST_SEAM_GAP)
            continue;
        /* the centre of mass over it (or coming onto it), pressed onto it */
        bool over = true;
        for (int k = 0; k < F->count && over; k++) over = !past_edge(gap_to_edge(o, ho, F, k, n2, c, m->v, a));
        if (!over || !(v3_dot(world_accel(w), n2) < -tol_accel(m, o))) continue;
        /* it slides on that face from here, the hover gap above it */
        long old = pair_index(w, i, from);
        if (old >= 0) w->pairs.p[old].touching = false;
        p->touching = true;
        closest_result r = pair_query(w, p, w->bodies[p->a], w->bodies[p->b]);
        pair_hit_from_query(w, p);
        if (r.status != CLOSEST_INVALID) m->x = v3_mad(m->x, n2, tol_hover(m, o) - r.distance);
        m->slide_on = link->other;
        m->slide_face = face;
        if (n2.x != n.x || n2.y != n.y || n2.z != n.z) {
            /* (along it, turning about its normal only) */
            m->slide_n = n2;
            m->v = v3_mad(m->v, n2, -v3_dot(m->v, n2));
            body_set_angular_vel(m, v3_scale(n2, v3_dot(m->w, n2)));
            m->rot_given = false;
        }
        return true;
    }
    return false;
}

/* ---- balance and rest ---- */

/* With friction, a slow object is held by the points of its hull within this
 * of its supports (relative to the sizes, as SIM_CONTACT_TOL), not only by
 * those in contact: a curved bottom's facets (a pillow's) rock among vertices
 * a fraction of a millimetre apart in height, and on its lowest vertex alone
 * no balance holds it, so that it rocked for good.  Without friction the
 * points in contact only, as before. */
#define REST_SUPPORT_DEPTH 1e-3

/* Pushes of a balance, at most: rolling resistance's couples and the supports'
 * pushes taking turns (rest_balanced); a ball on one point is held after one,
 * and objects pressed on several, whose couples are only near what they need,
 * after a few more. */
#define REST_ROLL_ROUNDS 100

/* The supports push the copies of rest_balanced (w->answer.now) at the nr points
 * of rows, with friction when rough (the cone solve's impulses in
 * friction_problem_of(w->answer.fw, nr).z), or along the normals: false when
 * that has no answer.  A push again (rough only: a round of rolling
 * resistance's couples) starts from the last push's impulses: the couples
 * change the speeds little, and a cone solve started from nothing each round
 * stopped short of its tolerance on a row of rough balls pressed end to end
 * (300 sweeps and the polish), leaving ~5e-6 of noise against still's 1e-6,
 * where one started from the last answer converges at once. */
static bool push(world *w, const impulse_row *rows, int nr, bool rough, bool again)
{
    body **bs = w->answer.now;
    row_work *rw = w->answer.rw;
    for (int k = 0; k < nr; k++) rw->u[k] = impulse_speed(&rows[k], bs);
    if (rough) {
        friction_flags f = {false, false, false};
        if (again) return friction_compress_again(nr, bs, w->answer.mark, rw->u, rw->lam, w->answer.fw, &f) == 0;
        return friction_compress(rows, nr, bs, w->answer.mark, rw->u, rw->lam, w->answer.fw, &f) == 0;
    }
    return impulse_solve_in(rows, nr, bs, w->answer.mark, rw->u, rw->lam, rw->lcp, rw->A, rw->q, rw->wv) == 0;
}

/* True when copy c is left still by its supports' push: moving and turning at
 * no more than the rounding of the force's second. */
static bool still(const body *c)
{
    double scale = 1 + c->shape.r_out;
    return v3_len(c->v) + v3_len(c->w) * c->shape.r_out <= 1e3 * SIM_ACCEL_ROUND * scale;
}

/* The copies of the n objects of list (w->answer.balanced, referenced from
 * w->answer.now), each moving as the force alone would make it in a second, and
 * turning as the couples M (three an object of list; NULL: none) would. */
static void push_copies(world *w, const int *list, int n, const double *M)
{
    for (int k = 0; k < n; k++) {
        int i = list[k];
        body *c = &w->answer.balanced[i];
        *c = *w->bodies[i];
        c->v = world_accel(w);
        c->L = M ? v3(M[3 * k], M[3 * k + 1], M[3 * k + 2]) : v3(0, 0, 0);
        body_update_w(c);
        w->answer.now[i] = c;
    }
}

/* What rolling resistance lets object i of the push resist: c r N summed over
 * its points that stick (friction_roll's law, friction.h), N and sticking from
 * the push's impulses z at the nr points of rows.  With dir (a unit axis;
 * NULL: none), *over gets how many times more than its turning about dir a
 * couple must be to stop it (roll_couples), HUGE_VAL without such a point. */
static double roll_can(const body *b, int i, const impulse_row *rows, int nr, const double *z, const vec3 *dir,
                       double *over)
{
    double can = 0, inertia = dir ? v3_dot(m3_mulv(body_inertia_world(b), *dir), *dir) : 0;
    if (over) *over = HUGE_VAL;
    for (int j = 0; j < nr; j++) {
        const double *zj = &z[3 * j];
        if ((rows[j].p != i && rows[j].q != i) || !(zj[0] > 0)) continue;
        if (!(hypot(zj[1], zj[2]) < rows[j].mu * zj[0] * (1 - 1e-9))) continue;
        can += rows[j].roll * v3_dist(rows[j].at, body_com(b)) * zj[0];
        if (!dir) continue;
        vec3 arm = v3_cross(*dir, v3_sub(body_com(b), rows[j].at));
        *over = d_min(*over, 1 + b->mass * v3_len2(arm) / inertia);
    }
    return can;
}

/* Rolling resistance's couples M (three an object of list) after a push that
 * left the copies turning: each object's less what it is left turning (its
 * copy's angular momentum after the second), so as to stop that, where that
 * is within what it resists (roll_can).  True when some couple changed.  (The
 * couples only grow towards what holds.  One that must pass that is left as
 * it was this round, not given up on: in a row of rough balls pressed end to
 * end, a ball wedged up between two others slips on both before its
 * neighbours' couples hold them, and so resists nothing at first, though
 * it turns by no more than the rounding; the balance still fails unless a
 * push leaves every copy still with each couple within what it resists then,
 * couples_hold.) */
static bool roll_couples(world *w, const int *list, int n, const impulse_row *rows, int nr, double *M)
{
    const double *z = friction_problem_of(w->answer.fw, nr).z;
    bool changed = false;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        vec3 m0 = v3(M[3 * k], M[3 * k + 1], M[3 * k + 2]), left = w->answer.now[i]->L;
        double len = v3_len(left), over;
        if (!(len > 0)) continue;
        vec3 dir = v3_scale(left, 1 / len);
        double can = roll_can(w->bodies[i], i, rows, nr, z, &dir, &over);
        /* turning about a stuck point, it answers a couple as its inertia
         * about that point, not about its centre of mass: so much more is
         * needed to stop it (a ball: 7/2 times; the least of its points',
         * so as not to overshoot) */
        vec3 m = v3_mad(m0, left, -(over < HUGE_VAL ? over : 1));
        if (v3_len(m) > can) continue;
        changed = changed || v3_dist(m, m0) > 0;
        M[3 * k] = m.x, M[3 * k + 1] = m.y, M[3 * k + 2] = m.z;
    }
    return changed;
}

/* True when each couple of M (roll_couples') is within what its object resists
 * after the last push (roll_can at its impulses). */
static bool couples_hold(world *w, const int *list, int n, const impulse_row *rows, int nr, const double *M)
{
    const double *z = friction_problem_of(w->answer.fw, nr).z;
    for (int k = 0; k < n; k++) {
        double len = v3_len(v3(M[3 * k], M[3 * k + 1], M[3 * k + 2]));
        if (len > 0 && len > roll_can(w->bodies[list[k]], list[k], rows, nr, z, NULL, NULL)) return false;
    }
    return true;
}

bool rest_balanced(world *w, const int *list, int n)
{
    /* each object's copy moves as the force alone would make it in a second, and
     * the supports push: what is left is its acceleration */
    body **bs = w->answer.now;
    bool *mobile = w->answer.mark;
    row_work *rw = w->answer.rw;
    row_list rl = {rw->sub, NULL, NULL, 0, rw->cap, false};
    bool ok = true;
    push_copies(w, list, n, NULL);
    for (int k = 0; k < n; k++) mobile[list[k]] = true;
    for (int k = 0; k < n && ok; k++) {
        int i = list[k];
        FOR_TOUCHING(w, i, p, o) {
            if (mobile[o] && o < i) continue; /* each pair once */
            const body *A = w->bodies[p->a], *B = w->bodies[p->b];
            closest_result r = pair_query(w, p, A, B);
            double depth = friction_mu(A, B) > 0 ? d_max(tol_contact(A, B), REST_SUPPORT_DEPTH * tol_size(A, B))
                                                 : tol_contact(A, B);
            /* (room for every point: a crowd's balance has hundreds) */
            ok = rows_room(rw, rl.n + CONTACT_MAX_POINTS, 0) == 0;
            rl.row = rw->sub;
            rl.cap = rw->cap;
            rows_add(&rl, p, A, B, &r, depth, 0, w->bodies);
            ok = ok && !rl.full;
        }
    }
    int nr = rl.n;
    impulse_row *rows = rw->sub;
    bool rough = nr > 0 && friction_any(rows, nr);
    ok = ok && nr > 0 && push(w, rows, nr, rough, false);
    /* Those the push leaves turning may yet be held by rolling resistance: a
     * couple of up to c r N at each point that sticks (friction.h).  A couple
     * that stops an object's turning about its centre of mass leaves it
     * sliding over its stuck points, which the supports turn again (a ball:
     * 5/7 of it): so each object's couple grows by what it is left turning and
     * the supports push again, until all are still (held: a ball on a slope
     * where tan th <= c, its couple m g r sin th, each couple within what its
     * points then resist) or no couple can grow within what its points
     * resist.  The couples are kept in rw->A (three an object; A is cap x
     * cap). */
    bool held = ok;
    for (int k = 0; k < n && held; k++) held = still(bs[list[k]]);
    if (ok && !held && rough && 3 * n <= rw->cap * rw->cap) {
        double *M = rw->A;
        for (int k = 0; k < 3 * n; k++) M[k] = 0;
        for (int round = 0; round < REST_ROLL_ROUNDS && ok && !held; round++) {
            if (!roll_couples(w, list, n, rows, nr, M)) break;
            push_copies(w, list, n, M);
            ok = push(w, rows, nr, rough, true);
            held = ok;
            for (int k = 0; k < n && held; k++) held = still(bs[list[k]]);
        }
        held = held && couples_hold(w, list, n, rows, nr, M);
    }
    for (int k = 0; k < n; k++) {
        bs[list[k]] = w->bodies[list[k]];
        mobile[list[k]] = false;
    }
    return ok && held;
}

/* The speed of b's fastest point, near enough: |v| + |w| R. */
static double speed_of(const body *b)
{
    return v3_len(b->v) + v3_len(b->w) * b->shape.r_out;
}

/* True when some lasting contact of object i loses energy (e < 1, or friction). */
static bool lossy(world *w, int i)
{
    FOR_TOUCHING(w, i, p, o) {
        const body *a = w->bodies[i], *b = w->bodies[o];
        if (d_min(a->elasticity, b->elasticity) < 1 || friction_mu(a, b) > 0) return true;
    }
    return false;
}

/* (one stuck on a face keeps its mode and its support: they are its state) */
static void come_to_rest(body *b)
{
    b->state = STATE_RESTING;
    if (b->mode != MODE_STICK) {
        b->mode = MODE_FREE;
        b->slide_on = -1;
    }
    b->v = b->L = b->w = v3(0, 0, 0);
}

int rest_frame_end(world *w)
{
    int count = 0, *list = w->answer.cluster;
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (b->state != STATE_DYNAMIC || b->mode == MODE_FREE) continue;
        double speed = speed_of(b);
        if (b->mode == MODE_STICK) {
            come_to_rest(b);
            count++;
            continue;
        }
        /* (with friction, a slide and a roll end at their own stops, exactly) */
        if (b->mode == MODE_ROLL ||
            (b->mode == MODE_SLIDE && b->slide_on >= 0 && friction_mu(b, w->bodies[b->slide_on]) > 0))
            continue;
        if (b->mode == MODE_SLIDE) {
            double scale = 1 + b->shape.r_out;
            bool level = v3_len(world_body_accel(w, b)) <= SIM_ACCEL_ROUND * scale;
            if (level && speed < SIM_REST_SPEED && (speed == 0 || lossy(w, i))) {
                come_to_rest(b);
                count++;
            }
            continue;
        }
        /* a cluster, from its first object */
        int m = rest_cluster(w, i, list);
        bool first = true, slow = true, loses = false;
        for (int k = 0; k < m; k++) {
            if (list[k] < i) first = false;
            slow = slow && speed_of(w->bodies[list[k]]) < SIM_REST_SPEED;
            loses = loses || speed_of(w->bodies[list[k]]) == 0 || lossy(w, list[k]);
        }
        if (!first || !slow || !loses || !rest_balanced(w, list, m)) continue;
        for (int k = 0; k < m; k++) come_to_rest(w->bodies[list[k]]);
        count += m;
    }
    return count;
}
