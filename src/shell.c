/* shell.c: running statements, messages with their place, and the input loops.
 *
 * On a terminal the prompt uses GNU readline's callback interface: select() waits
 * for a key or for the next frame's wall-clock time, so that after `start` time runs
 * in real time while the user types (no threads).  Ctrl-C only sets a flag: it
 * stops running time or an ongoing `run`, or clears the line being typed.  From a
 * pipe, lines are read plainly with no prompt.  (After Lua's lua.c and SQLite's
 * shell: readline only on a terminal, a signal handler that only sets a flag.)
 */
#define _GNU_SOURCE /* sigaction in <signal.h> with readline's headers */
#include "shell.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>

#include <readline/history.h>
#include <readline/readline.h>

#include "sim.h"
#include "view.h"

volatile sig_atomic_t shell_interrupted;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void shell_init(shell *sh, FILE *out, FILE *err)
{
    memset(sh, 0, sizeof *sh);
    world_init(&sh->w);
    sh->startup = sh->w.set;
    sh->rng = sh->w.set.seed;
    sh->current = sh->selected = sh->prev_selected = -1;
    sh->out = out;
    sh->err = err;
}

void shell_free(shell *sh)
{
    world_free(&sh->w);
    view_free(sh->view);
    sh->view = NULL;
}

/* ------------------------------------------------------------ messages */

static void vmsg(shell *sh, const stmt *st, const char *kind, const char *fmt, va_list ap)
{
    fflush(sh->out);
    if (st && st->file) fprintf(sh->err, "%s:%d: %s: ", st->file, st->line, kind);
    else fprintf(sh->err, "%s: ", kind);
    vfprintf(sh->err, fmt, ap);
    fputc('\n', sh->err);
    fflush(sh->err);
}

void sh_error(shell *sh, const stmt *st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(sh, st, "error", fmt, ap);
    va_end(ap);
}

void sh_warn(shell *sh, const stmt *st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(sh, st, "warning", fmt, ap);
    va_end(ap);
}

void sh_info(shell *sh, const char *fmt, ...)
{
    if (sh->quiet) return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(sh->out, fmt, ap);
    va_end(ap);
    fputc('\n', sh->out);
}

/* ------------------------------------------------------------ running */

cmd_status shell_run_program(shell *sh, const program *p)
{
    for (int i = 0; i < p->n; i++) {
        sh->found_apart = false; /* the statement may move anything */
        cmd_status r = p->s[i].cmd->run(sh, &p->s[i]);
        /* whatever a statement changed, the schedule's predictions start afresh */
        sh->w.sched_dirty = true;
        if (r != CMD_OK) return r;
    }
    return CMD_OK;
}

static lang_paths paths_of(const shell *sh) { return (lang_paths){NULL, sh->scene_dir}; }

static cmd_status run_parsed(shell *sh, program *p, const char *err)
{
    if (!p) {
        fflush(sh->out);
        fprintf(sh->err, "%s\n", err);
        return CMD_ERROR;
    }
    cmd_status r = shell_run_program(sh, p);
    program_free(p);
    fflush(sh->out);
    return r;
}

static cmd_status run_text_at(shell *sh, const char *text, const char *name, int line)
{
    char err[1024];
    lang_paths paths = paths_of(sh);
    program *p = lang_parse(text, strlen(text), name, line, &paths, 0, NULL, 0, err, sizeof err);
    return run_parsed(sh, p, err);
}

cmd_status shell_run_text(shell *sh, const char *text, const char *name)
{
    return run_text_at(sh, text, name, 1);
}

cmd_status shell_run_file(shell *sh, const char *path)
{
    char err[1024];
    lang_paths paths = paths_of(sh);
    program *p = lang_parse_file(path, &paths, 0, NULL, 0, NULL, 0, err, sizeof err);
    return run_parsed(sh, p, err);
}

typedef struct {
    shell *sh;
    const stmt *st;
} pen_ctx;

static void report_penetration(void *ctx, const body *a, const body *b, double depth)
{
    pen_ctx *c = ctx;
    char d[32];
    sh_error(c->sh, c->st, "'%s' and '%s' interpenetrate by %s m", a->name, b->name,
             fmt_num(d, depth));
}

cmd_status shell_check_start(shell *sh, const stmt *st)
{
    pen_ctx ctx = {sh, st};
    long n = sim_penetrations(&sh->w, report_penetration, &ctx);
    if (n < 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    if (n > 0) {
        sh_error(sh, st, "time cannot run while objects interpenetrate: move them apart first");
        return CMD_ERROR;
    }
    if (sim_prepare(&sh->w) != 0) {
        sh_error(sh, st, "out of memory");
        return CMD_ERROR;
    }
    sh->found_apart = true;
    return CMD_OK;
}

cmd_status shell_advance(shell *sh, const stmt *st, long n)
{
    char err[1024];
    if (n > 0 && !sh->found_apart && shell_check_start(sh, st) != CMD_OK) return CMD_ERROR;
    double t0 = now();
    cmd_status r = CMD_OK;
    for (long k = 0; k < n; k++) {
        if (shell_interrupted) {
            shell_interrupted = 0;
            char a[32];
            sh_info(sh, "interrupted at time = %s", fmt_num(a, sh->w.time));
            break;
        }
        if (sim_frame(&sh->w, err, sizeof err) != 0) {
            sh_error(sh, st, "%s", err);
            r = CMD_ERROR;
            break;
        }
        if (sh->w.set.record &&
            view_refresh(&sh->view, &sh->w, sh->w.frame, &sh->w.st, err, sizeof err) != 0) {
            /* at the prompt the simulation goes on without the pictures; a batch
             * run stops at its first error */
            sh->w.set.record = false;
            sh_error(sh, st, "record: %s; recording turned off%s", err,
                     sh->stop_on_error ? ", time stopped" : "");
            if (sh->stop_on_error) {
                r = CMD_ERROR;
                break;
            }
        }
    }
    sh->w.st.wall_time += now() - t0;
    return r;
}

/* ------------------------------------------------------------ the prompt */

static shell *g_sh;     /* the shell readline's callbacks work on */
static bool g_done;     /* quit or end of input */
static char g_history[4096];

static void on_sigint(int sig)
{
    (void)sig;
    shell_interrupted = 1;
}

static void install_sigint(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: select() returns EINTR */
    sigaction(SIGINT, &sa, NULL);
}

/* ---- completion: commands, properties of the current object, object names */

static char **g_cands;
static int g_ncands, g_capcands;

static void cand_add(const char *s)
{
    if (g_ncands == g_capcands) {
        int cap = g_capcands ? 2 * g_capcands : 64;
        char **n = realloc(g_cands, (size_t)cap * sizeof *n);
        if (!n) return;
        g_cands = n;
        g_capcands = cap;
    }
    char *d = strdup(s);
    if (d) g_cands[g_ncands++] = d;
}

static void cand_clear(void)
{
    for (int i = 0; i < g_ncands; i++) free(g_cands[i]);
    g_ncands = 0;
}

static char *cand_generator(const char *text, int state)
{
    static int i;
    static size_t len;
    if (state == 0) {
        i = 0;
        len = strlen(text);
    }
    while (i < g_ncands) {
        const char *c = g_cands[i++];
        if (strncmp(c, text, len) == 0) return strdup(c);
    }
    return NULL;
}

static void add_properties(const char *prefix, const body *b)
{
    char buf[BODY_NAME_MAX + 64];
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form == FORM_PROPERTY && (c->classes & (1u << b->sp.kind))) {
            snprintf(buf, sizeof buf, "%s%s", prefix, c->name);
            cand_add(buf);
        }
    }
}

static void add_names(const shell *sh, const char *suffix)
{
    char buf[BODY_NAME_MAX + 2];
    for (int i = 0; i < sh->w.n; i++) {
        snprintf(buf, sizeof buf, "%s%s", sh->w.bodies[i]->name, suffix);
        cand_add(buf);
    }
}

/* Candidates for the first word of a statement. */
static void first_word_candidates(const shell *sh, const char *text)
{
    const char *dot = strchr(text, '.');
    if (dot) {
        char name[BODY_NAME_MAX];
        size_t n = (size_t)(dot - text);
        if (n >= sizeof name) return;
        memcpy(name, text, n);
        name[n] = '\0';
        int i = world_find(&sh->w, name);
        if (i < 0) return;
        char prefix[BODY_NAME_MAX + 1];
        snprintf(prefix, sizeof prefix, "%s.", name);
        add_properties(prefix, sh->w.bodies[i]);
        return;
    }
    for (int i = 0; i < command_count; i++)
        if (command_table[i].form != FORM_PROPERTY) cand_add(command_table[i].name);
    if (sh->current >= 0) add_properties("", sh->w.bodies[sh->current]);
    add_names(sh, ".");
}

/* Candidates after the first word w0 (and '=' when has_eq). Returns false when
 * file names should be completed instead. */
static bool later_candidates(const shell *sh, const char *w0, bool has_eq)
{
    const char *dot = strchr(w0, '.');
    const command *c = command_find(dot ? dot + 1 : w0);
    if (!c) return true;
    switch (c->arg) {
    case ARG_NAME:
    case ARG_NAME2: add_names(sh, ""); return true;
    case ARG_OPT_WORD:
        for (int i = 0; i < command_count; i++) cand_add(command_table[i].name);
        return true;
    case ARG_FILE:
    case VAL_FILE: return false;
    case VAL_FILE_OR_OFF:
        if (!has_eq) return true;
        cand_add("off");
        return false;
    case ARG_OPT_ONOFF:
    case VAL_ONOFF:
        cand_add("on");
        cand_add("off");
        return true;
    case VAL_CHOICE: {
        char buf[64];
        for (const char *p = c->choices; *p;) {
            size_t n = strcspn(p, "|");
            snprintf(buf, sizeof buf, "%.*s", (int)n, p);
            cand_add(buf);
            p += n;
            if (*p) p++;
        }
        return true;
    }
    default: return true;
    }
}

static char **complete(const char *text, int start, int end)
{
    (void)end;
    cand_clear();
    /* the statement being typed starts after the last ';' before the cursor */
    int s = start;
    while (s > 0 && rl_line_buffer[s - 1] != ';') s--;
    while (s < start && (rl_line_buffer[s] == ' ' || rl_line_buffer[s] == '\t')) s++;
    rl_attempted_completion_over = 1;
    rl_completion_suppress_append = 0;
    if (s == start) {
        first_word_candidates(g_sh, text);
        if (strchr(text, '.') == NULL) {
            /* object names end with '.', do not add a space after them */
            bool all_dots = true;
            size_t len = strlen(text);
            for (int i = 0; i < g_ncands; i++)
                if (strncmp(g_cands[i], text, len) == 0 && g_cands[i][strlen(g_cands[i]) - 1] != '.')
                    all_dots = false;
            if (all_dots) rl_completion_suppress_append = 1;
        }
    } else {
        char w0[256];
        int e = s;
        while (e < start && rl_line_buffer[e] != ' ' && rl_line_buffer[e] != '\t' &&
               rl_line_buffer[e] != '=')
            e++;
        snprintf(w0, sizeof w0, "%.*s", e - s, rl_line_buffer + s);
        bool has_eq = memchr(rl_line_buffer + s, '=', (size_t)(start - s)) != NULL;
        if (!later_candidates(g_sh, w0, has_eq)) {
            rl_attempted_completion_over = 0; /* readline completes file names */
            if (g_ncands == 0) return NULL;
        }
    }
    return rl_completion_matches(text, cand_generator);
}

static void on_line(char *line)
{
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
    free(line);
}

/* Advances the frames that are due in real time; returns seconds to the next. */
static double run_due_frames(shell *sh, double *next)
{
    double h = sh->w.set.time_step;
    if (!sh->w.running || h <= 0) return -1;
    double t = now();
    if (*next <= 0) *next = t + h;
    if (t < *next) return *next - t;
    long due = (long)((t - *next) / h) + 1;
    if (due > 5) due = 5; /* fall behind rather than stall the prompt */
    if (shell_advance(sh, NULL, due) != CMD_OK) sh->w.running = false;
    *next += (double)due * h;
    if (*next < t) *next = t + h;
    return *next - now() > 0 ? *next - now() : 0;
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
    rl_attempted_completion_function = complete;
    rl_basic_word_break_characters = " \t\n\"(),=;#";
    rl_catch_signals = 0;
    install_sigint();
    rl_callback_handler_install("vroc> ", on_line);
    double next = 0;
    while (!g_done) {
        double wait = run_due_frames(sh, &next);
        if (!sh->w.running) next = 0;
        fd_set fds;
        FD_ZERO(&fds);
        FD_SET(fileno(rl_instream ? rl_instream : stdin), &fds);
        struct timeval tv, *tvp = NULL;
        if (wait >= 0) {
            tv.tv_sec = (time_t)wait;
            tv.tv_usec = (suseconds_t)((wait - (double)tv.tv_sec) * 1e6);
            tvp = &tv;
        }
        int n = select(fileno(rl_instream ? rl_instream : stdin) + 1, &fds, NULL, NULL, tvp);
        if (n < 0 && errno == EINTR) {
            if (!shell_interrupted) continue;
            shell_interrupted = 0;
            if (sh->w.running) {
                char a[32];
                sh->w.running = false;
                fprintf(sh->out, "\nstopped at time = %s\n", fmt_num(a, sh->w.time));
            } else {
                fputc('\n', sh->out);
            }
            rl_replace_line("", 0);
            rl_on_new_line();
            rl_redisplay();
            continue;
        }
        if (n > 0) rl_callback_read_char();
    }
    if (g_history[0]) write_history(g_history);
    clear_history();
    cand_clear();
    free(g_cands);
    g_cands = NULL;
    g_capcands = 0;
    return 0;
}

static int loop_lines(shell *sh, FILE *in)
{
    char *line = NULL;
    size_t cap = 0;
    int lineno = 0, status = 0;
    install_sigint();
    while (getline(&line, &cap, in) >= 0) {
        lineno++;
        cmd_status r = run_text_at(sh, line, "<stdin>", lineno);
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
