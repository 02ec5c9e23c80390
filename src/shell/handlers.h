/* handlers.h: one handler per command, with the signature of the command table
 * (commands.h).  Each either applies its statement whole or changes nothing and
 * reports an error.  They live by concern: cmd_object.c (objects and their
 * properties), cmd_setting.c (settings), cmd_time.c (time and files),
 * cmd_console.c (what a console tool adds), cmd_plot.c (plot), cmd_hand.c (the
 * hand and the tool panel), cmd_sound.c (sound and movies), random.c (random objects). */
#ifndef VROC_HANDLERS_H
#define VROC_HANDLERS_H

#include "commands.h"
#include "lang.h"

struct shell;

cmd_status cmd_create(struct shell *sh, const stmt *st);
cmd_status cmd_delete(struct shell *sh, const stmt *st);
cmd_status cmd_property(struct shell *sh, const stmt *st);
cmd_status cmd_exact(struct shell *sh, const stmt *st);
cmd_status cmd_file(struct shell *sh, const stmt *st);
cmd_status cmd_pieces(struct shell *sh, const stmt *st);
cmd_status cmd_sha256(struct shell *sh, const stmt *st);

cmd_status cmd_setting(struct shell *sh, const stmt *st);
cmd_status cmd_random_box(struct shell *sh, const stmt *st);
cmd_status cmd_seed(struct shell *sh, const stmt *st);
cmd_status cmd_image_size(struct shell *sh, const stmt *st);
cmd_status cmd_stereo(struct shell *sh, const stmt *st);
cmd_status cmd_real(struct shell *sh, const stmt *st);
cmd_status cmd_log(struct shell *sh, const stmt *st);
cmd_status cmd_gravity(struct shell *sh, const stmt *st);
cmd_status cmd_reset(struct shell *sh, const stmt *st);

cmd_status cmd_hand(struct shell *sh, const stmt *st);
cmd_status cmd_trigger(struct shell *sh, const stmt *st);
cmd_status cmd_select(struct shell *sh, const stmt *st);
cmd_status cmd_reselect(struct shell *sh, const stmt *st);
cmd_status cmd_tracker(struct shell *sh, const stmt *st);
cmd_status cmd_tracker_time(struct shell *sh, const stmt *st);
cmd_status cmd_hand_log(struct shell *sh, const stmt *st);
cmd_status cmd_grip(struct shell *sh, const stmt *st);
cmd_status cmd_hand_exact(struct shell *sh, const stmt *st);

cmd_status cmd_step(struct shell *sh, const stmt *st);
cmd_status cmd_run(struct shell *sh, const stmt *st);
cmd_status cmd_start(struct shell *sh, const stmt *st);
cmd_status cmd_stop(struct shell *sh, const stmt *st);
cmd_status cmd_restart(struct shell *sh, const stmt *st);
cmd_status cmd_read(struct shell *sh, const stmt *st);
cmd_status cmd_display(struct shell *sh, const stmt *st);
cmd_status cmd_refresh(struct shell *sh, const stmt *st);
cmd_status cmd_window(struct shell *sh, const stmt *st);
cmd_status cmd_save(struct shell *sh, const stmt *st);

cmd_status cmd_print(struct shell *sh, const stmt *st);
cmd_status cmd_list(struct shell *sh, const stmt *st);
cmd_status cmd_show(struct shell *sh, const stmt *st);
cmd_status cmd_time(struct shell *sh, const stmt *st);
cmd_status cmd_clock(struct shell *sh, const stmt *st);
cmd_status cmd_frame(struct shell *sh, const stmt *st);
cmd_status cmd_hash(struct shell *sh, const stmt *st);
cmd_status cmd_random_draws(struct shell *sh, const stmt *st);
cmd_status cmd_distance(struct shell *sh, const stmt *st);
cmd_status cmd_stats(struct shell *sh, const stmt *st);
cmd_status cmd_energy(struct shell *sh, const stmt *st);
cmd_status cmd_plot(struct shell *sh, const stmt *st);
cmd_status cmd_quit(struct shell *sh, const stmt *st);
cmd_status cmd_help(struct shell *sh, const stmt *st);

cmd_status cmd_random(struct shell *sh, const stmt *st);

cmd_status cmd_collision_sound(struct shell *sh, const stmt *st);
cmd_status cmd_sound(struct shell *sh, const stmt *st);
cmd_status cmd_soundtrack(struct shell *sh, const stmt *st);
cmd_status cmd_movie(struct shell *sh, const stmt *st);

#endif
