/* font.c: the stroke font of the tool panel's labels (font.h).
 *
 * Each glyph is a list of strokes separated by spaces; a stroke is a polyline
 * written as digit pairs, x then y, on a grid of x 0..4 and y 0..6 (the baseline
 * at y = 0).  "0004264440 0343" is an A: up the left side, over the apex, down the
 * right side, and the bar.
 */
#include "font.h"

#include "gl_load.h"
#include <string.h>

#define FONT_W 4.0   /* grid units of a glyph's width */
#define FONT_H 6.0   /*   and height */
#define FONT_GAP 1.5 /* between glyphs */

static const char *const letters[26] = {
    "0004264440 0343",                  /* A */
    "00063645443303 3342413000",        /* B */
    "4536160501103041",                 /* C */
    "00063645413000",                   /* D */
    "46060040 0333",                    /* E */
    "460600 0333",                      /* F */
    "45361605011030414323",             /* G */
    "0006 4640 0343",                   /* H */
    "1636 2620 1030",                   /* I */
    "4641301001",                       /* J */
    "0006 4602 1340",                   /* K */
    "060040",                           /* L */
    "0006244640",                       /* M */
    "00064046",                         /* N */
    "100105163645413010",               /* O */
    "00063645443303",                   /* P */
    "100105163645413010 2240",          /* Q */
    "00063645443303 2340",              /* R */
    "453616050413334241301001",         /* S */
    "0646 2620",                        /* T */
    "060110304146",                     /* U */
    "062046",                           /* V */
    "0610233046",                       /* W */
    "0046 0640",                        /* X */
    "0623 4623 2320",                   /* Y */
    "06464000",                         /* Z */
};

static const char *const digits[10] = {
    "100105163645413010 1135",          /* 0 */
    "152620 1030",                      /* 1 */
    "05163645440040",                   /* 2 */
    "05163645443313 334241301001",      /* 3 */
    "30360242",                         /* 4 */
    "4606033342413000",                 /* 5 */
    "4536160501103041423303",           /* 6 */
    "064610",                           /* 7 */
    "13040516364544331302011030414233", /* 8 */
    "4313040516364541301001",           /* 9 */
};

/* The strokes of character c, or "" for none. */
static const char *glyph(char c)
{
    if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
    if (c >= 'A' && c <= 'Z') return letters[c - 'A'];
    if (c >= '0' && c <= '9') return digits[c - '0'];
    switch (c) {
    case '.': return "1020211110";
    case '_': return "0040";
    case '-': return "1343";
    case ':': return "2122 2425";
    default: return "";
    }
}

double font_width(const char *text, double h)
{
    size_t n = strlen(text);
    return n == 0 ? 0 : h / FONT_H * ((double)n * (FONT_W + FONT_GAP) - FONT_GAP);
}

void font_draw(const char *text, double x, double y, double z, double h)
{
    double s = h / FONT_H;
    for (const char *c = text; *c; c++, x += s * (FONT_W + FONT_GAP)) {
        const char *g = glyph(*c);
        while (*g) {
            glBegin(GL_LINE_STRIP);
            for (; g[0] >= '0' && g[0] <= '9' && g[1] >= '0' && g[1] <= '9'; g += 2)
                glVertex3d(x + s * (g[0] - '0'), y + s * (g[1] - '0'), z);
            glEnd();
            while (*g == ' ') g++;
        }
    }
}
