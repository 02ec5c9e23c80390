/* commands.c: the command table and one handler per command (thesis Appendix A;
 * language.md).
 *
 * The parser has already checked every value against the table (types, ranges,
 * finiteness), so handlers check only what depends on the world: the current
 * object, names in use, files.  A handler either applies its statement whole or
 * changes nothing and reports an error.
 */
#include "commands.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "closest.h"
#include "help.h"
#include "lang.h"
#include "log.h"
#include "shell.h"
#include "sim.h"
#include "view.h"

#define S(field) offsetof(settings, field)

/* ------------------------------------------------------------ numbers */

const char *fmt_num(char buf[32], double x)
{
    if (x == 0) return strcpy(buf, "0"); /* also -0 */
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, 32, "%.*g", prec, x);
        if (strtod(buf, NULL) == x) break;
    }
    return buf;
}

static void put_vec(FILE *out, vec3 v)
{
    char a[32], b[32], c[32];
    fprintf(out, "(%s, %s, %s)", fmt_num(a, v.x), fmt_num(b, v.y), fmt_num(c, v.z));
}

static vec3 stmt_vec(const stmt *st) { return v3(st->num[0], st->num[1], st->num[2]); }

/* ------------------------------------------------------------ objects */

static body *target(shell *sh, const stmt *st)
{
    if (st->object) {
        int i = world_find(&sh->w, st->object);
        if (i < 0) sh_error(sh, st, "no object named '%s'", st->object);
        return i < 0 ? NULL : sh->w.bodies[i];
    }
    if (sh->current < 0) {
        sh_error(sh, st,
                 "%s: no current object: create one with sphere NAME, cube NAME or superquadric "
                 "NAME, or write NAME.%s = ...",
                 st->cmd->name, st->cmd->name);
        return NULL;
    }
    return sh->w.bodies[sh->current];
}

static cmd_status cmd_create(shell *sh, const stmt *st)
{
    shape_kind kind = strcmp(st->cmd->name, "sphere") == 0 ? SHAPE_SPHERE
                      : strcmp(st->cmd->name, "cube") == 0 ? SHAPE_CUBE
                                                           : SHAPE_SUPERQUADRIC;
    int i = world_find(&sh->w, st->word);
    if (i >= 0) {
        const body *b = sh->w.bodies[i];
        if (b->sp.kind != kind) {
            sh_error(sh, st, "'%s' is already a %s; it cannot also be a %s", st->word,
                     body_type_name(b->sp.kind), st->cmd->name);
            return CMD_ERROR;
        }
        sh->current = i;
        return CMD_OK;
    }
    body *b = malloc(sizeof *b);
    if (!b) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    body_init(b, st->word, kind);
    char err[256];
    if (body_build(b, err, sizeof err) != 0) {
        sh_error(sh, st, "%s", err);
        free(b);
        return CMD_ERROR;
    }
    i = world_add(&sh->w, b);
    if (i < 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    sh->current = i;
    return CMD_OK;
}

static void fix_index(int *idx, int deleted)
{
    if (*idx == deleted) *idx = -1;
    else if (*idx > deleted) (*idx)--;
}

static cmd_status cmd_delete(shell *sh, const stmt *st)
{
    int i = world_find(&sh->w, st->word);
    if (i < 0) {
        sh_error(sh, st, "no object named '%s'", st->word);
        return CMD_ERROR;
    }
    world_delete(&sh->w, i);
    fix_index(&sh->current, i);
    fix_index(&sh->selected, i);
    fix_index(&sh->prev_selected, i);
    return CMD_OK;
}

/* Rebuilds b's shape after sp changed; restores old on failure. */
static cmd_status rebuild(shell *sh, const stmt *st, body *b, shape_params old)
{
    char err[256];
    if (body_build(b, err, sizeof err) != 0) {
        b->sp = old;
        sh_error(sh, st, "%s", err);
        return CMD_ERROR;
    }
    return CMD_OK;
}

static cmd_status cmd_property(shell *sh, const stmt *st)
{
    body *b = target(sh, st);
    if (!b) return CMD_ERROR;
    const command *c = st->cmd;
    const char *n = c->name;
    if (!(c->classes & (1u << b->sp.kind))) {
        sh_warn(sh, st, "%s does not apply to %s '%s' (a %s); ignored", n,
                body_type_name(b->sp.kind), b->name, body_type_name(b->sp.kind));
        return CMD_OK;
    }
    double x = st->num[0];
    vec3 v = stmt_vec(st);
    shape_params old = b->sp;
    /* anything but the look or the sound of an object wakes it */
    if (strcmp(n, "color") != 0 && strcmp(n, "volume") != 0) {
        if (b->state == STATE_RESTING) b->state = STATE_DYNAMIC;
        b->slide = -1;
    }
    /* objects resting on this one lose their support's old place */
    sim_wake_on(&sh->w, world_find(&sh->w, b->name));
    if (strcmp(n, "linear_vel") == 0) b->v = v;
    else if (strcmp(n, "angular_vel") == 0) body_set_angular_vel(b, v);
    else if (strcmp(n, "elasticity") == 0) b->elasticity = x;
    else if (strcmp(n, "mass") == 0) {
        body_set_mass(b, x);
        sh->w.pairs_dirty = true; /* static objects have no pairs among themselves */
    }
    else if (strcmp(n, "volume") == 0) b->volume = x;
    else if (strcmp(n, "translate") == 0) b->x = v;
    else if (strcmp(n, "rotate") == 0) body_set_rotation(b, v, st->num[3]);
    else if (strcmp(n, "color") == 0)
        for (int k = 0; k < 3; k++) b->color[k] = (int)st->num[k];
    else {
        if (strcmp(n, "radius") == 0) b->sp.radius = x;
        else if (strcmp(n, "size") == 0) b->sp.size = v;
        else if (strcmp(n, "exp1") == 0) b->sp.exp1 = x;
        else if (strcmp(n, "exp2") == 0) b->sp.exp2 = x;
        else if (strcmp(n, "a1") == 0) b->sp.a1 = x;
        else if (strcmp(n, "a2") == 0) b->sp.a2 = x;
        else if (strcmp(n, "a3") == 0) b->sp.a3 = x;
        else if (strcmp(n, "ures") == 0) b->sp.ures = (int)x;
        else if (strcmp(n, "vres") == 0) b->sp.vres = (int)x;
        if (rebuild(sh, st, b, old) != CMD_OK) return CMD_ERROR;
        if ((strcmp(n, "exp1") == 0 || strcmp(n, "exp2") == 0) && x > 2)
            sh_warn(sh, st,
                    "%s = %g makes '%s' non-convex; its collision shape is the convex hull of "
                    "its tessellation",
                    n, x, b->name);
    }
    return CMD_OK;
}

/* ------------------------------------------------------------ settings */

static cmd_status cmd_setting(shell *sh, const stmt *st)
{
    const command *c = st->cmd;
    if (c->off == S(force)) sim_wake_all(&sh->w); /* rest depends on the force */
    char *field = (char *)&sh->w.set + c->off;
    switch (c->arg) {
    case VAL_NUMBER: *(double *)field = st->num[0]; break;
    case VAL_VECTOR: *(vec3 *)field = stmt_vec(st); break;
    case VAL_VECTOR_ANGLE: *(dir_amount *)field = (dir_amount){stmt_vec(st), st->num[3]}; break;
    case VAL_COLOR:
        for (int k = 0; k < 3; k++) ((int *)field)[k] = (int)st->num[k];
        break;
    case VAL_ONOFF: *(bool *)field = st->num[0] != 0; break;
    case VAL_FILE: snprintf(field, PATH_MAX_VROC, "%s", st->word); break;
    default: break;
    }
    return CMD_OK;
}

static cmd_status cmd_random_box(shell *sh, const stmt *st)
{
    vec3 v = stmt_vec(st);
    if (!(v.x > 0 && v.y > 0 && v.z > 0)) {
        sh_error(sh, st, "random_box half-extents must all be > 0");
        return CMD_ERROR;
    }
    sh->w.set.random_box = v;
    return CMD_OK;
}

static cmd_status cmd_seed(shell *sh, const stmt *st)
{
    sh->w.set.seed = (unsigned long)st->num[0];
    sh->rng = sh->w.set.seed;
    return CMD_OK;
}

static cmd_status cmd_image_size(shell *sh, const stmt *st)
{
    sh->w.set.image_w = (int)st->num[0];
    sh->w.set.image_h = (int)st->num[1];
    return CMD_OK;
}

static cmd_status cmd_stereo(shell *sh, const stmt *st)
{
    static const stereo_mode modes[] = {STEREO_PAIR, STEREO_SBS, STEREO_ANAGLYPH, STEREO_MONO};
    sh->w.set.stereo = modes[(int)st->num[0]];
    return CMD_OK;
}

static cmd_status cmd_real(shell *sh, const stmt *st)
{
    static const real_mode modes[] = {REAL_SOLID, REAL_WIRE, REAL_HIDDEN};
    sh->w.set.real = modes[(int)st->num[0]];
    return CMD_OK;
}

static const char *const builtin_sounds[] = {"click", "knock", "bell", "off", NULL};

static bool is_builtin_sound(const char *s)
{
    for (int i = 0; builtin_sounds[i]; i++)
        if (strcmp(s, builtin_sounds[i]) == 0) return true;
    return false;
}

/* A file the user names for reading must be a readable regular file. */
static bool readable_file(shell *sh, const stmt *st, const char *path)
{
    struct stat sb;
    FILE *f = fopen(path, "rb");
    if (!f) {
        sh_error(sh, st, "%s: cannot read '%s': %s", st->cmd->name, path, strerror(errno));
        return false;
    }
    bool dir = fstat(fileno(f), &sb) == 0 && S_ISDIR(sb.st_mode);
    fclose(f);
    if (dir) sh_error(sh, st, "%s: '%s' is a folder, not a file", st->cmd->name, path);
    return !dir;
}

static cmd_status cmd_collision_sound(shell *sh, const stmt *st)
{
    if (!is_builtin_sound(st->word) && !readable_file(sh, st, st->word)) return CMD_ERROR;
    snprintf(sh->w.set.collision_sound, PATH_MAX_VROC, "%s", st->word);
    return CMD_OK;
}

static cmd_status cmd_tracker(shell *sh, const stmt *st)
{
    if (st->n == 1) {
        sh->w.set.tracker[0] = '\0';
        return CMD_OK;
    }
    if (!readable_file(sh, st, st->word)) return CMD_ERROR;
    snprintf(sh->w.set.tracker, PATH_MAX_VROC, "%s", st->word);
    return CMD_OK;
}

static cmd_status cmd_log(shell *sh, const stmt *st)
{
    bool trace = strcmp(st->cmd->name, "trace") == 0;
    if (st->n == 1) {
        if (trace) log_trace_close(&sh->w);
        else log_events_close(&sh->w);
        return CMD_OK;
    }
    char err[PATH_MAX_VROC + 64];
    int r = trace ? log_trace_open(&sh->w, st->word, err, sizeof err)
                  : log_events_open(&sh->w, st->word, err, sizeof err);
    if (r != 0) {
        sh_error(sh, st, "%s: %s", st->cmd->name, err);
        return CMD_ERROR;
    }
    return CMD_OK;
}

static cmd_status cmd_gravity(shell *sh, const stmt *st)
{
    (void)st;
    sh->w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    sim_wake_all(&sh->w);
    return CMD_OK;
}

static cmd_status cmd_reset(shell *sh, const stmt *st)
{
    (void)st;
    settings d = settings_defaults();
    sh->w.set.head = d.head;
    sh->w.set.look_at = d.look_at;
    sh->w.set.up = d.up;
    return CMD_OK;
}

/* ------------------------------------------------------------ writing the language */

static void write_setting(FILE *out, const world *w, const command *c, int for_save)
{
    const settings *s = &w->set;
    const char *field = (const char *)s + c->off;
    char a[32];
    const char *n = c->name;
    if (strcmp(n, "trace") == 0 || strcmp(n, "events") == 0) {
        const char *path = n[0] == 't' ? w->trace_path : w->events_path;
        fprintf(out, "%s%s = %s%s%s\n", for_save ? "# " : "", n, path[0] ? "\"" : "",
                path[0] ? path : "off", path[0] ? "\"" : "");
        return;
    }
    if (strcmp(n, "tracker") == 0) {
        if (s->tracker[0]) fprintf(out, "tracker = \"%s\"\n", s->tracker);
        else fprintf(out, "tracker = off\n");
        return;
    }
    if (strcmp(n, "seed") == 0) {
        fprintf(out, "seed = %lu\n", s->seed);
        return;
    }
    if (strcmp(n, "image_size") == 0) {
        fprintf(out, "image_size = (%d, %d)\n", s->image_w, s->image_h);
        return;
    }
    if (strcmp(n, "stereo") == 0) {
        static const char *names[] = {"pair", "sbs", "anaglyph", "mono"};
        fprintf(out, "stereo = %s\n", names[s->stereo]);
        return;
    }
    if (strcmp(n, "real") == 0) {
        static const char *names[] = {"solid", "wire", "hidden"};
        fprintf(out, "real = %s\n", names[s->real]);
        return;
    }
    fprintf(out, "%s = ", n);
    switch (c->arg) {
    case VAL_NUMBER: fprintf(out, "%s", fmt_num(a, *(const double *)field)); break;
    case VAL_VECTOR: put_vec(out, *(const vec3 *)field); break;
    case VAL_VECTOR_ANGLE: {
        const dir_amount *d = (const dir_amount *)field;
        put_vec(out, d->dir);
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

static cmd_status cmd_select(shell *sh, const stmt *st);

void settings_write(FILE *out, const world *w, int for_save)
{
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form == FORM_SETTING) write_setting(out, w, c, for_save);
        else if (c->run == cmd_select) /* the hand's select mode is a setting too */
            fprintf(out, "select %s\n", w->set.select_mode ? "on" : "off");
    }
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
        put_vec(out, p->size);
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
    put_vec(out, b->x);
    vec3 axis = b->rot_axis;
    double angle = b->rot_angle;
    if (!b->rot_given) q_to_axis_angle(b->q, &axis, &angle);
    fprintf(out, "\nrotate = ");
    put_vec(out, axis);
    fprintf(out, " %s\nlinear_vel = ", fmt_num(a, angle));
    put_vec(out, b->v);
    fprintf(out, "\nangular_vel = ");
    put_vec(out, b->w);
    fputc('\n', out);
    if (b->state == STATE_RESTING) fprintf(out, "# resting\n");
}

/* ------------------------------------------------------------ console commands */

static cmd_status cmd_print(shell *sh, const stmt *st)
{
    int i = world_find(&sh->w, st->word);
    if (i < 0) {
        sh_error(sh, st, "no object named '%s'", st->word);
        return CMD_ERROR;
    }
    body_write(sh->out, sh->w.bodies[i]);
    return CMD_OK;
}

static cmd_status cmd_list(shell *sh, const stmt *st)
{
    (void)st;
    for (int i = 0; i < sh->w.n; i++) {
        const body *b = sh->w.bodies[i];
        fprintf(sh->out, "%-20s %-13s %s\n", b->name, body_type_name(b->sp.kind),
                log_state_name(b->state));
    }
    return CMD_OK;
}

static cmd_status cmd_show(shell *sh, const stmt *st)
{
    (void)st;
    settings_write(sh->out, &sh->w, 0);
    return CMD_OK;
}

static cmd_status cmd_save(shell *sh, const stmt *st)
{
    FILE *f = fopen(st->word, "w");
    if (!f) {
        sh_error(sh, st, "save: cannot write '%s': %s", st->word, strerror(errno));
        return CMD_ERROR;
    }
    char a[32];
    fprintf(f, "# vroc %s: world saved at time = %s (frame %ld)\n", VROC_VERSION,
            fmt_num(a, sh->w.time), sh->w.frame);
    fprintf(f, "# settings\n");
    settings_write(f, &sh->w, 1);
    fprintf(f, "\n# objects\n");
    for (int i = 0; i < sh->w.n; i++) {
        body_write(f, sh->w.bodies[i]);
        fputc('\n', f);
    }
    if (sh->current >= 0) fprintf(f, "# the current object\n%s %s\n",
                                  body_type_name(sh->w.bodies[sh->current]->sp.kind),
                                  sh->w.bodies[sh->current]->name);
    if (fclose(f) != 0) {
        sh_error(sh, st, "save: cannot write '%s': %s", st->word, strerror(errno));
        return CMD_ERROR;
    }
    sh_info(sh, "saved %d objects to %s", sh->w.n, st->word);
    return CMD_OK;
}

static cmd_status cmd_time(shell *sh, const stmt *st)
{
    (void)st;
    char a[32];
    fprintf(sh->out, "time = %s\n", fmt_num(a, sh->w.time));
    return CMD_OK;
}

static const char *feature_name(closest_feature f, char buf[48])
{
    if (f.kind == CLOSEST_SPHERE || f.kind == CLOSEST_NONE) return closest_kind_name(f.kind);
    snprintf(buf, 48, "%s %d", closest_kind_name(f.kind), f.index);
    return buf;
}

static cmd_status cmd_distance(shell *sh, const stmt *st)
{
    int ia = world_find(&sh->w, st->word), ib = world_find(&sh->w, st->word2);
    if (ia < 0 || ib < 0) {
        sh_error(sh, st, "no object named '%s'", ia < 0 ? st->word : st->word2);
        return CMD_ERROR;
    }
    if (ia == ib) {
        sh_error(sh, st, "distance: '%s' is the same object twice", st->word);
        return CMD_ERROR;
    }
    closest_result r = closest_query(sh->w.bodies[ia], sh->w.bodies[ib], NULL);
    if (r.status == CLOSEST_INVALID) {
        sh_error(sh, st, "distance: '%s' or '%s' has no valid shape or position", st->word,
                 st->word2);
        return CMD_ERROR;
    }
    char a[32], fa[48], fb[48];
    fprintf(sh->out, "distance = %s\npoint_A = ", fmt_num(a, r.distance));
    put_vec(sh->out, r.pa);
    fprintf(sh->out, "\npoint_B = ");
    put_vec(sh->out, r.pb);
    fprintf(sh->out, "\nnormal = ");
    put_vec(sh->out, r.normal);
    fprintf(sh->out, "\nfeature_A = %s\nfeature_B = %s\n", feature_name(r.fa, fa),
            feature_name(r.fb, fb));
    return CMD_OK;
}

static cmd_status cmd_stats(shell *sh, const stmt *st)
{
    (void)st;
    const world *w = &sh->w;
    char a[32];
    fprintf(sh->out, "objects = %d\n", w->n);
    fprintf(sh->out, "pairs = %ld\n", world_pairs(w));
    fprintf(sh->out, "subframes = %ld\n", world_subframes(w));
    fprintf(sh->out, "frames = %ld\n", w->st.frames);
    fprintf(sh->out, "pair_checks = %ld\n", w->st.pair_checks);
    fprintf(sh->out, "collisions = %ld\n", w->st.collisions);
    fprintf(sh->out, "sim_time = %s\n", fmt_num(a, w->time));
    fprintf(sh->out, "wall_time = %.6f\n", w->st.wall_time);
    fprintf(sh->out, "internal_steps = %ld\n", w->st.subframes);
    fprintf(sh->out, "heap_pops = %ld\n", w->st.heap_pops);
    fprintf(sh->out, "restarts = %ld\n", w->st.restarts);
    double nf = w->st.frames > 0 ? (double)w->st.frames : 1;
    fprintf(sh->out, "pair_checks_per_frame = %.6g\n", (double)w->st.pair_checks / nf);
    fprintf(sh->out, "heap_pops_per_frame = %.6g\n", (double)w->st.heap_pops / nf);
    fprintf(sh->out, "collisions_per_frame = %.6g\n", (double)w->st.collisions / nf);
    fprintf(sh->out, "render_time = %.6f\n", w->st.render_time);
    fprintf(sh->out, "files_written = %ld\n", w->st.frames_written);
    return CMD_OK;
}

static cmd_status cmd_step(shell *sh, const stmt *st) { return shell_advance(sh, st, 1); }

static cmd_status cmd_run(shell *sh, const stmt *st)
{
    return shell_advance(sh, st, (long)st->num[0]);
}

static cmd_status cmd_start(shell *sh, const stmt *st)
{
    if (shell_check_start(sh, st) != CMD_OK) return CMD_ERROR;
    sh->w.running = true;
    if (!sh->interactive)
        sh_info(sh, "time started; it runs in real time at the prompt (use run N in scripts)");
    return CMD_OK;
}

static cmd_status cmd_stop(shell *sh, const stmt *st)
{
    (void)st;
    sh->w.running = false;
    return CMD_OK;
}

static cmd_status cmd_restart(shell *sh, const stmt *st)
{
    (void)st;
    world_free(&sh->w);
    world_init(&sh->w);
    sh->w.set = sh->startup;
    sh->rng = sh->w.set.seed;
    sh->current = sh->selected = sh->prev_selected = -1;
    return CMD_OK;
}

static cmd_status cmd_quit(shell *sh, const stmt *st)
{
    (void)sh;
    (void)st;
    return CMD_QUIT;
}

static cmd_status cmd_read(shell *sh, const stmt *st)
{
    if (sh->read_depth >= LANG_MAX_DEPTH) {
        sh_error(sh, st, "read: files nested deeper than %d levels", LANG_MAX_DEPTH);
        return CMD_ERROR;
    }
    sh->read_depth++;
    cmd_status r = shell_run_program(sh, st->sub);
    sh->read_depth--;
    return r;
}

static cmd_status cmd_display(shell *sh, const stmt *st)
{
    char err[512];
    if (view_display(&sh->view, &sh->w, err, sizeof err) != 0) {
        sh_error(sh, st, "display: %s", err);
        return CMD_ERROR;
    }
    return CMD_OK;
}

static cmd_status cmd_refresh(shell *sh, const stmt *st)
{
    char err[512];
    if (view_refresh(&sh->view, &sh->w, sh->w.frame, &sh->w.st, err, sizeof err) != 0) {
        sh_error(sh, st, "refresh: %s", err);
        return CMD_ERROR;
    }
    return CMD_OK;
}

static cmd_status cmd_select(shell *sh, const stmt *st)
{
    if (st->n) {
        sh->w.set.select_mode = st->num[0] != 0;
    } else { /* the thesis's toggle: say where it went */
        sh->w.set.select_mode = !sh->w.set.select_mode;
        sh_info(sh, "select mode %s", sh->w.set.select_mode ? "on" : "off");
    }
    return CMD_OK;
}

static cmd_status cmd_reselect(shell *sh, const stmt *st)
{
    if (sh->prev_selected < 0) {
        sh_error(sh, st, "reselect: no object has been selected yet");
        return CMD_ERROR;
    }
    sh->current = sh->prev_selected;
    return CMD_OK;
}

static void help_summary(shell *sh)
{
    static const struct {
        const char *group, *title;
    } groups[] = {{"object", "Objects"},
                  {"property", "Properties of the current object (or NAME.property = value)"},
                  {"system", "System (thesis Table A.5)"},
                  {"console", "Console"},
                  {"view", "Views and hand"}};
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++) {
        fprintf(sh->out, "%s%s:\n", g ? "\n" : "", groups[g].title);
        for (int i = 0; i < command_count; i++) {
            const help_entry *h = help_find(command_table[i].name);
            if (h && strcmp(h->group, groups[g].group) == 0)
                fprintf(sh->out, "  %-30s %s\n", h->usage, h->summary);
        }
    }
    fprintf(sh->out, "\nhelp COMMAND tells more about one command.\n");
}

static cmd_status cmd_help(shell *sh, const stmt *st)
{
    if (!st->word) {
        help_summary(sh);
        return CMD_OK;
    }
    const help_entry *h = help_find(st->word);
    if (!h) {
        sh_error(sh, st, "help: no command named '%s' (help lists them all)", st->word);
        return CMD_ERROR;
    }
    fprintf(sh->out, "usage: %s\n  %s\n\n%s\n", h->usage, h->summary, h->description);
    if (h->example[0]) {
        fprintf(sh->out, "\nexample:\n");
        const char *p = h->example;
        while (*p) {
            size_t n = strcspn(p, "\n");
            fprintf(sh->out, "    %.*s\n", (int)n, p);
            p += n;
            if (*p) p++;
        }
    }
    return CMD_OK;
}

/* ------------------------------------------------------------ random */

/* splitmix64: small, fast, the same everywhere */
static unsigned long long rng_next(unsigned long long *s)
{
    unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static double rng_uniform(unsigned long long *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next(s) >> 11) * (1.0 / 9007199254740992.0);
}

static vec3 rng_unit(unsigned long long *s)
{
    for (;;) {
        vec3 v = v3(rng_uniform(s, -1, 1), rng_uniform(s, -1, 1), rng_uniform(s, -1, 1));
        double l = v3_len(v);
        if (l > 1e-3 && l <= 1) return v3_scale(v, 1 / l);
    }
}

/* True when a ball of radius r at c is clear of every object's circumscribed
 * sphere. */
static bool place_is_free(const world *w, vec3 c, double r)
{
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (v3_dist(c, body_com(b)) < r + b->shape.r_out) return false;
    }
    return true;
}

static cmd_status cmd_random(shell *sh, const stmt *st)
{
    long n = (long)st->num[0];
    world *w = &sh->w;
    vec3 box = w->set.random_box;
    double scale = fmin(box.x, fmin(box.y, box.z));
    int first = w->n;
    char err[256];
    for (long k = 0; k < n; k++) {
        body *b = malloc(sizeof *b);
        if (!b) goto oom;
        char name[BODY_NAME_MAX];
        for (long id = w->n + 1;; id++) {
            snprintf(name, sizeof name, "random%ld", id);
            if (world_find(w, name) < 0) break;
        }
        shape_kind kind = (shape_kind)(rng_next(&sh->rng) % 3);
        body_init(b, name, kind);
        double s = scale * rng_uniform(&sh->rng, 0.04, 0.1);
        b->sp.radius = s;
        b->sp.size = v3(s * rng_uniform(&sh->rng, 0.6, 1), s * rng_uniform(&sh->rng, 0.6, 1),
                        s * rng_uniform(&sh->rng, 0.6, 1));
        b->sp.exp1 = rng_uniform(&sh->rng, 0.3, 1.8);
        b->sp.exp2 = rng_uniform(&sh->rng, 0.3, 1.8);
        b->sp.a1 = s;
        b->sp.a2 = s * rng_uniform(&sh->rng, 0.6, 1);
        b->sp.a3 = s * rng_uniform(&sh->rng, 0.6, 1);
        for (int c = 0; c < 3; c++) b->color[c] = 64 + (int)(rng_next(&sh->rng) % 192);
        if (body_build(b, err, sizeof err) != 0) {
            free(b);
            sh_error(sh, st, "random: %s", err);
            goto undo;
        }
        double r = b->shape.r_out;
        bool placed = false;
        for (int tries = 0; tries < 2000 && !placed; tries++) {
            vec3 c = v3(rng_uniform(&sh->rng, -box.x + r, box.x - r),
                        rng_uniform(&sh->rng, -box.y + r, box.y - r),
                        rng_uniform(&sh->rng, -box.z + r, box.z - r));
            if (place_is_free(w, c, r)) {
                b->x = c;
                placed = true;
            }
        }
        if (!placed) {
            body_free(b);
            free(b);
            sh_error(sh, st,
                     "random: no free place for object %ld of %ld inside random_box; enlarge "
                     "random_box or add fewer objects",
                     k + 1, n);
            goto undo;
        }
        body_set_rotation(b, rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, M_PI));
        b->v = v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_linear)));
        body_set_angular_vel(
            b, v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_angular))));
        if (world_add(w, b) < 0) goto oom;
    }
    return CMD_OK;
oom:
    sh_error(sh, st, "out of memory");
undo:
    while (w->n > first) world_delete(w, w->n - 1);
    return CMD_ERROR;
}

/* ------------------------------------------------------------ the table */

#define INF HUGE_VAL
#define PROP(name, arg, range, lo, hi, classes) \
    {name, FORM_PROPERTY, arg, range, lo, hi, NULL, classes, 0, cmd_property}
#define SET(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, S(field), cmd_setting}
#define SETF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, S(field), fn}
#define ACT(name, arg, fn) {name, FORM_ACTION, arg, 0, 0, 0, NULL, 0, 0, fn}
#define COUNT(name, fn) {name, FORM_ACTION, ARG_COUNT, R_RANGE, 0, 1e9, NULL, 0, 0, fn}

/* In the order of help's groups; show and save write the settings in this order. */
const command command_table[] = {
    /* objects */
    ACT("sphere", ARG_NAME, cmd_create),
    ACT("cube", ARG_NAME, cmd_create),
    ACT("superquadric", ARG_NAME, cmd_create),
    ACT("delete", ARG_NAME, cmd_delete),
    /* properties (Tables A.1 to A.4) */
    PROP("linear_vel", VAL_VECTOR, 0, 0, 0, C_ALL),
    PROP("angular_vel", VAL_VECTOR, 0, 0, 0, C_ALL),
    PROP("elasticity", VAL_NUMBER, R_RANGE, 0, 1, C_ALL),
    PROP("mass", VAL_NUMBER, R_NONZERO, 0, 0, C_ALL),
    PROP("volume", VAL_NUMBER, R_RANGE, 0, INF, C_ALL),
    PROP("translate", VAL_VECTOR, 0, 0, 0, C_ALL),
    PROP("rotate", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, C_ALL),
    PROP("color", VAL_COLOR, 0, 0, 0, C_ALL),
    PROP("radius", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SPHERE),
    PROP("ures", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ),
    PROP("vres", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ),
    PROP("size", VAL_VECTOR, 0, 0, 0, C_CUBE),
    PROP("exp1", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ),
    PROP("exp2", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ),
    PROP("a1", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ),
    PROP("a2", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ),
    PROP("a3", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ),
    /* system (Table A.5) */
    ACT("read", ARG_FILE, cmd_read),
    ACT("display", ARG_NONE, cmd_display),
    ACT("reset", ARG_NONE, cmd_reset),
    ACT("restart", ARG_NONE, cmd_restart),
    ACT("start", ARG_NONE, cmd_start),
    ACT("stop", ARG_NONE, cmd_stop),
    ACT("step", ARG_NONE, cmd_step),
    ACT("refresh", ARG_NONE, cmd_refresh),
    ACT("help", ARG_OPT_WORD, cmd_help),
    ACT("quit", ARG_NONE, cmd_quit),
    SET("time_step", VAL_NUMBER, R_RANGE, 0, INF, time_step),
    SET("collision_dist", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, collision_dist),
    SET("internal_step", VAL_NUMBER, R_RANGE, 0, INF, internal_step),
    SET("max_linear", VAL_NUMBER, R_RANGE, 0, INF, max_linear),
    SET("max_angular", VAL_NUMBER, R_RANGE, 0, INF, max_angular),
    SET("force", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, force),
    ACT("gravity", ARG_NONE, cmd_gravity),
    SETF("collision_sound", VAL_FILE, 0, 0, 0, collision_sound, cmd_collision_sound),
    SET("collision_vol", VAL_NUMBER, R_RANGE, 0, INF, collision_vol),
    /* console */
    COUNT("run", cmd_run),
    ACT("time", ARG_NONE, cmd_time),
    ACT("list", ARG_NONE, cmd_list),
    ACT("print", ARG_NAME, cmd_print),
    ACT("show", ARG_NONE, cmd_show),
    ACT("save", ARG_FILE, cmd_save),
    ACT("distance", ARG_NAME2, cmd_distance),
    ACT("stats", ARG_NONE, cmd_stats),
    SETF("events", VAL_FILE_OR_OFF, 0, 0, 0, output, cmd_log),
    SETF("trace", VAL_FILE_OR_OFF, 0, 0, 0, output, cmd_log),
    SET("collision_heap", VAL_ONOFF, 0, 0, 0, collision_heap),
    COUNT("random", cmd_random),
    SETF("random_box", VAL_VECTOR, 0, 0, 0, random_box, cmd_random_box),
    SETF("seed", VAL_INTEGER, R_RANGE, 0, 4294967295.0, seed, cmd_seed),
    /* views and hand */
    SET("head", VAL_VECTOR, 0, 0, 0, head),
    SET("look_at", VAL_VECTOR, 0, 0, 0, look_at),
    SET("up", VAL_VECTOR, R_NONZERO_VEC, 0, 0, up),
    SET("ipd", VAL_NUMBER, R_RANGE, 0, INF, ipd),
    SET("fov", VAL_NUMBER, R_RANGE | R_LO_OPEN | R_HI_OPEN, 0, 180, fov),
    SETF("image_size", VAL_SIZE2, R_RANGE, 16, 8192, image_w, cmd_image_size),
    SET("output", VAL_FILE, 0, 0, 0, output),
    {"stereo", FORM_SETTING, VAL_CHOICE, 0, 0, 0, "pair|sbs|anaglyph|mono", 0, 0, cmd_stereo},
    SET("background", VAL_COLOR, 0, 0, 0, background),
    {"real", FORM_SETTING, VAL_CHOICE, 0, 0, 0, "solid|wire|hidden", 0, 0, cmd_real},
    SET("record", VAL_ONOFF, 0, 0, 0, record),
    SET("hand", VAL_VECTOR, 0, 0, 0, hand),
    SET("hand_rotate", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, hand_rotate),
    SET("trigger", VAL_ONOFF, 0, 0, 0, trigger),
    ACT("select", ARG_OPT_ONOFF, cmd_select),
    ACT("reselect", ARG_NONE, cmd_reselect),
    SETF("tracker", VAL_FILE_OR_OFF, 0, 0, 0, tracker, cmd_tracker),
};

const int command_count = (int)(sizeof command_table / sizeof command_table[0]);

const command *command_find(const char *name)
{
    for (int i = 0; i < command_count; i++)
        if (strcmp(command_table[i].name, name) == 0) return &command_table[i];
    return NULL;
}
