/* cmd_console.c: what a console tool adds to the thesis's language (language.md,
 * "Commands a console tool needs"): run, time, print, list, show, save, distance,
 * stats and help. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/closest.h"
#include "core/edit.h"
#include "handlers.h"
#include "outfile.h"
#include "shell.h"
#include "shell/help.h"
#include "writer.h"

cmd_status cmd_run(shell *sh, const stmt *st)
{
    return shell_advance(sh, st, (long)st->num[0]);
}

cmd_status cmd_time(shell *sh, const stmt *st)
{
    (void)st;
    char a[32];
    fprintf(sh->out, "time = %s\n", fmt_num(a, sh->w.time));
    return CMD_OK;
}

cmd_status cmd_print(shell *sh, const stmt *st)
{
    int i = world_find(&sh->w, st->word);
    if (i < 0) {
        sh_error(sh, st, "no object named '%s'", st->word);
        return CMD_ERROR;
    }
    body_write(sh->out, sh->w.bodies[i]);
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
    (void)st;
    settings_write(sh->out, sh, 0);
    return CMD_OK;
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
    settings_write(f, sh, 1);
    fprintf(f, "\n# objects\n");
    for (int i = 0; i < sh->w.n; i++) {
        body_write_for(f, sh->w.bodies[i], st->word);
        fputc('\n', f);
    }
    /* the contact state: placing an object ends its lasting contacts */
    fprintf(f, "# the contact state: modes, rest and lasting contacts, as the simulation left "
               "them\n");
    for (int i = 0; i < sh->w.n; i++) {
        fprintf(f, "%s %s\n", body_type_name(sh->w.bodies[i]->sp.kind), sh->w.bodies[i]->name);
        contact_write(f, &sh->w, i, 1);
    }
    /* the hand last: what it holds is gripped again */
    hand_write(f, sh);
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
    fprintf(sh->out, "distance = %s\npoint_A = ", fmt_num(a, r.distance));
    writer_vec(sh->out, r.pa);
    fprintf(sh->out, "\npoint_B = ");
    writer_vec(sh->out, r.pb);
    fprintf(sh->out, "\nnormal = ");
    writer_vec(sh->out, r.normal);
    fprintf(sh->out, "\nfeature_A = %s\nfeature_B = %s\n", feature_name(r.fa, fa),
            feature_name(r.fb, fb));
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
    fprintf(sh->out, "sim_time = %s\n", fmt_num(a, w->time));
    fprintf(sh->out, "wall_time = %.6f\n", sh->wall_time);
    fprintf(sh->out, "internal_steps = %ld\n", w->st.subframes);
    fprintf(sh->out, "heap_pops = %ld\n", w->st.heap_pops);
    fprintf(sh->out, "restarts = %ld\n", w->st.restarts);
    fprintf(sh->out, "speed_cuts = %ld\n", w->st.speed_cuts);
    double nf = w->st.frames > 0 ? (double)w->st.frames : 1;
    fprintf(sh->out, "pair_checks_per_frame = %.6g\n", (double)w->st.pair_checks / nf);
    fprintf(sh->out, "heap_pops_per_frame = %.6g\n", (double)w->st.heap_pops / nf);
    fprintf(sh->out, "collisions_per_frame = %.6g\n", (double)w->st.collisions / nf);
    fprintf(sh->out, "render_time = %.6f\n", sh->view_st.render_time);
    fprintf(sh->out, "files_written = %ld\n", sh->view_st.frames_written);
    fprintf(sh->out, "existing_pairs = %ld\n", w->pairs.live);
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
