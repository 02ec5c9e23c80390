/* world.c: the objects and the settings, with every start-up value in one place.
 *
 * Defaults come from the thesis's Table A.5 (time_step 0.1, collision_dist 0.25,
 * max_linear 8, max_angular 4) and from language.md for what vroc adds.
 */
#include "world.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

settings settings_defaults(void)
{
    settings s;
    memset(&s, 0, sizeof s);
    s.time_step = 0.1;
    s.collision_dist = 0.25;
    s.internal_step = 0;
    s.max_linear = 8.0;
    s.max_angular = 4.0;
    s.force = (dir_amount){v3(0, 0, 0), 0};
    snprintf(s.collision_sound, sizeof s.collision_sound, "click");
    s.collision_vol = 1.0;
    s.collision_heap = true;
    s.random_box = v3(2, 2, 2);
    s.seed = 1;
    s.head = v3(0, 0, 0);
    s.look_at = v3(0, 1, 0);
    s.up = v3(0, 0, 1);
    s.ipd = 0.064;
    s.fov = 60;
    s.image_w = 640;
    s.image_h = 512;
    snprintf(s.output, sizeof s.output, "frames");
    s.stereo = STEREO_PAIR;
    s.real = REAL_SOLID;
    s.record = false;
    s.hand = v3(0, 0, 0);
    s.hand_rotate = (dir_amount){v3(1, 0, 0), 0};
    s.trigger = false;
    s.select_mode = false;
    s.tracker[0] = '\0';
    return s;
}

void world_init(world *w)
{
    memset(w, 0, sizeof *w);
    w->set = settings_defaults();
}

void world_free_schedule(world *w)
{
    free(w->heap);
    free(w->heap_pos);
    free(w->bound);
    free(w->obj_first);
    free(w->obj_pairs);
    free(w->obj_other);
    free(w->box);
    free(w->parked);
    w->heap = NULL;
    w->heap_pos = NULL;
    w->bound = NULL;
    w->obj_first = w->obj_pairs = NULL;
    w->obj_other = NULL;
    w->box = NULL;
    w->parked = NULL;
    w->nheap = 0;
}

void world_free(world *w)
{
    for (int i = 0; i < w->n; i++) {
        body_free(w->bodies[i]);
        free(w->bodies[i]);
    }
    free(w->bodies);
    if (w->trace) fclose(w->trace);
    if (w->events) fclose(w->events);
    free(w->pairs);
    free(w->hits);
    free(w->snap);
    free(w->snap_t);
    free(w->snap_id);
    free(w->pre);
    free(w->scratch);
    free(w->end_id);
    free(w->touched);
    free(w->movers);
    world_free_schedule(w);
    free(w->due);
    free(w->due_next);
    w->due = NULL;
    w->due_next = NULL;
    w->capdue = 0;
    w->pairs = NULL;
    w->hits = NULL;
    w->snap = w->pre = w->scratch = NULL;
    w->end_id = NULL;
    w->touched = NULL;
    w->movers = NULL;
    w->nmovers = 0;
    w->snap_t = NULL;
    w->snap_id = NULL;
    w->npairs = w->cappairs = 0;
    w->capsnap = 0;
    w->bodies = NULL;
    w->n = w->cap = 0;
    w->trace = w->events = NULL;
}

int world_find(const world *w, const char *name)
{
    for (int i = 0; i < w->n; i++)
        if (strcmp(w->bodies[i]->name, name) == 0) return i;
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
    w->bodies[w->n] = b;
    w->pairs_dirty = true;
    return w->n++;
}

/* An object's index k after object i is deleted: -1 for i itself. */
static int index_after(int k, int i)
{
    return k == i ? -1 : k > i ? k - 1 : k;
}

void world_delete(world *w, int i)
{
    body_free(w->bodies[i]);
    free(w->bodies[i]);
    memmove(&w->bodies[i], &w->bodies[i + 1], (size_t)(w->n - i - 1) * sizeof *w->bodies);
    w->n--;
    w->pairs_dirty = true;
    for (int k = 0; k < w->n; k++) {
        body *b = w->bodies[k];
        b->support = index_after(b->support, i);
        b->slide = index_after(b->slide, i); /* its pair is found again (sim_update_pairs) */
        for (int s = 0; s < 2; s++) b->pinned_by[s] = index_after(b->pinned_by[s], i);
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
    const settings *s = &w->set;
    if (s->time_step <= 0) return 0;
    double h = s->internal_step > 0 ? s->internal_step : s->collision_dist / (2 * s->max_linear);
    if (!(h > 0) || isinf(h)) return 1;
    double n = ceil(s->time_step / h * (1 - 1e-12));
    if (n < 1) n = 1;
    return n > 1e12 ? (long)1e12 : (long)n;
}
