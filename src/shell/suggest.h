/* suggest.h: "did you mean": the nearest of a set of names to a word typed wrong
 * (language.md: an unknown command or property suggests the nearest name, at an
 * edit distance of at most 2). */
#ifndef VROC_SUGGEST_H
#define VROC_SUGGEST_H

#include <stddef.h>

#include "commands.h"

/* The furthest a suggestion may be from the word typed. */
#define SUGGEST_MAX 2

/* The edit distance between a and b (insertions, deletions, substitutions, and
 * swaps of two neighbouring characters, each 1; case counts), or limit + 1 when
 * it exceeds limit. */
int suggest_distance(const char *a, const char *b, int limit);

/* The nearest to word so far; offer candidates in order: the first of equals wins. */
typedef struct {
    const char *word;
    const char *best; /* NULL: none near enough */
    int dist;
} suggestion;

void suggest_init(suggestion *s, const char *word);
void suggest_offer(suggestion *s, const char *cand);

/* The words of choices ("a|b|c") offered in turn. */
void suggest_offer_choices(suggestion *s, const char *choices);

/* The command table's entries of the forms in form_mask (1 << FORM_ACTION, ...)
 * offered in turn. */
void suggest_offer_commands(suggestion *s, unsigned form_mask);

/* ": did you mean NAME?" when there is a suggestion, else "" (in buf). */
const char *suggest_text(const suggestion *s, char *buf, size_t len);

#endif
