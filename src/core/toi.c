/* toi.c: the first contact of a pair within an internal step (toi.h). */
#include "toi.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "contact.h"
#include "envelope.h"
#include "flight.h"
#include "schedule.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* Searches a pair may make in one internal step before it gives up on a grazing
 * run (the objects pass within the contact distance without meeting). */
#define TOI_MAX_QUERIES 100000

/* The points' bound (envelope.h) is looked for only when the surfaces' bound
 * advances less than this fraction of the time left to search (a speed-up alone:
 * both bounds are never late). */
#define TOI_ENVELOPE_WHEN 0.05

/* A vertex of feature f of hull h (its closest feature: near its lowest point
 * along the normal), or -1. */
static int feature_vertex(const poly *h, closest_feature f)
{
    if (f.kind == CLOSEST_VERTEX && f.index >= 0 && f.index < h->nv) return f.index;
    if (f.kind == CLOSEST_EDGE && f.index >= 0 && f.index < h->ne) return h->e[f.index].v[0];
    if (f.kind == CLOSEST_FACE && f.index >= 0 && f.index < h->nf) return h->face_vert[h->f[f.index].first];
    return -1;
}

/* The points of o (moving as mo) along side * n, from world point p, as lines of
 * time (envelope.h): a ball's lowest point, or every vertex's (walked on a large
 * hull); and *quad, the most their second derivative can take off them over t^2
 * (the centre's acceleration along side * n exactly, less a turn's w^2 R +
 * |dw/dt| R, |dw/dt| <= w^2 for a free body; for a held one, turning at a constant
 * w about its pivot, w^2 R with R its reach).  Returns 0,
 * or -1 when o has too many vertices to read and no closest data to walk. */
static int side_of(const body *o, const sched_move *mo, vec3 n, double side, vec3 p, closest_feature near,
                   env_side *out, double *quad)
{
    vec3 sn = v3_scale(n, side);
    vec3 v = mo->moves ? mo->v : v3(0, 0, 0), c = body_com(o);
    *quad = mo->moves ? 0.5 * v3_dot(mo->a, sn) - mo->rate * mo->rate * mo->reach : 0;
    if (o->sp.kind == SHAPE_SPHERE) {
        *out = (env_side){.hull = NULL, .near = -1};
        if (mo->held) { /* its centre goes round the pivot */
            out->h0 = v3_dot(v3_sub(c, p), sn) - o->sp.radius;
            out->h1 = v3_dot(o->v, sn);
            *quad = -mo->rate * mo->rate * v3_len(v3_sub(c, mo->c));
            return 0;
        }
        out->h0 = v3_dot(v3_sub(c, p), sn) - o->sp.radius;
        out->h1 = v3_dot(v, sn);
        *quad = mo->moves ? 0.5 * v3_dot(mo->a, sn) : 0; /* it turns into itself */
        return 0;
    }
    const poly *h = o->shape.hull;
    if (!h || (h->nv > ENV_FLAT_VERTICES && !o->shape.feat)) return -1;
    vec3 w = mo->moves ? o->w : v3(0, 0, 0);
    if (mo->held) c = mo->c; /* its points turn about the pivot, which moves at v */
    /* a vertex at x = o->x + R y: its height (x - p).sn and its speed along sn,
     * (v + w x (x - c)).sn = v.sn + (x - c).(sn x w), are each a constant plus y
     * dotted with a direction of the body's own frame */
    vec3 sw = v3_cross(sn, w);
    *out = (env_side){.h0 = v3_dot(v3_sub(o->x, p), sn),
                      .h1 = v3_dot(v, sn) + v3_dot(v3_sub(o->x, c), sw),
                      .dh0 = q_unrotate(o->q, sn),
                      .dh1 = q_unrotate(o->q, sw),
                      .hull = h,
                      .feat = o->shape.feat,
                      .near = feature_vertex(h, near)};
    return 0;
}

/* The time, never late, before which a (moving as ma) and b (mb) cannot close
 * their gap along r's normal (from b to a) down to target: the lowest of
 * a's points along n less the highest of b's, each point's height bounded by its
 * own rate now and the most it can accelerate.  Sharper than the surfaces' bound
 * as a whole (|w| R) when the points that meet close slowly, as a box settling
 * onto an edge does; valid whatever n is, and whatever the rounding of the
 * closest points it came from (a walk starts from r's features).  HUGE_VAL when
 * not within T, -1 when either has too many vertices and no closest data. */
static double envelope_time(const body *a, const sched_move *ma, const body *b,
                            const sched_move *mb, const closest_result *r, double target, double T)
{
    env_side sa, sb;
    double qa, qb;
    if (side_of(a, ma, r->normal, 1, r->pb, r->fa, &sa, &qa) < 0 ||
        side_of(b, mb, r->normal, -1, r->pb, r->fb, &sb, &qb) < 0)
        return -1;
    return env_first_time(&sa, &sb, qa + qb, target, tol_margin(a, b), T, NULL);
}

/* How a (moving as ma) and b (mb), touching with closest result r, meet there: 1
 * when some point of their contact region closes (approach) or is pressed together
 * (the relative acceleration along the normal closes), else 0.  (Bodies of
 * several pieces: at the pair of pieces r names alone.) */
static int meeting(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                   const closest_result *r, double tol)
{
    cpoint cp[CONTACT_MAX_POINTS];
    int n = contact_cpoints_of_pieces(a, b, r, tol, cp, CONTACT_MAX_POINTS);
    flight_motion fa = flight_motion_of(a, ma->moves, ma->a, ma->held ? &ma->c : NULL);
    flight_motion fb = flight_motion_of(b, mb->moves, mb->a, mb->held ? &mb->c : NULL);
    double su = tol_speed(a, b), sc = tol_accel(a, b);
    for (int k = 0; k < n; k++) {
        const body *P = cp[k].p == 0 ? a : b, *Q = cp[k].p == 0 ? b : a;
        const flight_motion *fp = cp[k].p == 0 ? &fa : &fb, *fq = cp[k].p == 0 ? &fb : &fa;
        vec3 nrm, at;
        cpoint_eval(&cp[k], P, Q, &nrm, &at);
        double u = v3_dot(v3_sub(flight_point_velocity(fp, at), flight_point_velocity(fq, at)), nrm);
        double c = v3_dot(v3_sub(flight_point_accel(fp, at), flight_point_accel(fq, at)), nrm);
        if (u < -su || (u <= su && c < -sc))
            return 1;
    }
    return 0;
}

/* The time, never late, before which a and b, d apart, cannot close their gap to
 * target whatever the direction: their points' relative speed is at most the
 * centres' |v_a - v_b| and each turn's rate R, and grows by at most the centres'
 * |a_a - a_b| and 2 rate^2 R each a second.  For bodies of several pieces, whose
 * nearest pieces change as they move: a bound along the normal of the nearest
 * (the schedule's) holds only for convex shapes. */
static double any_way_time(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                           double d, double target)
{
    double goal = d - target - tol_margin(a, b);
    if (!(goal > 0)) return 0;
    vec3 va = ma->moves ? ma->v : v3(0, 0, 0), vb = mb->moves ? mb->v : v3(0, 0, 0);
    vec3 aa = ma->moves ? ma->a : v3(0, 0, 0), ab = mb->moves ? mb->a : v3(0, 0, 0);
    double ra = ma->moves ? ma->rate : 0, rb = mb->moves ? mb->rate : 0;
    double s = v3_len(v3_sub(va, vb)) + ra * ma->reach + rb * mb->reach;
    double acc = v3_len(v3_sub(aa, ab)) + 2 * (ra * ra * ma->reach + rb * rb * mb->reach);
    /* goal = s t + acc t^2 / 2: the positive root, in the stable form */
    if (!(s > 0) && !(acc > 0)) return HUGE_VAL;
    double t = 2 * goal / (s + sqrt(s * s + 2 * acc * goal));
    return t * (1 - 1e-12);
}

/* The time, never late, before which a and b (distance d apart, closest result
 * r) cannot close their gap down to target: the later of the schedule's bound
 * and the points' (envelope_time), looked for within T. */
static double advance(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                      const closest_result *r, double d, const pieces_near *near, double target,
                      double T)
{
    if (!(d > target)) return 0;
    /* bodies of several pieces: each pair of pieces the query met as two convex
     * bodies, the others (no nearer than near->others) whatever their direction */
    double dt_near = HUGE_VAL;
    for (int k = 0; near && k < near->n; k++) {
        const closest_result *q = &near->r[k];
        body tq, tr;
        const body *qa = pieces_view(a, q->ka, &tq), *qb = pieces_view(b, q->kb, &tr);
        if (q->status != CLOSEST_SEPARATED || !(q->distance > target)) return 0;
        dt_near = d_min(dt_near, sched_ca_time(qa, ma, qb, mb, q->distance, q->normal, q->pa, q->pb, target));
    }
    if (near && near->others < HUGE_VAL)
        dt_near = d_min(dt_near, any_way_time(a, ma, b, mb, near->others, target));
    body ta, tb;
    if (near) { /* (only bodies of several pieces have them) */
        a = pieces_view(a, r->ka, &ta);
        b = pieces_view(b, r->kb, &tb);
    }
    double dt = sched_ca_time(a, ma, b, mb, d, r->normal, r->pa, r->pb, target);
    /* the points' bound costs a pass over their vertices: only where the surfaces'
     * would crawl (a twentieth of what is left to search, or less) */
    if (dt < TOI_ENVELOPE_WHEN * T)
        dt = d_max(dt, envelope_time(a, ma, b, mb, r, target, T));
    return d_min(dt, dt_near);
}

/* A search of a pair in lasting contact (its bodies of several pieces: pieces.h)
 * leaves out the pairs of pieces that touch as it begins (within the contact
 * region's thickness: a lasting contact hovers above it): the contact forces
 * keep those; it looks for another of their pieces meeting.  Marks them held. */
static void held_pieces(world *w, const toi_input *in, piece_pairs *pp, double touch)
{
    long k = pair_index(w, in->a, in->b);
    bool lasting = k >= 0 && w->pairs.p[k].touching;
    if (lasting) {
        const body *a = step_flown(w, in->a, in->lo, 0), *b = step_flown(w, in->b, in->lo, 0);
        pieces_hold(a, b, pp, d_max(touch, tol_contact(a, b)));
        return;
    }
    for (int t = 0; t < pp->n; t++) pp->e[t].held = false;
}

toi_output toi_find(world *w, const toi_input *in)
{
    assert(in->a != in->b && in->lo <= in->hi);
    toi_output out = {.state = TOI_NONE, .t = HUGE_VAL, .queries = 0};
    closest_cache cache = in->cache;
    double t = in->lo;
    const body *A0 = w->bodies[in->a], *B0 = w->bodies[in->b];
    piece_pairs *pp = in->pieces && in->pieces->n > 0 ? in->pieces : NULL;
    for (int k = 0; pp && k < pp->n; k++) pp->e[k].found = pp->e[k].hit;
    double touch = tol_touch(A0, B0);
    if (pp) held_pieces(w, in, pp, touch);
    double depth0 = 0; /* how deep in the pair was when first found in (by rounding) */
    while (out.queries < TOI_MAX_QUERIES) {
        const body *a = step_flown(w, in->a, t, 0), *b = step_flown(w, in->b, t, 0);
        pieces_near near_, *near = pp ? &near_ : NULL;
        closest_result r = pp ? pieces_distance_near(a, b, pp, PIECES_SEARCH, false, near)
                              : body_distance_apart(a, b, &cache);
        out.queries++;
        if (r.status == CLOSEST_INVALID) return out;
        sched_move ma = step_move(w, in->a, a), mb = step_move(w, in->b, b);
        double d = r.status == CLOSEST_SEPARATED ? r.distance : 0, target = 0.5 * touch, inside = 0;
        if (d <= touch) {
            if (r.status != CLOSEST_SEPARATED) {
                /* the normal, with the depth */
                r = pp ? pieces_distance_near(a, b, pp, PIECES_SEARCH, true, near)
                       : body_distance(a, b, &cache);
                out.queries++;
            }
            if (meeting(a, &ma, b, &mb, &r, tol_region(a, b, r.distance))) {
                out.state = TOI_HIT;
                out.t = t;
                out.r = r;
                out.cache = cache;
                return out;
            }
            /* they graze, or part from a little way in: on, until they part or meet */
            target = 0.5 * d;
            if (r.status != CLOSEST_SEPARATED) {
                inside = -r.distance;
                depth0 = d_max(depth0, inside);
            }
        }
        double dt = advance(a, &ma, b, &mb, &r, d, near, target, in->hi - t);
        if (!(t + dt > t)) {
            /* apart by less than rounding, not meeting: the time to move a contact
             * distance at their relative speed */
            double s = v3_len(v3_sub(ma.moves ? ma.v : v3(0, 0, 0), mb.moves ? mb.v : v3(0, 0, 0)));
            double depth = d_max(touch, d_max(inside, 0.1 * depth0));
            double turn = ma.rate * A0->shape.r_out + mb.rate * B0->shape.r_out;
            if (ma.held || mb.held) turn = ma.rate * ma.reach + mb.rate * mb.reach;
            dt = depth / d_max(s + turn, 1e-3);
        }
        double nt = t + dt;
        nt = nt > t ? nt : nextafter(t, HUGE_VAL);
        if (!(nt <= in->hi)) {
            /* apart through hi; they cannot touch before their gap could close to
             * the contact distance (not the search's half of it: that is where it
             * would look next) */
            double key = d > touch ? t + advance(a, &ma, b, &mb, &r, d, near, touch, HUGE_VAL) : t;
            out.t = d_max(key, nextafter(in->hi, HUGE_VAL));
            return out;
        }
        t = nt;
    }
    out.t = nextafter(in->hi, HUGE_VAL); /* (a guard: never reached in the tests) */
    return out;
}
