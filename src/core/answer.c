/* answer.c: answering a step's events (answer.h).
 *
 * A pair's contact, and a cluster's landing on a new support point, begin an
 * instant (instant.h).  A slide that leaves its face goes on across a seam, or
 * over the edge as a cluster.  A cluster's step that ends without a landing
 * ends with its last kicks (cluster_settle); then every object the event touched
 * gets its mode anew (rest_classify), and those left general start a cluster's
 * step (cluster.h).
 */
#include "answer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cluster.h"
#include "friction.h"
#include "grow.h"
#include "impulse.h"
#include "instant.h"
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
    free(s->flights);
    free(s->balanced);
    free(s->now);
    free(s->mark);
    free(s->landing);
    free(s->kicks);
    free(s->seeds);
    free(s->lcp);
    if (s->fw) friction_work_free(s->fw);
    free(s->fw);
    if (s->rw) rows_free(s->rw);
    free(s->rw);
    instant_free(s->instant);
    answer_init(s);
}

int answer_prepare(world *w, bool changed)
{
    answer_scratch *s = &w->answer;
    if (!s->lcp && !(s->lcp = malloc(lcp_work_size(IMPULSE_MAX_ROWS)))) return -1;
    if (!s->fw && !(s->fw = calloc(1, sizeof *s->fw))) return -1;
    if (!s->rw && !(s->rw = calloc(1, sizeof *s->rw))) return -1;
    if (rows_room(s->rw, SIM_CLUSTER_ROWS, SIM_CLUSTER_ROWS) != 0) return -1;
    if (instant_prepare(&s->instant, w->n) != 0) return -1;
    if (w->n > s->cap) {
        bool ok = true;
        changed = true;
        s->objects = grow_resized(s->objects, sizeof *s->objects, w->n, &ok);
        s->cluster = grow_resized(s->cluster, sizeof *s->cluster, w->n, &ok);
        s->classify = grow_resized(s->classify, sizeof *s->classify, w->n, &ok);
        s->kicked = grow_resized(s->kicked, sizeof *s->kicked, w->n, &ok);
        s->flights = grow_resized(s->flights, sizeof *s->flights, w->n, &ok);
        s->balanced = grow_resized(s->balanced, sizeof *s->balanced, w->n, &ok);
        s->now = grow_resized(s->now, sizeof *s->now, w->n, &ok);
        s->mark = grow_resized(s->mark, sizeof *s->mark, w->n, &ok);
        s->landing = grow_resized(s->landing, sizeof *s->landing, w->n, &ok);
        s->kicks = grow_resized(s->kicks, sizeof *s->kicks, w->n, &ok);
        s->seeds = grow_resized(s->seeds, sizeof *s->seeds, w->n, &ok);
        if (!ok) return -1;
        s->cap = w->n;
    }
    if (!changed) return 0;
    for (int i = 0; i < w->n; i++) {
        s->kicked[i] = s->balanced[i] = *w->bodies[i];
        s->now[i] = w->bodies[i];
        s->mark[i] = false;
        s->landing[i] = -1;
        s->kicks[i].h = 0;
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

void answer_count(world *w, friction_flags f, int object)
{
    if (f.energy_cut) w->st.energy_cuts++;
    if (f.unconverged) w->st.cone_unconverged++;
    if (f.painleve && w->st.painleve++ == 0) w->st.first_painleve = object;
}

void answer_contact(world *w, long k, double t, double t_end)
{
    instant_seed seed = {k, w->pairs.hits[k].r, w->pairs.hits[k].cache};
    /* (a pair of several pieces: its next search starts from the pieces' contact
     * this one found, as its hit cache does) */
    pieces_hit_from_found(pair_pieces(w, &w->pairs.p[k]));
    instant_answer(w, &seed, 1, t, t_end);
}

/* The landings that end the step of the cluster of the n objects of list (their
 * states at t): each pair once, closest as they are now, into seeds (room for
 * n); their count.  The objects' landings are cleared. */
static int landings(world *w, const int *list, int n, instant_seed *seeds)
{
    int ns = 0;
    long *landing = w->answer.landing;
    for (int j = 0; j < n; j++) {
        long k = landing[list[j]];
        landing[list[j]] = -1;
        bool seen = k < 0;
        for (int s = 0; s < ns && !seen; s++) seen = seeds[s].slot == k;
        if (seen) continue;
        pair *p = &w->pairs.p[k];
        closest_result r = pair_query(w, p, w->bodies[p->a], w->bodies[p->b]);
        if (r.status != CLOSEST_INVALID) seeds[ns++] = (instant_seed){k, r, p->cache};
    }
    return ns;
}

void answer_object(world *w, int i, double t, double t_end)
{
    int *mine = w->answer.objects;
    body *b = w->bodies[i];
    w->time = t;
    if (body_mode_on_face(b->mode)) {
        step_sync(w, i, t);
        /* its closed form's end: it sticks, rolls, slides on, or goes to a
         * cluster */
        if (rest_face_stop(w, i)) {
            retime_object(w, i, t);
            if (b->state == STATE_DYNAMIC && b->mode == MODE_GENERAL) answer_clusters(w, &i, 1, t, t_end);
            return;
        }
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
    for (int j = 0; j < n; j++) {
        step_sync(w, mine[j], t);
        w->answer.kicks[mine[j]].h = 0;
    }
    /* the step ends with its last kicks, which stop its closed points
     * approaching; where it ends at a new support point's landing, that is
     * then an instant, which goes on to the modes and the next step itself (so
     * that the landing meets the closed points at rest, as in the limit of short
     * steps: answered together with their approach, of order the step's
     * acceleration times its length, it would lose energy in proportion to the
     * landing's speed) */
    instant_seed *seeds = w->answer.seeds;
    int ns = landings(w, mine, n, seeds);
    cluster_settle(w, mine, n);
    if (ns > 0) {
        /* (their flights from the kicked states, which the instant brings its
         * objects to t by) */
        for (int j = 0; j < n; j++) step_start(w, mine[j], t);
        instant_answer(w, seeds, ns, t, t_end);
        return;
    }
    rest_classify(w, mine, n);
    for (int j = 0; j < n; j++) {
        const body *o = w->bodies[mine[j]];
        /* (one that goes on as a cluster has its flight started by its next
         * step's kicks, below: only its event ends here) */
        if (t < t_end && o->state == STATE_DYNAMIC && o->mode == MODE_GENERAL)
            retime_event(w, mine[j], HUGE_VAL);
        else
            retime_object(w, mine[j], t);
    }
    if (t < t_end) answer_clusters(w, mine, n, t, t_end);
}

