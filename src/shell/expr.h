/* expr.h: numbers written as arithmetic (language.md, "The console beyond the
 * thesis"): `radius = 1/3`, `rotate = (0, 0, 1) pi/2`, `angular_vel = (0, 0, 90 deg)`.
 *
 * An expression is read from text and evaluated as it is read, in doubles:
 *
 *   sum     = product { ("+" | "-") product }
 *   product = unary { ("*" | "/") unary }
 *   unary   = ("-" | "+") unary | power
 *   power   = postfix [ "^" unary ]           (right-associative: 2^3^2 = 2^9)
 *   postfix = primary [ "deg" ]               (deg binds tightest: 2*30 deg = pi/3)
 *   primary = NUMBER | "pi" | "e" | FUNCTION "(" sum { "," sum } ")" | "(" sum ")"
 *
 * So `-2^2` is -4 and `2^-1` is 0.5.  NUMBER is a C floating-point literal as
 * strtod reads it; a lone literal gives exactly strtod's double, so a value that
 * save wrote reads back to the bit.  FUNCTION is one of sqrt sin cos tan asin
 * acos atan2 exp log abs min max.  Reading stops before the first character that
 * cannot go on (a ',' or ')' that closes nothing, the end, or anything else), so
 * the caller reads vectors and what follows.
 *
 * Every error names its place: the position in the text of the token it is
 * about (the operator whose result is not finite, the unknown name, the '('
 * left open).
 */
#ifndef VROC_EXPR_H
#define VROC_EXPR_H

#include <stdbool.h>
#include <stddef.h>

/* What a value is, for `deg`: an angle in radians (deg converts degrees to it),
 * a number of degrees already (fov: deg would convert twice), or neither. */
typedef enum { EXPR_PLAIN, EXPR_RADIANS, EXPR_DEGREES } expr_unit;

/* How deep parentheses, unary signs and powers may nest (a hostile line cannot
 * exhaust the stack). */
#define EXPR_MAX_DEPTH 200

typedef struct {
    const char *what; /* the value's name, for messages ("radius") */
    expr_unit unit;
} expr_opts;

/* Reads one expression from *p (NUL-terminated text).  Returns 0 with its value
 * in *out and *p just after it (before any white space that follows), or -1 with
 * a message in msg and *p at the place the error is about. */
int expr_read(const char **p, const expr_opts *o, double *out, char *msg, size_t msglen);

/* Skips spaces and tabs. */
const char *expr_skip(const char *p);

/* The token at p for a message: 'word', the number as written, or the one
 * character, quoted as tok_text quotes (lex.h); "the end" at the end. */
const char *expr_token_text(const char *p, char buf[96]);

#endif
