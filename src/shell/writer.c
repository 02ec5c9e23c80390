/* writer.c: the world written in its own language (writer.h). */
#include "writer.h"

#include "fmt.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/meshfile.h"

#include "core/pairs.h"
#include "core/world.h"
#include "handlers.h"
#include "media.h"
#include "shell.h"

void writer_vec(FILE *out, vec3 v)
{
    char a[32], b[32], c[32];
    fprintf(out, "(%s, %s, %s)", fmt_num(a, v.x), fmt_num(b, v.y), fmt_num(c, v.z));
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

static void write_setting(FILE *out, const shell *sh, const command *c, int for_save)
{
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
    bool after = strcmp(n, "tracker") == 0 || strcmp(n, "tracker_time") == 0 ||
                 strcmp(n, "grip") == 0 || strcmp(n, "trigger") == 0;
    if (for_save && (after || (!sh->hand.used && (strcmp(n, "hand") == 0 || strcmp(n, "hand_rotate") == 0))))
        return;
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
        fprintf(out, "tracker_time = %s\n", fmt_num(a, hand_tracker_time(&sh->hand)));
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
        fprintf(out, "clock = (%s, %ld)\n", fmt_num(a, sh->w.time_base), sh->w.base_frames);
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
    case VAL_FILE: writer_quoted(out, field); break;
    default: break;
    }
    fputc('\n', out);
}

void settings_write(FILE *out, const shell *sh, int for_save)
{
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form == FORM_SETTING) write_setting(out, sh, c, for_save);
        else if (c->run == cmd_select) /* the hand's select mode is a setting too */
            fprintf(out, "select %s\n", sh->hand.set.select_mode ? "on" : "off");
    }
}

void hand_write(FILE *out, const shell *sh)
{
    const hand *h = &sh->hand;
    char a[32];
    if (!h->used) return;
    fprintf(out, "# the hand\n");
    if (h->playing) {
        fprintf(out, "tracker = ");
        writer_quoted(out, h->set.tracker);
        fprintf(out, "\ntracker_time = %s\n", fmt_num(a, hand_tracker_time(h)));
    } else if (h->set.tracker[0]) {
        fprintf(out, "# tracker = \"%s\" (a live feed: not opened again)\n", h->set.tracker);
    }
    char g[HAND_GRIP_TEXT];
    fprintf(out, "grip = %s\n", hand_grip_word(h, &sh->w, g));
}

void writer_path(const char *path, const char *save_path, char *out, size_t outlen)
{
    char real[PATH_MAX], dir[PATH_MAX];
    if (!realpath(path, real)) snprintf(real, sizeof real, "%s", path);
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

/* A polyhedron's shape: its file (with its SHA-256) and its scale; for print, the
 * pieces it collides as and its centre of mass. */
static void polyhedron_write(FILE *out, const body *b, const char *save_path)
{
    char a[32], c[32], d[32];
    const mesh_source *src = mesh_source_of(b->sp.src);
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
        fprintf(out, "scale = %s\n", fmt_num(a, k.x));
    } else {
        fprintf(out, "scale = ");
        writer_vec(out, k);
        fputc('\n', out);
    }
    if (save_path || !b->built) return;
    vec3 com = b->shape.mass.com;
    fprintf(out, "pieces = %d\n# centre of mass, in its own axes: (%s, %s, %s)\n",
            b->shape.pieces, fmt_num(a, com.x), fmt_num(c, com.y), fmt_num(d, com.z));
}

void body_write(FILE *out, const body *b) { body_write_for(out, b, NULL); }

void body_write_for(FILE *out, const body *b, const char *save_path)
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
    case SHAPE_POLYHEDRON: polyhedron_write(out, b, save_path); break;
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

void contact_write(FILE *out, const world *w, int i, int only_later)
{
    static const char *modes[] = {"free", "slide", "general"};
    const body *b = w->bodies[i];
    if (b->mode == MODE_SLIDE && b->slide_on >= 0 && b->slide_on < w->n)
        fprintf(out, "slide_on = %s\nslide_face = %d\n", w->bodies[b->slide_on]->name,
                b->slide_face);
    fprintf(out, "mode = %s\n", body_is_static(b) ? "free" : modes[b->mode]);
    if (!body_is_static(b)) fprintf(out, "resting = %s\n", b->state == STATE_RESTING ? "on" : "off");
    for (long k = 0; k < w->pairs.n; k++) {
        const pair *p = &w->pairs.p[k];
        if (!p->touching || (p->a != i && p->b != i)) continue;
        int o = p->a == i ? p->b : p->a;
        if (!only_later || o < i) fprintf(out, "touching = %s\n", w->bodies[o]->name);
    }
}
