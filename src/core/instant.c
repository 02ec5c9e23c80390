/* instant.c: contacts that begin at one instant, answered together in waves
 * (instant.h).
 *
 * The instant keeps a list of its contacts, each with the rows of its points
 * (rows.h) evaluated once, where the objects are at t: only their velocities
 * change within an instant.  An object's contacts are gathered when it first
 * takes an impulse (or begins the instant): its lasting contacts, and its pairs
 * within the contact distance (their bounding spheres first, so that far pairs
 * cost no query).  Each wave takes the contacts that approach; the bodies of
 * those that took an impulse have their contacts gathered for the next.
 */
#include "instant.h"

#include <math.h>
#include <stdlib.h>

#include "answer.h"
#include "cluster.h"
#include "friction.h"
#include "grow.h"
#include "impulse.h"
#include "pairs.h"
#include "rest.h"
#include "retime.h"
#include "rows.h"
#include "squeeze.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* Contacts, and rows of their points, that one instant has room for from the
 * start; a larger one (a crowd of hundreds struck at once) grows the room
 * (instant_room), so that no contact is left out. */
#define INSTANT_MAX_CONTACTS 64
#define INSTANT_MAX_ROWS (4 * IMPULSE_MAX_ROWS)
/* Waves an instant may take for each of its contacts before one last solve with
 * no restitution ends it. */
#define INSTANT_WAVES_PER_CONTACT 4

/* One contact of the instant. */
typedef struct {
    pair *p;
    long slot;
    closest_cache hit;  /* where the pair's next search starts */
    vec3 normal;        /* from p->b towards p->a */
    int first, n;       /* its rows */
    double e;           /* the pair's restitution */
    double kept;        /* how fast its points may close by a cluster's own steps
                         * (a lasting contact's; 0 for another) */
    bool lasting;       /* in lasting contact when the instant began */
    bool held;          /* a held object is one of its two */
    bool taken;         /* a wave took it */
    bool rough;         /* its pair has friction */
    double j, closing;  /* its impulse over the waves, the fastest it closed */
    vec3 at;            /* its rows' impulses times where they act, summed */
} contact;

/* How a solve treats its rows' restitution. */
typedef enum {
    SOLVE_WAVE,      /* each row's own (instant.h) */
    SOLVE_LAST,      /* none: the last solve, after 4 n waves */
    SOLVE_LIMITS,    /* none, and only what would approach again stops (the
                      * speed limits cut a result) */
    SOLVE_JAMMED     /* none, and nothing parts from a held object: it has
                      * stopped against what cannot give way (squeeze.h) */
} solve_kind;

struct instant_work {
    contact *c;
    int nc, nseeds, cap_c;
    impulse_row *row;
    int nr, cap_r;
    /* one solve: its rows, the contact of each, their normal speeds before (as
     * the problem takes them) and after, their impulses (room for cap_r) */
    impulse_row *take;
    int *of, m;
    double *u, *closing, *lambda;
    bool *wave;     /* the contacts a solve takes (room for cap_c) */
    bool *joined;   /* per object: brought to the instant (in `objects`) */
    bool *opened;   /* per object: its contacts gathered */
    int *objects;   /* the objects joined, in the order they joined */
    int nobj, cap;
    double t;
    bool cut;       /* the speed limits cut its result (limit_all) */
    bool hand;      /* a held object is among its objects (squeeze.h) */
    bool take_back; /* the joining objects' cluster kicks are taken back (join) */
    bool checked;   /* and instant_answer has seen that the seeds close without */
    int *backs;     /* the seeds' objects they were taken back from, nbacks */
    int nbacks;
};

/* Makes room for at least nc contacts and nr rows, keeping what I holds: 0, or
 * -1 when out of memory (the room as it was). */
static int instant_room(instant_work *I, int nc, int nr)
{
    bool ok = true;
    if (nc > I->cap_c) {
        long n = grow_doubled(nc, I->cap_c);
        I->c = grow_resized(I->c, sizeof *I->c, n, &ok);
        I->wave = grow_resized(I->wave, sizeof *I->wave, n, &ok);
        if (ok) I->cap_c = (int)n;
    }
    if (ok && nr > I->cap_r) {
        long n = grow_doubled(nr, I->cap_r);
        I->row = grow_resized(I->row, sizeof *I->row, n, &ok);
        I->take = grow_resized(I->take, sizeof *I->take, n, &ok);
        I->of = grow_resized(I->of, sizeof *I->of, n, &ok);
        I->u = grow_resized(I->u, sizeof *I->u, n, &ok);
        I->closing = grow_resized(I->closing, sizeof *I->closing, n, &ok);
        I->lambda = grow_resized(I->lambda, sizeof *I->lambda, n, &ok);
        if (ok) I->cap_r = (int)n;
    }
    return ok ? 0 : -1;
}

int instant_prepare(instant_work **iw, int n)
{
    if (!*iw && !(*iw = calloc(1, sizeof **iw))) return -1;
    instant_work *I = *iw;
    if (instant_room(I, INSTANT_MAX_CONTACTS, INSTANT_MAX_ROWS) != 0) return -1;
    if (n <= I->cap) return 0;
    bool ok = true;
    I->joined = grow_resized(I->joined, sizeof *I->joined, n, &ok);
    I->opened = grow_resized(I->opened, sizeof *I->opened, n, &ok);
    I->objects = grow_resized(I->objects, sizeof *I->objects, n, &ok);
    I->backs = grow_resized(I->backs, sizeof *I->backs, n, &ok);
    if (!ok) return -1;
    for (int i = I->cap; i < n; i++) I->joined[i] = I->opened[i] = false;
    I->cap = n;
    return 0;
}

void instant_free(instant_work *iw)
{
    if (!iw) return;
    free(iw->joined);
    free(iw->opened);
    free(iw->objects);
    free(iw->backs);
    free(iw->c);
    free(iw->wave);
    free(iw->row);
    free(iw->take);
    free(iw->of);
    free(iw->u);
    free(iw->closing);
    free(iw->lambda);
    free(iw);
}

static double closing_of(const world *w, const instant_work *I, const contact *c);

/* ------------------------------------------------------------ who joins */

/* True when object i moves with the instant's impulses: dynamic (or resting),
 * and not held. */
static bool mobile(const world *w, int i)
{
    const body *b = w->bodies[i];
    return !body_is_static(b) && !b->held;
}

/* The share of object i's cluster kick that is not yet spent at the instant
 * (join), added back times `sign` (-1 takes it back, +1 gives it again). */
static void kick_share(world *w, const instant_work *I, int i, double sign)
{
    const kick_record *k = &w->answer.kicks[i];
    body *b = w->bodies[i];
    double share = d_max(0, 1 - 2 * (I->t - k->t0) / k->h);
    b->v = v3_mad(b->v, k->dv, sign * share);
    b->L = v3_mad(b->L, k->dL, sign * share);
    body_update_w(b);
    step_start(w, i, I->t);
}

/* Object i joins the instant: brought to its time.  One within the first half
 * of a cluster's step has its velocities as the step's contact forces would
 * have them there: the step's start kick gave it at once the impulse of the
 * forces over the first half of the step (cluster.h), and by a fraction s of the
 * step they have given it their impulse over s of it, so a share 1 - 2 s of the
 * kick is taken back.  Without it, an object struck as its step begins (a row of
 * touching balls on a floor) would leave with the kick that was to hold it up
 * against gravity, and hop.  (Not in the second half: the kick may also have
 * stopped an approach left from before, which is no force to extrapolate; nor
 * where the kicks themselves made the instant: instant_answer.) */
static void join(world *w, instant_work *I, int i)
{
    if (I->joined[i]) return;
    I->joined[i] = true;
    I->objects[I->nobj++] = i;
    I->hand = I->hand || w->bodies[i]->held;
    step_sync(w, i, I->t);
    kick_record *k = &w->answer.kicks[i];
    if (I->take_back && k->h > 0 && I->t >= k->t0 && I->t < k->t0 + k->h) {
        kick_share(w, I, i, -1);
        if (!I->checked) { /* (the seeds' objects: instant_answer decides) */
            I->backs[I->nbacks++] = i;
            return;
        }
    }
    k->h = 0;
}

/* Object i's centre of mass at the instant, without bringing it there (for a
 * bound). */
static vec3 centre_at(world *w, instant_work *I, int i)
{
    const flight *f = &w->step.fl[i];
    if (I->joined[i] || !step_moves(w, i) || f->kind == FLIGHT_STILL) return body_com(w->bodies[i]);
    if (f->kind == FLIGHT_HELD) {
        join(w, I, i);
        return body_com(w->bodies[i]);
    }
    double h = I->t - f->t0;
    return v3_add(f->c0, v3_add(v3_scale(f->v0, h), v3_scale(f->a, 0.5 * h * h)));
}

/* True when pair slot is in the instant already. */
static bool listed(const instant_work *I, long slot)
{
    for (int k = 0; k < I->nc; k++)
        if (I->c[k].slot == slot) return true;
    return false;
}

/* Pair slot, its objects joined and closest as r, joins the instant with the
 * rows of its points; hit the features its next search starts from. */
static void add_contact(world *w, instant_work *I, long slot, const closest_result *r,
                        closest_cache hit)
{
    pair *p = &w->pairs.p[slot];
    if (r->status == CLOSEST_INVALID) return;
    /* (room for it: where memory runs out it is left out, counted) */
    if (instant_room(I, I->nc + 1, I->nr + CONTACT_MAX_POINTS) != 0) {
        w->st.unsolved++;
        return;
    }
    const body *A = w->bodies[p->a], *B = w->bodies[p->b];
    /* (a crowded object's contacts do not bounce: guard.h) */
    bool crowd = guard_crowded(&w->guard, p->a) || guard_crowded(&w->guard, p->b);
    double e = crowd ? 0 : d_min(A->elasticity, B->elasticity);
    row_list rl = {I->row + I->nr, NULL, NULL, 0, I->cap_r - I->nr, false};
    int n = rows_add(&rl, p, A, B, r, tol_region(A, B, r->distance), e, w->bodies);
    if (n == 0) return;
    contact *c = &I->c[I->nc++];
    *c = (contact){.p = p, .slot = slot, .hit = hit, .normal = r->normal, .first = I->nr, .n = n, .e = e,
                   .lasting = p->touching, .held = A->held || B->held, .closing = 0,
                   .rough = friction_mu(A, B) > 0};
    if (c->lasting) c->kept = cluster_stepping_speed(w, A) + cluster_stepping_speed(w, B);
    I->nr += n;
}

/* Object i's contacts join the instant (once): its lasting contacts, and its
 * pairs within the contact distance (within the squeeze gap where a held object
 * pushes: squeeze.h). */
static void gather(world *w, instant_work *I, int i)
{
    if (I->opened[i]) return;
    I->opened[i] = true;
    join(w, I, i);
    const body *bi = w->bodies[i];
    vec3 ci = body_com(bi);
    FOR_PAIRS_OF(w, i, link, p) {
        int o = link->other;
        if ((!p->near && !p->touching) || listed(I, link->slot)) continue;
        const body *bo = w->bodies[o];
        double reach = I->hand ? d_max(tol_touch(bi, bo), squeeze_gap(bi, bo)) : tol_touch(bi, bo);
        if (!p->touching) {
            /* (apart by more than the contact distance, bounding spheres and all) */
            double apart = v3_len(v3_sub(centre_at(w, I, o), ci)) - bi->shape.r_out - bo->shape.r_out;
            if (apart > 2 * reach) continue;
        }
        join(w, I, o);
        const body *A = w->bodies[p->a], *B = w->bodies[p->b];
        closest_result r = pair_query(w, p, A, B);
        if (r.status == CLOSEST_INVALID || (!p->touching && r.distance > reach)) continue;
        add_contact(w, I, link->slot, &r, p->cache);
    }
}

/* ------------------------------------------------------------ the waves */

/* How fast contact c's fastest point closes now (m/s, < 0 when all part). */
static double closing_of(const world *w, const instant_work *I, const contact *c)
{
    double s = -HUGE_VAL;
    for (int k = c->first; k < c->first + c->n; k++) s = d_max(s, -impulse_speed(&I->row[k], w->bodies));
    return s;
}

/* True when contact c approaches: faster than rounding, and than a cluster's
 * own steps close a lasting contact. */
static bool approaches(const world *w, const instant_work *I, const contact *c)
{
    const body *A = w->bodies[c->p->a], *B = w->bodies[c->p->b];
    return closing_of(w, I, c) > tol_speed(A, B) + c->kept;
}

/* A row's restitution in a wave, closing at that speed (instant.h). */
static double restitution(const contact *c, double closing)
{
    /* a rebound too slow to see, where the contact loses energy (e < 1, or
     * friction: a cube of e = 1 with friction rocked on its face for good,
     * its corners landing in turn ever faster, hundreds a frame) */
    if ((c->e < 1 || c->rough) && c->e * closing < SIM_BOUNCE_SPEED) return 0;
    if (c->lasting && closing <= c->kept) return 0; /* kept closed by its cluster */
    return c->e;
}

/* The m rows of I->take solved with friction (friction.h) into I->lambda, and
 * applied to the mobile objects mob: one point struck alone by Mirtich's
 * integration, points together by the cones' compression and then restitution
 * (e times each point's compression impulse, scaled down where it would raise
 * the energy; with a held object, its hand's energy is not bounded).  Returns
 * 0, or -1 when there are too many (nothing applied). */
static int solve_rough(world *w, instant_work *I, int m, const bool *mob, bool held)
{
    body **bs = w->bodies;
    friction_flags f = {false, false, false};
    const impulse_row *r0 = &I->take[0];
    int who = mob[r0->p] ? r0->p : r0->q;
    /* a held object that pushes what cannot give way: no answer, as without
     * friction, so that it stops (unsolved) */
    if (held && impulse_solvable(I->take, m, bs, mob, I->u, w->answer.lcp) != 0) return -1;
    if (m == 1 && !held) {
        f = friction_impact(&I->take[0], bs, mob, &I->lambda[0]);
    } else {
        double ke = friction_energy(I->take, m, bs, mob);
        if (friction_compress(I->take, m, bs, mob, I->u, I->lambda, w->answer.fw, &f) != 0) return -1;
        friction_restitute(I->take, m, bs, mob, I->lambda, held ? HUGE_VAL : ke, w->answer.fw, &f);
    }
    answer_count(w, f, who);
    return 0;
}

/* The contacts marked in I->wave solved together as `kind` says, their impulses
 * applied to the mobile objects and added to the contacts: 0, or -1 when there
 * is no answer (nothing applied).  The contacts are taken either way. */
static int solve(world *w, instant_work *I, solve_kind kind)
{
    int m = I->m = 0;
    bool held = false;
    for (int k = 0; k < I->nc; k++) {
        contact *c = &I->c[k];
        if (!I->wave[k]) continue;
        c->taken = true;
        held = held || c->held;
        for (int r = c->first; r < c->first + c->n; r++) {
            impulse_row *row = &I->take[m];
            *row = I->row[r];
            double u = impulse_speed(row, w->bodies);
            I->closing[m] = -u;
            row->e = kind == SOLVE_WAVE ? restitution(c, -u) : 0;
            if (kind == SOLVE_LIMITS) u = d_min(0, u);
            /* nothing stays on a held object: it parts at that speed (unless it
             * has stopped against what cannot give way) */
            if (c->held && row->e == 0 && kind != SOLVE_JAMMED) u -= SIM_BOUNCE_SPEED;
            I->u[m] = u;
            I->of[m++] = k;
        }
    }
    I->m = m;
    if (m == 0) return 0;
    bool *mob = w->answer.mark;
    for (int k = 0; k < I->nobj; k++) mob[I->objects[k]] = mobile(w, I->objects[k]);
    /* (with friction, the same-instant waves' compression and restitution; the
     * speed limits' last solve stays frictionless, as it only stops what would
     * approach again) */
    /* (a crowd's, past FRICTION_MAX_POINTS, with friction too, in blocks; but
     * one with a held object there along the normals alone, for whether it has
     * an answer at all (impulse_solvable) is asked of IMPULSE_MAX_ROWS at most;
     * frictionless beyond IMPULSE_MAX_ROWS in the clusters' scratch, rows.h) */
    int ok;
    if (kind != SOLVE_LIMITS && (m <= FRICTION_MAX_POINTS || !held) && friction_any(I->take, m)) {
        ok = solve_rough(w, I, m, mob, held);
    } else if (m <= IMPULSE_MAX_ROWS) {
        ok = impulse_solve(I->take, m, w->bodies, mob, I->u, I->lambda, w->answer.lcp);
    } else {
        row_work *rw = w->answer.rw;
        ok = rows_room(rw, m, 0) != 0 ? -1
                                       : impulse_solve_in(I->take, m, w->bodies, mob, I->u, I->lambda, rw->lcp,
                                                          rw->A, rw->q, rw->wv);
    }
    for (int k = 0; k < I->nobj; k++) mob[I->objects[k]] = false;
    if (ok != 0) return -1;
    for (int r = 0; r < m; r++) {
        contact *c = &I->c[I->of[r]];
        c->j += I->lambda[r];
        c->at = v3_mad(c->at, I->take[r].at, I->lambda[r]);
        if (kind == SOLVE_WAVE) c->closing = d_max(c->closing, I->closing[r]);
    }
    return 0;
}

/* A solve found no answer.  With a held object among the instant's, what it
 * pushes cannot give way (squeeze.h): it stops, and every contact is solved again
 * with no restitution against it standing still, so that what it pressed stops
 * too; where even that has no answer (rounding), they stop where they are.
 * Without one, a fault counted in stats. */
static void unsolved(world *w, instant_work *I)
{
    if (!I->hand) {
        w->st.unsolved++;
        return;
    }
    for (int k = 0; k < I->nobj; k++)
        if (w->bodies[I->objects[k]]->held) squeeze_hold_stop(w, I->objects[k], I->t);
    for (int k = 0; k < I->nc; k++) I->wave[k] = true;
    if (solve(w, I, SOLVE_JAMMED) == 0) return;
    w->st.unsolved++;
    for (int k = 0; k < I->nobj; k++) {
        body *b = w->bodies[I->objects[k]];
        if (!mobile(w, I->objects[k])) continue;
        b->v = v3(0, 0, 0);
        body_set_angular_vel(b, v3(0, 0, 0));
    }
}

/* The waves (instant.h), from the seeds' contacts. */
static void waves(world *w, instant_work *I)
{
    for (int wave = 0;; wave++) {
        bool any = false;
        for (int k = 0; k < I->nc; k++) {
            I->wave[k] = (wave == 0 && k < I->nseeds) || approaches(w, I, &I->c[k]);
            any = any || I->wave[k];
        }
        if (!any) return;
        if (wave >= INSTANT_WAVES_PER_CONTACT * I->nc) {
            /* one last solve of them all with no restitution ends it */
            w->st.waves_cut++;
            for (int k = 0; k < I->nc; k++) I->wave[k] = true;
            if (solve(w, I, SOLVE_LAST) != 0) unsolved(w, I);
            return;
        }
        if (solve(w, I, SOLVE_WAVE) != 0) {
            unsolved(w, I);
            return;
        }
        /* the contacts of the objects it set moving join the next */
        for (int r = 0; r < I->m; r++) {
            if (!(I->lambda[r] > 0)) continue;
            int p = I->take[r].p, q = I->take[r].q;
            if (mobile(w, p)) gather(w, I, p);
            if (mobile(w, q)) gather(w, I, q);
        }
    }
}

/* ------------------------------------------------------------ after the waves */

/* The speed limits on object i, where a collision set its speed: |v| <=
 * max_linear, |w| <= max_angular (L scaled down).  Writes what it cut to *cut;
 * true when it cut. */
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

/* The speed limits on the objects the instant's impulses moved; when one was cut,
 * the instant is counted in stats (the world's first such cut described), and
 * the points that would then approach again stop there. */
static void limit_all(world *w, instant_work *I)
{
    bool cut = false;
    sim_cut first = {-1, false, 0, 0, false}, one = first;
    bool *done = w->answer.mark;
    for (int k = 0; k < I->nc; k++) {
        const contact *c = &I->c[k];
        int ends[2] = {c->p->a, c->p->b};
        for (int s = 0; s < 2 && c->j > 0; s++) {
            int i = ends[s];
            if (done[i] || !mobile(w, i)) continue;
            done[i] = true;
            if (!limit_speeds(w, i, &one)) continue;
            if (!cut) first = one;
            cut = true;
        }
    }
    for (int k = 0; k < I->nobj; k++) done[I->objects[k]] = false;
    I->cut = cut;
    if (!cut) return;
    if (w->st.speed_cuts++ == 0) w->st.first_cut = first;
    for (int k = 0; k < I->nc; k++) I->wave[k] = true;
    solve(w, I, SOLVE_LIMITS);
}

/* One event for each contact that took an impulse, at the mean of where its
 * impulses act. */
static void report(world *w, const instant_work *I)
{
    for (int k = 0; k < I->nc; k++) {
        const contact *c = &I->c[k];
        if (!(c->j > 0)) continue;
        w->st.collisions++;
        world_event(w, &(sim_event){I->t, c->p->a, c->p->b, v3_scale(c->at, 1 / c->j), c->normal, c->j,
                                    c->closing});
    }
}

/* Each contact a wave took stays in lasting contact where a point of it no longer
 * moves apart (never with a held object: each of its contacts is a collision),
 * and parts where none does. */
static void stay_or_part(world *w, const instant_work *I)
{
    for (int k = 0; k < I->nc; k++) {
        const contact *c = &I->c[k];
        if (!c->taken) continue;
        pair *p = c->p;
        p->hit = c->hit;
        bool stays = false;
        /* (a lossy contact (e < 1, or friction), one kept closed, or one
         * whose result the speed limits cut (it lost energy, and its points
         * were stopped where they would approach again), that opens too
         * slowly to see a rebound: none;
         * else a cut spinning pair parts and meets again, ever more slowly) */
        const body *A = w->bodies[p->a], *B = w->bodies[p->b];
        double open = c->e < 1 || c->rough || c->lasting || I->cut ? SIM_BOUNCE_SPEED : 1e3 * tol_speed(A, B);
        for (int r = c->first; r < c->first + c->n && !c->held; r++)
            stays = stays || impulse_speed(&I->row[r], w->bodies) <= open;
        p->touching = stays;
    }
}

/* The modes and flights of the objects the instant touched, and of those pressed
 * together with them, from its time on; those left general start a cluster's
 * step (cluster.h). */
static void go_on(world *w, instant_work *I, double t_end)
{
    int *mine = w->answer.objects, n = 0;
    for (int k = 0; k < I->nobj; k++)
        if (mobile(w, I->objects[k])) mine[n++] = I->objects[k];
    n = rest_component(w, mine, n, mine);
    for (int j = 0; j < n; j++) join(w, I, mine[j]);
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) retime_object(w, mine[j], I->t);
    for (int k = 0; k < I->nobj; k++)
        if (w->bodies[I->objects[k]]->held) retime_object(w, I->objects[k], I->t);
    answer_clusters(w, mine, n, I->t, t_end);
}

void instant_answer(world *w, const instant_seed *seeds, int n, double t, double t_end)
{
    instant_work *I = w->answer.instant;
    I->t = t;
    I->nc = I->nr = I->nobj = I->nbacks = 0;
    I->take_back = true;
    I->checked = false;
    I->hand = false;
    w->time = t;
    for (int s = 0; s < n; s++) {
        const pair *p = &w->pairs.p[seeds[s].slot];
        join(w, I, p->a);
        join(w, I, p->b);
        if (!listed(I, seeds[s].slot)) add_contact(w, I, seeds[s].slot, &seeds[s].r, seeds[s].hit);
    }
    I->nseeds = I->nc;
    /* where none of the seeds approaches without the kicks taken back, the
     * kicks made the instant (a cluster pressed onto something new): it is
     * answered with them, as they are, else the next step's kicks would make it
     * again */
    bool closes = false;
    for (int k = 0; k < I->nseeds && !closes; k++) {
        const body *A = w->bodies[I->c[k].p->a], *B = w->bodies[I->c[k].p->b];
        closes = closing_of(w, I, &I->c[k]) > tol_speed(A, B);
    }
    for (int k = 0; k < I->nbacks; k++) {
        if (!closes) kick_share(w, I, I->backs[k], 1);
        w->answer.kicks[I->backs[k]].h = 0;
    }
    I->take_back = closes;
    I->checked = true;
    bool any = false;
    for (int k = 0; k < I->nobj; k++) any = any || mobile(w, I->objects[k]);
    if (!any) {
        /* held objects against static or held ones: they stop */
        for (int k = 0; k < I->nobj; k++)
            if (w->bodies[I->objects[k]]->held) squeeze_hold_stop(w, I->objects[k], t);
    } else {
        for (int s = 0; s < I->nseeds; s++) {
            const pair *p = I->c[s].p;
            if (mobile(w, p->a)) gather(w, I, p->a);
            if (mobile(w, p->b)) gather(w, I, p->b);
        }
        waves(w, I);
        limit_all(w, I);
        report(w, I);
        stay_or_part(w, I);
        go_on(w, I, t_end);
    }
    for (int k = 0; k < I->nobj; k++) I->joined[I->objects[k]] = I->opened[I->objects[k]] = false;
}

bool instant_closing(world *w, const pair *p, const closest_result *r)
{
    const body *A = w->bodies[p->a], *B = w->bodies[p->b];
    impulse_row rows[CONTACT_MAX_POINTS];
    row_list rl = {rows, NULL, NULL, 0, CONTACT_MAX_POINTS, false};
    int n = rows_add(&rl, p, A, B, r, tol_region(A, B, r->distance), 0, w->bodies);
    double limit = tol_speed(A, B) + cluster_stepping_speed(w, A) + cluster_stepping_speed(w, B);
    for (int k = 0; k < n; k++)
        if (-impulse_speed(&rows[k], w->bodies) > limit) return true;
    return false;
}
