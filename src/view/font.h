/* font.h: a small stroke font for the tool panel's labels, drawn with OpenGL lines
 * (no font files).
 *
 * Upper-case letters, digits and . _ - : and space, each a few strokes on a grid
 * four units wide and six tall; lower-case letters are drawn as upper case, and
 * other characters as a blank.  A label of height h (metres, in the current
 * model-view's units) is 5.5 h / 6 per character wide.
 */
#ifndef VROC_FONT_H
#define VROC_FONT_H

/* The width of text at height h. */
double font_width(const char *text, double h);

/* Draws text in the current model-view's x-y plane at depth z, its baseline's left
 * end at (x, y), h tall, as GL_LINE_STRIPs in the current colour (lighting off). */
void font_draw(const char *text, double x, double y, double z, double h);

#endif
