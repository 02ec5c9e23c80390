/* prompt.c: the input loops: the interactive prompt and plain lines from a pipe.
 *
 * On a terminal the prompt uses GNU readline's callback interface: select() waits
 * for a key, for the next frame's wall-clock time, or for rows of the hand's live
 * feed (a named pipe), so that after `start` time runs in real time while the user
 * types and the hand moves (no threads).  While time stands still the hand's
 * tracker clock runs on the wall clock (hand_wall), so that a recorded hand can
 * press Start.  Ctrl-C only sets a flag: it
 * stops running time or an ongoing `run`, or clears the line being typed.  From a
 * pipe, lines are read plainly with no prompt.  (After Lua's lua.c and SQLite's
 * shell: readline only on a terminal, a signal handler that only sets a flag.)
 * While time runs the prompt says so, with the time: vroc[t=12.3]>.
 *
 * One turn of the loop: the hand's wall clock, the live window (what the user
 * did in it: viewer.h), the frames that are due, the live sound, the prompt,
 * then select() on the keyboard and the hand's feed until the next thing is due
 * (with the window open, at most VIEWER_TICK: SDL gives no descriptor to wait
 * on).  A new source of events adds its descriptor to the select and its work to
 * the turn.
 */
#define _GNU_SOURCE /* sigaction in <signal.h> with readline's headers */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <unistd.h>

#include <readline/history.h>
#include <readline/readline.h>

#include "complete.h"
#include "media.h"
#include "shell.h"
#include "fmt.h"
#include "viewer.h"

static shell *g_sh;     /* the shell readline's callbacks work on */
static bool g_done;     /* quit or end of input */
static double g_wall;   /* the wall clock up to which the hand's clock ran */
static char g_history[4096];
static char g_prompt[64]; /* the prompt shown */
static double g_prompt_at; /* when it was last changed */

/* How often, at most, the prompt's time is redrawn while time runs, s. */
#define PROMPT_EVERY 0.25

/* Ctrl-C sets the flag; a second one before anything took the first (a loop
 * that does not look) ends vroc as Ctrl-C ends a program. */
static void on_sigint(int sig)
{
    if (shell_interrupted) {
        signal(sig, SIG_DFL);
        raise(sig);
        return;
    }
    shell_interrupted = 1;
}

void shell_catch_sigint(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: select() returns EINTR */
    sigaction(SIGINT, &sa, NULL);
}

/* The prompt and the line being typed, drawn again after a message broke them. */
static void mend_line(shell *sh)
{
    if (!sh->line_broken) return;
    sh->line_broken = false;
    rl_on_new_line();
    rl_redisplay();
}

/* The prompt: "vroc> ", or "vroc[t=T]> " while time runs. */
static void prompt_text(const shell *sh, char *buf, size_t len)
{
    char a[32];
    if (sh->running) snprintf(buf, len, "vroc[t=%s]> ", fmt_shown(a, sh->w.time, shell_shown(sh)));
    else snprintf(buf, len, "vroc> ");
}

/* Shows the prompt that fits now: at once when time starts or stops, and while
 * it runs at most every PROMPT_EVERY.  redraw: readline draws the line again
 * (not when it is about to, after a line was read). */
static void prompt_update(shell *sh, bool redraw)
{
    char want[sizeof g_prompt];
    prompt_text(sh, want, sizeof want);
    if (strcmp(want, g_prompt) == 0) return;
    double now = shell_clock();
    bool both_running = strncmp(want, "vroc[", 5) == 0 && strncmp(g_prompt, "vroc[", 5) == 0;
    if (both_running && now - g_prompt_at < PROMPT_EVERY) return;
    snprintf(g_prompt, sizeof g_prompt, "%s", want);
    g_prompt_at = now;
    rl_set_prompt(g_prompt);
    if (redraw) rl_redisplay();
}

/* How often the prompt wakes while the hand moves on the wall clock, s. */
#define HAND_TICK 0.02

/* While time stands still (stopped, or halted by time_step 0), the hand's clock
 * runs on the wall clock, up to now. */
static void hand_tick(shell *sh)
{
    double now = shell_clock();
    if (!sh->running || !(sh->w.set.time_step > 0)) {
        hand_wall(&sh->hand, &sh->w, now - g_wall);
        shell_after_hand(sh);
        mend_line(sh);
    }
    g_wall = now;
}

static void on_line(char *line)
{
    hand_tick(g_sh); /* what the statement sees of the hand is up to date */
    g_sh->at_prompt = false;
    if (!line) { /* Ctrl-D */
        g_done = true;
        rl_callback_handler_remove();
        fputc('\n', g_sh->out);
        return;
    }
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (*p) add_history(line);
    if (shell_run_text(g_sh, line, NULL) == CMD_QUIT) {
        g_done = true;
        rl_callback_handler_remove();
    }
    shell_interrupted = 0; /* a Ctrl-C the statement did not look for is spent */
    free(line);
    g_sh->at_prompt = !g_done;
    if (!g_done) prompt_update(g_sh, false); /* readline shows it next */
}

/* Advances the frames that are due in real time; returns seconds to the next.  A
 * frame runs when it begins, ahead of its time, so that its collisions' sounds are
 * queued before their moment (media.h). */
static double run_due_frames(shell *sh, double *next)
{
    double h = sh->w.set.time_step;
    if (!sh->running || h <= 0) return -1;
    double t = shell_clock();
    if (*next <= 0) *next = t;
    if (t < *next) return *next - t;
    long due = (long)((t - *next) / h) + 1;
    if (due > 5) due = 5; /* fall behind rather than stall the prompt */
    if (shell_advance(sh, NULL, due) != CMD_OK) sh->running = false;
    *next += (double)due * h;
    if (*next < t) *next = t + h;
    return *next - shell_clock() > 0 ? *next - shell_clock() : 0;
}

static void history_path(void)
{
    const char *home = getenv("HOME");
    if (home && *home) snprintf(g_history, sizeof g_history, "%s/.vroc_history", home);
}

static int loop_readline(shell *sh)
{
    g_sh = sh;
    g_done = false;
    history_path();
    using_history();
    stifle_history(2000);
    if (g_history[0]) read_history(g_history);
    rl_readline_name = "vroc";
    complete_install(sh);
    rl_basic_word_break_characters = " \t\n\"(),=;#";
    rl_catch_signals = 0;
    shell_catch_sigint();
    prompt_text(sh, g_prompt, sizeof g_prompt);
    rl_callback_handler_install(g_prompt, on_line);
    sh->at_prompt = true;
    double next = 0;
    g_wall = shell_clock();
    while (!g_done) {
        hand_tick(sh); /* it may press Start */
        viewer_turn(sh); /* keys and the mouse in the window */
        double wait = media_pump(sh, run_due_frames(sh, &next)); /* frames, live sound */
        mend_line(sh);
        prompt_update(sh, true);
        if (!sh->running) next = 0;
        if (sh->running && (wait < 0 || wait > PROMPT_EVERY)) wait = PROMPT_EVERY;
        if (hand_busy(&sh->hand) && (wait < 0 || wait > HAND_TICK)) wait = HAND_TICK;
        wait = viewer_wait(sh, wait);
        int in = fileno(rl_instream ? rl_instream : stdin), feed = hand_feed_fd(&sh->hand);
        fd_set fds;
        FD_ZERO(&fds);
        FD_SET(in, &fds);
        if (feed >= 0) FD_SET(feed, &fds);
        struct timeval tv, *tvp = NULL;
        if (wait >= 0) {
            tv.tv_sec = (time_t)wait;
            tv.tv_usec = (suseconds_t)((wait - (double)tv.tv_sec) * 1e6);
            tvp = &tv;
        }
        int n = select((feed > in ? feed : in) + 1, &fds, NULL, NULL, tvp);
        if (n < 0 && errno == EINTR) {
            if (!shell_interrupted) continue;
            shell_interrupted = 0;
            if (sh->running) {
                char a[32];
                sh->running = false;
                fprintf(sh->out, "\nstopped at time = %s\n", fmt_shown(a, sh->w.time, shell_shown(sh)));
            } else {
                fputc('\n', sh->out);
            }
            prompt_update(sh, false);
            rl_replace_line("", 0);
            rl_on_new_line();
            rl_redisplay();
            continue;
        }
        if (n > 0 && feed >= 0 && FD_ISSET(feed, &fds)) { /* rows act as they come */
            hand_poll(&sh->hand, &sh->w);
            shell_after_hand(sh);
            mend_line(sh);
        }
        if (n > 0 && FD_ISSET(in, &fds)) rl_callback_read_char();
    }
    sh->at_prompt = false;
    if (g_history[0]) write_history(g_history);
    clear_history();
    complete_free();
    return 0;
}

/* The next line of in into *line (room *cap), its newline removed: its length,
 * -1 at the end of input, or -2 when it is longer than LANG_MAX_LINE (the rest of
 * it is read and left out), so that a pipe of endless bytes (/dev/zero) cannot
 * take all the memory. */
static long next_line(FILE *in, char **line, size_t *cap)
{
    size_t n = 0;
    bool long_line = false;
    int c;
    while ((c = getc(in)) != EOF && c != '\n') {
        if (long_line || n >= (size_t)LANG_MAX_LINE) {
            long_line = true;
            continue;
        }
        if (n + 1 >= *cap) {
            size_t nc = *cap ? 2 * *cap : 256;
            char *nl = realloc(*line, nc);
            if (!nl) return -2;
            *line = nl;
            *cap = nc;
        }
        (*line)[n++] = (char)c;
    }
    if (c == EOF && n == 0 && !long_line) return -1;
    if (long_line) return -2;
    if (!*line && !(*line = malloc(*cap = 1))) return -2;
    (*line)[n] = '\0';
    return (long)n;
}

static int loop_lines(shell *sh, FILE *in)
{
    char *line = NULL;
    size_t cap = 0;
    int lineno = 0, status = 0;
    long len;
    shell_catch_sigint();
    while ((len = next_line(in, &line, &cap)) != -1) {
        lineno++;
        cmd_status r;
        if (len == -2 || memchr(line, '\0', (size_t)len)) {
            stmt where = {.file = "<stdin>", .line = lineno};
            if (len == -2) sh_error(sh, &where, "a line longer than %ld bytes", LANG_MAX_LINE);
            else sh_error(sh, &where, "a NUL byte (binary input?)");
            r = CMD_ERROR;
        } else {
            r = shell_run_text_at(sh, line, "<stdin>", lineno);
        }
        if (r == CMD_QUIT) break;
        if (r == CMD_ERROR && sh->stop_on_error) {
            status = 1;
            break;
        }
    }
    free(line);
    return status;
}

int shell_loop(shell *sh)
{
    if (sh->interactive) return loop_readline(sh);
    return loop_lines(sh, stdin);
}
