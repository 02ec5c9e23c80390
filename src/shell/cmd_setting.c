/* cmd_setting.c: the handlers of `name = value` settings (thesis Table A.5;
 * language.md): the generic one, which writes the value at the table's offset in
 * its owner's settings, and those that check or convert their value first. */
#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/edit.h"
#include "handlers.h"
#include "outfile.h"
#include "shell.h"

cmd_status cmd_setting(shell *sh, const stmt *st)
{
    const command *c = st->cmd;
    if (c->owner == OWN_SIM && c->off == offsetof(sim_settings, force)) {
        edit_force(&sh->w, (dir_amount){stmt_vec(st), st->num[3]}); /* wakes what rests */
        return CMD_OK;
    }
    char *field = shell_setting_field(sh, c);
    switch (c->arg) {
    case VAL_NUMBER: *(double *)field = st->num[0]; break;
    case VAL_VECTOR: *(vec3 *)field = stmt_vec(st); break;
    case VAL_RANGE2:
        ((double *)field)[0] = st->num[0];
        ((double *)field)[1] = st->num[1];
        break;
    case VAL_VECTOR_ANGLE: *(dir_amount *)field = (dir_amount){stmt_vec(st), st->num[3]}; break;
    case VAL_COLOR:
        for (int k = 0; k < 3; k++) ((int *)field)[k] = (int)st->num[k];
        break;
    case VAL_ONOFF: *(bool *)field = st->num[0] != 0; break;
    case VAL_CHOICE: *(int *)field = (int)st->num[0]; break;
    case VAL_FILE: { /* output: a folder vroc writes into */
        char err[VIEW_PATH_MAX + 256];
        if (outfile_allowed(st->word, err, sizeof err) != 0) {
            sh_error(sh, st, "%s: %s", c->name, err);
            return CMD_ERROR;
        }
        snprintf(field, c->owner == OWN_VIEW ? VIEW_PATH_MAX : SHELL_PATH_MAX, "%s", st->word);
        break;
    }
    default: break;
    }
    return CMD_OK;
}

cmd_status cmd_random_box(shell *sh, const stmt *st)
{
    vec3 v = stmt_vec(st);
    if (!(v.x > 0 && v.y > 0 && v.z > 0)) {
        sh_error(sh, st, "random_box half-extents must all be > 0");
        return CMD_ERROR;
    }
    sh->set.random_box = v;
    return CMD_OK;
}

cmd_status cmd_seed(shell *sh, const stmt *st)
{
    sh->set.seed = (unsigned long)st->num[0];
    sh->rng = sh->set.seed;
    return CMD_OK;
}

/* splitmix64 adds this to its state at every draw (random.c) */
#define DRAW_STEP 0x9E3779B97F4A7C15ULL

cmd_status cmd_random_draws(shell *sh, const stmt *st)
{
    sh->rng = sh->set.seed + (unsigned long long)st->num[0] * DRAW_STEP;
    return CMD_OK;
}

unsigned long long shell_random_draws(const shell *sh)
{
    /* the step's inverse modulo 2^64 (it is odd), by Newton's iteration */
    unsigned long long inv = DRAW_STEP;
    for (int k = 0; k < 6; k++) inv *= 2 - DRAW_STEP * inv;
    return (sh->rng - sh->set.seed) * inv;
}

cmd_status cmd_image_size(shell *sh, const stmt *st)
{
    sh->view_set.image_w = (int)st->num[0];
    sh->view_set.image_h = (int)st->num[1];
    return CMD_OK;
}

cmd_status cmd_stereo(shell *sh, const stmt *st)
{
    static const stereo_mode modes[] = {STEREO_PAIR, STEREO_SBS, STEREO_ANAGLYPH, STEREO_MONO};
    sh->view_set.stereo = modes[(int)st->num[0]];
    return CMD_OK;
}

cmd_status cmd_real(shell *sh, const stmt *st)
{
    static const real_mode modes[] = {REAL_SOLID, REAL_WIRE, REAL_HIDDEN};
    sh->view_set.real = modes[(int)st->num[0]];
    return CMD_OK;
}

cmd_status cmd_log(shell *sh, const stmt *st)
{
    bool trace = strcmp(st->cmd->name, "trace") == 0;
    char err[LOG_PATH_MAX + 256];
    int r;
    if (st->n != 1 && outfile_allowed(st->word, err, sizeof err) != 0)
        r = -1;
    else if (st->n == 1) /* off: the last rows are checked as the file closes */
        r = trace ? log_trace_close(&sh->logs, err, sizeof err)
                  : log_events_close(&sh->logs, err, sizeof err);
    else
        r = trace ? log_trace_open(&sh->logs, &sh->w, st->word, err, sizeof err)
                  : log_events_open(&sh->logs, st->word, err, sizeof err);
    if (r != 0) {
        sh_error(sh, st, "%s: %s", st->cmd->name, err);
        return CMD_ERROR;
    }
    return CMD_OK;
}
