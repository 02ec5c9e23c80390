/* child.h: the programs the views pipe pictures to (ffmpeg for movies, gnuplot
 * for plots), run as children: standard input from a pipe, standard output
 * thrown away, messages to a file the caller reads back for its errors, and a
 * process group of their own, so that Ctrl-C at the prompt reaches vroc alone. */
#ifndef VROC_CHILD_H
#define VROC_CHILD_H

#include <stddef.h>
#include <sys/types.h>

/* Runs the program argv[0] (found on PATH) with argv, its standard input from in
 * (or /dev/null when < 0), its standard error to log.  Returns 0 with *pid, or an
 * errno value (ENOENT: not installed). */
int child_spawn(char *const argv[], int in, int log, pid_t *pid);

/* Starts argv[0] as child_spawn does, its standard input a pipe whose writing
 * end is *in (the caller writes and closes it) and its messages in a log file
 * beside path (child_log_file), *log.  Returns 0 with *pid, or -1 with a message
 * in err ("the NAME program is not installed (not found on PATH; make deps
 * installs it)", or "cannot run NAME: REASON"), nothing left open. */
int child_open(char *const argv[], const char *path, pid_t *pid, int *in, int *log, char *err,
               size_t errlen);

/* Waits for pid.  Returns its exit status, or -1 when it did not exit by itself. */
int child_wait(pid_t pid);

/* dir/PREFIXNAMESUFFIX for path dir/NAME: the files a child's output is made
 * in, beside it, before it is put in place. */
void child_beside(char *out, size_t len, const char *path, const char *prefix, const char *suffix);

/* A file for a child's messages beside path (named .vroc-part-NAME.log there),
 * unlinked at once so that it is never left behind, or -1 with errno set. */
int child_log_file(const char *path);

/* Writes all of buf to the pipe fd with SIGPIPE held back: a child that stopped
 * gives EPIPE, not the end of vroc.  Returns 0, or an errno value. */
int child_write(int fd, const void *buf, size_t n);

#endif
