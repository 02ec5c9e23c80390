/* help.h: the command reference, built from commands/ into build/gen/help_data.c.
 *
 * One entry per file of commands/ (see src/mkhelp.awk), sorted by name.  The
 * command table (commands.c) holds dispatch; this holds the words; a unit test
 * checks that both name the same commands. */
#ifndef VROC_HELP_H
#define VROC_HELP_H

typedef struct {
    const char *name;        /* the command or property word */
    const char *group;       /* object, property, system, console or view */
    const char *usage;       /* one line: "radius = r" */
    const char *summary;     /* one line, lower case, no final period */
    const char *description; /* paragraphs, lines joined with \n */
    const char *example;     /* lines of the example, joined with \n */
} help_entry;

extern const help_entry help_entries[];
extern const int help_count;

/* The entry for name, or NULL. */
const help_entry *help_find(const char *name);

#endif
