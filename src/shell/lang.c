/* lang.c: the parser of the vroc language (language.md; thesis Appendix A).
 *
 * Statements end at a newline or ';'; '#' starts a comment; the lexer (lex.h)
 * makes the tokens.  A numeric value is read from the statement's text itself,
 * since every number may be an expression that the lexer's words would cut up
 * (expr.h); its errors quote the line with a caret under the place.  Each
 * statement is checked against the command table here, values and ranges
 * included, so that a file with an error anywhere is refused before anything in
 * it runs.  `read` statements load and parse their file at once, with the cycle
 * and depth checks.
 */
#include "lang.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/body.h"
#include "core/grow.h"
#include "core/limits.h"
#include "expr.h"
#include "fmt.h"
#include "infile.h"
#include "lex.h"
#include "sound/synth.h"
#include "suggest.h"

typedef struct {
    const char *name; /* file name for messages, or NULL */
    int line;
    char *err;
    size_t errlen;
    const char *text, *text_end; /* the line being parsed */
} where;

static void vperr(const where *at, const char *fmt, va_list ap)
{
    char msg[512];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (at->name)
        snprintf(at->err, at->errlen, "%s:%d: error: %s", at->name, at->line, msg);
    else
        snprintf(at->err, at->errlen, "error: %s", msg);
}

static void perr(const where *at, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void perr(const where *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vperr(at, fmt, ap);
    va_end(ap);
}

/* Columns of the line quoted around a caret: at most this many. */
#define EXCERPT 72

/* perr, then the line (or the part of it about pos) and a caret under pos. */
static void perr_at(const where *at, const char *pos, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void perr_at(const where *at, const char *pos, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vperr(at, fmt, ap);
    va_end(ap);
    if (!at->text || pos < at->text || pos > at->text_end) return;
    const char *from = at->text, *to = at->text_end;
    while (from < to && (*from == ' ' || *from == '\t')) from++;
    while (to > from && (to[-1] == ' ' || to[-1] == '\t' || to[-1] == '\r')) to--;
    if (pos < from) pos = from;
    bool cut_left = pos - from > EXCERPT - 20, cut_right;
    if (cut_left) from = pos - (EXCERPT - 20);
    cut_right = to - from > EXCERPT;
    if (cut_right) to = from + EXCERPT;
    /* the excerpt with tabs as spaces; the caret counts characters, not the
     * bytes of UTF-8 */
    char line[EXCERPT + 1];
    int len = (int)(to - from), col = cut_left ? 3 : 0;
    for (int k = 0; k < len; k++) line[k] = from[k] == '\t' ? ' ' : from[k];
    line[len] = '\0';
    for (const char *q = from; q < pos; q++)
        if (((unsigned char)*q & 0xc0) != 0x80) col++;
    size_t n = strlen(at->err);
    snprintf(at->err + n, at->errlen - n, "\n    %s%s%s\n    %*s^", cut_left ? "..." : "", line,
             cut_right ? "..." : "", col, "");
}

/* ---------------------------------------------------------------- values */

/* A numeric value's text: from its first token to the end of the statement,
 * copied with a final NUL for expr_read; src is where it starts in the line. */
typedef struct {
    char *text;
    const char *p;   /* the next character to read, in text */
    const char *src;
} cursor;

/* The place in the line of the cursor's position p. */
static const char *src_of(const cursor *cu, const char *p) { return cu->src + (p - cu->text); }

/* The tokens t[0..nt-1] (nt > 0) as a cursor.  A quoted string among them is
 * no number: an error, as is running out of memory. */
static int cursor_open(cursor *cu, const token *t, int nt, const command *c, const where *at)
{
    char buf[96];
    for (int k = 0; k < nt; k++) {
        if (t[k].k == T_STRING) {
            perr(at, "%s: expected a number, got %s", c->name, tok_text(&t[k], buf));
            return -1;
        }
    }
    const char *end = t[nt - 1].s + t[nt - 1].len;
    size_t n = (size_t)(end - t[0].s);
    cu->text = malloc(n + 1);
    if (!cu->text) {
        perr(at, "out of memory");
        return -1;
    }
    memcpy(cu->text, t[0].s, n);
    cu->text[n] = '\0';
    cu->p = cu->text;
    cu->src = t[0].s;
    return 0;
}

/* How deg applies to command c's numbers (after its vector: after). */
static expr_unit unit_of(const command *c, bool after)
{
    if (c->range & R_DEGREES) return EXPR_DEGREES;
    if ((c->range & R_RADIANS) && (after || c->arg != VAL_VECTOR_ANGLE)) return EXPR_RADIANS;
    return EXPR_PLAIN;
}

/* One number (an expression) at the cursor. */
static int get_number(cursor *cu, const command *c, expr_unit unit, double *out, const where *at)
{
    char msg[400];
    expr_opts o = {c->name, unit};
    const char *p = cu->p;
    if (expr_read(&p, &o, out, msg, sizeof msg) != 0) {
        perr_at(at, src_of(cu, p), "%s", msg);
        return -1;
    }
    cu->p = p;
    return 0;
}

/* '(' n numbers ')' at the cursor. */
static int get_tuple(cursor *cu, int n, const command *c, double *out, const where *at)
{
    static const char *forms[] = {"", "(x)", "(x, y)", "(x, y, z)", "(w, x, y, z)"};
    const char *form = forms[n];
    char buf[96];
    const char *p = expr_skip(cu->p);
    if (*p != '(') {
        perr_at(at, src_of(cu, p), "%s: expected %s, got %s", c->name, form,
                expr_token_text(p, buf));
        return -1;
    }
    cu->p = p + 1;
    for (int k = 0; k < n; k++) {
        if (!*expr_skip(cu->p)) {
            perr_at(at, src_of(cu, expr_skip(cu->p)), "%s: unfinished vector: expected %s",
                    c->name, form);
            return -1;
        }
        if (get_number(cu, c, unit_of(c, false), &out[k], at) != 0) return -1;
        p = expr_skip(cu->p);
        char want = k == n - 1 ? ')' : ',';
        if (*p != want) {
            if (!*p)
                perr_at(at, src_of(cu, p), "%s: unfinished vector: expected %s", c->name, form);
            else
                perr_at(at, src_of(cu, p), "%s: expected %s with %d numbers, got %s", c->name,
                        form, n, expr_token_text(p, buf));
            return -1;
        }
        cu->p = p + 1;
    }
    return 0;
}

static const char *num_text(double x, char buf[32]) { return fmt_num(buf, x); }

/* Whether x lies within lo and hi as the range flags say. */
static bool in_range(unsigned range, double lo, double hi, double x)
{
    if ((range & R_ZERO) && x == 0) return true;
    if (range & R_ABS) x = fabs(x);
    bool lo_ok = (range & R_LO_OPEN) ? x > lo : x >= lo;
    bool hi_ok = (range & R_HI_OPEN) ? x < hi : x <= hi;
    return lo_ok && hi_ok;
}

/* "between LO and HI" as the flags say, for a message. */
#define RANGE_TEXT 200
static const char *range_text(unsigned range, double lo, double hi, char buf[RANGE_TEXT])
{
    size_t len = RANGE_TEXT;
    char a[32], b[32];
    const char *excl = (range & (R_LO_OPEN | R_HI_OPEN)) ? ", limits excluded" : "";
    num_text(lo, a);
    num_text(hi, b);
    if (range & R_ABS) /* the negative side, larger magnitude first */
        snprintf(buf, len, "between %s and %s or between -%s and -%s%s", a, b, b, a, excl);
    else
        snprintf(buf, len, "%sbetween %s and %s%s", (range & R_ZERO) ? "0 or " : "", a, b, excl);
    return buf;
}

/* The range checks of the table entry on one number; what names it in the
 * message ("radius", "size components", "rotate: the angle"). */
static int check_range_of(const char *what, unsigned range, double lo, double hi, double x,
                          const where *at)
{
    char g[32], r[RANGE_TEXT];
    if ((range & R_NONZERO) && x == 0) {
        perr(at, "%s must not be 0", what);
        return -1;
    }
    if (!(range & R_RANGE) || in_range(range, lo, hi, x)) return 0;
    perr(at, "%s must be %s (got %s)", what, range_text(range, lo, hi, r),
         num_text(x, g));
    return -1;
}

static int check_range(const command *c, double x, const where *at)
{
    return check_range_of(c->name, c->range, c->lo, c->hi, x, at);
}

/* The checks of a vector's components, and of a direction's length. */
static int check_vector(const command *c, const double *v, const where *at)
{
    char what[96];
    snprintf(what, sizeof what, "%s components", c->name);
    for (int k = 0; k < 3; k++)
        if (check_range_of(what, c->range & ~(unsigned)R_NONZERO, c->lo, c->hi, v[k], at) != 0)
            return -1;
    if (!(c->range & R_NONZERO_VEC)) return 0;
    bool zero = v[0] == 0 && v[1] == 0 && v[2] == 0;
    if (zero && c->arg == VAL_VECTOR_ANGLE) return 0; /* with a 0 after it: checked later */
    if (zero) {
        perr(at, "%s must not be (0, 0, 0)", c->name);
        return -1;
    }
    /* scaled, so that no square underflows or overflows */
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    double len = m * sqrt((v[0] / m) * (v[0] / m) + (v[1] / m) * (v[1] / m) +
                          (v[2] / m) * (v[2] / m));
    if (len < LIM_DIR_MIN) {
        char a[32], b[32], d[32], e[32];
        perr(at, "%s: the direction (%s, %s, %s) is too short: it must be at least %s long",
             c->name, num_text(v[0], a), num_text(v[1], b), num_text(v[2], d),
             num_text(LIM_DIR_MIN, e));
        return -1;
    }
    return 0;
}

static int check_integer(const command *c, double x, const where *at)
{
    char g[32];
    if (x != floor(x) || fabs(x) > 1e15) {
        perr(at, "%s must be a whole number (got %s)", c->name, num_text(x, g));
        return -1;
    }
    return 0;
}

static int get_word(const token *t, int nt, int i, const command *c, const char *what, char **out,
                    const where *at)
{
    char buf[96];
    if (i >= nt) {
        perr(at, "%s: missing %s", c->name, what);
        return -1;
    }
    if (t[i].k != T_WORD && t[i].k != T_STRING) {
        perr(at, "%s: expected %s, got %s", c->name, what, tok_text(&t[i], buf));
        return -1;
    }
    *out = tok_dup(&t[i]);
    if (!*out) {
        perr(at, "out of memory");
        return -1;
    }
    return 0;
}

static int get_name(const token *t, int nt, int i, const command *c, char **out, const where *at)
{
    char buf[96];
    if (i < nt && t[i].k == T_STRING) {
        perr(at, "%s: an object name is not quoted (got %s)", c->name, tok_text(&t[i], buf));
        return -1;
    }
    if (get_word(t, nt, i, c, "an object name", out, at) != 0) return -1;
    if (!lang_valid_name(*out)) {
        perr(at,
             "%s is not a valid object name (letters, digits, _ and -, starting with a letter or "
             "_, at most %d characters)",
             tok_text(&t[i], buf), BODY_NAME_MAX - 1);
        free(*out);
        *out = NULL;
        return -1;
    }
    return 0;
}

/* Whether the value at p is a vector: it opens with '(' whose group holds a comma
 * of its own (so that "(1 + 1) * 2" is a number). */
static bool scale_is_vector(const char *p)
{
    p = expr_skip(p);
    if (*p != '(') return false;
    int depth = 0;
    for (; *p; p++) {
        if (*p == '(') depth++;
        else if (*p == ')' && --depth == 0) return false;
        else if (*p == ',' && depth == 1) return true;
    }
    return false;
}

/* The numbers of st's value at the cursor, with their checks. */
static int read_numbers(stmt *st, cursor *cu, const where *at)
{
    const command *c = st->cmd;
    switch (c->arg) {
    case ARG_COUNT:
    case VAL_NUMBER:
    case VAL_INTEGER:
        if (get_number(cu, c, unit_of(c, false), &st->num[0], at) != 0) return -1;
        if (c->arg != VAL_NUMBER && check_integer(c, st->num[0], at) != 0) return -1;
        if (check_range(c, st->num[0], at) != 0) return -1;
        st->n = 1;
        return 0;
    case VAL_VECTOR:
    case VAL_VECTOR_ANGLE:
        if (get_tuple(cu, 3, c, st->num, at) != 0) return -1;
        if (check_vector(c, st->num, at) != 0) return -1;
        st->n = 3;
        if (c->arg == VAL_VECTOR_ANGLE) {
            const char *p = expr_skip(cu->p);
            if (!*p) {
                perr(at, "%s: missing the number after the vector", c->name);
                return -1;
            }
            if (get_number(cu, c, unit_of(c, true), &st->num[3], at) != 0) return -1;
            char what[96];
            snprintf(what, sizeof what, "%s: the %s", c->name, c->what2);
            if (check_range_of(what, R_RANGE, c->lo2, c->hi2, st->num[3], at) != 0)
                return -1;
            st->n = 4;
            if ((c->range & R_NONZERO_VEC) && st->num[0] == 0 && st->num[1] == 0 &&
                st->num[2] == 0 && st->num[3] != 0) {
                perr(at, "%s: the direction (0, 0, 0) needs the %s to be 0", c->name, c->what2);
                return -1;
            }
        }
        return 0;
    case VAL_QUAT:
    case VAL_PAIR:
    case VAL_RANGE2: {
        int n = c->arg == VAL_QUAT ? 4 : 2;
        if (get_tuple(cu, n, c, st->num, at) != 0) return -1;
        char what[96];
        snprintf(what, sizeof what, "%s components", c->name);
        /* (a quaternion's length is its check: a unit one the simulation made may
         * have a component a rounding above 1) */
        for (int k = 0; k < n && c->arg != VAL_QUAT; k++)
            if (check_range_of(what, c->range, c->lo, c->hi, st->num[k], at) != 0) return -1;
        if (c->arg == VAL_QUAT) {
            double n2 = 0;
            for (int k = 0; k < 4; k++) n2 += st->num[k] * st->num[k];
            if (!(fabs(sqrt(n2) - 1) <= 1e-6)) {
                perr(at, "%s must be a unit quaternion (w, x, y, z), within 1e-6 of length 1",
                     c->name);
                return -1;
            }
        }
        if (c->arg == VAL_RANGE2 && !(st->num[0] <= st->num[1])) {
            char a[32], b[32];
            perr(at, "%s: the least must not exceed the most (got %s, %s)", c->name,
                 num_text(st->num[0], a), num_text(st->num[1], b));
            return -1;
        }
        st->n = n;
        return 0;
    }
    case VAL_SIZE2: {
        if (get_tuple(cu, 2, c, st->num, at) != 0) return -1;
        char what[96];
        snprintf(what, sizeof what, "%s components", c->name);
        for (int k = 0; k < 2; k++)
            if (check_integer(c, st->num[k], at) != 0 ||
                check_range_of(what, c->range, c->lo, c->hi, st->num[k], at) != 0)
                return -1;
        st->n = 2;
        return 0;
    }
    case VAL_COLOR:
        if (get_tuple(cu, 3, c, st->num, at) != 0) return -1;
        for (int k = 0; k < 3; k++) {
            if (st->num[k] != floor(st->num[k]) || !in_range(c->range, c->lo, c->hi, st->num[k])) {
                char g[32], r[RANGE_TEXT];
                perr(at, "%s components must be whole numbers %s (got %s)", c->name,
                     range_text(c->range, c->lo, c->hi, r), num_text(st->num[k], g));
                return -1;
            }
        }
        st->n = 3;
        return 0;
    case VAL_SCALE:
        /* s, or (x, y, z): a parenthesis holding a comma is the vector */
        if (scale_is_vector(cu->p)) {
            if (get_tuple(cu, 3, c, st->num, at) != 0) return -1;
            if (check_vector(c, st->num, at) != 0) return -1;
            st->n = 3;
            return 0;
        }
        if (get_number(cu, c, unit_of(c, false), &st->num[0], at) != 0) return -1;
        if (check_range(c, st->num[0], at) != 0) return -1;
        st->num[1] = st->num[2] = st->num[0];
        st->n = 1;
        return 0;
    default: return -1; /* never: parse_value calls this for numeric kinds only */
    }
}

/* The numbers of st's value (its command's arg is a numeric kind), read from the
 * text of the tokens t[0..nt-1], nt > 0, and checked. */
static int parse_numbers(stmt *st, const token *t, int nt, const where *at)
{
    const command *c = st->cmd;
    cursor cu;
    if (cursor_open(&cu, t, nt, c, at) != 0) return -1;
    int rc = read_numbers(st, &cu, at);
    if (rc == 0) {
        const char *p = expr_skip(cu.p);
        if (*p) {
            char buf[96];
            perr_at(at, src_of(&cu, p), "%s: unexpected %s after the value", c->name,
                    expr_token_text(p, buf));
            rc = -1;
        }
    }
    free(cu.text);
    return rc;
}

/* An object property's name: the command c names (NULL and a message, with the
 * nearest name, when it is none). */
static const command *find_property(const char *name, const where *at)
{
    const command *c = command_find(name);
    if (c && c->form == FORM_PROPERTY) return c;
    suggestion sg;
    char hint[96];
    suggest_init(&sg, name);
    suggest_offer_commands(&sg, 1u << FORM_PROPERTY);
    perr(at, "'%s' is not an object property%s (help lists them all)", name,
         suggest_text(&sg, hint, sizeof hint));
    return NULL;
}

/* NAME or NAME.property at t[i]: the name into st->word, the property's into
 * st->word2. */
static int get_name_dot(const token *t, int nt, int i, const command *c, stmt *st, const where *at)
{
    char *dot = i < nt && t[i].k == T_WORD ? memchr(t[i].s, '.', t[i].len) : NULL;
    if (!dot) return get_name(t, nt, i, c, &st->word, at);
    token name = t[i], prop = t[i];
    name.len = (size_t)(dot - t[i].s);
    prop.s = dot + 1;
    prop.len = t[i].len - name.len - 1;
    if (get_name(&name, 1, 0, c, &st->word, at) != 0) return -1;
    if (!(st->word2 = tok_dup(&prop))) {
        perr(at, "out of memory");
        return -1;
    }
    return find_property(st->word2, at) ? 0 : -1;
}

/* plot's QUANTITY = FILE (t[0..2]): the quantity into st->num[0] (PLOT_ENERGY,
 * PLOT_MOMENTUM, PLOT_HEIGHT with the object's name in st->object), the file into
 * st->word. */
static int get_plot(const token *t, int nt, const command *c, stmt *st, const where *at)
{
    char buf[96];
    if (nt < 1) {
        perr(at, "%s: missing the quantity: energy, momentum or NAME.height", c->name);
        return -1;
    }
    char q[BODY_NAME_MAX + 16];
    snprintf(q, sizeof q, "%.*s", (int)(t[0].len < sizeof q - 1 ? t[0].len : sizeof q - 1), t[0].s);
    char *dot = strchr(q, '.');
    bool word = t[0].k == T_WORD && t[0].len < sizeof q - 1;
    if (word && strcmp(q, "energy") == 0) {
        st->num[0] = PLOT_ENERGY;
    } else if (word && strcmp(q, "momentum") == 0) {
        st->num[0] = PLOT_MOMENTUM;
    } else if (word && dot && strcmp(dot + 1, "height") == 0) {
        *dot = '\0';
        if (!lang_valid_name(q)) {
            perr(at, "'%s' is not a valid object name", q);
            return -1;
        }
        if (!(st->object = strdup(q))) {
            perr(at, "out of memory");
            return -1;
        }
        st->num[0] = PLOT_HEIGHT;
    } else {
        suggestion sg;
        char hint[96];
        suggest_init(&sg, q);
        suggest_offer_choices(&sg, "energy|momentum");
        perr(at, "%s: the quantity is energy, momentum or NAME.height (got %s)%s", c->name,
             tok_text(&t[0], buf), suggest_text(&sg, hint, sizeof hint));
        return -1;
    }
    st->n = 1;
    if (nt < 2 || t[1].k != T_EQ) {
        perr(at, "%s: expected '= FILE.png' after the quantity%s%s", c->name, nt < 2 ? "" : ", got ",
             nt < 2 ? "" : tok_text(&t[1], buf));
        return -1;
    }
    if (get_word(t, nt, 2, c, "a file name", &st->word, at) != 0) return -1;
    size_t n = strlen(st->word);
    if (n < 5 || strcmp(st->word + n - 4, ".png") != 0) {
        perr(at, "%s: the file must be a .png (got %s)", c->name, tok_text(&t[2], buf));
        return -1;
    }
    return 0;
}

/* Converts the tokens after the command word (actions) or after '=' into st. */
static int parse_value(stmt *st, const token *t, int nt, const where *at)
{
    const command *c = st->cmd;
    char buf[96];
    int i = 0;
    switch (c->arg) {
    case ARG_NONE: break;
    case ARG_NAME:
        /* (grip: a quoted word is an object's name, whatever word it is) */
        if (c->choices && i < nt && t[i].k == T_STRING) {
            if (get_word(t, nt, i, c, "an object name", &st->word, at) != 0) return -1;
            if (!lang_valid_name(st->word)) {
                perr(at, "%s is not a valid object name", tok_text(&t[i], buf));
                return -1;
            }
            st->n = 1;
        } else if (get_name(t, nt, i, c, &st->word, at) != 0) {
            return -1;
        }
        i++;
        break;
    case ARG_NAME2:
        if (get_name(t, nt, i, c, &st->word, at) != 0) return -1;
        i++;
        if (get_name(t, nt, i, c, &st->word2, at) != 0) return -1;
        i++;
        break;
    case ARG_OPT_WORD:
    case ARG_SETTING:
        if (i < nt) {
            if (get_word(t, nt, i, c, c->arg == ARG_SETTING ? "a setting's name" : "a command name",
                         &st->word, at) != 0)
                return -1;
            i++;
        }
        break;
    case ARG_OPT_NAME:
        if (i < nt) {
            if (get_name(t, nt, i, c, &st->word, at) != 0) return -1;
            i++;
        }
        break;
    case ARG_PLOT:
        if (get_plot(t, nt, c, st, at) != 0) return -1;
        i = 3;
        break;
    case ARG_NAME_DOT:
        if (get_name_dot(t, nt, i, c, st, at) != 0) return -1;
        i++;
        break;
    case ARG_FILE:
    case VAL_FILE:
        if (get_word(t, nt, i, c, "a file name", &st->word, at) != 0) return -1;
        if (st->word[0] == '\0') {
            perr(at, "%s: the file name is empty", c->name);
            return -1;
        }
        i++;
        break;
    case VAL_FILE_OR_OFF:
        if (get_word(t, nt, i, c, "a file name or off", &st->word, at) != 0) return -1;
        if (st->word[0] == '\0') {
            perr(at, "%s: the file name is empty", c->name);
            return -1;
        }
        st->n = tok_is(&t[i], "off"); /* 1: off; a quoted "off" is a file */
        i++;
        break;
    case ARG_COUNT:
        if (i >= nt) {
            perr(at, "%s: missing count", c->name);
            return -1;
        }
        /* fall through */
    case VAL_NUMBER:
    case VAL_INTEGER:
    case VAL_VECTOR:
    case VAL_VECTOR_ANGLE:
    case VAL_QUAT:
    case VAL_PAIR:
    case VAL_RANGE2:
    case VAL_SIZE2:
    case VAL_COLOR:
    case VAL_SCALE:
        if (i >= nt) {
            perr(at, "%s: missing value", c->name);
            return -1;
        }
        return parse_numbers(st, t, nt, at);
    case VAL_NAME:
        if (get_name(t, nt, i, c, &st->word, at) != 0) return -1;
        i++;
        break;
    case ARG_OPT_ONOFF:
        if (i >= nt) break;
        /* fall through */
    case VAL_ONOFF:
        if (i >= nt) {
            perr(at, "%s: missing value: on or off", c->name);
            return -1;
        }
        if (!tok_is(&t[i], "on") && !tok_is(&t[i], "off")) {
            perr(at, "%s must be on or off (got %s)", c->name, tok_text(&t[i], buf));
            return -1;
        }
        st->n = 1;
        st->num[0] = tok_is(&t[i], "on");
        i++;
        break;
    case VAL_CHOICE: {
        if (i >= nt) {
            perr(at, "%s: missing value: one of %s", c->name, c->choices);
            return -1;
        }
        int k = 0;
        bool found = false;
        for (const char *p = c->choices; *p; k++) {
            size_t n = strcspn(p, "|");
            if (t[i].k == T_WORD && t[i].len == n && memcmp(t[i].s, p, n) == 0) {
                found = true;
                break;
            }
            p += n;
            if (*p) p++;
        }
        if (!found) {
            perr(at, "%s must be one of %s (got %s)", c->name, c->choices, tok_text(&t[i], buf));
            return -1;
        }
        st->n = 1;
        st->num[0] = k;
        i++;
        break;
    }
    }
    if (i < nt) {
        perr(at, "%s: unexpected %s after the %s", c->name, tok_text(&t[i], buf),
             c->arg == ARG_NONE ? "command (it takes no arguments)" : "value");
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- statements */

static void stmt_clear(stmt *st)
{
    free(st->object);
    free(st->word);
    free(st->word2);
    program_free(st->sub);
    memset(st, 0, sizeof *st);
}

/* Parses one statement (tokens t[0..nt-1], nt > 0) into st. */
static int parse_stmt(stmt *st, const token *t, int nt, const where *at)
{
    char buf[96];
    memset(st, 0, sizeof *st);
    st->line = at->line;
    if (t[0].k != T_WORD) {
        perr(at, "expected a command, got %s", tok_text(&t[0], buf));
        return -1;
    }
    char head[128];
    if (t[0].len >= sizeof head) {
        perr(at, "unknown command %s", tok_text(&t[0], buf));
        return -1;
    }
    memcpy(head, t[0].s, t[0].len);
    head[t[0].len] = '\0';
    char *dot = strchr(head, '.');
    const command *c;
    if (dot && !(head[0] >= '0' && head[0] <= '9') && head[0] != '.' && head[0] != '-') {
        *dot = '\0';
        if (!lang_valid_name(head)) {
            perr(at, "'%s' is not a valid object name", head);
            return -1;
        }
        c = find_property(dot + 1, at);
        if (!c) return -1;
        st->object = strdup(head);
        if (!st->object) {
            perr(at, "out of memory");
            return -1;
        }
    } else {
        c = command_find(head);
        if (!c) {
            suggestion sg;
            char hint[96];
            suggest_init(&sg, head);
            suggest_offer_commands(&sg, ~0u);
            perr(at, "unknown command %s%s (help lists them all)", tok_text(&t[0], buf),
                 suggest_text(&sg, hint, sizeof hint));
            return -1;
        }
    }
    st->cmd = c;
    bool has_eq = nt > 1 && t[1].k == T_EQ;
    if (c->form == FORM_ACTION) {
        if (has_eq) {
            perr(at, "%s is a command, not a setting: it takes no '='", c->name);
            return -1;
        }
        return parse_value(st, t + 1, nt - 1, at);
    }
    if (!has_eq) {
        if (nt == 1)
            perr(at, "%s: missing '= value'", c->name);
        else
            perr(at, "%s: expected '=', got %s", c->name, tok_text(&t[1], buf));
        return -1;
    }
    if (nt == 2) {
        perr(at, "%s: missing value after '='", c->name);
        return -1;
    }
    return parse_value(st, t + 2, nt - 2, at);
}

static int prog_push(program *p, const stmt *st)
{
    if (p->n == INT_MAX) return -1;
    stmt *ns = grow_for_one(p->s, p->n, &p->cap, sizeof *ns, 16);
    if (!ns) return -1;
    p->s = ns;
    p->s[p->n++] = *st;
    return 0;
}

void program_free(program *p)
{
    if (!p) return;
    for (int i = 0; i < p->n; i++) stmt_clear(&p->s[i]);
    free(p->s);
    free(p->path);
    free(p->real);
    free(p);
}

/* After a read statement is parsed: load and parse its file. */
static int load_sub(stmt *st, const lang_paths *paths, int depth, const char **stack, int n_stack,
                    const where *at)
{
    st->sub = lang_parse_file(st->word, paths, depth + 1, stack, n_stack, at->name, at->line,
                              at->err, at->errlen);
    return st->sub ? 0 : -1;
}

/* Whether s is a SHA-256 written out: 64 hexadecimal digits. */
static bool is_sha256(const char *s)
{
    size_t n = strlen(s);
    return n == 64 && strspn(s, "0123456789abcdefABCDEF") == 64;
}

/* True when statement st names a file it reads: a tracker file, a polyhedron's
 * file, or a sound file (not off or a built-in sound). */
static bool names_file(const stmt *st)
{
    const char *n = st->cmd->name;
    if (strcmp(n, "tracker") == 0) return st->n == 0;
    if (strcmp(n, "file") == 0) return true;
    return strcmp(n, "collision_sound") == 0 && strcmp(st->word, "off") != 0 && synth_find(st->word) < 0;
}

/* A file the statement reads (a tracker file, a polyhedron's file, a sound file) is found as read finds its file:
 * st->word becomes the path found, or stays as written when there is none (its
 * handler then says so).  Returns 0, or -1 when out of memory. */
static int resolve_word(stmt *st, const lang_paths *paths)
{
    char full[PATH_MAX];
    if (lang_resolve(st->word, paths, full, sizeof full) != 0 || strcmp(full, st->word) == 0) return 0;
    char *found = strdup(full);
    if (!found) return -1;
    free(st->word);
    st->word = found;
    return 0;
}

/* paths, with a budget of its own when the parse starts here (in *mine). */
static lang_paths with_budget(const lang_paths *paths, lang_budget *mine)
{
    lang_paths p = paths ? *paths : (lang_paths){NULL, NULL, NULL};
    if (!p.budget) {
        *mine = (lang_budget){0, 0, 0};
        p.budget = mine;
    }
    return p;
}

program *lang_parse(const char *text, size_t len, const char *name, int first_line,
                    const lang_paths *paths_in, int depth, const char **stack, int n_stack, char *err, size_t errlen)
{
    toklist tl = {0};
    lang_budget mine;
    lang_paths all = with_budget(paths_in, &mine), *paths = &all;
    program *prog = calloc(1, sizeof *prog);
    if (!prog) {
        snprintf(err, errlen, "error: out of memory");
        return NULL;
    }
    if (name && !(prog->path = strdup(name))) goto oom;
    where at = {prog->path, first_line - 1, err, errlen, NULL, NULL};
    infile_lines lines;
    infile_line ln;
    int got;
    char why[128];
    infile_lines_init(&lines, text, len, LANG_MAX_LINE);
    while ((got = infile_next_line(&lines, &ln, why, sizeof why)) != 0) {
        at.line = first_line - 1 + (int)ln.number;
        at.text = ln.s;
        at.text_end = ln.s + ln.len;
        if (got < 0) {
            perr(&at, "%s", why);
            goto fail;
        }
        const char *p = ln.s, *e = ln.s + ln.len;
        char msg[256];
        if (lex_line(p, e, &tl, msg, sizeof msg) != 0) {
            perr(&at, "%s", msg);
            goto fail;
        }
        int a = 0;
        while (a < tl.n) {
            int b = a;
            while (b < tl.n && !lex_is_sep(&tl.t[b])) b++;
            if (b > a) {
                stmt st;
                if (parse_stmt(&st, tl.t + a, b - a, &at) != 0) {
                    stmt_clear(&st);
                    goto fail;
                }
                st.file = prog->path;
                if (names_file(&st) && resolve_word(&st, paths) != 0) {
                    stmt_clear(&st);
                    goto oom;
                }
                if (strcmp(st.cmd->name, "sha256") == 0 && !is_sha256(st.word)) {
                    perr(&at, "sha256 must be 64 hexadecimal digits (got \"%.70s\")", st.word);
                    stmt_clear(&st);
                    goto fail;
                }
                if (strcmp(st.cmd->name, "read") == 0 &&
                    load_sub(&st, paths, depth, stack, n_stack, &at) != 0) {
                    stmt_clear(&st);
                    goto fail;
                }
                if (++paths->budget->statements > LANG_MAX_STATEMENTS) {
                    stmt_clear(&st);
                    perr(&at, "more than %ld statements in all, with the files read (a file "
                         "that reads others many times over?)", LANG_MAX_STATEMENTS);
                    goto fail;
                }
                if (prog_push(prog, &st) != 0) {
                    stmt_clear(&st);
                    goto oom;
                }
            }
            a = b + 1;
        }
    }
    free(tl.t);
    return prog;
oom:
    snprintf(err, errlen, "error: out of memory");
fail:
    free(tl.t);
    program_free(prog);
    return NULL;
}

static void dir_of(const char *path, char *out, size_t outlen)
{
    snprintf(out, outlen, "%s", path);
    char *slash = strrchr(out, '/');
    if (!slash)
        snprintf(out, outlen, ".");
    else if (slash == out)
        out[1] = '\0';
    else
        *slash = '\0';
}

static bool file_exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

int lang_resolve(const char *name, const lang_paths *paths, char *out, size_t outlen)
{
    if (name[0] == '/') {
        snprintf(out, outlen, "%s", name);
        return file_exists(out) ? 0 : -1;
    }
    if (paths && paths->base_dir && strcmp(paths->base_dir, ".") != 0)
        snprintf(out, outlen, "%s/%s", paths->base_dir, name);
    else
        snprintf(out, outlen, "%s", name);
    if (file_exists(out)) return 0;
    if (paths && paths->scene_dir) {
        char alt[PATH_MAX];
        snprintf(alt, sizeof alt, "%s/%s", paths->scene_dir, name);
        if (file_exists(alt)) {
            snprintf(out, outlen, "%s", alt);
            return 0;
        }
    }
    return -1;
}

program *lang_parse_file(const char *path, const lang_paths *paths_in, int depth,
                         const char **stack, int n_stack, const char *from_file, int from_line,
                         char *err, size_t errlen)
{
    lang_budget mine;
    lang_paths all = with_budget(paths_in, &mine), *paths = &all;
    char where_[PATH_MAX + 32] = "error";
    if (from_file) snprintf(where_, sizeof where_, "%s:%d: error", from_file, from_line);
    if (depth > LANG_MAX_DEPTH) {
        snprintf(err, errlen, "%s: files read each other deeper than %d levels (at '%s')", where_,
                 LANG_MAX_DEPTH, path);
        return NULL;
    }
    char full[PATH_MAX];
    if (lang_resolve(path, paths, full, sizeof full) != 0) {
        snprintf(err, errlen, "%s: cannot read '%s': %s", where_, path, strerror(ENOENT));
        return NULL;
    }
    char real[PATH_MAX];
    if (!realpath(full, real)) snprintf(real, sizeof real, "%s", full);
    for (int i = 0; i < n_stack; i++) {
        if (strcmp(stack[i], real) == 0) {
            snprintf(err, errlen, "%s: '%s' reads itself (directly or through other files)",
                     where_, path);
            return NULL;
        }
    }
    if (++paths->budget->reads > LANG_MAX_READS) {
        snprintf(err, errlen, "%s: cannot read '%s': more than %ld files read in all (files that "
                 "read others many times over?)", where_, path, LANG_MAX_READS);
        return NULL;
    }
    infile text;
    char why[256];
    if (infile_read(&text, full, LANG_MAX_FILE, why, sizeof why) != 0) {
        snprintf(err, errlen, "%s: cannot read '%s': %s", where_, path, why);
        return NULL;
    }
    paths->budget->bytes += (long)text.len;
    if (paths->budget->bytes > LANG_MAX_TOTAL) {
        snprintf(err, errlen, "%s: cannot read '%s': the files read add up to more than %ld "
                 "bytes (files that read others many times over?)", where_, path, LANG_MAX_TOTAL);
        infile_free(&text);
        return NULL;
    }
    char dir[PATH_MAX];
    dir_of(full, dir, sizeof dir);
    lang_paths sub = {dir, paths->scene_dir, paths->budget};
    const char **st2 = malloc((size_t)(n_stack + 1) * sizeof *st2);
    if (!st2) {
        infile_free(&text);
        snprintf(err, errlen, "error: out of memory");
        return NULL;
    }
    for (int i = 0; i < n_stack; i++) st2[i] = stack[i];
    st2[n_stack] = real;
    program *p = lang_parse(text.data, text.len, full, 1, &sub, depth, st2, n_stack + 1, err, errlen);
    free(st2);
    infile_free(&text);
    if (p && !(p->real = strdup(real))) {
        program_free(p);
        snprintf(err, errlen, "error: out of memory");
        return NULL;
    }
    return p;
}

bool lang_valid_name(const char *s)
{
    size_t n = strlen(s);
    if (n == 0 || n >= BODY_NAME_MAX) return false;
    if (!((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z') || s[0] == '_'))
        return false;
    for (size_t i = 1; i < n; i++) {
        char c = s[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-'))
            return false;
    }
    return true;
}
