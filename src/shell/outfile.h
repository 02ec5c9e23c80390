/* outfile.h: the check every file vroc writes goes through.
 *
 * vroc writes files while time runs (trace, events, frames; later the soundtrack
 * and the movie) and on command (save).  A write that fails is never silent: the
 * writer flushes what it wrote and asks the system whether it arrived, and a
 * failure becomes "cannot write 'PATH': REASON" with the system's reason.  A
 * statement that fails so (save, trace = FILE) is an error like any other; for an
 * output written while time runs there is one rule, shell_output_failed
 * (shell.h): the output is turned off and said so, at the prompt time goes on, a
 * batch run stops with status 1.  A writer that does not use stdio (libsndfile,
 * an encoder) only has to produce the same message and call the same function.
 */
#ifndef VROC_OUTFILE_H
#define VROC_OUTFILE_H

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
 * so a relative path without a ".." part (what the fuzz campaign runs with: vroc
 * itself makes no links, so nothing it writes can leave that folder).  Returns 0,
 * or -1 with a message in err. */
int outfile_allowed(const char *path, char *err, size_t errlen);

/* Checks f's writes as outfile_flush does, then closes it (NULL: nothing to do).
 * Returns 0, or -1 with the message in err; f is closed either way. */
int outfile_close(FILE *f, const char *path, char *err, size_t errlen);

#endif
