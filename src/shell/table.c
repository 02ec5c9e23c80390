/* table.c: the command table, the single source of vroc's language (commands.h).
 *
 * One row per command, in the order of help's groups; show and save write the
 * settings in this order.  A property names its field in the body (edit.h sets
 * it), a setting its field in its owner's settings.
 */
#include "commands.h"

#include <math.h>
#include <string.h>

#include "core/world.h"
#include "handlers.h"
#include "shell.h"
#include "view/view.h"

#define INF HUGE_VAL
/* a property of the body, at field (of body) */
#define PROP(name, arg, range, lo, hi, classes, field) \
    {name, FORM_PROPERTY, arg, range, lo, hi, NULL, classes, OWN_NONE, offsetof(body, field), cmd_property}
/* settings of the simulation, the views and the shell, at field of their struct */
#define SIM(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SIM, offsetof(sim_settings, field), cmd_setting}
#define VIEW(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_VIEW, offsetof(view_settings, field), cmd_setting}
#define VIEWF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_VIEW, offsetof(view_settings, field), fn}
#define SHELL(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SHELL, offsetof(shell_settings, field), cmd_setting}
#define SHELLF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SHELL, offsetof(shell_settings, field), fn}
#define HAND(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_HAND, offsetof(hand_settings, field), cmd_setting}
#define HANDF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_HAND, offsetof(hand_settings, field), fn}
/* a setting kept elsewhere (the logs): its handler knows where */
#define OTHER(name, arg, fn) {name, FORM_SETTING, arg, 0, 0, 0, NULL, 0, OWN_NONE, 0, fn}
#define CHOICE(name, choices, fn) {name, FORM_SETTING, VAL_CHOICE, 0, 0, 0, choices, 0, OWN_VIEW, 0, fn}
#define ACT(name, arg, fn) {name, FORM_ACTION, arg, 0, 0, 0, NULL, 0, OWN_NONE, 0, fn}
#define COUNT(name, fn) {name, FORM_ACTION, ARG_COUNT, R_RANGE, 0, 1e9, NULL, 0, OWN_NONE, 0, fn}

/* In the order of help's groups; show and save write the settings in this order. */
const command command_table[] = {
    /* objects */
    ACT("sphere", ARG_NAME, cmd_create),
    ACT("cube", ARG_NAME, cmd_create),
    ACT("superquadric", ARG_NAME, cmd_create),
    ACT("delete", ARG_NAME, cmd_delete),
    /* properties (Tables A.1 to A.4) */
    PROP("linear_vel", VAL_VECTOR, 0, 0, 0, C_ALL, v),
    PROP("angular_vel", VAL_VECTOR, 0, 0, 0, C_ALL, w),
    PROP("elasticity", VAL_NUMBER, R_RANGE, 0, 1, C_ALL, elasticity),
    PROP("mass", VAL_NUMBER, R_NONZERO, 0, 0, C_ALL, mass),
    PROP("volume", VAL_NUMBER, R_RANGE, 0, INF, C_ALL, volume),
    PROP("translate", VAL_VECTOR, 0, 0, 0, C_ALL, x),
    PROP("rotate", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, C_ALL, rot_axis),
    PROP("color", VAL_COLOR, 0, 0, 0, C_ALL, color),
    PROP("radius", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SPHERE, sp.radius),
    PROP("ures", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ, sp.ures),
    PROP("vres", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ, sp.vres),
    PROP("size", VAL_VECTOR, 0, 0, 0, C_CUBE, sp.size),
    PROP("exp1", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ, sp.exp1),
    PROP("exp2", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ, sp.exp2),
    PROP("a1", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ, sp.a1),
    PROP("a2", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ, sp.a2),
    PROP("a3", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, C_SQ, sp.a3),
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
    SIM("time_step", VAL_NUMBER, R_RANGE, 0, INF, time_step),
    SIM("collision_dist", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, INF, collision_dist),
    SIM("internal_step", VAL_NUMBER, R_RANGE, 0, INF, internal_step),
    SIM("max_linear", VAL_NUMBER, R_RANGE, 0, INF, max_linear),
    SIM("max_angular", VAL_NUMBER, R_RANGE, 0, INF, max_angular),
    SIM("force", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, force),
    ACT("gravity", ARG_NONE, cmd_gravity),
    SHELLF("collision_sound", VAL_FILE, 0, 0, 0, collision_sound, cmd_collision_sound),
    SHELL("collision_vol", VAL_NUMBER, R_RANGE, 0, INF, collision_vol),
    /* console */
    COUNT("run", cmd_run),
    ACT("time", ARG_NONE, cmd_time),
    ACT("list", ARG_NONE, cmd_list),
    ACT("print", ARG_NAME, cmd_print),
    ACT("show", ARG_NONE, cmd_show),
    ACT("save", ARG_FILE, cmd_save),
    ACT("distance", ARG_NAME2, cmd_distance),
    ACT("stats", ARG_NONE, cmd_stats),
    OTHER("events", VAL_FILE_OR_OFF, cmd_log),
    OTHER("trace", VAL_FILE_OR_OFF, cmd_log),
    SIM("collision_heap", VAL_ONOFF, 0, 0, 0, collision_heap),
    COUNT("random", cmd_random),
    SHELLF("random_box", VAL_VECTOR, 0, 0, 0, random_box, cmd_random_box),
    SHELLF("seed", VAL_INTEGER, R_RANGE, 0, 4294967295.0, seed, cmd_seed),
    /* views and hand */
    VIEW("head", VAL_VECTOR, 0, 0, 0, head),
    VIEW("look_at", VAL_VECTOR, 0, 0, 0, look_at),
    VIEW("up", VAL_VECTOR, R_NONZERO_VEC, 0, 0, up),
    VIEW("ipd", VAL_NUMBER, R_RANGE, 0, INF, ipd),
    VIEW("fov", VAL_NUMBER, R_RANGE | R_LO_OPEN | R_HI_OPEN, 0, 180, fov),
    VIEWF("image_size", VAL_SIZE2, R_RANGE, 16, 8192, image_w, cmd_image_size),
    VIEW("output", VAL_FILE, 0, 0, 0, output),
    CHOICE("stereo", "pair|sbs|anaglyph|mono", cmd_stereo),
    VIEW("background", VAL_COLOR, 0, 0, 0, background),
    CHOICE("real", "solid|wire|hidden", cmd_real),
    VIEW("record", VAL_ONOFF, 0, 0, 0, record),
    HANDF("hand", VAL_VECTOR, 0, 0, 0, hand, cmd_hand),
    HANDF("hand_rotate", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, hand_rotate, cmd_hand),
    HANDF("trigger", VAL_ONOFF, 0, 0, 0, trigger, cmd_trigger),
    ACT("select", ARG_OPT_ONOFF, cmd_select),
    ACT("reselect", ARG_NONE, cmd_reselect),
    HAND("reach", VAL_NUMBER, R_RANGE, 0, INF, reach),
    HAND("fly_speed", VAL_NUMBER, R_RANGE, 0, INF, fly_speed),
    HANDF("tracker", VAL_FILE_OR_OFF, 0, 0, 0, tracker, cmd_tracker),
    {"tracker_time", FORM_SETTING, VAL_NUMBER, R_RANGE, 0, INF, NULL, 0, OWN_NONE, 0, cmd_tracker_time},
    HANDF("hand_log", VAL_FILE_OR_OFF, 0, 0, 0, hand_log, cmd_hand_log),
    {"grip", FORM_SETTING, ARG_NAME, 0, 0, 0, "off|none|fly|panel|time_step|collision_dist", 0, OWN_NONE, 0,
     cmd_grip},
    HAND("panel", VAL_ONOFF, 0, 0, 0, panel),
    HAND("panel_at", VAL_VECTOR, 0, 0, 0, panel_at),
    HAND("panel_rotate", VAL_VECTOR_ANGLE, R_NONZERO_VEC, 0, 0, panel_rotate),
};

const int command_count = (int)(sizeof command_table / sizeof command_table[0]);

const command *command_find(const char *name)
{
    for (int i = 0; i < command_count; i++)
        if (strcmp(command_table[i].name, name) == 0) return &command_table[i];
    return NULL;
}

