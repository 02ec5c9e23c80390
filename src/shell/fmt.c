/* fmt.c: numbers as text that reads back to the bit (fmt.h). */
#include <math.h>
#include "fmt.h"

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
