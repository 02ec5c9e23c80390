/* cmd_hand.c: the handlers of the hand-held tracker and the tool panel (thesis
 * Appendix A.1; language.md, "The hand and the tool panel"): hand, hand_rotate,
 * trigger, select, reselect, tracker, tracker_time, hand_log and grip, and the
 * hand's exact state as save writes it (hand_orientation, tracker_clock, ...).  The hand
 * itself (src/hand/) does what they ask; the tool panel's settings (panel,
 * panel_at, panel_rotate) and reach and fly_speed are plain settings. */
#include <limits.h>
#include <string.h>

#include "handlers.h"
#include "shell.h"

cmd_status cmd_hand(shell *sh, const stmt *st)
{
    hand *h = &sh->hand;
    quat q = h->q;
    vec3 p = h->p;
    if (strcmp(st->cmd->name, "hand") == 0) {
        p = stmt_vec(st);
        h->set.hand = p;
    } else if (strcmp(st->cmd->name, "hand_orientation") == 0) { /* exactly */
        q = q_as_unit((quat){st->num[0], st->num[1], st->num[2], st->num[3]});
        /* show's hand_rotate stays as typed when it gives this orientation */
        quat typed = q_axis_angle(h->set.hand_rotate.dir, h->set.hand_rotate.amount);
        if (memcmp(&typed, &q, sizeof q) != 0) {
            vec3 axis;
            q_to_axis_angle(q, &axis, &h->set.hand_rotate.amount);
            h->set.hand_rotate.dir = axis;
        }
    } else {
        h->set.hand_rotate = (dir_amount){stmt_vec(st), st->num[3]};
        q = q_axis_angle(stmt_vec(st), st->num[3]);
    }
    hand_move(h, &sh->w, p, q);
    return CMD_OK;
}

cmd_status cmd_trigger(shell *sh, const stmt *st)
{
    hand_trigger(&sh->hand, &sh->w, st->num[0] != 0);
    return CMD_OK;
}

cmd_status cmd_select(shell *sh, const stmt *st)
{
    bool *mode = &sh->hand.set.select_mode;
    if (st->n) {
        *mode = st->num[0] != 0;
    } else { /* the thesis's toggle: say where it went */
        *mode = !*mode;
        sh_info(sh, "select mode %s", *mode ? "on" : "off");
    }
    return CMD_OK;
}

/* A handler's answer: ok when rc is 0, else the error err under its command's
 * name. */
static cmd_status answer(shell *sh, const stmt *st, int rc, const char *err)
{
    if (rc == 0) return CMD_OK;
    sh_error(sh, st, "%s: %s", st->cmd->name, err);
    return CMD_ERROR;
}

cmd_status cmd_reselect(shell *sh, const stmt *st)
{
    char err[256];
    return answer(sh, st, hand_reselect(&sh->hand, &sh->w, err, sizeof err), err);
}

cmd_status cmd_tracker(shell *sh, const stmt *st)
{
    if (st->n == 1) {
        hand_tracker_off(&sh->hand);
        return CMD_OK;
    }
    char err[HAND_PATH_MAX + 400];
    return answer(sh, st, hand_tracker(&sh->hand, st->word, err, sizeof err), err);
}

cmd_status cmd_tracker_time(shell *sh, const stmt *st)
{
    char err[256];
    return answer(sh, st, hand_seek(&sh->hand, &sh->w, st->num[0], err, sizeof err), err);
}

/* hand_log = FILE or off: the old log's last rows are checked as it closes. */
cmd_status cmd_hand_log(shell *sh, const stmt *st)
{
    char err[HAND_PATH_MAX + 400];
    int rc = st->n == 1 ? hand_log_close(&sh->hand, err, sizeof err)
                        : hand_log_open(&sh->hand, st->word, err, sizeof err);
    return answer(sh, st, rc, err);
}

cmd_status cmd_grip(shell *sh, const stmt *st)
{
    char err[BODY_NAME_MAX + 200];
    return answer(sh, st, hand_set_grip(&sh->hand, &sh->w, st->word, st->n == 1, err, sizeof err), err);
}

/* The hand's exact state, as save writes it (hand.h). */
cmd_status cmd_hand_exact(shell *sh, const stmt *st)
{
    hand *h = &sh->hand;
    const char *n = st->cmd->name;
    char err[BODY_NAME_MAX + 200];
    int rc = 0;
    if (strcmp(n, "tracker_clock") == 0) {
        hand_set_clock(h, st->num[0], st->num[1]);
    } else if (strcmp(n, "tracker_row") == 0) {
        rc = hand_set_row(h, st->num[0] < INT_MAX ? (int)st->num[0] : INT_MAX, err, sizeof err);
    } else if (strcmp(n, "hand_velocity") == 0) {
        hand_set_velocity(h, stmt_vec(st), st->num[3]);
    } else if (strcmp(n, "hand_spin") == 0) {
        hand_set_spin(h, stmt_vec(st));
    } else if (strcmp(n, "grip_at") == 0) {
        vec3 x = stmt_vec(st);
        hand_set_grip_pose(h, &x, NULL);
    } else if (strcmp(n, "grip_orientation") == 0) {
        quat q = q_as_unit((quat){st->num[0], st->num[1], st->num[2], st->num[3]});
        hand_set_grip_pose(h, NULL, &q);
    } else { /* last_held */
        rc = hand_set_last_held(h, &sh->w, st->word, st->n == 1, err, sizeof err);
    }
    return answer(sh, st, rc, err);
}
