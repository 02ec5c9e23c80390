/* cmd_system.c: the system commands of the thesis's Table A.5 that are actions:
 * gravity, reset, step, start, stop, restart, quit, read, display and refresh. */
#include "core/edit.h"
#include "handlers.h"
#include "shell.h"
#include "view/view.h"

cmd_status cmd_gravity(shell *sh, const stmt *st)
{
    (void)st;
    edit_force(&sh->w, (dir_amount){v3(0, 0, -1), 9.8});
    return CMD_OK;
}

cmd_status cmd_reset(shell *sh, const stmt *st)
{
    (void)st;
    view_settings d = view_settings_defaults();
    sh->view_set.head = d.head;
    sh->view_set.look_at = d.look_at;
    sh->view_set.up = d.up;
    return CMD_OK;
}

cmd_status cmd_step(shell *sh, const stmt *st) { return shell_advance(sh, st, 1); }

cmd_status cmd_start(shell *sh, const stmt *st)
{
    if (shell_check_start(sh, st) != CMD_OK) return CMD_ERROR;
    char a[32];
    const char *t = fmt_shown(a, sh->w.time, shell_shown(sh));
    if (!sh->interactive)
        sh_info(sh, "time started; it runs in real time at the prompt (use run N in scripts)");
    else if (sh->running)
        sh_info(sh, "time is running already (time = %s)", t);
    else
        sh_info(sh, "time runs from time = %s: stop or Ctrl-C stops it", t);
    sh->running = true;
    return CMD_OK;
}

cmd_status cmd_stop(shell *sh, const stmt *st)
{
    (void)st;
    char a[32];
    if (sh->interactive)
        sh_info(sh, sh->running ? "stopped at time = %s" : "time was not running (time = %s)",
                fmt_shown(a, sh->w.time, shell_shown(sh)));
    sh->running = false;
    return CMD_OK;
}

cmd_status cmd_restart(shell *sh, const stmt *st)
{
    /* the logs end with the world they logged (commands/trace, commands/events,
     * commands/hand_log) */
    cmd_status r = shell_close_logs(sh, st);
    world_free(&sh->w);
    world_init(&sh->w);
    sh->w.set = sh->startup.sim;
    sh->view_set = sh->startup.view;
    sh->set = sh->startup.shell;
    sh->sound_set = sh->startup.sound; /* the soundtrack and movie go on, as the logs do */
    sh->rng = sh->set.seed;
    sh->current = -1;
    sh->made = 0;
    hand_free(&sh->hand);
    hand_init(&sh->hand, sh->hand.say, sh->hand.say_ctx);
    figures_clear(&sh->figs);
    return r;
}

cmd_status cmd_quit(shell *sh, const stmt *st)
{
    (void)sh;
    (void)st;
    return CMD_QUIT;
}

/* The file was parsed with the statement, nesting checked (lang.h).  It starts a
 * new run for plot (figures.h). */
cmd_status cmd_read(shell *sh, const stmt *st)
{
    figures_clear(&sh->figs);
    return shell_run_program(sh, st->sub);
}

cmd_status cmd_display(shell *sh, const stmt *st)
{
    char err[512];
    if (view_display(&sh->view, &sh->view_set, err, sizeof err) != 0) {
        sh_error(sh, st, "display: %s", err);
        return CMD_ERROR;
    }
    return CMD_OK;
}

cmd_status cmd_refresh(shell *sh, const stmt *st)
{
    char err[512];
    shell_overlay(sh);
    if (view_refresh(&sh->view, &sh->w, &sh->view_set, sh->w.frame, &sh->view_st, err,
                     sizeof err) != 0) {
        sh_error(sh, st, "refresh: %s", err);
        return CMD_ERROR;
    }
    return CMD_OK;
}
