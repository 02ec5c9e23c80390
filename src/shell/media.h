/* media.h: the shell's side of sound and movies (language.md, "Sound and movies").
 *
 * The shell calls media_frame once after each frame it advances: the frame's
 * collisions go to the sound engine (src/sound/), its view to the movie
 * (view/movie.h); and media_pump from the prompt's loop, which feeds the live
 * stream in real time.  Here too is the clock both run on: elapsed simulated time,
 * each frame adding its time_step (sound.h).  The state is made on first need, so
 * a run with no sound and no movie costs one test a frame.
 *
 * Live sound follows language.md: off in batch; at an interactive prompt the
 * server is asked when time first runs there (never at start-up), and where none
 * answers there is one warning and `sound` turns off.
 *
 * The soundtrack, the movie and the live stream are outputs like the logs
 * (outfile.h): one that cannot be written while time runs is turned off through
 * shell_output_failed ("cannot write 'PATH': REASON"; at the prompt time goes
 * on, a batch run stops with status 1), and one that fails as a statement makes
 * or finishes it is that statement's error.  Nothing here changes the world. */
#ifndef VROC_MEDIA_H
#define VROC_MEDIA_H

#include <stdbool.h>
#include <stddef.h>

#include "commands.h"

struct shell;
struct stmt;
typedef struct media media;

/* Before each frame: where the bodies start it, for a movie's pictures within it
 * (nothing without a movie). */
void media_frame_begin(struct shell *sh);

/* After each frame: sounds of its collisions, frames of the movie.  A soundtrack
 * or movie that fails is turned off (shell_output_failed); returns CMD_ERROR when
 * the run must stop. */
cmd_status media_frame(struct shell *sh, const struct stmt *st);

/* Feeds the live stream.  wait is the seconds the prompt means to sleep (< 0: until
 * a key); returns that or less, so that it is called again in time.  A stream the
 * server no longer takes turns `sound` off (shell_output_failed). */
double media_pump(struct shell *sh, double wait);

/* `collision_sound = name`: checks it, loading a sound file.  0, or -1 with a
 * message in err. */
int media_choose_sound(struct shell *sh, const char *name, char *err, size_t errlen);

/* `soundtrack = path` (NULL: off), statement st.  Reports its errors: a file
 * that cannot be made (the soundtrack open before goes on), or the one open
 * before that cannot be finished. */
cmd_status media_soundtrack(struct shell *sh, const struct stmt *st, const char *path);

/* `movie = path` (NULL: off, finishing it with the soundtrack's sound), statement
 * st.  Reports its errors as media_soundtrack does. */
cmd_status media_movie(struct shell *sh, const struct stmt *st, const char *path);

/* `sound = off`: closes the live stream. */
void media_live_off(struct shell *sh);

/* What show and save write: the open soundtrack's and movie's paths (NULL when
 * none), and whether live sound is on. */
const char *media_soundtrack_path(const struct shell *sh);
const char *media_movie_path(const struct shell *sh);
bool media_live_on(const struct shell *sh);

/* Finishes the movie, then the soundtrack, and closes the live stream: the end of
 * the program (shell_close_outputs).  Returns 0, or -1 after reporting an
 * error. */
int media_finish(struct shell *sh);

/* media_finish, then frees the state. */
void media_free(struct shell *sh);

#endif
