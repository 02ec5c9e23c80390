/* fmt.h: numbers as text that reads back to the bit, for messages and for the
 * statements vroc writes; and messages made safe to print. */
#ifndef VROC_FMT_H
#define VROC_FMT_H

/* The shortest text of x that reads back to exactly x ("%.17g" at most). */
const char *fmt_num(char buf[32], double x);

#include <stdio.h>

/* Writes s to f with every byte that is not printable text escaped as \xHH:
 * control characters (newlines and tabs too), DEL, and bytes that are not
 * well-formed UTF-8 or encode a control character.  What a message quotes from a
 * file or a command line (a word, a path, a row) cannot then write raw bytes to a
 * terminal, nor break the message's line. */
void fmt_escaped(FILE *f, const char *s);

#endif
