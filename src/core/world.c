/* world.c: the objects, the simulation settings with every start-up value in one
 * place, and the frame's events.
 *
 * Defaults come from the thesis's Table A.5 (time_step 0.1, collision_dist 0.25,
 * max_linear 8, max_angular 4) and from language.md for what vroc adds.
 */
#include "world.h"

#include <assert.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

sim_settings sim_settings_defaults(void)
{
    sim_settings s;
    memset(&s, 0, sizeof s);
    s.time_step = 0.1;
    s.collision_dist = 0.25;
    s.internal_step = 0;
    s.max_linear = 8.0;
    s.max_angular = 4.0;
    s.force = (dir_amount){v3(0, 0, 0), 0};
    s.collision_heap = true;
    s.default_friction = 0.5;
    s.default_rolling_friction = 0.01;
    return s;
}

void world_init(world *w)
{
    memset(w, 0, sizeof *w);
    w->set = sim_settings_defaults();
    pairs_init(&w->pairs);
    broad_init(&w->broad);
    sched_init(&w->sched);
    step_init(&w->step);
    answer_init(&w->answer);
    guard_init(&w->guard);
}

void world_free(world *w)
{
    for (int i = 0; i < w->n; i++) {
        body_free(w->bodies[i]);
        free(w->bodies[i]);
    }
    free(w->bodies);
    w->bodies = NULL;
    w->n = w->cap = 0;
    free(w->names);
    w->names = NULL;
    w->ncap = 0;
    free(w->events);
    w->events = NULL;
    w->nevents = w->capevents = 0;
    pairs_free(&w->pairs);
    broad_free(&w->broad);
    sched_free(&w->sched);
    step_free(&w->step);
    answer_free(&w->answer);
    guard_free(&w->guard);
}

void world_event(world *w, const sim_event *e)
{
    if (w->nevents == w->capevents) {
        long cap = w->capevents ? 2 * w->capevents : 64;
        sim_event *ne = realloc(w->events, (size_t)cap * sizeof *ne);
        if (!ne) {
            w->st.events_lost++;
            return;
        }
        w->events = ne;
        w->capevents = cap;
    }
    w->events[w->nevents++] = *e;
}

/* ---- the index of the names: so that finding an object, and making one with a
 * new name, costs the same whatever the number of objects ---- */

/* FNV-1a. */
static unsigned name_hash(const char *s)
{
    unsigned h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

/* Puts object i in the index (which has room). */
static void name_put(world *w, int i)
{
    unsigned m = (unsigned)w->ncap - 1, at = name_hash(w->bodies[i]->name) & m;
    while (w->names[at]) at = (at + 1) & m;
    w->names[at] = i + 1;
}

/* Makes the index anew with room for cap objects: 0, or -1 when out of memory
 * (the old index stays). */
static int names_rebuild(world *w, int cap)
{
    int ncap = 16;
    while (ncap < 2 * cap) ncap *= 2;
    int *names = calloc((size_t)ncap, sizeof *names);
    if (!names) return -1;
    free(w->names);
    w->names = names;
    w->ncap = ncap;
    for (int i = 0; i < w->n; i++) name_put(w, i);
    return 0;
}

int world_find(const world *w, const char *name)
{
    if (w->ncap == 0) return -1;
    unsigned m = (unsigned)w->ncap - 1;
    for (unsigned at = name_hash(name) & m; w->names[at]; at = (at + 1) & m)
        if (strcmp(w->bodies[w->names[at] - 1]->name, name) == 0) return w->names[at] - 1;
    return -1;
}

int world_add(world *w, body *b)
{
    if (w->n == w->cap) {
        int cap = w->cap ? 2 * w->cap : 16;
        body **nb = realloc(w->bodies, (size_t)cap * sizeof *nb);
        if (!nb) {
            body_free(b);
            free(b);
            return -1;
        }
        w->bodies = nb;
        w->cap = cap;
    }
    /* (at most half full) */
    if (2 * (w->n + 1) > w->ncap && names_rebuild(w, 2 * (w->n + 1)) != 0) {
        body_free(b);
        free(b);
        return -1;
    }
    w->bodies[w->n] = b;
    name_put(w, w->n);
    w->pairs.dirty = true;
    return w->n++;
}

/* An object's index k after object i is deleted: -1 for i itself. */
static int index_after(int k, int i)
{
    return k == i ? -1 : k > i ? k - 1 : k;
}

void world_delete(world *w, int i)
{
    assert(i >= 0 && i < w->n);
    body_free(w->bodies[i]);
    free(w->bodies[i]);
    memmove(&w->bodies[i], &w->bodies[i + 1], (size_t)(w->n - i - 1) * sizeof *w->bodies);
    w->n--;
    /* the indices after i moved: the index is made again in place */
    memset(w->names, 0, (size_t)w->ncap * sizeof *w->names);
    for (int k = 0; k < w->n; k++) name_put(w, k);
    w->pairs.dirty = true;
    for (int k = 0; k < w->n; k++) {
        body *b = w->bodies[k];
        b->slide_on = index_after(b->slide_on, i);
        if (b->slide_on < 0 && body_mode_on_face(b->mode)) b->mode = MODE_FREE;
    }
    /* the pairs keep their objects (pairs_update finds the lasting contacts again
     * by them): those of i end */
    for (long k = 0; k < w->pairs.n; k++) {
        pair *p = &w->pairs.p[k];
        if (p->a < 0) continue; /* a free slot */
        if (p->a == i || p->b == i) {
            p->touching = false;
            p->a = p->b = 0;
            continue;
        }
        p->a = index_after(p->a, i);
        p->b = index_after(p->b, i);
    }
}

void world_counts(const world *w, int *dynamic, int *stat)
{
    int d = 0, s = 0;
    for (int i = 0; i < w->n; i++) {
        if (body_is_static(w->bodies[i])) s++;
        else d++;
    }
    *dynamic = d;
    *stat = s;
}

long world_pairs(const world *w)
{
    int d, s;
    world_counts(w, &d, &s);
    return (long)d * (d - 1) / 2 + (long)d * s;
}

long world_subframes(const world *w)
{
    const sim_settings *s = &w->set;
    if (s->time_step <= 0) return 0;
    double h = s->internal_step > 0 ? s->internal_step : s->collision_dist / (2 * s->max_linear);
    if (!(h > 0) || isinf(h)) return 1;
    double n = ceil(s->time_step / h * (1 - 1e-12));
    if (n < 1) n = 1;
    return n > 1e12 ? (long)1e12 : (long)n;
}

/* FNV-1a over n bytes at p, continuing from h. */
static unsigned long long fnv(unsigned long long h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t k = 0; k < n; k++) h = (h ^ c[k]) * 0x100000001b3ULL;
    return h;
}

unsigned long long world_hash(const world *w)
{
    unsigned long long h = fnv(0xcbf29ce484222325ULL, &w->time, sizeof w->time);
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        int tags[2] = {(int)b->state, (int)b->mode};
        double s[16] = {b->x.x, b->x.y, b->x.z, b->q.w, b->q.x, b->q.y, b->q.z,
                        b->v.x, b->v.y, b->v.z, b->L.x, b->L.y, b->L.z, b->w.x, b->w.y, b->w.z};
        h = fnv(h, b->name, strlen(b->name) + 1);
        h = fnv(h, tags, sizeof tags);
        h = fnv(h, s, sizeof s);
        if (b->held) { /* (hold.h; a world holding nothing hashes as before) */
            double hs[6] = {b->hold_pivot.x, b->hold_pivot.y, b->hold_pivot.z,
                            b->hold_v.x,     b->hold_v.y,     b->hold_v.z};
            h = fnv(h, hs, sizeof hs);
        }
    }
    return h;
}
