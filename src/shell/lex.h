/* lex.h: the lexer of the vroc language (language.md, "Lexical rules").
 *
 * A line becomes tokens: a word (any run of characters but white space and
 * ( ) , = ; # "), a "quoted string" (backslash escapes the next character), or one
 * of ( ) , =; ';' separates statements and '#' ends the line.  The parser
 * (lang.c) reads numbers, names and files from the words.
 */
#ifndef VROC_LEX_H
#define VROC_LEX_H

#include <stdbool.h>
#include <stddef.h>

typedef enum { T_WORD, T_STRING, T_LP, T_RP, T_COMMA, T_EQ } tkind;

typedef struct {
    tkind k;
    const char *s; /* start in the source (strings: after the quote); NULL for the
                    * statement separator ';', which has kind T_EQ */
    size_t len;
} token;

typedef struct {
    token *t;
    int n, cap;
} toklist;

/* Lexes one line [s, e) into tl (emptied first).  Returns 0, or -1 with a message
 * (without a place) in msg. */
int lex_line(const char *s, const char *e, toklist *tl, char *msg, size_t msglen);

/* True for the separator ';' between statements. */
bool lex_is_sep(const token *t);

/* A token's text for a message: quoted, at most 40 characters. */
const char *tok_text(const token *t, char buf[96]);

/* The token's text as a new string (escapes of a quoted string undone), or NULL
 * when out of memory. */
char *tok_dup(const token *t);

/* True when t is the word word. */
bool tok_is(const token *t, const char *word);

#endif
