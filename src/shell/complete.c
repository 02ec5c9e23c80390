/* complete.c: tab completion at the prompt: commands and settings first, then the
 * properties of the current object (or of NAME. as typed), object names, and what
 * may follow a word (names, on/off, choices, file names), all from the command
 * table. */
#include "complete.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <readline/readline.h>

static const shell *g_sh; /* the shell completion works for */

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
    char buf[BODY_NAME_MAX + 16];
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

/* The words of choices, "a|b|c" (NULL: none). */
static void add_choices(const char *choices)
{
    char buf[64];
    for (const char *p = choices; p && *p;) {
        size_t n = strcspn(p, "|");
        snprintf(buf, sizeof buf, "%.*s", (int)n, p);
        cand_add(buf);
        p += n;
        if (*p) p++;
    }
}

/* Candidates after the first word w0 (and '=' when has_eq), for the word text.
 * Returns false when file names should be completed where none of them fits
 * (value words come first: collision_sound's click, knock, bell, off). */
static bool later_candidates(const shell *sh, const char *w0, bool has_eq, const char *text)
{
    const char *dot = strchr(w0, '.');
    const command *c = command_find(dot ? dot + 1 : w0);
    if (!c) return true;
    switch (c->arg) {
    case ARG_NAME:
    case ARG_NAME2:
    case ARG_OPT_NAME:
    case VAL_NAME:
        add_names(sh, "");
        add_choices(c->choices);
        return true;
    case ARG_NAME_DOT: { /* print NAME or NAME.property */
        const char *tdot = strchr(text, '.');
        if (!tdot) {
            add_names(sh, "");
            return true;
        }
        char name[BODY_NAME_MAX], prefix[BODY_NAME_MAX + 1];
        size_t n = (size_t)(tdot - text);
        if (n >= sizeof name) return true;
        memcpy(name, text, n);
        name[n] = '\0';
        int i = world_find(&sh->w, name);
        snprintf(prefix, sizeof prefix, "%s.", name);
        if (i >= 0) add_properties(prefix, sh->w.bodies[i]);
        return true;
    }
    case ARG_OPT_WORD:
        for (int i = 0; i < command_count; i++) cand_add(command_table[i].name);
        return true;
    case ARG_SETTING:
        for (int i = 0; i < command_count; i++)
            if (command_table[i].form == FORM_SETTING) cand_add(command_table[i].name);
        cand_add("select");
        return true;
    case ARG_FILE: return false;
    case ARG_PLOT:
        if (has_eq) return false;
        cand_add("energy");
        cand_add("momentum");
        add_names(sh, ".height");
        return true;
    case VAL_FILE:
        if (has_eq) add_choices(c->choices);
        return false;
    case VAL_FILE_OR_OFF:
        if (!has_eq) return true;
        cand_add("off");
        return false;
    case ARG_OPT_ONOFF:
    case VAL_ONOFF:
        cand_add("on");
        cand_add("off");
        return true;
    case VAL_CHOICE: add_choices(c->choices); return true;
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
        if (!later_candidates(g_sh, w0, has_eq, text)) {
            rl_attempted_completion_over = 0; /* readline completes file names */
            size_t len = strlen(text);
            bool fits = false;
            for (int i = 0; i < g_ncands && !fits; i++) fits = strncmp(g_cands[i], text, len) == 0;
            if (!fits) return NULL;
        }
    }
    return rl_completion_matches(text, cand_generator);
}

void complete_install(const shell *sh)
{
    g_sh = sh;
    rl_attempted_completion_function = complete;
}

void complete_free(void)
{
    cand_clear();
    free(g_cands);
    g_cands = NULL;
    g_capcands = 0;
}
