/* table.c: the command table, the single source of vroc's language (commands.h).
 *
 * One row per command, in the order of help's groups; show and save write the
 * settings in this order.  A property names its field in the body (edit.h sets
 * it), a setting its field in its owner's settings.
 */
#include "commands.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "core/limits.h"
#include "core/world.h"
#include "handlers.h"
#include "shell.h"
#include "view/view.h"

/* Every number has limits (core/limits.h), under which the simulation stays
 * finite; a velocity may be any finite vector, since it is limited to max_linear
 * or max_angular as it is set (edit.h). */
#define POS LIM_POSITION_MAX
/* the number after a VAL_VECTOR_ANGLE's vector (what it is, its limits): none */
#define NO_AFTER NULL, 0, 0
/* a property of the body, at field (of body) */
#define PROP(name, arg, range, lo, hi, classes, field) \
    {name, FORM_PROPERTY, arg, range, lo, hi, NULL, classes, OWN_NONE, offsetof(body, field), cmd_property, NO_AFTER}
/* settings of the simulation, the views, the shell, the sound and the hand, at field of their struct */
#define SIM(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SIM, offsetof(sim_settings, field), cmd_setting, NO_AFTER}
#define VIEW(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_VIEW, offsetof(view_settings, field), cmd_setting, NO_AFTER}
#define VIEWF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_VIEW, offsetof(view_settings, field), fn, NO_AFTER}
#define SHELL(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SHELL, offsetof(shell_settings, field), cmd_setting, NO_AFTER}
#define SHELLF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SHELL, offsetof(shell_settings, field), fn, NO_AFTER}
#define SOUND(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SOUND, offsetof(sound_settings, field), cmd_setting, NO_AFTER}
#define SOUNDF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_SOUND, offsetof(sound_settings, field), fn, NO_AFTER}
#define HAND(name, arg, range, lo, hi, field) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_HAND, offsetof(hand_settings, field), cmd_setting, NO_AFTER}
#define HANDF(name, arg, range, lo, hi, field, fn) \
    {name, FORM_SETTING, arg, range, lo, hi, NULL, 0, OWN_HAND, offsetof(hand_settings, field), fn, NO_AFTER}
/* a setting kept elsewhere (the logs, the soundtrack, the movie): its handler knows where */
#define OTHER(name, arg, fn) {name, FORM_SETTING, arg, 0, 0, 0, NULL, 0, OWN_NONE, 0, fn, NO_AFTER}
#define OTHER_R(name, arg, lo, hi, fn) \
    {name, FORM_SETTING, arg, R_RANGE, lo, hi, NULL, 0, OWN_NONE, 0, fn, NO_AFTER}
#define CHOICE(name, choices, fn) {name, FORM_SETTING, VAL_CHOICE, 0, 0, 0, choices, 0, OWN_VIEW, 0, fn, NO_AFTER}
#define ACT(name, arg, fn) {name, FORM_ACTION, arg, 0, 0, 0, NULL, 0, OWN_NONE, 0, fn, NO_AFTER}
#define COUNT(name, fn) {name, FORM_ACTION, ARG_COUNT, R_RANGE, 0, 1e9, NULL, 0, OWN_NONE, 0, fn, NO_AFTER}
/* a property of the exact state (language.md, "Exact state"), at field of body */
#define EXACT(name, arg, range, lo, hi, field) \
    {name, FORM_PROPERTY, arg, range, lo, hi, NULL, C_ALL, OWN_NONE, offsetof(body, field), cmd_exact, NO_AFTER}
/* a vector and a number (VAL_VECTOR_ANGLE): what2 names the number, lo2 to hi2
 * its limits */
#define PROP_A(name, range, lo, hi, classes, field, what2, lo2, hi2) \
    {name, FORM_PROPERTY, VAL_VECTOR_ANGLE, range, lo, hi, NULL, classes, OWN_NONE, offsetof(body, field), cmd_property, what2, lo2, hi2}
#define SIM_A(name, range, lo, hi, field, what2, lo2, hi2) \
    {name, FORM_SETTING, VAL_VECTOR_ANGLE, range, lo, hi, NULL, 0, OWN_SIM, offsetof(sim_settings, field), cmd_setting, what2, lo2, hi2}
#define HAND_A(name, range, lo, hi, field, what2, lo2, hi2, fn) \
    {name, FORM_SETTING, VAL_VECTOR_ANGLE, range, lo, hi, NULL, 0, OWN_HAND, offsetof(hand_settings, field), fn, what2, lo2, hi2}

/* In the order of help's groups; show and save write the settings in this order. */
const command command_table[] = {
    /* objects */
    ACT("sphere", ARG_NAME, cmd_create),
    ACT("cube", ARG_NAME, cmd_create),
    ACT("superquadric", ARG_NAME, cmd_create),
    ACT("polyhedron", ARG_NAME, cmd_create),
    ACT("delete", ARG_NAME, cmd_delete),
    /* properties (Tables A.1 to A.4) */
    PROP("linear_vel", VAL_VECTOR, R_RANGE, -DBL_MAX, DBL_MAX, C_ALL, v),
    PROP("angular_vel", VAL_VECTOR, R_RANGE | R_RADIANS, -DBL_MAX, DBL_MAX, C_ALL, w),
    PROP("elasticity", VAL_NUMBER, R_RANGE, 0, 1, C_ALL, elasticity),
    PROP("friction", VAL_NUMBER, R_RANGE, 0, LIM_FRICTION_MAX, C_ALL, friction),
    PROP("rolling_friction", VAL_NUMBER, R_RANGE, 0, LIM_FRICTION_MAX, C_ALL, rolling_friction),
    PROP("mass", VAL_NUMBER, R_NONZERO | R_RANGE | R_ABS, LIM_MASS_MIN, LIM_MASS_MAX, C_ALL, mass),
    PROP("volume", VAL_NUMBER, R_RANGE, 0, LIM_LOUD_MAX, C_ALL, volume),
    PROP("translate", VAL_VECTOR, R_RANGE, -POS, POS, C_ALL, x),
    PROP_A("rotate", R_NONZERO_VEC | R_RANGE | R_RADIANS, -POS, POS, C_ALL, rot_axis,
           "angle", -LIM_ANGLE_MAX, LIM_ANGLE_MAX),
    PROP("color", VAL_COLOR, R_RANGE, 0, 255, C_ALL, color),
    PROP("radius", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_SPHERE, sp.radius),
    PROP("ures", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ, sp.ures),
    PROP("vres", VAL_INTEGER, R_RANGE, 3, 1000, C_SPHERE | C_SQ, sp.vres),
    PROP("size", VAL_VECTOR, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_CUBE, sp.size),
    PROP("exp1", VAL_NUMBER, R_RANGE, LIM_EXP_MIN, LIM_EXP_MAX, C_SQ, sp.exp1),
    PROP("exp2", VAL_NUMBER, R_RANGE, LIM_EXP_MIN, LIM_EXP_MAX, C_SQ, sp.exp2),
    PROP("a1", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_SQ, sp.a1),
    PROP("a2", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_SQ, sp.a2),
    PROP("a3", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_SQ, sp.a3),
    {"file", FORM_PROPERTY, VAL_FILE, 0, 0, 0, NULL, C_POLY, OWN_NONE, offsetof(body, sp.src),
     cmd_file, NO_AFTER},
    PROP("scale", VAL_SCALE, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_POLY, sp.scale),
    PROP("thickness", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, C_POLY, sp.thickness),
    /* read only: checked against the object (print writes it) */
    {"pieces", FORM_PROPERTY, VAL_INTEGER, R_RANGE, 1, 1e6, NULL, C_POLY, OWN_NONE,
     offsetof(body, shape.pieces), cmd_pieces, NO_AFTER},
    /* the file's SHA-256 as save wrote it: a warning when the file changed since */
    {"sha256", FORM_PROPERTY, VAL_FILE, 0, 0, 0, NULL, C_POLY, OWN_NONE, offsetof(body, sp.src),
     cmd_sha256, NO_AFTER},
    /* exact state, as save writes it */
    EXACT("orientation", VAL_QUAT, 0, 0, 0, q),
    EXACT("velocity", VAL_VECTOR, R_RANGE, -LIM_SPEED_MAX, LIM_SPEED_MAX, v),
    EXACT("angular_momentum", VAL_VECTOR, R_RANGE, -LIM_MOMENTUM_MAX, LIM_MOMENTUM_MAX, L),
    EXACT("slide_on", VAL_NAME, 0, 0, 0, slide_on),
    EXACT("slide_face", VAL_INTEGER, R_RANGE, 0, 1e6, slide_face),
    {"mode", FORM_PROPERTY, VAL_CHOICE, 0, 0, 0, "free|slide|general|stick|roll", C_ALL, OWN_NONE,
     offsetof(body, mode), cmd_exact, NO_AFTER},
    EXACT("resting", VAL_ONOFF, 0, 0, 0, state),
    EXACT("touching", VAL_NAME, 0, 0, 0, moved),
    EXACT("hold_pivot", VAL_VECTOR, R_RANGE, -POS, POS, hold_pivot),
    EXACT("hold_velocity", VAL_VECTOR, R_RANGE, -LIM_SPEED_MAX, LIM_SPEED_MAX, hold_v),
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
    ACT("exit", ARG_NONE, cmd_quit),
    SIM("time_step", VAL_NUMBER, R_RANGE | R_ZERO, LIM_TIME_MIN, LIM_TIME_MAX, time_step),
    SIM("collision_dist", VAL_NUMBER, R_RANGE, LIM_LENGTH_MIN, LIM_LENGTH_MAX, collision_dist),
    SIM("internal_step", VAL_NUMBER, R_RANGE | R_ZERO, LIM_TIME_MIN, LIM_TIME_MAX, internal_step),
    SIM("max_linear", VAL_NUMBER, R_RANGE, 0, LIM_SPEED_MAX, max_linear),
    SIM("max_angular", VAL_NUMBER, R_RANGE | R_RADIANS, 0, LIM_SPIN_MAX, max_angular),
    SIM("default_friction", VAL_NUMBER, R_RANGE, 0, LIM_FRICTION_MAX, default_friction),
    SIM("default_rolling_friction", VAL_NUMBER, R_RANGE, 0, LIM_FRICTION_MAX, default_rolling_friction),
    SIM_A("force", R_NONZERO_VEC | R_RANGE, -POS, POS, force,
          "magnitude", -LIM_ACCEL_MAX, LIM_ACCEL_MAX),
    ACT("gravity", ARG_NONE, cmd_gravity),
    /* (its built-in words, which completion offers before file names) */
    {"collision_sound", FORM_SETTING, VAL_FILE, 0, 0, 0, "click|knock|bell|off", 0, OWN_SOUND,
     offsetof(sound_settings, collision_sound), cmd_collision_sound, NO_AFTER},
    SOUND("collision_vol", VAL_NUMBER, R_RANGE, 0, LIM_LOUD_MAX, collision_vol),
    /* console */
    COUNT("run", cmd_run),
    ACT("time", ARG_NONE, cmd_time),
    OTHER_R("clock", VAL_PAIR, 0, LIM_CLOCK_MAX, cmd_clock),
    OTHER_R("frame", VAL_INTEGER, 0, LIM_FRAMES_MAX, cmd_frame),
    ACT("hash", ARG_NONE, cmd_hash),
    ACT("list", ARG_NONE, cmd_list),
    ACT("print", ARG_NAME_DOT, cmd_print),
    ACT("show", ARG_SETTING, cmd_show),
    {"precision", FORM_SETTING, VAL_CHOICE, 0, 0, 0, "short|exact", 0, OWN_SHELL,
     offsetof(shell_settings, precision), cmd_setting, NO_AFTER},
    ACT("save", ARG_FILE, cmd_save),
    ACT("distance", ARG_NAME2, cmd_distance),
    ACT("stats", ARG_NONE, cmd_stats),
    ACT("energy", ARG_OPT_NAME, cmd_energy),
    ACT("plot", ARG_PLOT, cmd_plot),
    OTHER("events", VAL_FILE_OR_OFF, cmd_log),
    OTHER("trace", VAL_FILE_OR_OFF, cmd_log),
    SIM("collision_heap", VAL_ONOFF, 0, 0, 0, collision_heap),
    COUNT("random", cmd_random),
    SHELLF("random_box", VAL_VECTOR, R_RANGE, LIM_RANDOM_BOX_MIN, LIM_LENGTH_MAX, random_box,
           cmd_random_box),
    SHELL("random_size", VAL_RANGE2, R_RANGE, LIM_RANDOM_SIZE_MIN, LIM_LENGTH_MAX, random_size),
    SHELLF("seed", VAL_INTEGER, R_RANGE, 0, 4294967295.0, seed, cmd_seed),
    OTHER_R("random_draws", VAL_INTEGER, 0, LIM_FRAMES_MAX, cmd_random_draws),
    /* views and hand */
    VIEW("head", VAL_VECTOR, R_RANGE, -POS, POS, head),
    VIEW("look_at", VAL_VECTOR, R_RANGE, -POS, POS, look_at),
    VIEW("up", VAL_VECTOR, R_NONZERO_VEC | R_RANGE, -POS, POS, up),
    VIEW("ipd", VAL_NUMBER, R_RANGE, 0, LIM_LENGTH_MAX, ipd),
    VIEW("fov", VAL_NUMBER, R_RANGE | R_LO_OPEN | R_HI_OPEN | R_DEGREES, 0, 180, fov),
    VIEWF("image_size", VAL_SIZE2, R_RANGE, 16, 8192, image_w, cmd_image_size),
    VIEW("output", VAL_FILE, 0, 0, 0, output),
    CHOICE("stereo", "pair|sbs|anaglyph|mono", cmd_stereo),
    VIEW("background", VAL_COLOR, R_RANGE, 0, 255, background),
    CHOICE("real", "solid|wire|hidden", cmd_real),
    VIEW("hulls", VAL_ONOFF, 0, 0, 0, hulls),
    VIEW("record", VAL_ONOFF, 0, 0, 0, record),
    OTHER("window", VAL_ONOFF, cmd_window),
    HANDF("hand", VAL_VECTOR, R_RANGE, -POS, POS, hand, cmd_hand),
    HAND_A("hand_rotate", R_NONZERO_VEC | R_RANGE | R_RADIANS, -POS, POS, hand_rotate,
           "angle", -LIM_ANGLE_MAX, LIM_ANGLE_MAX, cmd_hand),
    HANDF("trigger", VAL_ONOFF, 0, 0, 0, trigger, cmd_trigger),
    ACT("select", ARG_OPT_ONOFF, cmd_select),
    ACT("reselect", ARG_NONE, cmd_reselect),
    HAND("reach", VAL_NUMBER, R_RANGE, 0, LIM_LENGTH_MAX, reach),
    HAND("fly_speed", VAL_NUMBER, R_RANGE, 0, LIM_SPEED_MAX, fly_speed),
    HANDF("tracker", VAL_FILE_OR_OFF, 0, 0, 0, tracker, cmd_tracker),
    OTHER_R("tracker_time", VAL_NUMBER, 0, LIM_CLOCK_MAX, cmd_tracker_time),
    HANDF("hand_log", VAL_FILE_OR_OFF, 0, 0, 0, hand_log, cmd_hand_log),
    {"grip", FORM_SETTING, ARG_NAME, 0, 0, 0, "off|none|fly|panel|time_step|collision_dist", 0, OWN_NONE, 0,
     cmd_grip, NO_AFTER},
    /* the hand's exact state, as save writes it */
    OTHER_R("tracker_clock", VAL_PAIR, -LIM_CLOCK_MAX, LIM_CLOCK_MAX, cmd_hand_exact),
    OTHER_R("tracker_row", VAL_INTEGER, 0, LIM_FRAMES_MAX, cmd_hand_exact),
    {"hand_orientation", FORM_SETTING, VAL_QUAT, 0, 0, 0, NULL, 0, OWN_NONE, 0, cmd_hand, NO_AFTER},
    {"hand_velocity", FORM_SETTING, VAL_VECTOR_ANGLE, R_RANGE, -DBL_MAX, DBL_MAX, NULL, 0, OWN_NONE, 0,
     cmd_hand_exact, "time", 0, LIM_CLOCK_MAX},
    OTHER_R("hand_spin", VAL_VECTOR, -DBL_MAX, DBL_MAX, cmd_hand_exact),
    OTHER_R("grip_at", VAL_VECTOR, -4 * POS, 4 * POS, cmd_hand_exact),
    {"grip_orientation", FORM_SETTING, VAL_QUAT, 0, 0, 0, NULL, 0, OWN_NONE, 0, cmd_hand_exact, NO_AFTER},
    {"last_held", FORM_SETTING, ARG_NAME, 0, 0, 0, "none", 0, OWN_NONE, 0, cmd_hand_exact, NO_AFTER},
    HAND("panel", VAL_ONOFF, 0, 0, 0, panel),
    HAND("panel_at", VAL_VECTOR, R_RANGE, -POS, POS, panel_at),
    HAND_A("panel_rotate", R_NONZERO_VEC | R_RANGE | R_RADIANS, -POS, POS, panel_rotate,
           "angle", -LIM_ANGLE_MAX, LIM_ANGLE_MAX, cmd_setting),
    /* sound and movies */
    SOUNDF("sound", VAL_ONOFF, 0, 0, 0, live, cmd_sound),
    OTHER("soundtrack", VAL_FILE_OR_OFF, cmd_soundtrack),
    OTHER("movie", VAL_FILE_OR_OFF, cmd_movie),
    VIEW("movie_rate", VAL_NUMBER, R_RANGE | R_LO_OPEN, 0, VIEW_MOVIE_RATE_MAX, movie_rate),
};

const int command_count = (int)(sizeof command_table / sizeof command_table[0]);

const command *command_find(const char *name)
{
    for (int i = 0; i < command_count; i++)
        if (strcmp(command_table[i].name, name) == 0) return &command_table[i];
    return NULL;
}

