/* writer.h: the world written in its own language: numbers that read back to the
 * bit, objects (print, save) and settings (show, save). */
#ifndef VROC_WRITER_H
#define VROC_WRITER_H

#include <stdio.h>

#include "core/body.h"
#include "fmt.h"

struct shell;
struct world;

/* Writes v as "(x, y, z)", each number by fmt_num. */
void writer_vec(FILE *out, vec3 v);

/* Writes every setting as statements of the language, in the command table's
 * order: for show (save_path NULL), or for a world saved to save_path, where the
 * log files (trace, events, hand_log) are written as comments, since reading
 * them back would truncate the logs, a sound file's path is written as savepath.h
 * says, and the hand is left to hand_write. */
void settings_write(FILE *out, const struct shell *sh, const char *save_path);

/* For a world saved to save_path, after the objects and their contact state:
 * the hand's exact state (when it has been used): the tracker file (savepath.h)
 * and the place in it, the pose, the velocity its statements gave it, what the
 * trigger holds (grip) and how, the held object's motion, and the object the
 * re-select button takes; all read back without pressing or grabbing anything. */
void hand_write(FILE *out, const struct shell *sh, const char *save_path);

/* Writes body b as statements that recreate it (its creation line first): as
 * typed (rotate, linear_vel, angular_vel), then exactly (orientation, velocity,
 * angular_momentum), so that it reads back to the bit. */
void body_write(FILE *out, const body *b);

/* Writes the contact state of body i of w (language.md, "Exact state"): its mode,
 * with its slide's support and face, whether it rests, and the objects it is in
 * lasting contact with (each pair once, on its later object, when only_later). */
void contact_write(FILE *out, const struct world *w, int i, int only_later);

#endif
