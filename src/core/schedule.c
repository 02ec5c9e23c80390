/* schedule.c: expected collision times and the collision heap (thesis 3.3.1.1 and
 * 3.3.1.2; design.md, "Schedule").
 *
 * The bound on how far two objects can close in t seconds is the sum over the
 * moving ones of
 *   min(|v| t + |a| t^2 / 2, max_linear t)   (the centre of mass: vroc integrates
 *                                             x += v h + a h^2/2 and clamps the
 *                                             step to max_linear h, so no step
 *                                             goes further)
 * + min(R - r, w_max R t)                    (the surface turning about the centre:
 *                                             a convex body stays between its
 *                                             inscribed and circumscribed spheres)
 * with w_max = 3 |L| / I_min, which bounds how far vroc's rotation integrator turns
 * a body per second for any inertia tensor (see spin_bound).  The bound grows with
 * t and is quadratic between a few breakpoints, so the earliest time is the root
 * of a quadratic on the right piece, taken from below and checked: the time
 * returned is never later than the true one.
 */
#include "schedule.h"


#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world.h"

/* Relative margins for rounding: a distance or a reach is taken SCHED_ROUND of
 * the sizes involved short (or long), and a time found is taken SCHED_EARLY of
 * itself early, then SCHED_ROUND earlier until the bound checks out. */
#define SCHED_ROUND 1e-9
#define SCHED_EARLY 1e-12

/* A bound on how fast the body's points turn about its centre of mass, rad/s, as
 * vroc integrates rotation: each step is five rotations about principal axes by
 * angles of at most |L| / I_min times their share of the step (1/2, 1/2, 1, 1/2,
 * 1/2), so the body turns by at most 3 |L| / I_min per second of steps; a
 * symmetric top turns about L at |L| / I_p and about its axis at no more than
 * |L| / I_min, 2 |L| / I_min in all (flight.c, rotate_free). */
static double spin_bound(const body *b)
{
    double imin = d_min(b->I_princ.x, d_min(b->I_princ.y, b->I_princ.z));
    return imin > 0 ? 3 * v3_len(b->L) / imin : 0;
}

/* Body b's part of the bound; its turn at the rate its spin allows, or, with
 * whole set, by all of R - r at once when turn says it counts (whatever its spin). */
static sched_reach terms_of(const body *b, double acc, double vmax, double slack, bool whole,
                            bool turn)
{
    sched_reach r;
    r.s = v3_len(b->v) + slack;
    r.acc = acc;
    r.vmax = vmax;
    if (r.s >= vmax) r.t_lin = 0;
    else r.t_lin = acc > 0 ? 2 * (vmax - r.s) / acc : HUGE_VAL;
    if (whole) {
        r.rate = 0;
        r.cap = turn ? b->shape.r_out - b->shape.r_in : 0;
    } else {
        r.rate = spin_bound(b) * b->shape.r_out;
        r.cap = r.rate > 0 ? b->shape.r_out - b->shape.r_in : 0; /* no spin, no turn */
    }
    r.t_rot = r.rate > 0 ? r.cap / r.rate : 0;
    return r;
}

static void add_piece(const sched_reach *r, double t, double *a, double *b, double *c)
{
    if (t < r->t_lin) {
        *b += r->s;
        *c += 0.5 * r->acc;
    } else {
        *b += r->vmax;
    }
    if (t < r->t_rot) *b += r->rate;
    else *a += r->cap;
}

static double eval(const sched_reach *r, int n, double t)
{
    double f = 0;
    for (int k = 0; k < n; k++) {
        f += t < r[k].t_lin ? r[k].s * t + 0.5 * r[k].acc * t * t : r[k].vmax * t;
        f += t < r[k].t_rot ? r[k].rate * t : r[k].cap;
    }
    return f;
}

double sched_predict(const world *w, const pair *p, double d)
{
    return sched_predict_bodies(w, w->bodies[p->a], w->bodies[p->b], d);
}

/* When the centre of an object whose bound is r has gone left (> 0) at most;
 * HUGE_VAL when it never does. */
static double centre_time(const sched_reach *r, double left)
{
    if (r->s >= r->vmax) return left / r->vmax;
    double t = r->acc > 0 ? 2 * left / (r->s + sqrt(r->s * r->s + 2 * r->acc * left))
                          : (r->s > 0 ? left / r->s : HUGE_VAL);
    return t > r->t_lin ? left / r->vmax : t; /* at the speed limit by then */
}

/* The root above lo of the quadratic a + b t + c t^2 = target (b, c >= 0), or
 * HUGE_VAL when it never gets there. */
static double piece_root(double a, double b, double c, double target)
{
    double cc = a - target;
    if (c > 0) { /* c t^2 + b t + cc = 0, stably */
        double disc = d_max(0, b * b - 4 * c * cc);
        double q = -0.5 * (b + sqrt(disc));
        return fabs(q) > 0 ? cc / q : 0;
    }
    return b > 0 ? -cc / b : HUGE_VAL;
}

/* The earliest time the bound (its terms filled in by the caller) reaches d, or
 * HUGE_VAL when it never does; 0 when d <= 0.  turn[k] (with any_spin) says
 * whether object k's turn counts at all: a gap the turn cannot change (between
 * spheres about the centres of mass) leaves it out. */
static double predict(const world *w, const body *a, const body *b, double d, bool any_spin,
                      const bool turn[2], const double slack[2], sched_bound *keep)
{
    const body *ob[2] = {a, b};
    double vmax = w->set.max_linear;
    sched_reach r[2];
    int n = 0;
    for (int k = 0; k < 2; k++) {
        if (ob[k]->state != STATE_DYNAMIC) continue;
        /* with any_spin (far), the whole turn at once, when it counts, and the
         * whole force unless a steady slide takes part of it */
        const body *o = ob[k];
        bool whole = any_spin && !(o->slide >= 0 && o->slide_steady);
        double acc = v3_len(whole ? force_accel(w->set.force) : force_on(w->set.force, o));
        r[n++] = terms_of(o, acc, vmax, slack[k], any_spin, turn[k]);
    }
    if (keep) {
        keep->dist = d;
        keep->n = n;
        for (int k = 0; k < n; k++) keep->r[k] = r[k];
    }
    if (d <= 0) return 0;
    if (n == 0) return HUGE_VAL;
    /* a margin for the rounding of the flight and of the distance */
    double target = d - SCHED_ROUND * (1 + ob[0]->shape.r_out + ob[1]->shape.r_out);
    if (target <= 0) return 0;
    if (n == 1 && r[0].t_rot == 0) { /* one object, its turn all at once: in closed form */
        const sched_reach *o = &r[0];
        double left = target - o->cap;
        if (left <= 0) return 0;
        double t = centre_time(o, left);
        if (t == HUGE_VAL) return HUGE_VAL;
        t *= 1 - SCHED_EARLY;
        while (t > 0 && eval(r, 1, t) >= target) t *= 1 - SCHED_ROUND; /* never late */
        return t;
    }
    /* the breakpoints, in order; between two of them the bound is quadratic */
    double bp[5];
    int nb = 0;
    for (int k = 0; k < n; k++) {
        if (r[k].t_lin > 0 && r[k].t_lin < HUGE_VAL) bp[nb++] = r[k].t_lin;
        if (r[k].t_rot > 0) bp[nb++] = r[k].t_rot;
    }
    bp[nb++] = HUGE_VAL;
    for (int i = 1; i < nb; i++)
        for (int j = i; j > 0 && bp[j] < bp[j - 1]; j--) {
            double x = bp[j];
            bp[j] = bp[j - 1];
            bp[j - 1] = x;
        }
    double lo = 0;
    for (int i = 0; i < nb; lo = bp[i++]) {
        double hi = bp[i];
        if (hi <= lo) continue;
        double pa = 0, pb = 0, pc = 0; /* the bound on [lo, hi): pa + pb t + pc t^2 */
        for (int k = 0; k < n; k++) add_piece(&r[k], lo, &pa, &pb, &pc);
        double t = piece_root(pa, pb, pc, target);
        if (t == HUGE_VAL && hi == HUGE_VAL) return HUGE_VAL; /* nothing moves closer */
        if (!(t < hi)) continue; /* the bound stays short of d on this piece */
        t = d_max(lo, t) * (1 - SCHED_EARLY);
        while (t > 0 && eval(r, n, t) >= target) t *= 1 - SCHED_ROUND; /* never late */
        return t;
    }
    return HUGE_VAL;
}

static const bool both[2] = {true, true};

double sched_predict_bodies(const world *w, const body *a, const body *b, double d)
{
    static const double none[2] = {0, 0};
    return predict(w, a, b, d, false, both, none, NULL);
}

double sched_predict_far(const world *w, const body *a, const body *b, double d, bool turn_a,
                         bool turn_b)
{
    static const double slack[2] = {SCHED_SLACK, SCHED_SLACK};
    const bool turn[2] = {turn_a, turn_b};
    return predict(w, a, b, d - SCHED_JUMP, true, turn, slack, NULL);
}

double sched_predict_kept(const world *w, const body *a, const body *b, double d, double slack_a,
                          double slack_b, sched_bound *keep)
{
    const double slack[2] = {slack_a, slack_b};
    return predict(w, a, b, d, false, both, slack, keep);
}

double sched_closing(const world *w, const body *a, const body *b, double slack_a, double slack_b,
                   double t)
{
    sched_bound k;
    const double slack[2] = {slack_a, slack_b};
    predict(w, a, b, 0, false, both, slack, &k);
    return eval(k.r, k.n, t);
}

double sched_left(const sched_bound *k, double t)
{
    return k->dist - eval(k->r, k->n, t);
}

/* ---- along the normal ---- */

/* The first t in [lo, hi) at which p0 + p1 t + p2 t^2 reaches target, known to be
 * short of it at lo; HUGE_VAL when it does not. */
static double first_reach(double p0, double p1, double p2, double target, double lo, double hi)
{
    double q = p0 - target; /* f(t) = p2 t^2 + p1 t + q, f(lo) < 0 */
    double t = HUGE_VAL;
    if (p2 == 0) {
        if (p1 > 0) t = -q / p1;
    } else {
        double disc = p1 * p1 - 4 * p2 * q;
        if (disc < 0) return HUGE_VAL; /* (only when p2 < 0: it never gets there) */
        double m = -0.5 * (p1 + copysign(sqrt(disc), p1));
        double r1 = m / p2, r2 = m != 0 ? q / m : r1;
        double small = d_min(r1, r2), big = d_max(r1, r2);
        /* convex: the upward crossing is the larger root; concave: the smaller */
        t = p2 > 0 ? big : small;
    }
    return t >= lo && t < hi ? t : HUGE_VAL;
}

/* One moving object's part of the bound along n: how fast its centre comes on
 * along n (and with what acceleration), and how its surface turns. */
typedef struct {
    double s, acc;           /* centre: s t + acc t^2 / 2 towards the other, exactly */
    double rate, cap, t_rot; /* surface: rate t further out until t_rot, then cap */
} along_reach;

static double along_eval(const along_reach *r, int n, double t)
{
    double f = 0;
    for (int k = 0; k < n; k++) f += r[k].s * t + 0.5 * r[k].acc * t * t + d_min(r[k].cap, r[k].rate * t);
    return f;
}

double sched_predict_along(const world *w, const body *a, const body *b, double d, vec3 n, vec3 pa,
                           vec3 pb)
{
    const body *ob[2] = {a, b};
    along_reach r[2];
    int m = 0;
    double horizon = HUGE_VAL, vmax = w->set.max_linear;
    for (int k = 0; k < 2; k++) {
        const body *x = ob[k];
        if (x->state != STATE_DYNAMIC) continue;
        double sign = k == 0 ? 1 : -1; /* a comes on along n, b along -n */
        vec3 acc = force_on(w->set.force, x), c = body_com(x);
        double speed = v3_len(x->v), am = v3_len(acc);
        /* until its speed could reach max_linear its centre flies the parabola
         * exactly; the time is not trusted beyond */
        if (speed >= vmax) return 0;
        if (am > 0) horizon = d_min(horizon, (vmax - speed) / am);
        r[m].s = sign * v3_dot(x->v, n);
        r[m].acc = sign * v3_dot(acc, n);
        /* how far out along n its surface reaches from its centre now, and how
         * much further a turn can take it (to R at most, at w_max R) */
        double out = k == 0 ? v3_dot(v3_sub(pa, c), n) : v3_dot(v3_sub(c, pb), n);
        r[m].rate = spin_bound(x) * x->shape.r_out;
        r[m].cap = r[m].rate > 0 ? d_max(0, x->shape.r_out - out) : 0;
        r[m].t_rot = r[m].rate > 0 ? r[m].cap / r[m].rate : 0;
        m++;
    }
    if (m == 0 || d <= 0) return d <= 0 ? 0 : HUGE_VAL;
    double target = d - SCHED_ROUND * (1 + a->shape.r_out + b->shape.r_out);
    if (target <= 0) return 0;
    /* breakpoints: where each turn reaches its cap, then the horizon */
    double bp[3];
    int nb = 0;
    for (int k = 0; k < m; k++)
        if (r[k].t_rot > 0 && r[k].t_rot < horizon) bp[nb++] = r[k].t_rot;
    if (nb == 2 && bp[1] < bp[0]) {
        double x = bp[0];
        bp[0] = bp[1];
        bp[1] = x;
    }
    bp[nb++] = horizon;
    double lo = 0;
    for (int i = 0; i < nb; lo = bp[i++]) {
        double hi = bp[i];
        if (hi <= lo) continue;
        double p0 = 0, p1 = 0, p2 = 0; /* the bound on [lo, hi) */
        for (int k = 0; k < m; k++) {
            p1 += r[k].s;
            p2 += 0.5 * r[k].acc;
            if (lo < r[k].t_rot) p1 += r[k].rate;
            else p0 += r[k].cap;
        }
        if (p0 + p1 * lo + p2 * lo * lo >= target) return lo * (1 - SCHED_EARLY);
        double t = first_reach(p0, p1, p2, target, lo, hi);
        if (t == HUGE_VAL) continue;
        t *= 1 - SCHED_EARLY;
        while (t > 0 && along_eval(r, m, t) >= target) t *= 1 - SCHED_ROUND; /* never late */
        return t;
    }
    return horizon; /* short of d until then: made again there */
}

/* ---- bounding gaps ---- */

/* How far the sphere of radius r about c is outside b's bounding box (negative
 * inside it). */
static double box_gap(vec3 c, double r, const body *b)
{
    vec3 p = q_unrotate(b->q, v3_sub(c, b->x));
    vec3 lo = b->shape.box_lo, hi = b->shape.box_hi;
    /* how far p is outside the box along each axis (0 within it) */
    vec3 out = v3(p.x < lo.x ? lo.x - p.x : p.x > hi.x ? p.x - hi.x : 0,
                  p.y < lo.y ? lo.y - p.y : p.y > hi.y ? p.y - hi.y : 0,
                  p.z < lo.z ? lo.z - p.z : p.z > hi.z ? p.z - hi.z : 0);
    return v3_len(out) - r;
}

double sched_bound_gap(const body *a, const body *b, bool *turn_a, bool *turn_b)
{
    vec3 ca = body_com(a), cb = body_com(b);
    double ra = a->shape.r_out, rb = b->shape.r_out;
    double gap = v3_len(v3_sub(ca, cb)) - ra - rb;
    double box = ra > 2 * rb ? box_gap(cb, rb, a) : rb > 2 * ra ? box_gap(ca, ra, b) : gap;
    bool to_box = box > gap;
    if (turn_a) *turn_a = to_box && ra > 2 * rb;
    if (turn_b) *turn_b = to_box && rb > 2 * ra;
    return to_box ? box : gap;
}

/* ---- the indexed binary heap ---- */

static void place(world *w, long pos, sched_entry e)
{
    w->sched.heap[pos] = e;
    w->sched.heap_pos[e.pair] = pos;
}

static void sift_up(world *w, long pos)
{
    sched_entry e = w->sched.heap[pos];
    while (pos > 0) {
        long parent = (pos - 1) / 2;
        if (!(e.next < w->sched.heap[parent].next)) break;
        place(w, pos, w->sched.heap[parent]);
        pos = parent;
    }
    place(w, pos, e);
}

static void sift_down(world *w, long pos)
{
    long n = w->sched.nheap;
    sched_entry e = w->sched.heap[pos];
    for (;;) {
        long c = 2 * pos + 1;
        if (c >= n) break;
        /* the earlier child (past the last, the end mark, never earlier): chosen
         * without a jump, which a processor cannot guess here */
        c += w->sched.heap[c + 1].next < w->sched.heap[c].next;
        if (!(w->sched.heap[c].next < e.next)) break;
        place(w, pos, w->sched.heap[c]);
        pos = c;
    }
    place(w, pos, e);
}

void sched_init(schedule *s)
{
    memset(s, 0, sizeof *s);
}

void sched_free(schedule *s)
{
    free(s->heap);
    free(s->heap_pos);
    free(s->bound);
    free(s->obj_first);
    free(s->obj_pairs);
    free(s->obj_other);
    free(s->box);
    free(s->parked);
    sched_init(s);
}

int sched_build(world *w, double t)
{
    long np = w->pairs.n, nh = np + w->n;
    sched_entry *heap = malloc((size_t)(nh + 1) * sizeof *heap); /* and an end mark */
    long *pos = malloc((size_t)(nh ? nh : 1) * sizeof *pos);
    sched_bound *bound = malloc((size_t)(np ? np : 1) * sizeof *bound);
    long *first = malloc((size_t)(w->n + 1) * sizeof *first);
    long *list = malloc((size_t)(2 * np + 1) * sizeof *list);
    int *other = malloc((size_t)(2 * np + 1) * sizeof *other);
    sched_box *box = malloc((size_t)(w->n ? w->n : 1) * sizeof *box);
    bool *parked = malloc((size_t)(np ? np : 1) * sizeof *parked);
    if (!heap || !pos || !bound || !first || !list || !other || !box || !parked) {
        free(heap);
        free(pos);
        free(bound);
        free(first);
        free(list);
        free(other);
        free(box);
        free(parked);
        return -1;
    }
    sched_free(&w->sched);
    w->sched.heap = heap;
    w->sched.heap_pos = pos;
    w->sched.bound = bound;
    w->sched.obj_first = first;
    w->sched.obj_pairs = list;
    w->sched.obj_other = other;
    w->sched.box = box;
    w->sched.parked = parked;
    w->sched.nheap = nh;
    for (int k = 0; k <= w->n; k++) first[k] = 0;
    for (long i = 0; i < np; i++) {
        first[w->pairs.p[i].a + 1]++;
        first[w->pairs.p[i].b + 1]++;
    }
    for (int k = 0; k < w->n; k++) first[k + 1] += first[k];
    long *fill = malloc((size_t)(w->n + 1) * sizeof *fill);
    if (!fill) return -1;
    for (int k = 0; k <= w->n; k++) fill[k] = first[k];
    for (long i = 0; i < np; i++) {
        int a = w->pairs.p[i].a, b = w->pairs.p[i].b;
        other[fill[a]] = b;
        list[fill[a]++] = i;
        other[fill[b]] = a;
        list[fill[b]++] = i;
    }
    free(fill);
    for (long i = 0; i < np; i++) {
        w->pairs.p[i].next = t;
        parked[i] = false;
        place(w, i, (sched_entry){t, i}); /* all equal: already a heap */
        bound[i] = (sched_bound){.dist = 0}; /* none kept yet */
    }
    for (int k = 0; k < w->n; k++) {
        box[k] = (sched_box){.lo = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL),
                             .hi = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), .from = t, .until = t};
        place(w, np + k, (sched_entry){t, np + k});
    }
    heap[nh] = (sched_entry){HUGE_VAL, -1}; /* nothing comes after it */
    return 0;
}

void sched_set(world *w, long i, double next)
{
    long pos = w->sched.heap_pos[i];
    double old = w->sched.heap[pos].next;
    if (i < w->pairs.n) {
        w->pairs.p[i].next = next;
        if (next < HUGE_VAL) w->sched.parked[i] = false;
    }
    w->sched.heap[pos].next = next;
    if (next < old) sift_up(w, pos);
    else if (next > old) sift_down(w, pos);
}

long sched_top(const world *w, double *next)
{
    if (w->sched.nheap == 0) return -1;
    *next = w->sched.heap[0].next;
    return w->sched.heap[0].pair;
}

/* ---- the boxes ---- */

/* True when boxes x and y do not meet. */
static bool apart(const sched_box *x, const sched_box *y)
{
    return x->hi.x < y->lo.x || y->hi.x < x->lo.x || x->hi.y < y->lo.y || y->hi.y < x->lo.y ||
           x->hi.z < y->lo.z || y->hi.z < x->lo.z;
}

/* Object k's box ends at t: until it is made again it meets every other. */
static void box_ends(world *w, int k, double t)
{
    sched_box *x = &w->sched.box[k];
    x->lo = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    x->hi = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
    x->until = t;
    if (w->sched.heap[w->sched.heap_pos[w->pairs.n + k]].next > t) sched_set(w, w->pairs.n + k, t);
}

/* The box that holds still object o where it is: its own box turned into the
 * world's axes, within the one about its bounding sphere. */
static void still_box(const body *o, sched_box *x)
{
    vec3 mid = v3_scale(v3_add(o->shape.box_lo, o->shape.box_hi), 0.5);
    vec3 half = v3_scale(v3_sub(o->shape.box_hi, o->shape.box_lo), 0.5);
    mat3 r = m3_from_quat(o->q);
    vec3 c = v3_add(o->x, m3_mulv(r, mid)), e;
    e.x = fabs(r.m[0][0]) * half.x + fabs(r.m[0][1]) * half.y + fabs(r.m[0][2]) * half.z;
    e.y = fabs(r.m[1][0]) * half.x + fabs(r.m[1][1]) * half.y + fabs(r.m[1][2]) * half.z;
    e.z = fabs(r.m[2][0]) * half.x + fabs(r.m[2][1]) * half.y + fabs(r.m[2][2]) * half.z;
    vec3 com = body_com(o), s = v3(o->shape.r_out, o->shape.r_out, o->shape.r_out);
    double m = SCHED_ROUND * (1 + o->shape.r_out); /* for rounding */
    vec3 pad = v3(m, m, m);
    x->lo = v3_sub(v3_max(v3_sub(c, e), v3_sub(com, s)), pad);
    x->hi = v3_add(v3_min(v3_add(c, e), v3_add(com, s)), pad);
}

void sched_box_renew(world *w, int k, const body *o, double from, double t, double t_end)
{
    sched_box *x = &w->sched.box[k];
    x->from = from;
    x->jumped = o->jumped;
    if (o->state != STATE_DYNAMIC) {
        still_box(o, x);
        x->until = HUGE_VAL;
        x->speed = x->acc = 0;
    } else {
        /* the far bound's reach with no turn: its centre, as sched_predict_far
         * lets it go (the whole force unless it slides steadily) */
        bool whole = !(o->slide >= 0 && o->slide_steady);
        double acc = v3_len(whole ? force_accel(w->set.force) : force_on(w->set.force, o));
        sched_reach r = terms_of(o, acc, w->set.max_linear, SCHED_SLACK, true, false);
        /* long enough to reach SCHED_BOX_REACH, and past the step's end */
        x->until = from + centre_time(&r, SCHED_BOX_REACH);
        if (!(x->until > t_end)) x->until = nextafter(t_end, HUGE_VAL);
        double reach = eval(&r, 1, x->until - from) + o->shape.r_out + SCHED_JUMP;
        reach += SCHED_ROUND * (1 + reach); /* for rounding */
        vec3 c = body_com(o), e = v3(reach, reach, reach);
        x->lo = v3_sub(c, e);
        x->hi = v3_add(c, e);
        x->speed = r.s;
        x->acc = acc;
    }
    sched_set(w, w->pairs.n + k, x->until);
    /* a still object's box lies within the one it had (which held it): its
     * parked pairs stay so, and the others are left to the moving objects' boxes */
    if (o->state != STATE_DYNAMIC) return;
    for (long j = w->sched.obj_first[k]; j < w->sched.obj_first[k + 1]; j++) {
        long i = w->sched.obj_pairs[j];
        if (apart(x, &w->sched.box[w->sched.obj_other[j]])) {
            if (!w->sched.parked[i]) {
                sched_set(w, i, HUGE_VAL);
                w->sched.parked[i] = true;
            }
        } else if (w->sched.parked[i]) {
            sched_set(w, i, t);
        }
    }
}

bool sched_box_holds(const world *w, int k, const body *b, double t)
{
    const sched_box *x = &w->sched.box[k];
    if (b->state != STATE_DYNAMIC) return true; /* it stopped within */
    return v3_len(b->v) <= x->speed + x->acc * (t - x->from) &&
           v3_len(force_on(w->set.force, b)) <= x->acc && b->jumped - x->jumped <= SCHED_JUMP;
}

bool sched_boxes_apart(const world *w, int a, int b)
{
    return apart(&w->sched.box[a], &w->sched.box[b]);
}

void sched_slide_ends(world *w, int k, double t)
{
    if (!w->sched.obj_first) return;
    /* a box that counted the slide's lesser acceleration ends, and its parked
     * pairs are due with the rest */
    bool box_ends_now = w->sched.box[k].acc < v3_len(force_accel(w->set.force)) && w->bodies[k]->state == STATE_DYNAMIC;
    if (box_ends_now) box_ends(w, k, t);
    for (long j = w->sched.obj_first[k]; j < w->sched.obj_first[k + 1]; j++) {
        long i = w->sched.obj_pairs[j];
        const pair *p = &w->pairs.p[i];
        if (w->sched.parked[i] && !box_ends_now) continue;
        bool holds = !w->sched.parked[i] && p->far && !(p->a == k ? p->far_slide_a : p->far_slide_b);
        if (!holds && p->next > t) sched_set(w, i, t);
    }
}

void sched_object_due(world *w, int k, double t)
{
    if (!w->sched.obj_first) return;
    box_ends(w, k, t);
    for (long j = w->sched.obj_first[k]; j < w->sched.obj_first[k + 1]; j++) {
        long i = w->sched.obj_pairs[j];
        if (w->pairs.p[i].next > t) sched_set(w, i, t);
    }
}

int sched_check(const world *w)
{
    if (w->sched.nheap != w->pairs.n + w->n || w->sched.heap[w->sched.nheap].next != HUGE_VAL) return -1; /* the end mark */
    for (long pos = 0; pos < w->sched.nheap; pos++) {
        long i = w->sched.heap[pos].pair;
        if (i < 0 || i >= w->sched.nheap || w->sched.heap_pos[i] != pos) return -1;
        if (i < w->pairs.n && (w->pairs.p[i].next != w->sched.heap[pos].next ||
                              (w->sched.parked[i] && w->pairs.p[i].next != HUGE_VAL)))
            return -1;
        if (pos > 0 && w->sched.heap[pos].next < w->sched.heap[(pos - 1) / 2].next) return -1;
    }
    return 0;
}
