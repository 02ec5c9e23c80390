/* child.h: the programs the views pipe pictures to (ffmpeg for movies, gnuplot
 * for plots), run as children: standard input from a pipe, standard output
 * thrown away, messages to a file in memory the caller reads back for its errors
 * (not beside the output, where a full disk would swallow the message that says
 * so), and a process group of their own, so that Ctrl-C at the prompt reaches
 * vroc alone.  A child that stalls is seen: writing to it and waiting for it give
 * up after infile_timeout() seconds (VROC_TIMEOUT) in which it neither takes a
 * byte nor works (uses no processor time), and it is then killed. */
#ifndef VROC_CHILD_H
#define VROC_CHILD_H

#include <stddef.h>
#include <sys/types.h>

/* Runs the program argv[0] (found on PATH) with argv, its standard input from in
 * (or /dev/null when < 0), its standard error to log.  Returns 0 with *pid, or an
 * errno value (ENOENT: not installed). */
int child_spawn(char *const argv[], int in, int log, pid_t *pid);

/* Starts argv[0] as child_spawn does, its standard input a pipe whose writing
 * end is *in (non-blocking: the caller writes with child_write and closes it)
 * and its messages in a file in memory, *log.  Returns 0 with *pid, or -1 with a
 * message in err ("the NAME program is not installed (not found on PATH; make
 * deps installs it)", or "cannot run NAME: REASON"), nothing left open. */
int child_open(char *const argv[], pid_t *pid, int *in, int *log, char *err, size_t errlen);

/* Waits for pid to end, as long as it works.  Returns its exit status, -1 when
 * it did not exit by itself, or -2 when it was killed for stalling. */
int child_wait(pid_t pid);

/* Stops pid and what it runs (its process group) at once, and waits for it. */
void child_kill(pid_t pid);

/* dir/PREFIXNAMESUFFIX for path dir/NAME: the files a child's output is made
 * in, beside it, before it is put in place. */
void child_beside(char *out, size_t len, const char *path, const char *prefix, const char *suffix);

/* Writes all n bytes of buf to fd, child_open's pipe to the child pid, with
 * SIGPIPE held back.  Returns 0, or an errno value: EPIPE when the child stopped
 * reading, ETIMEDOUT when it stalled (see above). */
int child_write(int fd, const void *buf, size_t n, pid_t pid);

#endif
