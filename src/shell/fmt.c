/* fmt.c: numbers as text, to the bit or as a person reads them (fmt.h). */
#include "fmt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *fmt_num(char buf[32], double x)
{
    if (x == 0) return strcpy(buf, signbit(x) ? "-0" : "0"); /* -0 reads back as -0 */
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, 32, "%.*g", prec, x);
        if (strtod(buf, NULL) == x) break;
    }
    return buf;
}

const char *fmt_shown(char buf[32], double x, fmt_style s)
{
    if (s == FMT_EXACT) return fmt_num(buf, x);
    /* %g drops trailing zeros; -0 is shown as 0 */
    snprintf(buf, 32, "%.*g", FMT_DIGITS, x == 0 ? 0.0 : x);
    return buf;
}

void fmt_shown_vec(char out[][32], const double *v, int n, fmt_style s)
{
    double big = 0;
    for (int k = 0; k < n; k++)
        if (fabs(v[k]) > big) big = fabs(v[k]);
    for (int k = 0; k < n; k++)
        fmt_shown(out[k], s == FMT_SHORT && fabs(v[k]) < 1e-12 * big ? 0.0 : v[k], s);
}

/* The length of the well-formed UTF-8 sequence of a printable character at s
 * (1 for printable ASCII), or 0. */
static int printable_at(const unsigned char *s)
{
    unsigned char c = s[0];
    if ((c >= 0x20 && c < 0x7f) || c == '\n') return 1;
    int n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    if (n == 0) return 0;
    /* the second byte's range: no overlong forms, no surrogates, nothing past U+10FFFF */
    unsigned char lo = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80;
    unsigned char hi = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
    if (s[1] < lo || s[1] > hi) return 0;
    for (int k = 2; k < n; k++)
        if (s[k] < 0x80 || s[k] > 0xbf) return 0;
    if (c == 0xc2 && s[1] < 0xa0) return 0; /* U+0080..U+009F: the C1 controls */
    return n;
}

void fmt_escaped(FILE *f, const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    while (*p) {
        int n = printable_at(p);
        if (n > 0) {
            fwrite(p, 1, (size_t)n, f);
            p += n;
        } else {
            fprintf(f, "\\x%02x", *p);
            p++;
        }
    }
}
