/* writer.c: the world written in its own language (writer.h). */
#include "writer.h"

#include "fmt.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "core/pairs.h"
#include "core/world.h"
#include "handlers.h"
#include "media.h"
#include "savepath.h"
#include "shell.h"
#include "sound/synth.h"

void writer_vec(FILE *out, vec3 v)
{
    char a[32], b[32], c[32];
    fprintf(out, "(%s, %s, %s)", fmt_num(a, v.x), fmt_num(b, v.y), fmt_num(c, v.z));
}

/* The hand's exact state (hand.h), each setting by name; true when c is one of
 * them (and was written, unless there is nothing to write). */
static bool write_hand_exact(FILE *out, const shell *sh, const char *n)
{
    const hand *h = &sh->hand;
    char a[32], b[32], c[32], d[32];
    if (strcmp(n, "tracker_clock") == 0) {
        double clock, start;
        hand_clock_of(h, &clock, &start);
        fprintf(out, "tracker_clock = (%s, %s)\n", fmt_num(a, clock), fmt_num(b, start));
    } else if (strcmp(n, "tracker_row") == 0) {
        fprintf(out, "tracker_row = %d\n", hand_row(h));
    } else if (strcmp(n, "hand_orientation") == 0) {
        fprintf(out, "hand_orientation = (%s, %s, %s, %s)\n", fmt_num(a, h->q.w), fmt_num(b, h->q.x),
                fmt_num(c, h->q.y), fmt_num(d, h->q.z));
    } else if (strcmp(n, "hand_velocity") == 0) {
        fprintf(out, "hand_velocity = ");
        writer_vec(out, h->sv);
        fprintf(out, " %s\n", fmt_num(a, h->stmt_time));
    } else if (strcmp(n, "hand_spin") == 0) {
        fprintf(out, "hand_spin = ");
        writer_vec(out, h->sw);
        fputc('\n', out);
    } else if (strcmp(n, "grip_at") == 0 || strcmp(n, "grip_orientation") == 0) {
        vec3 x;
        quat q;
        hand_grip_pose(h, &x, &q);
        if (n[5] == 'a') {
            fprintf(out, "grip_at = ");
            writer_vec(out, x);
            fputc('\n', out);
        } else {
            fprintf(out, "grip_orientation = (%s, %s, %s, %s)\n", fmt_num(a, q.w), fmt_num(b, q.x),
                    fmt_num(c, q.y), fmt_num(d, q.z));
        }
    } else if (strcmp(n, "last_held") == 0) {
        fprintf(out, "last_held = %s\n", h->last_held >= 0 && h->last_held < sh->w.n
                                               ? sh->w.bodies[h->last_held]->name : "none");
    } else {
        return false;
    }
    return true;
}

/* The settings save leaves to hand_write: the hand's, after the objects it may
 * hold. */
static bool hand_later(const char *n)
{
    static const char *const later[] = {"hand", "hand_rotate", "trigger", "tracker", "tracker_time",
                                        "grip", "tracker_clock", "tracker_row", "hand_orientation",
                                        "hand_velocity", "hand_spin", "grip_at", "grip_orientation",
                                        "last_held"};
    for (size_t k = 0; k < sizeof later / sizeof *later; k++)
        if (strcmp(n, later[k]) == 0) return true;
    return false;
}

static void write_setting(FILE *out, const shell *sh, const command *c, const char *save_path)
{
    int for_save = save_path != NULL;
    const shell_settings *s = &sh->set;
    const view_settings *vs = &sh->view_set;
    char a[32];
    const char *n = c->name;
    const hand_settings *hs = &sh->hand.set;
    bool hand_log = strcmp(n, "hand_log") == 0;
    if (strcmp(n, "trace") == 0 || strcmp(n, "events") == 0 || strcmp(n, "soundtrack") == 0 ||
        strcmp(n, "movie") == 0 || hand_log) { /* outputs: a save does not start them again */
        const char *path = hand_log                   ? hs->hand_log
                           : strcmp(n, "trace") == 0  ? sh->logs.trace_path
                           : strcmp(n, "events") == 0 ? sh->logs.events_path
                           : n[0] == 's'              ? media_soundtrack_path(sh)
                                                      : media_movie_path(sh);
        if (!path) path = "";
        fprintf(out, "%s%s = %s%s%s\n", for_save ? "# " : "", n, path[0] ? "\"" : "",
                path[0] ? path : "off", path[0] ? "\"" : "");
        return;
    }
    /* what the hand does, after the objects it may hold (hand_write) */
    /* (the clock runs whether or not the hand was used) */
    if (for_save && hand_later(n) && (sh->hand.used || strcmp(n, "tracker_clock") != 0)) return;
    if (write_hand_exact(out, sh, n)) return;
    if (strcmp(n, "collision_sound") == 0 && for_save) {
        char rel[PATH_MAX];
        const char *snd = sh->sound_set.collision_sound;
        bool file = strcmp(snd, "off") != 0 && synth_find(snd) < 0;
        fprintf(out, "collision_sound = \"%s\"\n", file ? savepath(snd, save_path, rel, sizeof rel) : snd);
        return;
    }
    if (strcmp(n, "tracker") == 0) {
        if (hs->tracker[0]) fprintf(out, "tracker = \"%s\"\n", hs->tracker);
        else fprintf(out, "tracker = off\n");
        return;
    }
    if (strcmp(n, "sound") == 0) {
        fprintf(out, "sound = %s\n", media_live_on(sh) ? "on" : "off");
        return;
    }
    if (strcmp(n, "tracker_time") == 0) {
        fprintf(out, "tracker_time = %s\n", fmt_num(a, hand_tracker_time(&sh->hand)));
        return;
    }
    if (strcmp(n, "grip") == 0) {
        fprintf(out, "grip = %s\n", hand_grip_word(&sh->hand, &sh->w));
        return;
    }
    if (strcmp(n, "seed") == 0) {
        fprintf(out, "seed = %lu\n", s->seed);
        return;
    }
    if (strcmp(n, "random_draws") == 0) {
        fprintf(out, "random_draws = %llu\n", shell_random_draws(sh));
        return;
    }
    if (strcmp(n, "clock") == 0) {
        /* the clock counts frames of the time_step it had when they ran; one
         * changed since (a slider of the panel, at a frame's end) counts from the
         * next frame on (with no frames counted, the step does not matter) */
        const world *w = &sh->w;
        bool changed =
            w->base_frames > 0 && memcmp(&w->base_step, &w->set.time_step, sizeof w->base_step) != 0;
        char b[32];
        if (changed) fprintf(out, "time_step = %s\n", fmt_num(b, w->base_step));
        fprintf(out, "clock = (%s, %ld)\n", fmt_num(a, w->time_base), w->base_frames);
        if (changed) fprintf(out, "time_step = %s\n", fmt_num(b, w->set.time_step));
        return;
    }
    if (strcmp(n, "frame") == 0) {
        fprintf(out, "frame = %ld\n", sh->w.frame);
        return;
    }
    if (strcmp(n, "image_size") == 0) {
        fprintf(out, "image_size = (%d, %d)\n", vs->image_w, vs->image_h);
        return;
    }
    if (strcmp(n, "stereo") == 0) {
        static const char *names[] = {"pair", "sbs", "anaglyph", "mono"};
        fprintf(out, "stereo = %s\n", names[vs->stereo]);
        return;
    }
    if (strcmp(n, "real") == 0) {
        static const char *names[] = {"solid", "wire", "hidden"};
        fprintf(out, "real = %s\n", names[vs->real]);
        return;
    }
    const char *field = shell_setting_value(sh, c);
    fprintf(out, "%s = ", n);
    switch (c->arg) {
    case VAL_NUMBER: fprintf(out, "%s", fmt_num(a, *(const double *)field)); break;
    case VAL_VECTOR: writer_vec(out, *(const vec3 *)field); break;
    case VAL_RANGE2: {
        const double *d = (const double *)field;
        char b[32];
        fprintf(out, "(%s, %s)", fmt_num(a, d[0]), fmt_num(b, d[1]));
        break;
    }
    case VAL_VECTOR_ANGLE: {
        const dir_amount *d = (const dir_amount *)field;
        writer_vec(out, d->dir);
        fprintf(out, " %s", fmt_num(a, d->amount));
        break;
    }
    case VAL_COLOR: {
        const int *k = (const int *)field;
        fprintf(out, "(%d, %d, %d)", k[0], k[1], k[2]);
        break;
    }
    case VAL_ONOFF: fprintf(out, "%s", *(const bool *)field ? "on" : "off"); break;
    case VAL_FILE: fprintf(out, "\"%s\"", field); break;
    default: break;
    }
    fputc('\n', out);
}

void settings_write(FILE *out, const shell *sh, const char *save_path)
{
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form == FORM_SETTING) write_setting(out, sh, c, save_path);
        else if (c->run == cmd_select) /* the hand's select mode is a setting too */
            fprintf(out, "select %s\n", sh->hand.set.select_mode ? "on" : "off");
    }
}

void hand_write(FILE *out, const shell *sh, const char *save_path)
{
    const hand *h = &sh->hand;
    char a[32], rel[PATH_MAX];
    if (!h->used) return;
    fprintf(out, "# the hand: its tracker and the place in it, its pose, what it holds\n");
    if (h->playing) {
        fprintf(out, "tracker = \"%s\"\ntracker_time = %s\n",
                savepath(h->set.tracker, save_path, rel, sizeof rel), fmt_num(a, hand_tracker_time(h)));
    } else if (h->set.tracker[0]) {
        fprintf(out, "# tracker = \"%s\" (a live feed: not opened again)\n", h->set.tracker);
    }
    write_hand_exact(out, sh, "tracker_clock");
    if (h->playing) write_hand_exact(out, sh, "tracker_row");
    fprintf(out, "hand = ");
    writer_vec(out, h->p);
    fprintf(out, "\nhand_rotate = ");
    writer_vec(out, h->set.hand_rotate.dir);
    fprintf(out, " %s\n", fmt_num(a, h->set.hand_rotate.amount));
    write_hand_exact(out, sh, "hand_orientation");
    write_hand_exact(out, sh, "hand_velocity");
    write_hand_exact(out, sh, "hand_spin");
    fprintf(out, "grip = %s\n", hand_grip_word(h, &sh->w));
    if (h->grip == GRIP_OBJECT || h->grip == GRIP_PANEL) {
        write_hand_exact(out, sh, "grip_at");
        write_hand_exact(out, sh, "grip_orientation");
    }
    if (h->grip == GRIP_OBJECT && h->held >= 0 && h->held < sh->w.n) {
        /* the held object's motion as it was: the grip above gave it the hand's */
        const body *b = sh->w.bodies[h->held];
        fprintf(out, "%s.velocity = ", b->name);
        writer_vec(out, b->v);
        fprintf(out, "\n%s.angular_vel = ", b->name);
        writer_vec(out, b->w);
        fprintf(out, "\n%s.angular_momentum = ", b->name);
        writer_vec(out, b->L);
        fprintf(out, "\n%s.hold_pivot = ", b->name);
        writer_vec(out, b->hold_pivot);
        fprintf(out, "\n%s.hold_velocity = ", b->name);
        writer_vec(out, b->hold_v);
        fputc('\n', out);
    }
    write_hand_exact(out, sh, "last_held");
}

void body_write(FILE *out, const body *b)
{
    char a[32];
    const shape_params *p = &b->sp;
    fprintf(out, "%s %s\n", body_type_name(p->kind), b->name);
    fprintf(out, "mass = %s\n", fmt_num(a, b->mass));
    fprintf(out, "elasticity = %s\n", fmt_num(a, b->elasticity));
    fprintf(out, "volume = %s\n", fmt_num(a, b->volume));
    fprintf(out, "color = (%d, %d, %d)\n", b->color[0], b->color[1], b->color[2]);
    switch (p->kind) {
    case SHAPE_SPHERE:
        fprintf(out, "radius = %s\n", fmt_num(a, p->radius));
        fprintf(out, "ures = %d\nvres = %d\n", p->ures, p->vres);
        break;
    case SHAPE_CUBE:
        fprintf(out, "size = ");
        writer_vec(out, p->size);
        fputc('\n', out);
        break;
    case SHAPE_SUPERQUADRIC:
        fprintf(out, "exp1 = %s\n", fmt_num(a, p->exp1));
        fprintf(out, "exp2 = %s\n", fmt_num(a, p->exp2));
        fprintf(out, "a1 = %s\n", fmt_num(a, p->a1));
        fprintf(out, "a2 = %s\n", fmt_num(a, p->a2));
        fprintf(out, "a3 = %s\n", fmt_num(a, p->a3));
        fprintf(out, "ures = %d\nvres = %d\n", p->ures, p->vres);
        break;
    }
    fprintf(out, "translate = ");
    writer_vec(out, b->x);
    vec3 axis = b->rot_axis;
    double angle = b->rot_angle;
    if (!b->rot_given) q_to_axis_angle(b->q, &axis, &angle);
    fprintf(out, "\nrotate = ");
    writer_vec(out, axis);
    fprintf(out, " %s\nlinear_vel = ", fmt_num(a, angle));
    writer_vec(out, b->v);
    fprintf(out, "\nangular_vel = ");
    writer_vec(out, b->w);
    char c[32], d[32], e[32];
    fprintf(out, "\norientation = (%s, %s, %s, %s)\nvelocity = ", fmt_num(a, b->q.w),
            fmt_num(c, b->q.x), fmt_num(d, b->q.y), fmt_num(e, b->q.z));
    writer_vec(out, b->v);
    fprintf(out, "\nangular_momentum = ");
    writer_vec(out, b->L);
    fputc('\n', out);
}

static int cmp_int(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    return (a > b) - (a < b);
}

/* The other object of pair k when it is a lasting contact of object i (and the
 * other comes before i, when only_later), else -1. */
static int contact_other(const world *w, long k, int i, int only_later)
{
    const pair *p = &w->pairs.p[k];
    if (!p->touching || (p->a != i && p->b != i)) return -1;
    int o = p->a == i ? p->b : p->a;
    return only_later && o > i ? -1 : o;
}

void contact_write(FILE *out, const world *w, int i, int only_later)
{
    static const char *modes[] = {"free", "slide", "general"};
    const body *b = w->bodies[i];
    if (b->mode == MODE_SLIDE && b->slide_on >= 0 && b->slide_on < w->n)
        fprintf(out, "slide_on = %s\nslide_face = %d\n", w->bodies[b->slide_on]->name,
                b->slide_face);
    fprintf(out, "mode = %s\n", body_is_static(b) ? "free" : modes[b->mode]);
    if (!body_is_static(b)) fprintf(out, "resting = %s\n", b->state == STATE_RESTING ? "on" : "off");
    /* in the order of the other objects, whatever the order the pairs were made
     * in: a world saved, read back and saved again gives the same file (in the
     * pairs' order when there is no memory to sort them: the same contacts) */
    int m = 0;
    for (long k = 0; k < w->pairs.n; k++) m += contact_other(w, k, i, only_later) >= 0;
    int local[32], *other = m <= 32 ? local : malloc((size_t)m * sizeof *other), n = 0;
    for (long k = 0; k < w->pairs.n; k++) {
        int o = contact_other(w, k, i, only_later);
        if (o < 0) continue;
        if (other) other[n++] = o;
        else fprintf(out, "touching = %s\n", w->bodies[o]->name);
    }
    if (n > 1) qsort(other, (size_t)n, sizeof *other, cmp_int);
    for (int k = 0; k < n; k++) fprintf(out, "touching = %s\n", w->bodies[other[k]]->name);
    if (other != local) free(other);
}
