/* writer.h: the world written in its own language: numbers that read back to the
 * bit (save) or as a person reads them (print, show: fmt.h), objects (print,
 * save, print NAME.property) and settings (show, show NAME, save). */
#ifndef VROC_WRITER_H
#define VROC_WRITER_H

#include <stdbool.h>
#include <stdio.h>

#include "commands.h"
#include "core/body.h"
#include "fmt.h"

struct shell;
struct world;

/* How an object is written: its numbers (FMT_EXACT for save), whether each
 * quantity is written once (print), leaving out rotate (orientation gives it) and
 * velocity (linear_vel's alias), and for `save` the file written (NULL for print):
 * a polyhedron's file is then written relative to its folder when it lies under it,
 * else as an absolute path; print also writes the pieces a polyhedron collides as
 * and its centre of mass (a comment). */
typedef struct {
    fmt_style num;
    bool once;
    const char *save_path;
} write_style;

/* Writes v as "(x, y, z)" in style s (fmt_shown_vec). */
void writer_vec(FILE *out, vec3 v, fmt_style s);

/* Writes s (a path) as a quoted string of the language, a backslash before each
 * '"' and '\\' in it, so that it reads back as it is. */
void writer_quoted(FILE *out, const char *s);

/* Writes every setting as statements of the language, in the command table's
 * order: for show (save_path NULL), or for a world saved to save_path, where the
 * log files (trace, events, hand_log) are written as comments, since reading
 * them back would truncate the logs, a sound file's path is written as
 * writer_path says, and the hand is left to hand_write. */
void settings_write(FILE *out, const struct shell *sh, const char *save_path);

/* Writes the setting c (a FORM_SETTING, or select) as show does, "NAME = value". */
void setting_write(FILE *out, const struct shell *sh, const command *c);

/* For a world saved to save_path, after the objects and their contact state:
 * the hand's exact state (when it has been used): the tracker file (writer_path)
 * and the place in it, the pose, the velocity its statements gave it, what the
 * trigger holds (grip) and how, the held object's motion, and the object the
 * re-select button takes; all read back without pressing or grabbing anything. */
void hand_write(FILE *out, const struct shell *sh, const char *save_path);

/* Writes body b as statements that recreate it (its creation line first): as
 * typed (rotate, linear_vel, angular_vel), then exactly (orientation, velocity,
 * angular_momentum), so that with FMT_EXACT it reads back to the bit. */
void body_write(FILE *out, const body *b, write_style s);

/* Writes the property c of body i of w as "NAME.property = value" (touching: a
 * line per object touched), in style s.  What does not hold (no slide, nothing
 * touched) is written as a comment that says so. */
void property_write(FILE *out, const struct world *w, int i, const command *c, fmt_style s);

/* The path of path (absolute, or from the current folder) as a saved file at
 * save_path names it: relative to save_path's folder when path lies under it
 * (both taken through realpath), else absolute; read takes a relative path in a
 * file from that file's folder, so the saved world finds its files from any
 * folder.  The one rule for every file save names: a polyhedron's, the tracker's,
 * the collision sound's. */
void writer_path(const char *path, const char *save_path, char *out, size_t outlen);

/* Writes the contact state of body i of w (language.md, "Exact state"): its mode,
 * with its slide's support and face, whether it rests, and the objects it is in
 * lasting contact with (each pair once, on its later object, when only_later). */
void contact_write(FILE *out, const struct world *w, int i, int only_later);

#endif
