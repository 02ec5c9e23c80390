/* lang.h: lexer and parser of the vroc language (language.md, "Lexical rules").
 *
 * Text becomes a program: a list of statements, each checked against the command
 * table (form, arguments, value ranges) with its file and line.  A file is parsed
 * whole, and every file it reads is parsed with it (paths resolved, cycles and
 * depth checked), before any statement runs: a typo on line 80 changes nothing.
 * Checks that depend on the world (no current object, a name in use with another
 * type) are left to the handlers.
 */
#ifndef VROC_LANG_H
#define VROC_LANG_H

#include <stdbool.h>
#include <stddef.h>

#include "commands.h"

/* How deep files may read each other, counting the first (lang_parse_file). */
#define LANG_MAX_DEPTH 16

/* The caps of what one parse takes in (infile.h): each file at most LANG_MAX_FILE
 * bytes, each line at most LANG_MAX_LINE; and all the files a text or a file reads,
 * through reads nested in reads (ten files that each read the next ten times
 * would otherwise grow tenfold a level), at most LANG_MAX_READS files,
 * LANG_MAX_TOTAL bytes and LANG_MAX_STATEMENTS statements together (a saved world
 * of 10,000 objects is one file of 8 MB and 190,000 statements). */
#define LANG_MAX_FILE (64L * 1024 * 1024)
#define LANG_MAX_LINE (1L * 1024 * 1024)
#define LANG_MAX_READS 10000L
#define LANG_MAX_TOTAL (64L * 1024 * 1024)
#define LANG_MAX_STATEMENTS 1000000L

struct program;

typedef struct stmt {
    const command *cmd;
    char *object;          /* NAME of NAME.property = value (and of plot NAME.height),
                            * else NULL */
    int n;                 /* numbers in num */
    double num[4];         /* numeric value(s) */
    char *word;            /* name, file, choice or on/off word */
    char *word2;           /* second name (distance A B) */
    const char *file;      /* where it was written (NULL at the prompt) */
    int line;
    struct program *sub;   /* read FILE: the parsed file */
} stmt;

/* plot's quantities (stmt.num[0] of a plot statement). */
enum { PLOT_ENERGY, PLOT_MOMENTUM, PLOT_HEIGHT };

/* The statement's vector value (x, y, z). */
static inline vec3 stmt_vec(const stmt *st) { return v3(st->num[0], st->num[1], st->num[2]); }

typedef struct program {
    stmt *s;
    int n, cap;
    char *path;            /* the file as named by the user (for messages) */
    char *real;            /* its resolved path (cycle detection) */
} program;

/* What one parse has taken in so far, through all its reads (LANG_MAX_TOTAL). */
typedef struct {
    long reads;
    long bytes;
    long statements;
} lang_budget;

/* Where `read` looks for relative paths. */
typedef struct {
    const char *base_dir;  /* folder of the file being parsed; NULL at the prompt */
    const char *scene_dir; /* the installed scenes folder (NULL for none) */
    lang_budget *budget;   /* what the parse has taken in; NULL: a parse starts here */
} lang_paths;

/* Parses text (len bytes, need not be NUL-terminated) named name (a file path, or
 * NULL at the prompt and for -c), its first line numbered first_line.  Files read by `read` statements are loaded and parsed
 * too, `depth` levels deep already, `stack` holding the real paths of the files
 * being parsed (n_stack of them).  Returns the program, or NULL with the message
 * "file:line: error: ..." (or "error: ...") in err. */
program *lang_parse(const char *text, size_t len, const char *name, int first_line,
                    const lang_paths *paths, int depth, const char **stack, int n_stack, char *err, size_t errlen);

/* Reads and parses the file at path (resolved as `read` resolves it from paths),
 * which is at nesting level depth: 1 for a file named on the command line or read
 * from the prompt or -c, one more for each file between it and them.  A file
 * deeper than LANG_MAX_DEPTH is an error: files nest LANG_MAX_DEPTH deep. */
program *lang_parse_file(const char *path, const lang_paths *paths, int depth,
                         const char **stack, int n_stack, const char *from_file, int from_line,
                         char *err, size_t errlen);

void program_free(program *p);

/* Resolves a file name for `read` into out: absolute names as they are; relative
 * names from paths->base_dir when set, else the current folder, then from
 * paths->scene_dir (so a script can read the installed scenes as the prompt
 * can).  Returns 0 when the file exists, else -1 (out holds the first
 * candidate). */
int lang_resolve(const char *name, const lang_paths *paths, char *out, size_t outlen);

/* True when s is a valid object name: letters, digits, _ and -, starting with a
 * letter or _, at most BODY_NAME_MAX - 1 characters. */
bool lang_valid_name(const char *s);

#endif
