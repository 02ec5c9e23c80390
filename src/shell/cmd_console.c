/* cmd_console.c: what a console tool adds to the thesis's language (language.md,
 * "Commands a console tool needs" and "The console beyond the thesis"): run,
 * time, print, list, show, save, distance, stats, energy and help. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/closest.h"
#include "core/edit.h"
#include "core/energy.h"
#include "handlers.h"
#include "outfile.h"
#include "shell.h"
#include "shell/help.h"
#include "suggest.h"
#include "writer.h"

cmd_status cmd_run(shell *sh, const stmt *st)
{
    return shell_run_frames(sh, st, (long)st->num[0]);
}

cmd_status cmd_time(shell *sh, const stmt *st)
{
    (void)st;
    char a[32];
    fprintf(sh->out, "time = %s\n", fmt_shown(a, sh->w.time, shell_shown(sh)));
    return CMD_OK;
}

cmd_status cmd_print(shell *sh, const stmt *st)
{
    int i = world_find(&sh->w, st->word);
    if (i < 0) {
        sh_error(sh, st, "no object named '%s'", st->word);
        return CMD_ERROR;
    }
    const body *b = sh->w.bodies[i];
    if (st->word2) { /* print NAME.property */
        const command *c = command_find(st->word2);
        if (!(c->classes & (1u << b->sp.kind))) {
            sh_error(sh, st, "print: %s does not apply to %s '%s'", c->name,
                     body_type_name(b->sp.kind), b->name);
            return CMD_ERROR;
        }
        property_write(sh->out, &sh->w, i, c, shell_shown(sh));
        return CMD_OK;
    }
    body_write(sh->out, b, (write_style){shell_shown(sh), true, NULL});
    contact_write(sh->out, &sh->w, i, 0);
    return CMD_OK;
}

cmd_status cmd_list(shell *sh, const stmt *st)
{
    (void)st;
    for (int i = 0; i < sh->w.n; i++) {
        const body *b = sh->w.bodies[i];
        fprintf(sh->out, "%-20s %-13s %s\n", b->name, body_type_name(b->sp.kind), log_body_state(b));
    }
    return CMD_OK;
}

cmd_status cmd_show(shell *sh, const stmt *st)
{
    if (!st->word) {
        settings_write(sh->out, sh, NULL);
        return CMD_OK;
    }
    const command *c = command_find(st->word);
    if (c && (c->form == FORM_SETTING || c->run == cmd_select)) {
        setting_write(sh->out, sh, c);
        return CMD_OK;
    }
    if (c && c->form == FORM_PROPERTY) {
        sh_error(sh, st, "show: %s is a property of objects: print NAME.%s shows it", c->name,
                 c->name);
        return CMD_ERROR;
    }
    suggestion sg;
    char hint[96];
    suggest_init(&sg, st->word);
    suggest_offer_commands(&sg, 1u << FORM_SETTING);
    sh_error(sh, st, "show: '%s' is not a setting%s (show lists them all)", st->word,
             suggest_text(&sg, hint, sizeof hint));
    return CMD_ERROR;
}

cmd_status cmd_save(shell *sh, const stmt *st)
{
    /* written beside the file, which it replaces only once written whole */
    outfile o;
    char err[PATH_MAX + 256];
    if (outfile_begin(&o, st->word, OUTFILE_STREAM, err, sizeof err) != 0) {
        sh_error(sh, st, "save: %s", err);
        return CMD_ERROR;
    }
    FILE *f = o.f;
    char a[32];
    fprintf(f, "# vroc %s: world saved at time = %s (frame %ld)\n", VROC_VERSION,
            fmt_num(a, sh->w.time), sh->w.frame);
    fprintf(f, "# settings\n");
    settings_write(f, sh, st->word);
    fprintf(f, "\n# objects\n");
    for (int i = 0; i < sh->w.n; i++) {
        body_write(f, sh->w.bodies[i], (write_style){FMT_EXACT, false, st->word});
        fputc('\n', f);
    }
    /* the contact state: placing an object ends its lasting contacts */
    fprintf(f, "# the contact state: modes, rest and lasting contacts, as the simulation left "
               "them\n");
    for (int i = 0; i < sh->w.n; i++) {
        /* (one a command placed has its contacts found by the next frame, as the
         * read-back world's does: objects made touching, a cradle's balls) */
        if (sh->w.bodies[i]->moved) continue;
        fprintf(f, "%s %s\n", body_type_name(sh->w.bodies[i]->sp.kind), sh->w.bodies[i]->name);
        contact_write(f, &sh->w, i, 1);
    }
    /* the hand last: what it holds is gripped again */
    hand_write(f, sh, st->word);
    if (sh->current >= 0) fprintf(f, "\n# the current object\n%s %s\n",
                                  body_type_name(sh->w.bodies[sh->current]->sp.kind),
                                  sh->w.bodies[sh->current]->name);
    if (outfile_finish(&o, err, sizeof err) != 0) {
        sh_error(sh, st, "save: %s", err);
        return CMD_ERROR;
    }
    sh_info(sh, "saved %d objects to %s", sh->w.n, st->word);
    return CMD_OK;
}

static const char *feature_name(closest_feature f, char buf[48])
{
    if (f.kind == CLOSEST_SPHERE || f.kind == CLOSEST_NONE) return closest_kind_name(f.kind);
    snprintf(buf, 48, "%s %d", closest_kind_name(f.kind), f.index);
    return buf;
}

cmd_status cmd_distance(shell *sh, const stmt *st)
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
    closest_result r = body_distance(sh->w.bodies[ia], sh->w.bodies[ib], NULL);
    if (r.status == CLOSEST_INVALID) {
        sh_error(sh, st, "distance: '%s' or '%s' has no valid shape or position", st->word,
                 st->word2);
        return CMD_ERROR;
    }
    char a[32], fa[48], fb[48];
    fmt_style s = shell_shown(sh);
    fprintf(sh->out, "distance = %s\npoint_A = ", fmt_shown(a, r.distance, s));
    writer_vec(sh->out, r.pa, s);
    fprintf(sh->out, "\npoint_B = ");
    writer_vec(sh->out, r.pb, s);
    fprintf(sh->out, "\nnormal = ");
    writer_vec(sh->out, r.normal, s);
    fprintf(sh->out, "\nfeature_A = %s\nfeature_B = %s\n", feature_name(r.fa, fa),
            feature_name(r.fb, fb));
    /* (bodies of several pieces: whose hull the feature is of) */
    if (sh->w.bodies[ia]->shape.pieces > 1) fprintf(sh->out, "piece_A = %d\n", r.ka + 1);
    if (sh->w.bodies[ib]->shape.pieces > 1) fprintf(sh->out, "piece_B = %d\n", r.kb + 1);
    const body *A = sh->w.bodies[ia], *B = sh->w.bodies[ib];
    fprintf(sh->out, "friction = %s\n", fmt_shown(a, friction_mu(A, B), s));
    fprintf(sh->out, "rolling_friction = %s\n", fmt_shown(a, friction_rolling(A, B), s));
    return CMD_OK;
}

cmd_status cmd_stats(shell *sh, const stmt *st)
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
    fprintf(sh->out, "sim_time = %s\n", fmt_shown(a, w->time, shell_shown(sh)));
    fprintf(sh->out, "wall_time = %.6f\n", sh->wall_time);
    fprintf(sh->out, "internal_steps = %ld\n", w->st.subframes);
    fprintf(sh->out, "heap_pops = %ld\n", w->st.heap_pops);
    fprintf(sh->out, "restarts = %ld\n", w->st.restarts);
    double nf = w->st.frames > 0 ? (double)w->st.frames : 1;
    fprintf(sh->out, "pair_checks_per_frame = %.6g\n", (double)w->st.pair_checks / nf);
    fprintf(sh->out, "heap_pops_per_frame = %.6g\n", (double)w->st.heap_pops / nf);
    fprintf(sh->out, "collisions_per_frame = %.6g\n", (double)w->st.collisions / nf);
    fprintf(sh->out, "render_time = %.6f\n", sh->view_st.render_time);
    fprintf(sh->out, "files_written = %ld\n", sh->view_st.frames_written);
    fprintf(sh->out, "existing_pairs = %ld\n", w->pairs.live);
    fprintf(sh->out, "unsolved = %ld\n", w->st.unsolved);
    fprintf(sh->out, "overflows = %ld\n", w->st.overflows);
    fprintf(sh->out, "crowds = %ld\n", w->st.crowds);
    fprintf(sh->out, "guards = %ld\n", w->st.guards);
    fprintf(sh->out, "speed_cuts = %ld\n", w->st.speed_cuts);
    fprintf(sh->out, "energy_cuts = %ld\n", w->st.energy_cuts);
    fprintf(sh->out, "cone_unconverged = %ld\n", w->st.cone_unconverged);
    fprintf(sh->out, "painleve = %ld\n", w->st.painleve);
    fprintf(sh->out, "fallen = %ld\n", w->st.fallen);
    long resting = 0;
    for (int i = 0; i < w->n; i++) resting += w->bodies[i]->state == STATE_RESTING;
    fprintf(sh->out, "resting = %ld\n", resting);
    fprintf(sh->out, "waves_cut = %ld\n", w->st.waves_cut);
    fprintf(sh->out, "separations = %ld\n", w->st.separations);
#ifdef VROC_VALIDATE
    /* (the validation build's watch: that nothing passes into anything) */
    fprintf(sh->out, "deepest = %.17g\n", w->st.deepest);
#endif
    return CMD_OK;
}

cmd_status cmd_energy(shell *sh, const stmt *st)
{
    const world *w = &sh->w;
    energy_sum e;
    const body *b = NULL;
    if (st->word) {
        int i = world_find(w, st->word);
        if (i < 0) {
            sh_error(sh, st, "no object named '%s'", st->word);
            return CMD_ERROR;
        }
        b = w->bodies[i];
        if (body_is_static(b)) {
            fprintf(sh->out, "# %s is static: it never moves, and holds no energy\n", b->name);
            return CMD_OK;
        }
        e = energy_of_body(w, b);
    } else {
        e = energy_of_world(w);
    }
    fmt_style s = shell_shown(sh);
    char a[32];
    fprintf(sh->out, "kinetic_energy = %s\n", fmt_shown(a, energy_kinetic(e), s));
    fprintf(sh->out, "kinetic_linear = %s\n", fmt_shown(a, e.linear, s));
    fprintf(sh->out, "kinetic_rotational = %s\n", fmt_shown(a, e.rotational, s));
    fprintf(sh->out, "potential_energy = %s\n", fmt_shown(a, e.potential, s));
    fprintf(sh->out, "total_energy = %s\n", fmt_shown(a, energy_total(e), s));
    fprintf(sh->out, "linear_momentum = ");
    writer_vec(sh->out, e.momentum, s);
    fprintf(sh->out, "\nangular_momentum = ");
    writer_vec(sh->out, e.angular_momentum, s);
    if (b) {
        fprintf(sh->out, "\nangular_momentum_com = ");
        writer_vec(sh->out, b->L, s);
    }
    fputc('\n', sh->out);
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
                  {"view", "Views and hand"},
                  {"sound", "Sound and movies"}};
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

cmd_status cmd_help(shell *sh, const stmt *st)
{
    if (!st->word) {
        help_summary(sh);
        return CMD_OK;
    }
    const help_entry *h = help_find(st->word);
    if (!h) {
        suggestion sg;
        char hint[96];
        suggest_init(&sg, st->word);
        suggest_offer_commands(&sg, ~0u);
        sh_error(sh, st, "help: no command named '%s'%s (help lists them all)", st->word,
                 suggest_text(&sg, hint, sizeof hint));
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

cmd_status cmd_clock(shell *sh, const stmt *st)
{
    if (st->num[1] < 0 || st->num[1] != floor(st->num[1])) {
        sh_error(sh, st, "clock: the frames N in (T0, N) must be a whole number >= 0");
        return CMD_ERROR;
    }
    edit_clock(&sh->w, st->num[0], (long)st->num[1]);
    return CMD_OK;
}

cmd_status cmd_frame(shell *sh, const stmt *st)
{
    sh->w.frame = (long)st->num[0];
    return CMD_OK;
}

cmd_status cmd_hash(shell *sh, const stmt *st)
{
    (void)st;
    fprintf(sh->out, "hash = %016llx\n", world_hash(&sh->w));
    return CMD_OK;
}
