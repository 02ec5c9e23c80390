/* answer.c: answering a step's events (answer.h).
 *
 * A collision is answered with every lasting contact of the objects pressed
 * together with its own (rest_component): their rows (rows.h) make one contact
 * problem (impulse.h), each collision point with Newton's restitution and each
 * lasting contact's with none, so that a box landing on a stack moves the stack
 * as one.  What the impulses leave moving faster than the speed limits is cut to
 * them, and the points that would then approach again stop there.  A point that
 * no longer moves apart stays in lasting contact, and the modes of every object
 * the collision touched are found anew (rest_classify); those left general start
 * a cluster's step (cluster.h).  A held object (hold.h) is moved by none of it.
 */
#include "answer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cluster.h"
#include "friction.h"
#include "grow.h"
#include "impulse.h"
#include "pairs.h"
#include "rest.h"
#include "retime.h"
#include "rows.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

void answer_init(answer_scratch *s)
{
    memset(s, 0, sizeof *s);
}

void answer_free(answer_scratch *s)
{
    free(s->objects);
    free(s->cluster);
    free(s->classify);
    free(s->kicked);
    free(s->balanced);
    free(s->now);
    free(s->mark);
    free(s->lcp);
    free(s->fw);
    answer_init(s);
}

int answer_prepare(world *w, bool changed)
{
    answer_scratch *s = &w->answer;
    int rows = IMPULSE_MAX_ROWS > SIM_CLUSTER_ROWS ? IMPULSE_MAX_ROWS : SIM_CLUSTER_ROWS;
    if (!s->lcp && !(s->lcp = malloc(lcp_work_size(rows)))) return -1;
    if (!s->fw && !(s->fw = malloc(sizeof *s->fw))) return -1;
    if (w->n > s->cap) {
        bool ok = true;
        changed = true;
        s->objects = grow_resized(s->objects, sizeof *s->objects, w->n, &ok);
        s->cluster = grow_resized(s->cluster, sizeof *s->cluster, w->n, &ok);
        s->classify = grow_resized(s->classify, sizeof *s->classify, w->n, &ok);
        s->kicked = grow_resized(s->kicked, sizeof *s->kicked, w->n, &ok);
        s->balanced = grow_resized(s->balanced, sizeof *s->balanced, w->n, &ok);
        s->now = grow_resized(s->now, sizeof *s->now, w->n, &ok);
        s->mark = grow_resized(s->mark, sizeof *s->mark, w->n, &ok);
        if (!ok) return -1;
        s->cap = w->n;
    }
    if (!changed) return 0;
    for (int i = 0; i < w->n; i++) {
        s->kicked[i] = s->balanced[i] = *w->bodies[i];
        s->now[i] = w->bodies[i];
        s->mark[i] = false;
    }
    return 0;
}

void answer_clusters(world *w, const int *list, int n, double t, double t_end)
{
    int *k_list = w->answer.cluster;
    for (int k = 0; k < n; k++) {
        int i = list[k];
        const body *b = w->bodies[i];
        /* (a cluster begun already has its step's end as its objects' event) */
        if (b->state != STATE_DYNAMIC || b->mode != MODE_GENERAL || w->step.event[i] != HUGE_VAL)
            continue;
        int m = rest_cluster(w, i, k_list);
        double h = cluster_kick(w, k_list, m, t, t_end);
        for (int j = 0; j < m; j++) {
            retime_object(w, k_list[j], t);
            retime_event(w, k_list[j], t + h);
        }
    }
}

/* A collision being answered: the contact problem of its pair's points and of
 * the lasting contacts of the objects pressed together with them. */
typedef struct {
    long k;               /* the pair's slot */
    pair *p;
    const int *objects;   /* the objects pressed together with it (mobile), n */
    int n;
    int held;             /* the pair's held object (hold.h), or -1 */
    double e;             /* the pair's restitution */
    impulse_row rows[IMPULSE_MAX_ROWS]; /* the pair's own `own`, then the lasting */
    int own, nr;                        /*   contacts', nr in all */
    double u[IMPULSE_MAX_ROWS];         /* each row's normal speed before */
    double lambda[IMPULSE_MAX_ROWS];    /* and its impulse */
    double closing;       /* the fastest the pair's own points approached */
} collision;

/* Appends the rows of pair p's contact points (its objects in the states of
 * w->bodies, r their closest result, e the restitution of every row). */
static void rows_of(world *w, row_list *l, const pair *p, const closest_result *r, double e)
{
    const body *A = w->bodies[p->a], *B = w->bodies[p->b];
    rows_add(l, p, A, B, r, tol_contact(A, B), e, w->bodies);
}

/* The rows of collision c: its pair's own points (with the pair's restitution),
 * then the lasting contacts of its objects (none), each pair once.  Marks its
 * objects mobile. */
static void gather(world *w, collision *c)
{
    row_list rl = {c->rows, NULL, NULL, 0, IMPULSE_MAX_ROWS, false};
    rows_of(w, &rl, c->p, &w->pairs.hits[c->k].r, c->e);
    c->own = rl.n;
    bool *mobile = w->answer.mark;
    for (int j = 0; j < c->n; j++) mobile[c->objects[j]] = true;
    for (int j = 0; j < c->n; j++) {
        int i = c->objects[j];
        FOR_PAIRS_OF(w, i, link, o) {
            int other = link->other;
            if (!o->touching || o == c->p || (mobile[other] && other < i)) continue;
            closest_result r = pair_query(w, o, w->bodies[o->a], w->bodies[o->b]);
            rows_of(w, &rl, o, &r, 0);
        }
    }
    c->nr = rl.n;
}

/* The speed limits on object i, where a collision set its speed: |v| <=
 * max_linear, |w| <= max_angular (L scaled down).  Writes what it cut first to
 * *cut; true when it cut. */
static bool limit_speeds(world *w, int i, sim_cut *cut)
{
    body *b = w->bodies[i];
    double vl = v3_len(b->v), wl = v3_len(b->w);
    bool linear = vl > w->set.max_linear, angular = wl > w->set.max_angular;
    if (linear) {
        *cut = (sim_cut){i, false, vl, w->set.max_linear, false};
        b->v = v3_scale(b->v, w->set.max_linear / vl);
    }
    if (angular) {
        if (!linear) *cut = (sim_cut){i, true, wl, w->set.max_angular, false};
        b->L = v3_scale(b->L, w->set.max_angular / wl);
        body_update_w(b);
    }
    return linear || angular;
}

/* The speed limits on the n objects of list; true when one was cut, the
 * collision then counted in stats (the world's first such, with what it cut). */
static bool limit_all(world *w, const int *list, int n)
{
    bool cut = false;
    sim_cut first = {-1, false, 0, 0, false}, one = first;
    for (int j = 0; j < n; j++) {
        if (!limit_speeds(w, list[j], &one)) continue;
        if (!cut) first = one;
        cut = true;
    }
    if (cut && w->st.speed_cuts++ == 0) w->st.first_cut = first;
    return cut;
}

void answer_count(world *w, friction_flags f, int object)
{
    if (f.energy_cut) w->st.energy_cuts++;
    if (f.unconverged) w->st.cone_unconverged++;
    if (f.painleve && w->st.painleve++ == 0) w->st.first_painleve = object;
}

/* Collision c's impulses with friction (friction.h), of its first n rows: one
 * point struck alone by Mirtich's integration, points together by the cones'
 * compression and then restitution.  Applies them; false when the problem is
 * too large (nothing applied). */
static bool solve_rough(world *w, collision *c, int n)
{
    body **now = w->answer.now;
    bool *mobile = w->answer.mark;
    friction_flags f = {false, false, false};
    int who = body_is_static(w->bodies[c->p->a]) || w->bodies[c->p->a]->held ? c->p->b : c->p->a;
    if (n == 1 && c->held < 0) {
        f = friction_impact(&c->rows[0], now, mobile, &c->lambda[0]);
    } else {
        double ke = friction_energy(c->rows, n, now, mobile);
        if (friction_compress(c->rows, n, now, mobile, c->u, c->lambda, w->answer.fw, &f) != 0)
            return false;
        friction_restitute(c->rows, n, now, mobile, c->lambda, c->held < 0 ? ke : HUGE_VAL,
                           w->answer.fw, &f);
    }
    for (int r = n; r < c->nr; r++) c->lambda[r] = 0;
    answer_count(w, f, who);
    return true;
}

/* Solves collision c's impulses and applies them, then the speed limits: true
 * when solved (nothing is applied when not).  Its objects are mobile no more. */
static bool solve(world *w, collision *c)
{
    body **now = w->answer.now;
    bool *mobile = w->answer.mark, hand = c->held >= 0;
    impulse_row *rows = c->rows;
    for (int r = 0; r < c->nr; r++) {
        c->u[r] = impulse_speed(&rows[r], now);
        if (r < c->own) c->closing = d_max(c->closing, -c->u[r]);
        /* a rebound too slow to see is no rebound: they stay in contact */
        if (rows[r].e < 1 && rows[r].e * -c->u[r] < SIM_BOUNCE_SPEED) rows[r].e = 0;
        /* but nothing stays on a held object: it parts at that speed */
        if (hand && r < c->own && rows[r].e == 0) c->u[r] -= SIM_BOUNCE_SPEED;
    }
    bool solved;
    if (friction_any(rows, c->nr)) {
        solved = solve_rough(w, c, c->nr);
        if (!solved && c->own < c->nr) solved = solve_rough(w, c, c->own);
    } else {
        solved = impulse_solve(rows, c->nr, now, mobile, c->u, c->lambda, w->answer.lcp) == 0;
        if (!solved && c->own < c->nr) /* too many: the contact's own points alone */
            solved = impulse_solve(rows, c->own, now, mobile, c->u, c->lambda, w->answer.lcp) == 0;
    }
    if (solved && limit_all(w, c->objects, c->n)) {
        /* the limits must not turn a point back into its contact: those that would
         * approach again stop there */
        double u2[IMPULSE_MAX_ROWS], l2[IMPULSE_MAX_ROWS];
        for (int r = 0; r < c->nr; r++) {
            rows[r].e = 0;
            u2[r] = d_min(0, impulse_speed(&rows[r], now));
        }
        if (impulse_solve(rows, c->nr, now, mobile, u2, l2, w->answer.lcp) == 0)
            for (int r = 0; r < c->nr; r++) c->lambda[r] += l2[r];
    }
    for (int j = 0; j < c->n; j++) mobile[c->objects[j]] = false;
    return solved;
}

/* Collision c's event at time t, from its pair's own impulses (none when they
 * sum to nothing). */
static void report(world *w, const collision *c, double t)
{
    double j_sum = 0;
    vec3 at = v3(0, 0, 0);
    for (int r = 0; r < c->own; r++) {
        j_sum += c->lambda[r];
        at = v3_mad(at, c->rows[r].at, c->lambda[r]);
    }
    if (!(j_sum > 0)) return;
    w->st.collisions++;
    vec3 nab = w->pairs.hits[c->k].r.normal; /* from b to a */
    world_event(w, &(sim_event){t, c->p->a, c->p->b, v3_scale(at, 1 / j_sum), nab, j_sum, c->closing});
}

/* Collision c's pair stays in lasting contact where a point of its own no longer
 * moves apart (never with a held object: each of its contacts is a collision). */
static void stay_or_part(world *w, const collision *c)
{
    pair *p = c->p;
    double still = 1e3 * tol_speed(w->bodies[p->a], w->bodies[p->b]);
    p->hit = w->pairs.hits[c->k].cache;
    pieces_hit_from_found(pair_pieces(w, p));
    for (int r = 0; r < c->own && c->held < 0; r++) {
        /* (a lossy contact that opens too slowly to see a rebound: none) */
        double open = c->rows[r].e < 1 || c->e < 1 ? SIM_BOUNCE_SPEED : still;
        if (impulse_speed(&c->rows[r], w->answer.now) <= open) p->touching = true;
    }
}

/* Held body i stops where it is at time t, until the hand sets its motion again
 * (hold.h): it met what cannot give way. */
static void hold_stop(world *w, int i, double t)
{
    body *b = w->bodies[i];
    step_sync(w, i, t);
    b->hold_v = b->v = v3(0, 0, 0);
    body_set_angular_vel(b, v3(0, 0, 0));
    retime_object(w, i, t);
}

void answer_contact(world *w, long k, double t, double t_end)
{
    pair *p = &w->pairs.p[k];
    int seeds[2] = {-1, -1}, ns = 0, *mine = w->answer.objects;
    bool ha = w->bodies[p->a]->held, hb = w->bodies[p->b]->held, hand = ha || hb;
    if (!body_is_static(w->bodies[p->a]) && !ha) seeds[ns++] = p->a;
    if (!body_is_static(w->bodies[p->b]) && !hb) seeds[ns++] = p->b;
    if (hand && ns == 0) {
        w->time = t;
        if (ha) hold_stop(w, p->a, t);
        if (hb) hold_stop(w, p->b, t);
        return;
    }
    int n = rest_component(w, seeds, ns, mine);
    for (int j = 0; j < n; j++) step_sync(w, mine[j], t);
    int held = ha ? p->a : hb ? p->b : -1;
    if (hand) step_sync(w, held, t);
    w->time = t;
    /* (its arrays are written as they are filled: kilobytes a collision would
     * otherwise clear) */
    collision c;
    c.k = k;
    c.p = p;
    c.objects = mine;
    c.n = n;
    c.held = held;
    c.e = d_min(w->bodies[p->a]->elasticity, w->bodies[p->b]->elasticity);
    c.closing = 0;
    gather(w, &c);
    if (solve(w, &c)) report(w, &c, t);
    else if (hand) hold_stop(w, held, t); /* what it pushes cannot give way */
    else w->st.unsolved++;
    stay_or_part(w, &c);
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) retime_object(w, mine[j], t);
    if (hand) retime_object(w, held, t);
    answer_clusters(w, mine, n, t, t_end);
}

void answer_object(world *w, int i, double t, double t_end)
{
    int *mine = w->answer.objects;
    body *b = w->bodies[i];
    w->time = t;
    if (b->mode == MODE_SLIDE) {
        step_sync(w, i, t);
        /* across a seam, onto a coplanar face: on it slides */
        if (rest_slide_on(w, i)) {
            retime_object(w, i, t);
            return;
        }
        /* over the edge: the cluster's steps decide what it does there */
        b->mode = MODE_GENERAL;
        b->slide_on = -1;
        retime_object(w, i, t);
        answer_clusters(w, &i, 1, t, t_end);
        return;
    }
    int n = rest_cluster(w, i, mine);
    for (int j = 0; j < n; j++) step_sync(w, mine[j], t);
    cluster_settle(w, mine, n);
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) retime_object(w, mine[j], t);
    if (t < t_end) answer_clusters(w, mine, n, t, t_end);
}

