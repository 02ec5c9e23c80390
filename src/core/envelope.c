/* envelope.c: the points' bound of the time of impact, over all vertices or
 * walked over a large hull's faces (envelope.h). */
#include "envelope.h"

#include <math.h>
#include <stdbool.h>

/* A height along the normal that changes at a constant rate: h0 + h1 t. */
typedef struct {
    double h0, h1;
} line;

/* A piece of a lower envelope: line l (of vertex v) from time t on. */
typedef struct {
    double t;
    line l;
    int v;
} piece;

/* One side's envelope as far as it is known. */
typedef struct {
    const env_side *s;
    piece *p;
    int k;      /* pieces found */
    bool done;  /* no more before T */
    double cut; /* where a walk stopped for want of room (else HUGE_VAL): the
                   envelope is not known from there on */
    double T;
    int reads;
} side_env;

static line vertex_line(const env_side *s, vec3 y)
{
    return (line){s->h0 + v3_dot(y, s->dh0), s->h1 + v3_dot(y, s->dh1)};
}

/* The lower envelope of the n vertices' lines over [0, T]: its pieces, in time
 * order. */
static int lower_envelope(const env_side *s, line *ln, int n, double T, piece *out)
{
    for (int i = 0; i < n; i++) ln[i] = vertex_line(s, s->hull->v[i]);
    int cur = 0, m = 0;
    for (int i = 1; i < n; i++)
        if (ln[i].h0 < ln[cur].h0 || (ln[i].h0 == ln[cur].h0 && ln[i].h1 < ln[cur].h1)) cur = i;
    double t = 0;
    for (;;) {
        out[m++] = (piece){t, ln[cur], cur};
        int next = -1;
        double tx = HUGE_VAL;
        for (int i = 0; i < n; i++) {
            if (!(ln[i].h1 < ln[cur].h1)) continue;
            double x = (ln[i].h0 - ln[cur].h0) / (ln[cur].h1 - ln[i].h1);
            if (x < t) x = t;
            if (x < tx || (x == tx && ln[i].h1 < ln[next].h1)) {
                tx = x;
                next = i;
            }
        }
        if (next < 0 || !(tx < T) || m == n) return m;
        cur = next;
        t = tx;
    }
}

/* Vertex u as the walk's next piece after cur from time t, if it crosses
 * below it soonest (ties: the one falling fastest, as lower_envelope). */
static void consider(side_env *e, const piece *cur, int u, int *next, line *ln, double *tx)
{
    line l = vertex_line(e->s, e->s->hull->v[u]);
    e->reads++;
    if (!(l.h1 < cur->l.h1)) return;
    double x = (l.h0 - cur->l.h0) / (cur->l.h1 - l.h1);
    if (x < cur->t) x = cur->t;
    if (x < *tx || (x == *tx && l.h1 < ln->h1)) {
        *tx = x;
        *next = u;
        *ln = l;
    }
}

/* The walked envelope's next piece: the vertices sharing a face with the lowest
 * now (its edges' other ends, and the vertices of its faces of more than three). */
static void walk_on(side_env *e)
{
    const poly *h = e->s->hull;
    const piece *cur = &e->p[e->k - 1];
    int v = cur->v, next = -1;
    double tx = HUGE_VAL;
    line ln = {0, 0};
    for (int k = h->vert_first[v]; k < h->vert_first[v + 1]; k++) {
        const poly_edge *ed = &h->e[h->vert_edge[k]];
        consider(e, cur, ed->v[0] == v ? ed->v[1] : ed->v[0], &next, &ln, &tx);
        for (int s = 0; s < 2; s++) {
            const poly_face *f = &h->f[ed->f[s]];
            if (f->count <= 3) continue;
            for (int i = 0; i < f->count; i++)
                if (h->face_vert[f->first + i] != v) consider(e, cur, h->face_vert[f->first + i], &next, &ln, &tx);
        }
    }
    if (next < 0 || !(tx < e->T)) {
        e->done = true;
        return;
    }
    if (e->k == ENV_FLAT_VERTICES) {
        e->done = true;
        e->cut = tx;
        return;
    }
    e->p[e->k++] = (piece){tx, ln, next};
}

/* Whether piece i of e's envelope is before T (walking on to it if need be). */
static bool have(side_env *e, int i)
{
    while (i >= e->k && !e->done) walk_on(e);
    return i < e->k;
}

static void side_start(side_env *e, const env_side *s, double T, line *ln, piece *p)
{
    *e = (side_env){.s = s, .p = p, .T = T, .cut = HUGE_VAL};
    if (!s->hull) {
        p[0] = (piece){0, {s->h0, s->h1}, -1};
        e->k = 1;
        e->done = true;
        return;
    }
    if (s->hull->nv > ENV_FLAT_VERTICES && !s->feat) { /* (unknown from the start) */
        p[0] = (piece){0, {s->h0, s->h1}, -1};
        e->k = 1;
        e->done = true;
        e->cut = 0;
        return;
    }
    if (s->hull->nv <= ENV_WALK_VERTICES || (s->hull->nv <= ENV_FLAT_VERTICES && !s->feat)) {
        e->k = lower_envelope(s, ln, s->hull->nv, T, p);
        e->reads = s->hull->nv;
        e->done = true;
        return;
    }
    /* the lowest vertex now: the furthest along -dh0, by a climb from a vertex
     * near it or down the hierarchy (ties of height are walked off at time 0 to
     * the one falling fastest) */
    int v = s->near >= 0 && s->near < s->hull->nv ? poly_climb(s->hull, v3_neg(s->dh0), s->near)
                                                 : closest_hull_support(s->feat, v3_neg(s->dh0));
    p[0] = (piece){0, vertex_line(s, s->hull->v[v]), v};
    e->k = 1;
    e->reads = 1;
}

double env_first_time(const env_side *a, const env_side *b, double q, double target,
                      double margin, double T, int *reads)
{
    static _Thread_local line la[ENV_FLAT_VERTICES], lb[ENV_FLAT_VERTICES];
    static _Thread_local piece pa_[ENV_FLAT_VERTICES], pb_[ENV_FLAT_VERTICES];
    side_env ea, eb;
    side_start(&ea, a, T, la, pa_);
    side_start(&eb, b, T, lb, pb_);
    const piece *pa = pa_, *pb = pb_;
    double out = HUGE_VAL;
    int i = 0, j = 0;
    for (double t0 = 0; t0 < T;) {
        if (!(t0 < ea.cut && t0 < eb.cut)) { /* not known from here */
            out = t0;
            break;
        }
        double t1 = T;
        if (have(&ea, i + 1)) t1 = d_min(t1, pa[i + 1].t);
        if (have(&eb, j + 1)) t1 = d_min(t1, pb[j + 1].t);
        t1 = d_min(t1, d_min(ea.cut, eb.cut));
        /* f(t) = c0 + c1 t + q t^2 - target on [t0, t1] */
        double c0 = pa[i].l.h0 + pb[j].l.h0 - target - margin, c1 = pa[i].l.h1 + pb[j].l.h1;
        double f0 = c0 + c1 * t0 + q * t0 * t0;
        if (!(f0 > 0)) {
            out = t0;
            break;
        }
        double r = HUGE_VAL;
        if (q == 0) {
            if (c1 < 0) r = -c0 / c1;
        } else {
            double r1, r2;
            if (quad_roots(q, c1, c0, &r1, &r2)) {
                if (r1 >= t0 && r1 < r) r = r1;
                if (r2 >= t0 && r2 < r) r = r2;
            }
        }
        if (r <= t1) {
            /* never late: back off until it checks out */
            double t = r * (1 - 1e-12);
            for (double f = 1e-9; t > t0 && c0 + c1 * t + q * t * t <= 0; f *= 2)
                t = f < 0.5 ? d_max(t0, t * (1 - f)) : t0;
            out = t;
            break;
        }
        t0 = t1;
        if (i + 1 < ea.k && pa[i + 1].t <= t0) i++;
        if (j + 1 < eb.k && pb[j + 1].t <= t0) j++;
    }
    if (reads) *reads = ea.reads + eb.reads;
    return out;
}
