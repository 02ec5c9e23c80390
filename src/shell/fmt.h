/* fmt.h: numbers as text: to the bit, for the statements vroc writes back (save,
 * trace, events, messages), or as a person reads them (print, show, distance,
 * stats, energy, the prompt; language.md, `precision`); and messages made safe
 * to print. */
#ifndef VROC_FMT_H
#define VROC_FMT_H

#include <stdio.h>

/* The shortest text of x that reads back to exactly x ("%.17g" at most). */
const char *fmt_num(char buf[32], double x);

/* How numbers are shown: FMT_SHORT, 12 significant digits with trailing zeros
 * dropped and -0 shown as 0; FMT_EXACT, fmt_num's text.  (The order is
 * `precision`'s choices: short|exact.) */
typedef enum { FMT_SHORT, FMT_EXACT } fmt_style;

/* Significant digits of FMT_SHORT. */
#define FMT_DIGITS 12

/* x in style s. */
const char *fmt_shown(char buf[32], double x, fmt_style s);

/* The components of a vector shown in style s into out[0..n-1]: with FMT_SHORT
 * a component below 1e-12 of the largest is shown as 0 (what is left of a
 * rounding, beside the part that matters). */
void fmt_shown_vec(char out[][32], const double *v, int n, fmt_style s);

/* Writes s to f with every byte that is not printable text escaped as \xHH:
 * control characters (tabs too) but the newline, DEL, and bytes that are not
 * well-formed UTF-8 or encode a control character.  What a message quotes from a
 * file or a command line (a word, a path, a row) cannot then write raw bytes to a
 * terminal.  (A newline stays: a message may have lines of its own, as an
 * expression's error points at its column; no word, path or row vroc quotes
 * holds one.) */
void fmt_escaped(FILE *f, const char *s);

#endif
