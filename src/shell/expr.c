/* expr.c: numbers written as arithmetic, read by recursive descent and evaluated
 * as they are read (expr.h). */
#include "expr.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "lex.h"
#include "suggest.h"

typedef struct {
    const char *p;       /* the next character */
    const char *err_at;  /* where the error is */
    const expr_opts *o;
    char *msg;
    size_t msglen;
    int depth;
} reader;

static int fail(reader *r, const char *at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail(reader *r, const char *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->msg, r->msglen, fmt, ap);
    va_end(ap);
    r->err_at = at;
    return -1;
}

const char *expr_skip(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' || *p == '\v') p++;
    return p;
}

static bool name_start(char c) { return isalpha((unsigned char)c) || c == '_'; }
static bool name_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

static size_t name_len(const char *p)
{
    size_t n = 0;
    if (!name_start(p[0])) return 0;
    while (name_char(p[n])) n++;
    return n;
}

static bool name_is(const char *p, size_t n, const char *word)
{
    return strlen(word) == n && memcmp(p, word, n) == 0;
}

/* A word for a message: the run of characters a lexer word would hold, without
 * the operators, so that 'x' in "(1, x, 3)" and 'abc.d' are quoted whole. */
static size_t word_len(const char *p)
{
    size_t n = 0;
    while (p[n] && !strchr(" \t\r\f\v(),=;#\"+-*/^", p[n])) n++;
    return n;
}

const char *expr_token_text(const char *p, char buf[96])
{
    if (!*p) return "the end";
    size_t n = 0;
    if (isdigit((unsigned char)*p) || *p == '.') {
        char *end;
        (void)strtod(p, &end);
        n = (size_t)(end - p);
    }
    if (n == 0) n = word_len(p);
    if (n == 0) n = 1;
    token t = {T_WORD, p, n};
    return tok_text(&t, buf);
}

typedef double (*fn1)(double);
static double absolute(double x) { return fabs(x); }

static const struct {
    const char *name;
    int args;  /* 1, 2, or -2: two or more */
    fn1 f;     /* of one argument */
} functions[] = {
    {"sqrt", 1, sqrt}, {"sin", 1, sin},   {"cos", 1, cos},        {"tan", 1, tan},
    {"asin", 1, asin}, {"acos", 1, acos}, {"atan2", 2, NULL},     {"exp", 1, exp},
    {"log", 1, log},   {"abs", 1, absolute}, {"min", -2, NULL},   {"max", -2, NULL},
};
#define NFUNCTIONS (int)(sizeof functions / sizeof functions[0])

static int read_sum(reader *r, double *out);
static int read_unary(reader *r, double *out);

/* The result of the operation at `at` must be finite. */
static int finite_or_fail(reader *r, const char *at, double x, const char *what)
{
    if (isfinite(x)) return 0;
    return fail(r, at, "%s: %s is not a finite number", r->o->what, what);
}

/* A function's arguments, after its '(' (at open), up to its ')'. */
static int read_args(reader *r, const char *open, double *args, int max, int *n)
{
    *n = 0;
    for (;;) {
        double x;
        if (read_sum(r, &x) != 0) return -1;
        if (*n < max) args[*n] = x;
        (*n)++;
        r->p = expr_skip(r->p);
        if (*r->p == ',') {
            r->p++;
            continue;
        }
        if (*r->p == ')') {
            r->p++;
            return 0;
        }
        if (!*r->p) return fail(r, open, "%s: this '(' is not closed", r->o->what);
        char buf[96];
        return fail(r, r->p, "%s: expected ',' or ')' in the function's arguments, got %s",
                    r->o->what, expr_token_text(r->p, buf));
    }
}

/* A function call: name at `at`, k its index in functions. */
static int call(reader *r, int k, const char *at, double *out)
{
    const char *name = functions[k].name;
    r->p = expr_skip(r->p);
    if (*r->p != '(')
        return fail(r, at, "%s: %s is a function: write %s(x)", r->o->what, name, name);
    const char *open = r->p++;
    double a[16];
    int n;
    if (read_args(r, open, a, 16, &n) != 0) return -1;
    int want = functions[k].args;
    if ((want > 0 && n != want) || (want < 0 && n < -want)) {
        if (want > 0)
            return fail(r, at, "%s: %s takes %d number%s (got %d)", r->o->what, name, want,
                        want == 1 ? "" : "s", n);
        return fail(r, at, "%s: %s takes %d numbers or more (got %d)", r->o->what, name, -want, n);
    }
    if (n > 16) return fail(r, at, "%s: %s takes at most 16 numbers (got %d)", r->o->what, name, n);
    double x = a[0];
    if (strcmp(name, "sqrt") == 0 && x < 0)
        return fail(r, at, "%s: sqrt of a negative number (%.6g)", r->o->what, x);
    if (strcmp(name, "log") == 0 && !(x > 0))
        return fail(r, at, "%s: log of a number that is not > 0 (%.6g)", r->o->what, x);
    if ((strcmp(name, "asin") == 0 || strcmp(name, "acos") == 0) && !(fabs(x) <= 1))
        return fail(r, at, "%s: %s of a number outside -1 to 1 (%.6g)", r->o->what, name, x);
    if (want == 1) {
        x = functions[k].f(x);
    } else if (want == 2) {
        x = atan2(a[0], a[1]);
    } else {
        bool is_min = strcmp(name, "min") == 0;
        for (int i = 1; i < n; i++) x = is_min ? fmin(x, a[i]) : fmax(x, a[i]);
    }
    char what[32];
    snprintf(what, sizeof what, "%s(...)", name);
    if (finite_or_fail(r, at, x, what) != 0) return -1;
    *out = x;
    return 0;
}

static int read_primary(reader *r, double *out)
{
    r->p = expr_skip(r->p);
    const char *at = r->p;
    char buf[96];
    if (isdigit((unsigned char)*at) || (*at == '.' && isdigit((unsigned char)at[1]))) {
        char *end;
        double x = strtod(at, &end);
        r->p = end;
        if (!isfinite(x)) {
            size_t n = (size_t)(end - at);
            return fail(r, at, "%s must be a finite number (got %s)", r->o->what,
                        n <= 40 ? (snprintf(buf, sizeof buf, "%.*s", (int)n, at), buf)
                                : expr_token_text(at, buf));
        }
        *out = x;
        return 0;
    }
    if (*at == '(') {
        r->p++;
        if (read_sum(r, out) != 0) return -1;
        r->p = expr_skip(r->p);
        if (*r->p == ')') {
            r->p++;
            return 0;
        }
        if (!*r->p) return fail(r, at, "%s: this '(' is not closed", r->o->what);
        return fail(r, r->p, "%s: expected ')' to close the '(', got %s", r->o->what,
                    expr_token_text(r->p, buf));
    }
    size_t n = name_len(at);
    if (n == 0) {
        if (!*at) return fail(r, at, "%s: expected a number at the end", r->o->what);
        return fail(r, at, "%s: expected a number, got %s", r->o->what, expr_token_text(at, buf));
    }
    r->p = at + n;
    if (name_is(at, n, "pi")) {
        *out = M_PI;
        return 0;
    }
    if (name_is(at, n, "e")) {
        *out = M_E;
        return 0;
    }
    for (int k = 0; k < NFUNCTIONS; k++)
        if (name_is(at, n, functions[k].name)) return call(r, k, at, out);
    /* not a number, as strtod's words are: said as before expressions */
    if ((n == 3 && (strncasecmp(at, "nan", 3) == 0 || strncasecmp(at, "inf", 3) == 0)) ||
        (n == 8 && strncasecmp(at, "infinity", 8) == 0))
        return fail(r, at, "%s must be a finite number (got %.*s)", r->o->what, (int)n, at);
    if (name_is(at, n, "deg"))
        return fail(r, at, "%s: deg follows the number it converts: write 30 deg", r->o->what);
    char word[64], hint[96];
    snprintf(word, sizeof word, "%.*s", (int)(n < 63 ? n : 63), at);
    suggestion s;
    suggest_init(&s, word);
    suggest_offer(&s, "pi");
    for (int k = 0; k < NFUNCTIONS; k++) suggest_offer(&s, functions[k].name);
    suggest_offer(&s, "deg");
    if (word_len(at) != n) s.best = NULL; /* 'abc.d': not a name typed wrong */
    return fail(r, at, "%s: expected a number, got %s%s", r->o->what, expr_token_text(at, buf),
                suggest_text(&s, hint, sizeof hint));
}

/* primary [deg] */
static int read_postfix(reader *r, double *out)
{
    if (read_primary(r, out) != 0) return -1;
    const char *q = expr_skip(r->p);
    size_t n = name_len(q);
    if (!name_is(q, n, "deg")) return 0;
    switch (r->o->unit) {
    case EXPR_RADIANS: break;
    case EXPR_DEGREES:
        return fail(r, q, "%s is in degrees already: write the number without deg", r->o->what);
    default:
        return fail(r, q, "%s is not an angle: deg (degrees to radians) does not apply",
                    r->o->what);
    }
    r->p = q + n;
    *out *= M_PI / 180;
    return 0;
}

/* postfix [^ unary] */
static int read_power(reader *r, double *out)
{
    if (read_postfix(r, out) != 0) return -1;
    const char *q = expr_skip(r->p);
    if (*q != '^') return 0;
    r->p = q + 1;
    double y;
    if (read_unary(r, &y) != 0) return -1;
    double x = *out;
    if (x < 0 && y != floor(y))
        return fail(r, q, "%s: a negative number to a power that is not whole has no real value",
                    r->o->what);
    if (x == 0 && y < 0) return fail(r, q, "%s: 0 to a negative power is not a number", r->o->what);
    *out = pow(x, y);
    return finite_or_fail(r, q, *out, "the power");
}

static int read_unary(reader *r, double *out)
{
    if (++r->depth > EXPR_MAX_DEPTH)
        return fail(r, r->p, "%s: the expression nests deeper than %d levels", r->o->what,
                    EXPR_MAX_DEPTH);
    const char *q = expr_skip(r->p);
    int rc;
    if (*q == '-' || *q == '+') {
        r->p = q + 1;
        rc = read_unary(r, out);
        if (rc == 0 && *q == '-') *out = -*out;
    } else {
        rc = read_power(r, out);
    }
    r->depth--;
    return rc;
}

static int read_product(reader *r, double *out)
{
    if (read_unary(r, out) != 0) return -1;
    for (;;) {
        const char *q = expr_skip(r->p);
        if (*q != '*' && *q != '/') return 0;
        r->p = q + 1;
        double y;
        if (read_unary(r, &y) != 0) return -1;
        if (*q == '/' && y == 0) return fail(r, q, "%s: division by zero", r->o->what);
        *out = *q == '*' ? *out * y : *out / y;
        if (finite_or_fail(r, q, *out, *q == '*' ? "the product" : "the quotient") != 0)
            return -1;
    }
}

static int read_sum(reader *r, double *out)
{
    if (++r->depth > EXPR_MAX_DEPTH)
        return fail(r, r->p, "%s: the expression nests deeper than %d levels", r->o->what,
                    EXPR_MAX_DEPTH);
    int rc = read_product(r, out);
    while (rc == 0) {
        const char *q = expr_skip(r->p);
        if (*q != '+' && *q != '-') break;
        r->p = q + 1;
        double y;
        rc = read_product(r, &y);
        if (rc == 0) {
            *out = *q == '+' ? *out + y : *out - y;
            rc = finite_or_fail(r, q, *out, *q == '+' ? "the sum" : "the difference");
        }
    }
    r->depth--;
    return rc;
}

int expr_read(const char **p, const expr_opts *o, double *out, char *msg, size_t msglen)
{
    reader r = {*p, NULL, o, msg, msglen, 0};
    if (read_sum(&r, out) != 0) {
        *p = r.err_at ? r.err_at : r.p;
        return -1;
    }
    *p = r.p;
    return 0;
}
