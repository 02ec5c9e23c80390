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
