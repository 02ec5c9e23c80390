/* movie.h: the views of every frame encoded into a video by the ffmpeg program
 * (`movie = FILE`; language.md, "Sound and movies").
 *
 * movie_open starts `ffmpeg` (found on PATH) reading raw RGB frames from a pipe and
 * writing a file beside the movie's (shell/outfile.h: ".vroc-part-XXXXXX-NAME");
 * movie_close finishes it and, given a WAV file, muxes that in as the sound into
 * another file beside it, then puts the result in place: a movie is its video
 * and its sound, or, when either fails, nothing, and the file that was there stays
 * whole.  The container is what the file's extension names; .mp4, .m4v, .mov and
 * .mkv get H.264 (yuv420p) and, for the first three, AAC sound; other extensions
 * get ffmpeg's choice for them.
 *
 * The layout and size are fixed when the movie starts: `pair` and `sbs` put the
 * two eyes side by side (left eye on the left), `mono` shows the left eye,
 * `anaglyph` the red-cyan image of view.c (view_anaglyph_pixel); a width or
 * height that is odd is padded by one, repeating the last column or row.  If image_size changes while
 * the movie runs, later frames are scaled to the movie's size.  The frame rate is
 * 1 / period (movie_rate's), fixed too; the caller adds each picture when it
 * is due (movie_add's copies), to keep video time with simulated time.
 *
 * ffmpeg runs in a process group of its own, so that Ctrl-C at the prompt does not
 * stop it; its messages (errors only) go to a file in memory (not beside the
 * movie, where a full disk would swallow them), which errors quote.  A write of
 * ffmpeg's that fails is told the way every file vroc writes tells it
 * (shell/outfile.h): "cannot write 'PATH': REASON", with the system's reason that
 * ffmpeg's message ends with.  An ffmpeg that takes no frame, or does not finish,
 * while it does no work for VROC_TIMEOUT seconds (child.h: child_write, child_wait)
 * is stopped, and the movie with it.  A path that exists and is not a regular
 * file (a device, a pipe) is refused, since the movie is put in its place by
 * rename.  Nothing here reads or changes the world: frames come from the view's
 * last render. */
#ifndef VROC_MOVIE_H
#define VROC_MOVIE_H

#include <stddef.h>

#include "view/view.h"

typedef struct movie movie;

/* Starts a movie at path of the views as vs lays them out now (stereo,
 * image_size), period seconds per frame.  Returns 0, or -1 with a message in err:
 * the path cannot be written (or is there and not a regular file), it names no
 * format (no extension), the period is not > 0, or ffmpeg cannot be run. */
int movie_open(movie **m, const char *path, const view_settings *vs, double period, char *err,
               size_t errlen);

/* Adds the view's last rendered frame, copies times (0 adds nothing).  Returns 0,
 * or -1 with a message: ffmpeg stopped or logged an error (such as a write that
 * failed: "cannot write 'PATH': REASON"), or the view has no image of an eye the
 * layout needs. */
int movie_add(movie *m, const view *v, long copies, char *err, size_t errlen);

/* The movie's frame size (even), for a layout and eye size. */
void movie_size(stereo_mode mode, int eye_w, int eye_h, int *w, int *h);

/* True when the layout needs the right eye. */
int movie_needs_right(const movie *m);

/* A path beside the movie where the caller may write the WAV file to mux in
 * (movie_close removes it). */
const char *movie_sound_path(const movie *m);

long movie_frames(const movie *m);
double movie_period(const movie *m);
const char *movie_path(const movie *m);

/* Finishes the movie, with the sound of the WAV file wav (NULL: none), and frees m.
 * A movie with no frame leaves no file.  Returns 0, or -1 with a message: then
 * nothing is written, and the file that was there stays whole. */
int movie_close(movie *m, const char *wav, char *err, size_t errlen);

/* Gives the movie up (ffmpeg stopped, nothing written, the file that was there
 * whole) and frees m. */
void movie_abort(movie *m);

/* The most copies of one frame a movie takes for one time step (a time_step
 * grown from 1e-6 to 1000 would want 1e9): the caller skips the rest. */
#define MOVIE_MAX_COPIES 1000

#endif
