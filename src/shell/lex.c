/* lex.c: the lexer of the vroc language (lex.h). */
#include "lex.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/grow.h"

/* A token's text for a message: quoted, at most 40 characters. */
const char *tok_text(const token *t, char buf[96])
{
    switch (t->k) {
    case T_LP: return "'('";
    case T_RP: return "')'";
    case T_COMMA: return "','";
    case T_EQ: return "'='";
    default: break;
    }
    if (t->len > 40)
        snprintf(buf, 96, "'%.32s...' (%zu characters)", t->s, t->len);
    else
        snprintf(buf, 96, "'%.*s'", (int)t->len, t->s);
    return buf;
}

char *tok_dup(const token *t)
{
    char *s = malloc(t->len + 1);
    if (!s) return NULL;
    size_t j = 0;
    for (size_t i = 0; i < t->len; i++) {
        if (t->k == T_STRING && t->s[i] == '\\' && i + 1 < t->len) i++;
        s[j++] = t->s[i];
    }
    s[j] = '\0';
    return s;
}

bool tok_is(const token *t, const char *word)
{
    return t->k == T_WORD && strlen(word) == t->len && memcmp(t->s, word, t->len) == 0;
}

static bool is_word_char(unsigned char c)
{
    return c > ' ' && c != 0x7f && !strchr("(),=;#\"", c);
}

static int tl_push(toklist *tl, token t)
{
    token *nt = grow_for_one(tl->t, tl->n, &tl->cap, sizeof *nt, 32);
    if (!nt) return -1;
    tl->t = nt;
    tl->t[tl->n++] = t;
    return 0;
}

int lex_line(const char *s, const char *e, toklist *tl, char *msg, size_t msglen)
{
    tl->n = 0;
    const char *p = s;
    while (p < e) {
        unsigned char ch = (unsigned char)*p;
        if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\f' || ch == '\v') {
            p++;
            continue;
        }
        if (ch == '#') break;
        token t = {T_WORD, p, 1};
        if (ch < ' ' || ch == 0x7f) {
            snprintf(msg, msglen, "unexpected control character 0x%02x (binary file?)", ch);
            return -1;
        }
        switch (ch) {
        case '(': t.k = T_LP; p++; break;
        case ')': t.k = T_RP; p++; break;
        case ',': t.k = T_COMMA; p++; break;
        case '=': t.k = T_EQ; p++; break;
        case ';':
            t.k = T_EQ;
            t.s = NULL; /* statement separator */
            t.len = 0;
            p++;
            break;
        case '"': {
            const char *q = ++p;
            while (q < e && *q != '"') {
                if (*q == '\\' && q + 1 < e) q++;
                q++;
            }
            if (q >= e) {
                snprintf(msg, msglen, "unterminated string (a \" is missing)");
                return -1;
            }
            t.k = T_STRING;
            t.s = p;
            t.len = (size_t)(q - p);
            p = q + 1;
            break;
        }
        default: {
            const char *q = p;
            while (q < e && is_word_char((unsigned char)*q)) q++;
            t.len = (size_t)(q - p);
            p = q;
        }
        }
        if (tl_push(tl, t) != 0) {
            snprintf(msg, msglen, "out of memory");
            return -1;
        }
    }
    return 0;
}

bool lex_is_sep(const token *t) { return t->k == T_EQ && t->s == NULL; }
