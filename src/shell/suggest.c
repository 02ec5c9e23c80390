/* suggest.c: the nearest name to a word typed wrong, by edit distance (the
 * optimal-string-alignment form of Damerau-Levenshtein: a swap of neighbours, the
 * commonest typo, costs 1) (suggest.h). */
#include "suggest.h"

#include <stdio.h>
#include <string.h>

/* Longest word compared: longer ones are never near a name of the language. */
#define SUGGEST_LEN 64

int suggest_distance(const char *a, const char *b, int limit)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la >= SUGGEST_LEN || lb >= SUGGEST_LEN) return limit + 1;
    if ((la > lb ? la - lb : lb - la) > (size_t)limit) return limit + 1;
    /* three rows of the table: i - 2, i - 1 and i */
    int rows[3][SUGGEST_LEN + 1];
    for (size_t j = 0; j <= lb; j++) rows[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        int *cur = rows[i % 3], *prev = rows[(i - 1) % 3], *prev2 = rows[(i + 1) % 3];
        cur[0] = (int)i;
        int row_min = cur[0];
        for (size_t j = 1; j <= lb; j++) {
            int cost = a[i - 1] != b[j - 1];
            int d = prev[j] + 1;
            if (cur[j - 1] + 1 < d) d = cur[j - 1] + 1;
            if (prev[j - 1] + cost < d) d = prev[j - 1] + cost;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                prev2[j - 2] + 1 < d)
                d = prev2[j - 2] + 1;
            cur[j] = d;
            if (d < row_min) row_min = d;
        }
        if (row_min > limit) return limit + 1;
    }
    int d = rows[la % 3][lb];
    return d > limit ? limit + 1 : d;
}

void suggest_init(suggestion *s, const char *word)
{
    s->word = word;
    s->best = NULL;
    s->dist = SUGGEST_MAX + 1;
}

void suggest_offer(suggestion *s, const char *cand)
{
    /* a word as short as its distance shares nothing with the name */
    int len = (int)strlen(s->word);
    int d = suggest_distance(s->word, cand, SUGGEST_MAX);
    if (d > 0 && d < s->dist && d < len) {
        s->best = cand;
        s->dist = d;
    }
}

void suggest_offer_choices(suggestion *s, const char *choices)
{
    char one[SUGGEST_LEN];
    for (const char *p = choices; p && *p;) {
        size_t n = strcspn(p, "|");
        if (n < sizeof one) {
            memcpy(one, p, n);
            one[n] = '\0';
            /* the choice's text lives in choices: keep a pointer into it */
            int before = s->dist;
            suggest_offer(s, one);
            if (s->dist < before) s->best = p;
        }
        p += n;
        if (*p) p++;
    }
}

void suggest_offer_commands(suggestion *s, unsigned form_mask)
{
    for (int i = 0; i < command_count; i++)
        if (form_mask & (1u << command_table[i].form)) suggest_offer(s, command_table[i].name);
}

const char *suggest_text(const suggestion *s, char *buf, size_t len)
{
    if (!s->best) return "";
    size_t n = strcspn(s->best, "|"); /* a choice ends at its '|' */
    snprintf(buf, len, ": did you mean %.*s?", (int)n, s->best);
    return buf;
}
