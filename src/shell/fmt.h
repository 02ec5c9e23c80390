/* fmt.h: numbers as text that reads back to the bit, for messages and for the
 * statements vroc writes. */
#ifndef VROC_FMT_H
#define VROC_FMT_H

/* The shortest text of x that reads back to exactly x ("%.17g" at most). */
const char *fmt_num(char buf[32], double x);

#endif
