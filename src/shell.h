/* shell.h: runs statements against the world: dispatch, messages, the input loop.
 *
 * The shell owns the world, the current object and the off-screen view.  Input comes
 * from files (parsed whole before running), from -c, from a terminal through GNU
 * readline (with real-time running while the user types), or line by line from a
 * pipe.  Handlers (commands.c) report through sh_error / sh_warn / sh_info so that
 * every message carries its file and line.
 */
#ifndef VROC_SHELL_H
#define VROC_SHELL_H

#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>

#include "commands.h"
#include "lang.h"
#include "world.h"

struct view;

typedef struct shell {
    world w;
    int current;           /* index of the current object, or -1 */
    int selected;          /* object held by the hand, or -1 */
    int prev_selected;     /* for reselect, or -1 */
    settings startup;      /* what restart returns to: defaults and -o */
    bool interactive;      /* a terminal with readline */
    bool quiet;            /* -q */
    bool stop_on_error;    /* -b, or input that is not a terminal */
    FILE *out, *err;
    const char *scene_dir; /* installed scenes folder */
    struct view *view;     /* off-screen context, created on first need */
    int read_depth;        /* files being run */
    unsigned long long rng; /* state of `random`, reset by seed */
    bool found_apart;      /* shell_check_start found no overlap since the last
                            * statement began: time may run on unchecked */
} shell;

/* Set by the SIGINT handler; long operations (run, start) stop when it is set. */
extern volatile sig_atomic_t shell_interrupted;

void shell_init(shell *sh, FILE *out, FILE *err);
void shell_free(shell *sh);

/* Parses text named name (NULL: typed at the prompt; "-c": the command line)
 * and runs it.  Returns CMD_QUIT on quit, CMD_ERROR on the first error (after
 * printing it; later statements of that text do not run), else CMD_OK. */
cmd_status shell_run_text(shell *sh, const char *text, const char *name);

/* Parses the file at path whole and runs it, as `read` does from the prompt. */
cmd_status shell_run_file(shell *sh, const char *path);

/* Runs a parsed program, stopping at the first error (or quit). */
cmd_status shell_run_program(shell *sh, const program *p);

/* Refuses to let time run while objects interpenetrate (thesis 3.4.2, step 1):
 * names every such pair with its depth.  The check queries every pair, so it is
 * made once per statement: the frames start advances in real time between
 * statements are not checked again (nothing but the simulation moved). */
cmd_status shell_check_start(shell *sh, const stmt *st);

/* Advances n frames (honouring Ctrl-C); records frames when record is on. */
cmd_status shell_advance(shell *sh, const stmt *st, long n);

/* Messages about statement st (NULL: no location). */
void sh_error(shell *sh, const stmt *st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void sh_warn(shell *sh, const stmt *st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* An informational line on the output, silenced by -q. */
void sh_info(shell *sh, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The interactive loop on a terminal (readline) or the line loop on a pipe. */
int shell_loop(shell *sh);

#endif
