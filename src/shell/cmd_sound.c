/* cmd_sound.c: the handlers of sound and movies (language.md, "Sound and movies"):
 * collision_sound, sound, soundtrack and movie.  collision_vol is a plain setting
 * (cmd_setting); the work is media.c's. */
#include <stdio.h>

#include "handlers.h"
#include "media.h"
#include "outfile.h"
#include "shell.h"

cmd_status cmd_collision_sound(shell *sh, const stmt *st)
{
    char err[1024];
    if (media_choose_sound(sh, st->word, err, sizeof err) != 0) {
        sh_error(sh, st, "collision_sound: %s", err);
        return CMD_ERROR;
    }
    snprintf(sh->sound_set.collision_sound, sizeof sh->sound_set.collision_sound, "%s",
             st->word);
    return CMD_OK;
}

cmd_status cmd_sound(shell *sh, const stmt *st)
{
    if (st->num[0] != 0) {
        sh->sound_set.live = SOUND_LIVE_ON; /* the server is asked when time runs */
    } else {
        sh->sound_set.live = SOUND_LIVE_OFF;
        media_live_off(sh);
    }
    return CMD_OK;
}

/* soundtrack and movie: a file (where VROC_SANDBOX allows it: outfile.h), or
 * off. */
static cmd_status media_output(shell *sh, const stmt *st,
                               cmd_status (*set)(shell *, const stmt *, const char *))
{
    const char *path = st->n == 1 ? NULL : st->word;
    char err[2048];
    if (path && outfile_allowed(path, err, sizeof err) != 0) {
        sh_error(sh, st, "%s: %s", st->cmd->name, err);
        return CMD_ERROR;
    }
    return set(sh, st, path);
}

cmd_status cmd_soundtrack(shell *sh, const stmt *st) { return media_output(sh, st, media_soundtrack); }

cmd_status cmd_movie(shell *sh, const stmt *st) { return media_output(sh, st, media_movie); }
