/* writer.c: the world written in its own language (writer.h). */
#include "writer.h"

#include "fmt.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mesh/meshfile.h"

#include "core/pairs.h"
#include "core/world.h"
#include "handlers.h"
#include "media.h"
#include "shell.h"
#include "sound/synth.h"
#include "viewer.h"

/* n numbers as "(a, b, ...)" in style s. */
static void write_tuple(FILE *out, const double *v, int n, fmt_style s)
{
    char t[4][32];
    fmt_shown_vec(t, v, n, s);
    fputc('(', out);
    for (int k = 0; k < n; k++) fprintf(out, "%s%s", k ? ", " : "", t[k]);
    fputc(')', out);
}

void writer_vec(FILE *out, vec3 v, fmt_style s)
{
    write_tuple(out, (const double[3]){v.x, v.y, v.z}, 3, s);
}

static void write_quat(FILE *out, quat q, fmt_style s)
{
    write_tuple(out, (const double[4]){q.w, q.x, q.y, q.z}, 4, s);
}

/* The k-th word of choices ("a|b|c"). */
static void write_choice(FILE *out, const char *choices, int k)
{
    const char *p = choices;
    for (; k > 0 && *p; k--) p += strcspn(p, "|") + (p[strcspn(p, "|")] ? 1 : 0);
    fprintf(out, "%.*s", (int)strcspn(p, "|"), p);
}

void writer_quoted(FILE *out, const char *s)
{
    fputc('"', out);
    for (const char *p = s; *p; p++) {
        if (*p == '"' || *p == '\\') fputc('\\', out);
        fputc(*p, out);
    }
    fputc('"', out);
}

/* The hand's exact state (hand.h), the setting named n, in style num; false when
 * n is none of them. */
static bool write_hand_exact(FILE *out, const shell *sh, const char *n, fmt_style num)
{
    const hand *h = &sh->hand;
    char a[32], b[32];
    vec3 x;
    quat q;
    hand_grip_pose(h, &x, &q);
    if (strcmp(n, "tracker_clock") == 0) {
        double clock, start;
        hand_clock_of(h, &clock, &start);
        fprintf(out, "tracker_clock = (%s, %s)\n", fmt_shown(a, clock, num), fmt_shown(b, start, num));
        return true;
    }
    if (strcmp(n, "tracker_row") == 0) {
        fprintf(out, "tracker_row = %d\n", hand_row(h));
        return true;
    }
    if (strcmp(n, "last_held") == 0) {
        const char *held = h->last_held >= 0 && h->last_held < sh->w.n ? sh->w.bodies[h->last_held]->name : NULL;
        fputs("last_held = ", out);
        /* (an object named none is written quoted, so that it reads back as that object) */
        if (held && strcmp(held, "none") == 0) writer_quoted(out, held);
        else fputs(held ? held : "none", out);
        fputc('\n', out);
        return true;
    }
    bool quat_ = strcmp(n, "hand_orientation") == 0 || strcmp(n, "grip_orientation") == 0;
    bool vec = strcmp(n, "hand_velocity") == 0 || strcmp(n, "hand_spin") == 0 || strcmp(n, "grip_at") == 0;
    if (!quat_ && !vec) return false;
    fprintf(out, "%s = ", n);
    if (quat_) write_quat(out, n[0] == 'h' ? h->q : q, num);
    else writer_vec(out, n[0] == 'g' ? x : n[5] == 'v' ? h->sv : h->sw, num);
    if (strcmp(n, "hand_velocity") == 0) fprintf(out, " %s", fmt_shown(a, h->stmt_time, num));
    fputc('\n', out);
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
    fmt_style num = for_save ? FMT_EXACT : shell_shown(sh);
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
    /* how numbers are shown is the console's, not the world's, as is the window */
    if (for_save && strcmp(n, "precision") == 0) return;
    if (strcmp(n, "window") == 0) {
        if (!for_save) fprintf(out, "window = %s\n", viewer_is_open(sh) ? "on" : "off");
        return;
    }
    /* what the hand does, after the objects it may hold (hand_write) */
    /* (the clock runs whether or not the hand was used) */
    if (for_save && hand_later(n) && (sh->hand.used || strcmp(n, "tracker_clock") != 0)) return;
    if (write_hand_exact(out, sh, n, num)) return;
    if (strcmp(n, "collision_sound") == 0 && for_save) {
        char rel[PATH_MAX];
        const char *snd = sh->sound_set.collision_sound;
        bool file = strcmp(snd, "off") != 0 && synth_find(snd) < 0;
        if (file) writer_path(snd, save_path, rel, sizeof rel);
        fprintf(out, "collision_sound = ");
        writer_quoted(out, file ? rel : snd);
        fputc('\n', out);
        return;
    }
    if (strcmp(n, "tracker") == 0) {
        fprintf(out, "tracker = ");
        if (hs->tracker[0]) writer_quoted(out, hs->tracker);
        else fprintf(out, "off");
        fputc('\n', out);
        return;
    }
    if (strcmp(n, "sound") == 0) {
        fprintf(out, "sound = %s\n", media_live_on(sh) ? "on" : "off");
        return;
    }
    if (strcmp(n, "tracker_time") == 0) {
        fprintf(out, "tracker_time = %s\n", fmt_shown(a, hand_tracker_time(&sh->hand), num));
        return;
    }
    if (strcmp(n, "grip") == 0) {
        char g[HAND_GRIP_TEXT];
        fprintf(out, "grip = %s\n", hand_grip_word(&sh->hand, &sh->w, g));
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
        if (changed) fprintf(out, "time_step = %s\n", fmt_shown(b, w->base_step, num));
        fprintf(out, "clock = (%s, %ld)\n", fmt_shown(a, w->time_base, num), w->base_frames);
        if (changed) fprintf(out, "time_step = %s\n", fmt_shown(b, w->set.time_step, num));
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
    case VAL_NUMBER: fprintf(out, "%s", fmt_shown(a, *(const double *)field, num)); break;
    case VAL_VECTOR: writer_vec(out, *(const vec3 *)field, num); break;
    case VAL_RANGE2: write_tuple(out, (const double *)field, 2, num); break;
    case VAL_VECTOR_ANGLE: {
        const dir_amount *d = (const dir_amount *)field;
        writer_vec(out, d->dir, num);
        fprintf(out, " %s", fmt_shown(a, d->amount, num));
        break;
    }
    case VAL_COLOR: {
        const int *k = (const int *)field;
        fprintf(out, "(%d, %d, %d)", k[0], k[1], k[2]);
        break;
    }
    case VAL_ONOFF: fprintf(out, "%s", *(const bool *)field ? "on" : "off"); break;
    case VAL_FILE: writer_quoted(out, field); break;
    case VAL_CHOICE: write_choice(out, c->choices, *(const int *)field); break;
    default: break;
    }
    fputc('\n', out);
}

void setting_write(FILE *out, const shell *sh, const command *c)
{
    if (c->run == cmd_select) fprintf(out, "select %s\n", sh->hand.set.select_mode ? "on" : "off");
    else write_setting(out, sh, c, NULL);
}

void settings_write(FILE *out, const shell *sh, const char *save_path)
{
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form == FORM_SETTING) write_setting(out, sh, c, save_path);
        else if (c->run == cmd_select) /* the hand's select mode is a setting too */
            setting_write(out, sh, c);
    }
}

void hand_write(FILE *out, const shell *sh, const char *save_path)
{
    const hand *h = &sh->hand;
    const fmt_style x = FMT_EXACT;
    char a[32], rel[PATH_MAX];
    if (!h->used) return;
    fprintf(out, "# the hand: its tracker and the place in it, its pose, what it holds\n");
    if (h->playing) {
        writer_path(h->set.tracker, save_path, rel, sizeof rel);
        fprintf(out, "tracker = ");
        writer_quoted(out, rel);
        fprintf(out, "\ntracker_time = %s\n", fmt_shown(a, hand_tracker_time(h), x));
    } else if (h->set.tracker[0]) {
        fprintf(out, "# tracker = \"%s\" (a live feed: not opened again)\n", h->set.tracker);
    }
    write_hand_exact(out, sh, "tracker_clock", x);
    if (h->playing) write_hand_exact(out, sh, "tracker_row", x);
    fprintf(out, "hand = ");
    writer_vec(out, h->p, x);
    fprintf(out, "\nhand_rotate = ");
    writer_vec(out, h->set.hand_rotate.dir, x);
    fprintf(out, " %s\n", fmt_shown(a, h->set.hand_rotate.amount, x));
    write_hand_exact(out, sh, "hand_orientation", x);
    write_hand_exact(out, sh, "hand_velocity", x);
    write_hand_exact(out, sh, "hand_spin", x);
    char g[HAND_GRIP_TEXT];
    fprintf(out, "grip = %s\n", hand_grip_word(h, &sh->w, g));
    if (h->grip == GRIP_OBJECT || h->grip == GRIP_PANEL) {
        write_hand_exact(out, sh, "grip_at", x);
        write_hand_exact(out, sh, "grip_orientation", x);
    }
    if (h->grip == GRIP_OBJECT && h->held >= 0 && h->held < sh->w.n) {
        /* the held object's motion as it was: the grip above gave it the hand's */
        const body *b = sh->w.bodies[h->held];
        const char *what[] = {"velocity", "angular_vel", "angular_momentum", "hold_pivot", "hold_velocity"};
        const vec3 value[] = {b->v, b->w, b->L, b->hold_pivot, b->hold_v};
        for (int k = 0; k < 5; k++) {
            fprintf(out, "%s.%s = ", b->name, what[k]);
            writer_vec(out, value[k], x);
            fputc('\n', out);
        }
    }
    write_hand_exact(out, sh, "last_held", x);
}

void writer_path(const char *path, const char *save_path, char *out, size_t outlen)
{
    char real[PATH_MAX], dir[PATH_MAX], cwd[PATH_MAX];
    if (!realpath(path, real)) { /* (a file gone since: its path from here) */
        bool joined = path[0] != '/' && getcwd(cwd, sizeof cwd) &&
                      snprintf(real, sizeof real, "%s/%s", cwd, path) < (int)sizeof real;
        if (!joined) snprintf(real, sizeof real, "%s", path);
    }
    snprintf(dir, sizeof dir, "%s", save_path);
    char *slash = strrchr(dir, '/');
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == dir) dir[1] = '\0';
    else *slash = '\0';
    char real_dir[PATH_MAX];
    size_t n = realpath(dir, real_dir) ? strlen(real_dir) : 0;
    if (n > 0 && strncmp(real, real_dir, n) == 0 && (real[n] == '/' || real_dir[n - 1] == '/'))
        snprintf(out, outlen, "%s", real + n + (real[n] == '/'));
    else
        snprintf(out, outlen, "%s", real);
}

/* A polyhedron's shape: its file (with its SHA-256; for save, its path from the
 * saved file's folder) and its scale; for print, the pieces it collides as and its
 * centre of mass. */
static void polyhedron_write(FILE *out, const body *b, write_style st)
{
    char a[32], c[32], d[32];
    const char *save_path = st.save_path;
    fmt_style s = st.num;
    const mesh_source *src = mesh_source_of(b->sp.src);
    /* (before the file: a static one's open pieces are built at their thickness) */
    fprintf(out, "thickness = %s\n", fmt_shown(a, b->sp.thickness, s));
    if (src) {
        char path[PATH_MAX];
        if (save_path) writer_path(src->path, save_path, path, sizeof path);
        else snprintf(path, sizeof path, "%s", src->path);
        fprintf(out, "file = ");
        writer_quoted(out, path);
        fprintf(out, "\nsha256 = \"");
        for (int k = 0; k < (int)sizeof src->sha256; k++) fprintf(out, "%02x", src->sha256[k]);
        fprintf(out, "\"\n");
    }
    vec3 k = b->sp.scale;
    if (k.x == k.y && k.y == k.z) {
        fprintf(out, "scale = %s\n", fmt_shown(a, k.x, s));
    } else {
        fprintf(out, "scale = ");
        writer_vec(out, k, s);
        fputc('\n', out);
    }
    if (save_path || !b->built) return;
    vec3 com = b->shape.mass.com;
    if (s == FMT_SHORT) { /* rounding dust of the volume integrals, against the size */
        double dust = 1e-12 * b->shape.r_out;
        if (fabs(com.x) < dust) com.x = 0;
        if (fabs(com.y) < dust) com.y = 0;
        if (fabs(com.z) < dust) com.z = 0;
    }
    fprintf(out, "pieces = %d\n# centre of mass, in its own axes: (%s, %s, %s)\n",
            b->shape.pieces, fmt_shown(a, com.x, s), fmt_shown(c, com.y, s), fmt_shown(d, com.z, s));
}

/* The orientation as an axis and an angle: as typed while it holds, else from q. */
static void body_axis_angle(const body *b, vec3 *axis, double *angle)
{
    *axis = b->rot_axis;
    *angle = b->rot_angle;
    if (!b->rot_given) q_to_axis_angle(b->q, axis, angle);
}

void body_write(FILE *out, const body *b, write_style st)
{
    char a[32];
    fmt_style s = st.num;
    const shape_params *p = &b->sp;
    fprintf(out, "%s %s\n", body_type_name(p->kind), b->name);
    fprintf(out, "mass = %s\n", fmt_shown(a, b->mass, s));
    fprintf(out, "elasticity = %s\n", fmt_shown(a, b->elasticity, s));
    fprintf(out, "friction = %s\n", fmt_shown(a, b->friction, s));
    fprintf(out, "rolling_friction = %s\n", fmt_shown(a, b->rolling_friction, s));
    fprintf(out, "volume = %s\n", fmt_shown(a, b->volume, s));
    fprintf(out, "color = (%d, %d, %d)\n", b->color[0], b->color[1], b->color[2]);
    switch (p->kind) {
    case SHAPE_SPHERE:
        fprintf(out, "radius = %s\n", fmt_shown(a, p->radius, s));
        fprintf(out, "ures = %d\nvres = %d\n", p->ures, p->vres);
        break;
    case SHAPE_CUBE:
        fprintf(out, "size = ");
        writer_vec(out, p->size, s);
        fputc('\n', out);
        break;
    case SHAPE_SUPERQUADRIC:
        fprintf(out, "exp1 = %s\n", fmt_shown(a, p->exp1, s));
        fprintf(out, "exp2 = %s\n", fmt_shown(a, p->exp2, s));
        fprintf(out, "a1 = %s\n", fmt_shown(a, p->a1, s));
        fprintf(out, "a2 = %s\n", fmt_shown(a, p->a2, s));
        fprintf(out, "a3 = %s\n", fmt_shown(a, p->a3, s));
        fprintf(out, "ures = %d\nvres = %d\n", p->ures, p->vres);
        break;
    case SHAPE_POLYHEDRON: polyhedron_write(out, b, st); break;
    }
    fprintf(out, "translate = ");
    writer_vec(out, b->x, s);
    fputc('\n', out);
    if (!st.once) {
        vec3 axis;
        double angle;
        body_axis_angle(b, &axis, &angle);
        fprintf(out, "rotate = ");
        writer_vec(out, axis, s);
        fprintf(out, " %s\n", fmt_shown(a, angle, s));
    }
    fprintf(out, "linear_vel = ");
    writer_vec(out, b->v, s);
    fprintf(out, "\nangular_vel = ");
    writer_vec(out, b->w, s);
    fprintf(out, "\norientation = ");
    write_quat(out, b->q, s);
    if (!st.once) {
        fprintf(out, "\nvelocity = ");
        writer_vec(out, b->v, s);
    }
    fprintf(out, "\nangular_momentum = ");
    writer_vec(out, b->L, s);
    fputc('\n', out);
}

/* Object b's mode as the language names it (the command table's `mode`). */
static void write_mode(FILE *out, const body *b)
{
    write_choice(out, command_find("mode")->choices, body_is_static(b) ? MODE_FREE : (int)b->mode);
}

void property_write(FILE *out, const world *w, int i, const command *c, fmt_style s)
{
    const body *b = w->bodies[i];
    const char *field = (const char *)b + c->off;
    const char *n = c->name;
    char a[32];
    if (strcmp(n, "touching") == 0) {
        bool any = false;
        for (long k = 0; k < w->pairs.n; k++) {
            const pair *p = &w->pairs.p[k];
            if (!p->touching || (p->a != i && p->b != i)) continue;
            fprintf(out, "%s.touching = %s\n", b->name, w->bodies[p->a == i ? p->b : p->a]->name);
            any = true;
        }
        if (!any) fprintf(out, "# %s touches nothing lasting\n", b->name);
        return;
    }
    bool slide = body_mode_on_face(b->mode) && b->slide_on >= 0 && b->slide_on < w->n;
    if ((strcmp(n, "slide_on") == 0 || strcmp(n, "slide_face") == 0) && !slide) {
        fprintf(out, "# %s is on no face (mode = ", b->name);
        write_mode(out, b);
        fprintf(out, ")\n");
        return;
    }
    fprintf(out, "%s.%s = ", b->name, n);
    if (strcmp(n, "slide_on") == 0) {
        fprintf(out, "%s", w->bodies[b->slide_on]->name);
    } else if (strcmp(n, "mode") == 0) {
        write_mode(out, b);
    } else if (strcmp(n, "resting") == 0) {
        fprintf(out, "%s", b->state == STATE_RESTING ? "on" : "off");
    } else {
        switch (c->arg) {
        case VAL_NUMBER: fprintf(out, "%s", fmt_shown(a, *(const double *)field, s)); break;
        case VAL_INTEGER: fprintf(out, "%d", *(const int *)field); break;
        case VAL_VECTOR: writer_vec(out, *(const vec3 *)field, s); break;
        case VAL_COLOR: {
            const int *k = (const int *)field;
            fprintf(out, "(%d, %d, %d)", k[0], k[1], k[2]);
            break;
        }
        case VAL_QUAT: write_quat(out, *(const quat *)field, s); break;
        case VAL_VECTOR_ANGLE: {
            vec3 axis;
            double angle;
            body_axis_angle(b, &axis, &angle);
            writer_vec(out, axis, s);
            fprintf(out, " %s", fmt_shown(a, angle, s));
            break;
        }
        default: break;
        }
    }
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
    const body *b = w->bodies[i];
    if (body_mode_on_face(b->mode) && b->slide_on >= 0 && b->slide_on < w->n)
        fprintf(out, "slide_on = %s\nslide_face = %d\n", w->bodies[b->slide_on]->name,
                b->slide_face);
    fprintf(out, "mode = ");
    write_mode(out, b);
    fputc('\n', out);
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
