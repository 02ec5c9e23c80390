/* outfile.h: the door every file vroc writes goes through.
 *
 * vroc writes files while time runs (trace, events, frames, the soundtrack, the
 * movie) and on command (save).  A write that fails is never silent: the writer
 * flushes what it wrote and asks the system whether it arrived, and a failure
 * becomes "cannot write 'PATH': REASON" with the system's reason.  A statement
 * that fails so (save, trace = FILE) is an error like any other; for an output
 * written while time runs there is one rule, shell_output_failed (shell.h): the
 * output is turned off and said so, at the prompt time goes on, a batch run stops
 * with status 1.  A writer that does not use stdio (the soundtrack, an encoder)
 * only has to produce the same message and call the same function.
 *
 * A write never destroys what was there (outfile_begin): a file is written
 * beside its path, as DIR/.vroc-part-XXXXXX-NAME, and put in its place by rename
 * only once everything written has arrived (outfile_place, outfile_finish); a
 * failure removes the part file and leaves the old file whole (outfile_abort).
 * save and the soundtrack are placed when they are finished, trace, events and
 * hand_log once their header and first rows are written, the movie when ffmpeg
 * has finished it, each frame's picture when it is written.  Where the path is a
 * device or a named pipe (/dev/full, a pipe a program reads), it is written in
 * place: a named pipe no program reads is refused at once rather than waited
 * for.  A link is followed to the file it names, which is replaced (the link
 * stays), except under VROC_SANDBOX.
 */
#ifndef VROC_OUTFILE_H
#define VROC_OUTFILE_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Flushes f and checks that everything written to it so far reached the system.
 * Returns 0, or -1 with "cannot write 'path': reason" in err. */
int outfile_flush(FILE *f, const char *path, char *err, size_t errlen);

/* The message of a write to path that failed with errno e (0: EIO, nothing says
 * why any more), in err: -1. */
int outfile_failed(const char *path, int e, char *err, size_t errlen);

/* Whether vroc may write at path.  Anywhere, unless the environment variable
 * VROC_SANDBOX is set (to anything but ""): then only below the current folder,
 * so a relative path without a ".." part, which resolves (realpath: through the
 * links on its way, as far as it exists) to a place below the current folder too
 * (what the fuzz campaign runs with).  Returns 0, or -1 with a message in err. */
int outfile_allowed(const char *path, char *err, size_t errlen);

/* True under VROC_SANDBOX: where vroc opens a file to write in place, it follows
 * no link (O_NOFOLLOW). */
bool outfile_sandboxed(void);

/* ---- writing beside, then in place ---- */

/* What the writer needs of the file (outfile_begin's flags). */
enum {
    OUTFILE_STREAM = 1,  /* a stdio stream on it (o->f) */
    OUTFILE_SEEK = 2,    /* to seek in it (the soundtrack rewrites its header): no pipe */
    OUTFILE_REGULAR = 4  /* to be a regular file (the movie: ffmpeg writes it by name) */
};

/* A file being written. */
typedef struct {
    FILE *f;                 /* OUTFILE_STREAM's stream, else NULL */
    int fd;                  /* its descriptor (f's, when f), -1 when closed */
    char path[PATH_MAX];     /* where it goes (a link's target) */
    char part[PATH_MAX];     /* the part file it is written in until placed; "" when it
                              * is written in place or was placed */
} outfile;

/* Starts writing the file at path (outfile_allowed is checked): a new part file
 * beside it, with the mode the file at path has (or would get); or path itself
 * when it is a device or a named pipe (with a reader), unless flags rule that
 * out.  Returns 0 with o open, or -1 with "cannot write 'PATH': REASON" in err and
 * nothing left behind. */
int outfile_begin(outfile *o, const char *path, unsigned flags, char *err, size_t errlen);

/* The name the file is written under now: its part file until it is placed. */
const char *outfile_now(const outfile *o);

/* Checks everything written so far (a stream is flushed), then puts the part file
 * in its place: from now on path is the new file, which o goes on writing.
 * Returns 0, or -1 with the message in err, the file closed and the part file
 * removed: path is as it was. */
int outfile_place(outfile *o, char *err, size_t errlen);

/* Checks everything written, closes the file and puts it in its place (if not
 * done yet).  Returns 0, or -1 with the message in err, the part file removed. */
int outfile_finish(outfile *o, char *err, size_t errlen);

/* Gives up: closes the file and removes the part file (path is as it was). */
void outfile_abort(outfile *o);

/* Checks f's writes as outfile_flush does, then closes it (NULL: nothing to do).
 * Returns 0, or -1 with the message in err; f is closed either way. */
int outfile_close(FILE *f, const char *path, char *err, size_t errlen);

#endif
