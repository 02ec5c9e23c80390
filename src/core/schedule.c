/* schedule.c: lower bounds on when pairs could touch, and the heap (schedule.h;
 * thesis 3.3.1.1 and 3.3.1.2).
 *
 * Every bound is a sum of terms that grow with t and is quadratic between a few
 * breakpoints, so its earliest time is the root of a quadratic on the right piece,
 * taken from below and checked: the time returned is never later than the true
 * one.
 */
#include "schedule.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tolerance.h"
#include "world.h"

/* Relative margins for rounding: a bounding gap is taken SCHED_ROUND of the
 * pair's size (1 + S, tolerance.h) short, and a time found is taken SCHED_EARLY of
 * itself early, then SCHED_ROUND earlier until the bound checks out.  (A distance
 * a query found is taken tol_margin short.) */
#define SCHED_ROUND 1e-9
#define SCHED_EARLY 1e-12

/* The first t in [lo, hi) at which p0 + p1 t + p2 t^2 reaches target, known to be
 * short of it at lo; HUGE_VAL when it does not. */
static double first_reach(double p0, double p1, double p2, double target, double lo, double hi)
{
    double q = p0 - target; /* f(t) = p2 t^2 + p1 t + q, f(lo) < 0 */
    double t = HUGE_VAL;
    if (p2 == 0) {
        if (p1 > 0) t = -q / p1;
    } else {
        /* (no real root only when p2 < 0: it never gets there) */
        double r1, r2;
        if (!quad_roots(p2, p1, q, &r1, &r2)) return HUGE_VAL;
        double small = d_min(r1, r2), big = d_max(r1, r2);
        /* convex: the upward crossing is the larger root; concave: the smaller */
        t = p2 > 0 ? big : small;
    }
    return t >= lo && t < hi ? t : HUGE_VAL;
}

/* One moving object's part of the bound along the normal: how fast its centre
 * comes on (and with what acceleration), and how its surface turns out. */
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

double sched_ca_time(const body *a, const sched_move *ma, const body *b, const sched_move *mb,
                     double d, vec3 n, vec3 pa, vec3 pb, double target)
{
    const sched_move *mo[2] = {ma, mb};
    along_reach r[2];
    int m = 0;
    for (int k = 0; k < 2; k++) {
        const sched_move *x = mo[k];
        if (!x->moves) continue;
        double sign = k == 0 ? 1 : -1; /* a comes on along -n, b along +n */
        r[m].s = -sign * v3_dot(x->v, n);
        r[m].acc = -sign * v3_dot(x->a, n);
        /* how far out along the normal its surface reaches from its centre now,
         * and how much further a turn can take it (to R at most, at |w| R) */
        double R = x->reach;
        double out = k == 0 ? v3_dot(v3_sub(x->c, pa), n) : v3_dot(v3_sub(pb, x->c), n);
        r[m].rate = x->rate * R;
        r[m].cap = r[m].rate > 0 ? d_max(0, R - out) : 0;
        r[m].t_rot = r[m].rate > 0 ? r[m].cap / r[m].rate : 0;
        m++;
    }
    if (m == 0) return HUGE_VAL;
    /* (the distance is known to far better than the contact distance) */
    double goal = d - target - tol_margin(a, b);
    if (goal <= 0) return 0;
    /* breakpoints: where each turn reaches its cap */
    double bp[3];
    int nb = 0;
    for (int k = 0; k < m; k++)
        if (r[k].t_rot > 0) bp[nb++] = r[k].t_rot;
    if (nb == 2 && bp[1] < bp[0]) {
        double x = bp[0];
        bp[0] = bp[1];
        bp[1] = x;
    }
    bp[nb++] = HUGE_VAL;
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
        if (p0 + p1 * lo + p2 * lo * lo >= goal) return lo * (1 - SCHED_EARLY);
        double t = first_reach(p0, p1, p2, goal, lo, hi);
        if (t == HUGE_VAL) continue;
        t *= 1 - SCHED_EARLY;
        /* never late: back off, by twice as much each time, until it checks out */
        for (double f = SCHED_ROUND; t > lo && along_eval(r, m, t) >= goal; f *= 2)
            t = f < 0.5 ? d_max(lo, t * (1 - f)) : lo;
        return t > lo ? t : lo * (1 - SCHED_EARLY);
    }
    return HUGE_VAL;
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


double sched_sphere_time(const body *a, const sched_move *ma, const body *b, const sched_move *mb)
{
    if (!ma->moves && !mb->moves) return HUGE_VAL;
    if (ma->held || mb->held) return 0; /* the hand may move it anywhere */
    bool turn_a, turn_b;
    double gap = sched_bound_gap(a, b, &turn_a, &turn_b);
    /* a box turns with its object: all of that object's R - r at once */
    if (turn_a && ma->moves) gap -= a->shape.r_out - a->shape.r_in;
    if (turn_b && mb->moves) gap -= b->shape.r_out - b->shape.r_in;
    gap -= SCHED_ROUND * (1 + tol_size(a, b)) + tol_round(a, b);
    if (gap <= 0) return 0;
    vec3 va = ma->moves ? ma->v : v3(0, 0, 0), vb = mb->moves ? mb->v : v3(0, 0, 0);
    vec3 aa = ma->moves ? ma->a : v3(0, 0, 0), ab = mb->moves ? mb->a : v3(0, 0, 0);
    double s = v3_len(v3_sub(va, vb)), c = 0.5 * v3_len(v3_sub(aa, ab));
    double t = c > 0 ? 2 * gap / (s + sqrt(s * s + 4 * c * gap)) : s > 0 ? gap / s : HUGE_VAL;
    if (t == HUGE_VAL) return t;
    t *= 1 - SCHED_EARLY;
    for (double f = SCHED_ROUND; t > 0 && s * t + c * t * t >= gap; f *= 2)
        t = f < 0.5 ? t * (1 - f) : 0; /* never late: backing off faster each time */
    return t;
}

/* ---- the indexed binary heap ---- */

static void place(world *w, long pos, sched_entry e)
{
    w->sched.heap[pos] = e;
    w->sched.heap_pos[e.id] = pos;
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
    sched_init(s);
}

/* Room for ids below n (and as many entries).  Returns 0 or -1. */
static int reserve(schedule *s, long n)
{
    if (n <= s->cap) return 0;
    long cap = s->cap ? s->cap : 64;
    while (cap < n) cap *= 2;
    sched_entry *heap = realloc(s->heap, (size_t)(cap + 1) * sizeof *heap);
    if (heap) s->heap = heap;
    long *pos = realloc(s->heap_pos, (size_t)cap * sizeof *pos);
    if (pos) s->heap_pos = pos;
    if (!heap || !pos) return -1;
    for (long k = s->cap; k < cap; k++) pos[k] = -1;
    s->cap = cap;
    return 0;
}

int sched_build(world *w, double t)
{
    schedule *s = &w->sched;
    s->nobj = w->n;
    if (reserve(s, w->n + w->pairs.n + 1) != 0) return -1;
    long m = 0;
    for (long i = 0; i < w->pairs.n; i++) {
        s->heap_pos[sched_pair_id(s, i)] = -1;
        if (w->pairs.p[i].a < 0) continue;
        w->pairs.p[i].next = t;
        place(w, m++, (sched_entry){t, sched_pair_id(s, i)});
    }
    /* (the pairs all at t, then the objects at +inf: already a heap) */
    for (int k = 0; k < w->n; k++) place(w, m++, (sched_entry){HUGE_VAL, sched_obj_id(k)});
    s->nheap = m;
    s->heap[m] = (sched_entry){HUGE_VAL, -1}; /* nothing comes after it */
    return 0;
}

void sched_set(world *w, long id, double next)
{
    long pos = w->sched.heap_pos[id];
    double old = w->sched.heap[pos].next;
    long nobj = w->sched.nobj;
    if (id >= nobj) w->pairs.p[id - nobj].next = next;
    w->sched.heap[pos].next = next;
    if (next < old) sift_up(w, pos);
    else if (next > old) sift_down(w, pos);
}

int sched_add(world *w, long slot, double next)
{
    schedule *s = &w->sched;
    long id = sched_pair_id(s, slot);
    if (reserve(s, id + 1) != 0 || reserve(s, s->nheap + 2) != 0) return -1;
    w->pairs.p[slot].next = next;
    long pos = s->nheap++;
    s->heap[s->nheap] = (sched_entry){HUGE_VAL, -1};
    place(w, pos, (sched_entry){next, id});
    sift_up(w, pos);
    return 0;
}

void sched_remove(world *w, long slot)
{
    schedule *s = &w->sched;
    long id = sched_pair_id(s, slot), pos = s->heap_pos[id];
    if (pos < 0) return;
    s->heap_pos[id] = -1;
    long last = --s->nheap;
    sched_entry e = s->heap[last];
    s->heap[last] = (sched_entry){HUGE_VAL, -1};
    if (pos == last) return;
    double old = s->heap[pos].next;
    place(w, pos, e);
    if (e.next < old) sift_up(w, pos);
    else sift_down(w, pos);
}

long sched_top(const world *w, double *next)
{
    if (w->sched.nheap == 0) return -1;
    *next = w->sched.heap[0].next;
    return w->sched.heap[0].id;
}

int sched_check(const world *w)
{
    const schedule *s = &w->sched;
    if (s->nheap != w->pairs.live + s->nobj || s->heap[s->nheap].next != HUGE_VAL)
        return -1; /* the end mark */
    for (long pos = 0; pos < s->nheap; pos++) {
        long i = s->heap[pos].id;
        if (i < 0 || i >= s->cap || s->heap_pos[i] != pos) return -1;
        if (i >= s->nobj && (w->pairs.p[i - s->nobj].a < 0 || w->pairs.p[i - s->nobj].next != s->heap[pos].next))
            return -1;
        if (pos > 0 && s->heap[pos].next < s->heap[(pos - 1) / 2].next) return -1;
    }
    return 0;
}
