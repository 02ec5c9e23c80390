/* commands.h: the command table, the single source of vroc's language.
 *
 * Each entry names a command, its form (an action, an object property or a system
 * setting), what follows it and the checks on its value, where its value lives
 * (the offset of a property in the body, or of a setting in its owner's settings)
 * and its handler.  The parser checks statements against it, the shell dispatches
 * through it, the writer and completion list it, and a unit test checks it
 * against the reference in commands/ (help.h), from which `help` and the man page
 * are built.  The table itself is in table.c, the handlers in the cmd_*.c files.
 */
#ifndef VROC_COMMANDS_H
#define VROC_COMMANDS_H

#include <stddef.h>

#include "core/body.h"

struct shell;
struct stmt;

typedef enum {
    FORM_ACTION,   /* word [arguments] */
    FORM_PROPERTY, /* property = value, applies to an object */
    FORM_SETTING,  /* setting = value, a system setting */
} cmd_form;

/* What follows the command word (actions) or the '=' (properties, settings). */
typedef enum {
    ARG_NONE,         /* nothing */
    ARG_NAME,         /* an object name */
    ARG_NAME2,        /* two object names */
    ARG_OPT_WORD,     /* an optional word (help) */
    ARG_FILE,         /* a file name: bare word or "string" */
    ARG_COUNT,        /* an integer >= 0 */
    ARG_OPT_ONOFF,    /* optional on or off (select) */
    ARG_NAME_DOT,     /* an object name, or NAME.property (print) */
    ARG_SETTING,      /* an optional setting name (show) */
    ARG_OPT_NAME,     /* an optional object name (energy) */
    ARG_PLOT,         /* QUANTITY = FILE (plot) */
    VAL_NUMBER,       /* one number */
    VAL_INTEGER,      /* one integer */
    VAL_VECTOR,       /* (x, y, z) */
    VAL_VECTOR_ANGLE, /* (x, y, z) r */
    VAL_SIZE2,        /* (w, h), integers */
    VAL_RANGE2,       /* (min, max), numbers, min <= max */
    VAL_COLOR,        /* (r, g, b), integers 0..255 */
    VAL_ONOFF,        /* on or off */
    VAL_CHOICE,       /* one of the words in choices */
    VAL_FILE,         /* a file name */
    VAL_FILE_OR_OFF,  /* a file name, or off */
    VAL_NAME,         /* an object name */
    VAL_QUAT,         /* (w, x, y, z) */
    VAL_PAIR,         /* (a, b) */
    VAL_SCALE,        /* s or (x, y, z): one number is the same on every axis */
} arg_kind;

/* Range flags.  R_RANGE: every number of the value (each component of a vector)
 * must lie from lo to hi; > lo (not >=) with R_LO_OPEN, < hi with R_HI_OPEN; with
 * R_ZERO, 0 is accepted too (time_step's halt); with R_ABS, the limits bound |x|
 * and x may be negative (mass: static).  R_NONZERO: the number must not be 0.
 * R_NONZERO_VEC: the vector is a direction, at least LIM_DIR_MIN long (with
 * VAL_VECTOR_ANGLE, (0, 0, 0) is accepted when the number after it is 0).
 * Every numeric command has R_RANGE, with limits from core/limits.h, under which
 * the simulation stays finite; tests/test_limits.c walks them.  Units, for the
 * postfix `deg` of expressions (expr.h): R_RADIANS, the value is an angle or a
 * rate in radians (with VAL_VECTOR_ANGLE: the number after the vector), so deg
 * may convert degrees to it; R_DEGREES, the value is in degrees already (fov);
 * anywhere else deg is an error. */
enum { R_LO_OPEN = 1, R_HI_OPEN = 2, R_NONZERO = 4, R_NONZERO_VEC = 8, R_RANGE = 16,
       R_ZERO = 32, R_ABS = 64, R_RADIANS = 128, R_DEGREES = 256 };

/* shape classes a property applies to */
enum { C_SPHERE = 1 << SHAPE_SPHERE, C_CUBE = 1 << SHAPE_CUBE, C_SQ = 1 << SHAPE_SUPERQUADRIC,
       C_POLY = 1 << SHAPE_POLYHEDRON, C_ALL = C_SPHERE | C_CUBE | C_SQ | C_POLY };

typedef enum { CMD_OK, CMD_ERROR, CMD_QUIT } cmd_status;

/* Whose settings a FORM_SETTING's field is in: the simulation's (world.set), the
 * views' (shell.view_set), the sound's (shell.sound_set), the hand's
 * (shell.hand.set) or the shell's own (shell.set). */
typedef enum { OWN_NONE, OWN_SIM, OWN_VIEW, OWN_SHELL, OWN_SOUND, OWN_HAND } setting_owner;

typedef struct command {
    const char *name;
    cmd_form form;
    arg_kind arg;
    unsigned range;      /* R_ flags; R_RANGE: check lo and hi */
    double lo, hi;
    const char *choices; /* VAL_CHOICE: "pair|sbs|anaglyph|mono"; ARG_NAME: words
                          * allowed besides names; VAL_FILE: besides files
                          * (completion offers them) */
    unsigned classes;    /* FORM_PROPERTY: the C_ classes it applies to */
    setting_owner owner; /* FORM_SETTING: whose settings hold its field */
    size_t off;          /* FORM_PROPERTY: offset of its field in body (edit.h);
                          * FORM_SETTING: offset of its field in its owner's */
    cmd_status (*run)(struct shell *sh, const struct stmt *st);
    /* VAL_VECTOR_ANGLE: what the number after the vector is ("angle") and its
     * limits (lo2 to hi2) */
    const char *what2;
    double lo2, hi2;
} command;

extern const command command_table[];
extern const int command_count;

/* The command named name, or NULL. */
const command *command_find(const char *name);

#endif
